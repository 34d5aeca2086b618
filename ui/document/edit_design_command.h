#pragma once
// One undoable edit of the design: it holds the design (and crank angle) before and after. Consecutive edits
// with the same merge key (the moves of one drag, the steps of one slider) merge into a
// single undo step, keeping the first "before" and the last "after".

#include "kinematics/design/design.h"

#include <QUndoCommand>

#include <cstddef>
#include <optional>

namespace linkwright::ui {

class MechanismDocument;

/// What a continuous edit changes, for merging its steps.
enum class ContinuousEdit { DragPoint, Parameter, Speed, Acceleration, SynthesisTargets };

/// Consecutive edits with equal keys (the moves of one drag, the steps of one slider) merge
/// into one undo step. `serial` tells one drag or press of the same thing from the next, so
/// two drags of a point stay two undo steps.
struct MergeKey {
  ContinuousEdit edit = ContinuousEdit::DragPoint;
  std::size_t item = 0;  ///< the point dragged, or the dimensions field changed
  int serial = 0;
  bool operator==(const MergeKey&) const = default;
};

/// A design (four-bar or any linkage) and the crank angle (rad) it is shown at; on a time
/// base, the instant (s), which sets the angle.
struct DesignState {
  kinematics::Design design;
  double crankAngle = 0.0;
  double time = 0.0;
};

class EditDesignCommand : public QUndoCommand {
public:
  /// Without a merge key the edit never merges. `another`: the after state is another linkage
  /// (MechanismDocument::replace), so undo and redo each bring a different one back.
  EditDesignCommand(MechanismDocument* document, DesignState before, DesignState after, const QString& text,
                    std::optional<MergeKey> mergeKey, bool another = false);

  void undo() override;
  void redo() override;
  /// One id for every mergeable edit (QUndoStack only offers equal ids to mergeWith, which
  /// compares the keys); -1: never merges.
  int id() const override { return m_mergeKey ? 0 : -1; }
  bool mergeWith(const QUndoCommand* other) override;

private:
  MechanismDocument* m_document;
  DesignState m_before;
  DesignState m_after;
  std::optional<MergeKey> m_mergeKey;
  bool m_another;
};

}  // namespace linkwright::ui
