#pragma once
// The velocity and acceleration polygons at one crank angle as JSON
// (kinematics/analysis/vector_polygon.h), written once for linkwright-cli polygon --json and
// Python's Linkage.polygons: the crank's state, then each polygon's unit, box, equations,
// vectors in drawing order and images, lengths in the linkage's unit.

#include "kinematics/analysis/vector_polygon.h"
#include "kinematics/io/json.h"

namespace linkwright::kinematics::io {

/// One polygon: unit, box {lower, upper}, equations [{text, ends, solver}], vectors [{step,
/// label, from, to, magnitude, meaning}], images [{label, position, coincident}].
JsonValue polygonJson(const VectorPolygon& polygon);

/// Both polygons at crank angle `crankAngleDeg` (degrees) and the driver's ω and α (rad/s,
/// rad/s²): {crank_angle_deg, omega_rad_s, alpha_rad_s2, velocity, acceleration}.
JsonValue polygonsJson(double crankAngleDeg, const DriverState& driver, const ClassroomPolygons& polygons);

}  // namespace linkwright::kinematics::io
