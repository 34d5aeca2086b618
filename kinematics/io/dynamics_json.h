#pragma once
// A linkage's masses and loads (LinkageDynamics, mass_properties.h) as the optional
// "dynamics" member of a Linkwright document (version 3; see document_json.h). Links are keyed
// by name; positions on a link are in the document's length unit, everything else SI with the
// unit in the member's name. Members that are empty or default are left out.
//
//   "dynamics": {
//     "links": {
//       "crank": {"mass_kg": 0.2, "centre": {"along": 5, "across": 0}, "inertia_kg_m2": 1e-05},
//       "coupler": {"mass_kg": 0.6}                 (centre: the midpoint; inertia: m·L²/12)
//     },
//     "sliders": [{"point": "C", "mass_kg": 0.5, "inertia_kg_m2": 0}],   ("guide": 1 for a prp's second)
//     "gravity_m_s2": {"x": 0, "y": -9.80665},                            (absent: no gravity)
//     "torques": [{"link": "rocker", "torque_N_m": -2}],
//     "forces": [{"link": "coupler", "point": "P", "x_N": 5, "y_N": -12},
//                {"slider": "C", "x_N": -3000, "y_N": 0}]
//   }

#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/io/json_reader.h"
#include "kinematics/model/mechanism.h"

#include <optional>
#include <ostream>

namespace linkwright::kinematics::io {

/// Writes `,\n  "dynamics": {…}` (indented for the document's root) unless `dynamics` is empty.
void writeDynamicsMember(std::ostream& out, const LinkageDynamics& dynamics);

/// Reads the optional member "dynamics" of the document's root (empty if absent). Errors
/// (missing or mistyped members) go to `reader`, naming the path ("dynamics.links.crank.mass_kg").
LinkageDynamics readDynamicsMember(const JsonValue& root, JsonReader& reader);

/// checkDynamics, with the error's field and message naming the document's member
/// ("dynamics.links.coupler.mass_kg must be finite and ≥ 0 (got -1)").
std::optional<Error> checkDocumentDynamics(const Mechanism& mechanism, const LinkageDynamics& dynamics);

}  // namespace linkwright::kinematics::io
