#pragma once
// The range of each number of the synthesis targets and bounds (synthesis_targets.h) as the
// designer's fields hold it, and so as a document may store it: the document reader
// (io/synthesis_json.cpp) refuses a number outside it, naming the member, the value and the
// range, and the fields cannot hold one. The CLI's options lie within; each synthesis checks
// its own problem's narrower range when it runs, so a target being typed is kept, not refused.

namespace linkwright::kinematics {

/// Lengths, coordinates and plain numbers (a time ratio, x0, x1), in their unit: the input
/// domain's coordinate bound (model/validate.h). Angles are held within as many degrees (the
/// fields show degrees, the targets hold radians).
inline constexpr double kMaxTargetValue = 1e9;

/// The transmission angle a candidate must reach, degrees either way.
inline constexpr double kMaxTransmissionBoundDeg = 1e6;

}  // namespace linkwright::kinematics
