#pragma once
// One undoable edit of the design: it holds the design (and crank angle) before and after. Consecutive edits
// with the same merge key (the moves of one drag, the steps of one slider) merge into a
// single undo step, keeping the first "before" and the last "after".

#include "kinematics/design/mechanism_design.h"

#include <QUndoCommand>

namespace linkwright::ui {

class MechanismDocument;

/// A design (four-bar or any linkage) and the crank angle (rad) it is shown at.
struct DesignState {
  kinematics::Design design;
  double crankAngle = 0.0;
};

class EditDesignCommand : public QUndoCommand {
public:
  /// `mergeKey` < 0: never merges.
  EditDesignCommand(MechanismDocument* document, DesignState before, DesignState after, const QString& text, int mergeKey);

  void undo() override;
  void redo() override;
  int id() const override { return m_mergeKey; }
  bool mergeWith(const QUndoCommand* other) override;

private:
  MechanismDocument* m_document;
  DesignState m_before;
  DesignState m_after;
  int m_mergeKey;
};

/// Merge keys of the continuous edits; each drag handle and slider has its own. Callers
/// multiply a key by 1000 and add a serial number, so two drags stay two undo steps.
namespace merge {
inline constexpr int kDragO2 = 1;
inline constexpr int kDragO4 = 2;
inline constexpr int kDragB = 3;
inline constexpr int kDragC = 4;
inline constexpr int kDragCouplerPoint = 5;
inline constexpr int kFrameLength = 10;
inline constexpr int kCrankLength = 11;
inline constexpr int kCouplerLength = 12;
inline constexpr int kRockerLength = 13;
inline constexpr int kSpeed = 20;
inline constexpr int kAlpha = 21;
/// A dimension field of any linkage: kDimension + field number (dimensions panel).
inline constexpr int kDimension = 100;
/// A drag of point i of any linkage: kDragPoint + i.
inline constexpr int kDragPoint = 1000;
} // namespace merge

} // namespace linkwright::ui
