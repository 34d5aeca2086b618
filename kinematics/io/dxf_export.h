#pragma once
// Writes a link drawing (link_drawing.h) as an AutoCAD R2000 (AC1015) ASCII DXF file with
// dxflib, the DXF library behind QCAD, so LibreCAD, QCAD, FreeCAD and ezdxf read it: one layer
// per part (GROUND first), outlines as closed LWPOLYLINEs with bulges, holes as CIRCLEs, the
// ground pivots' crosses as LINEs. $INSUNITS names the length unit (dxfInsUnits). Every real
// is printed as the shortest decimal that reads back as the same double (dxflib's own
// "%.16f" keeps fewer than 17 significant digits below 1). Built as its own library
// (linkwright_dxf) so the core stays free of dxflib; the CLI and the designer link it.

#include "kinematics/analysis/link_drawing.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"

#include <optional>
#include <string>

namespace linkwright::kinematics::io {

/// The DXF $INSUNITS code of a length unit: in 1, ft 2, mi 3, mm 4, cm 5, m 6, km 7, yd 10,
/// nm 12, um 13, dm 14; 0 (unitless) for any other name.
int dxfInsUnits(const std::string& lengthUnit);

/// Writes `drawing` to `path` whole or not at all (a temporary file beside it, renamed over
/// it). nullopt on success, else an Error (field "output") naming the file and the reason.
std::optional<Error> writeDxf(const LinkDrawing& drawing, const std::string& path);

/// The drawing of `mechanism` at `pose` (linkDrawing) written to `path` (writeDxf): the
/// designer's File ▸ Export ▸ DXF and the CLI's dxf command in one call. On any error nothing
/// is written.
std::optional<Error> exportLinkDrawingDxf(const Mechanism& mechanism, const Pose& pose, const DrawingOptions& options,
                                          const std::string& path);

}  // namespace linkwright::kinematics::io
