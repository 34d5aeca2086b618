#pragma once
// What the synthesis panel shows for one solved problem: its candidates in the order the
// table lists them, each with the input its preview is drawn at and the targets drawn with it,
// and how the problem's error reads. Plain values, made by synthesis_solve.h from the core's
// results; the table, the preview and the panel only read them.

#include "kinematics/design/synthesis_targets.h"
#include "kinematics/synthesis/candidate.h"
#include "kinematics/synthesis/motion_generation.h"

#include <Eigen/Core>

#include <QString>

#include <vector>

namespace linkwright::ui {

/// The problems the panel offers, in its chooser's order: the core's (synthesis_targets.h).
using kinematics::SynthesisProblem;
inline constexpr int kSynthesisProblemCount = 6;

/// What the preview marks besides the linkage (length unit, model frame).
struct PreviewMarks {
  std::vector<Eigen::Vector2d> points;         ///< crosses
  std::vector<kinematics::CouplerPose> poses;  ///< a point with a short arrow along its angle
  bool operator==(const PreviewMarks&) const = default;
};

/// One row of the candidates table.
struct SynthesisRow {
  kinematics::SynthesisCandidate candidate;
  QString label;              ///< the index column: "best", "1", "2", …
  double previewInput = 0.0;  ///< the design's input (rad) at its first target: the preview's pose
  PreviewMarks targets;       ///< this candidate's own marks (a rocker's limit positions, say)
  bool operator==(const SynthesisRow&) const = default;
};

struct SynthesisOutcome {
  std::vector<SynthesisRow> rows;
  PreviewMarks targets;     ///< the problem's targets, marked whichever row is chosen
  QString errorUnit;        ///< the error column's unit: the length unit, or "°"
  bool exact = false;       ///< a construction that meets its targets exactly: the column reads "exact"
  double errorScale = 1.0;  ///< shown error = candidate.error × errorScale (rad → ° for angles)
  QString summary;          ///< one line under the table ("41 crank-rockers, best μ 47.3°")
  bool operator==(const SynthesisOutcome&) const = default;
};

}  // namespace linkwright::ui
