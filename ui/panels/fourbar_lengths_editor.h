#pragma once
// The dimensions panel's face for a recognised four-bar (model/recognise.h), however it was
// built or stored: its frame, crank, coupler and rocker lengths by name, each a spin box for
// exact values and a slider for quick changes, and the point P on its coupler. Edits go
// through the core's fourbar_dimensions.h and the document (validated, undoable); the outcome
// is reported with edited() so the panel shows a refusal, and the editors snap back to the
// document's values.

#include <QWidget>

#include <array>
#include <optional>

class QCheckBox;

namespace linkwright::ui {

class LengthEditor;
class MechanismDocument;

class FourBarLengthsEditor : public QWidget {
  Q_OBJECT
public:
  explicit FourBarLengthsEditor(MechanismDocument* document, QWidget* parent = nullptr);

  /// The editor of frame (0), crank (1), coupler (2), rocker (3).
  LengthEditor* lengthEditor(int index) const { return m_lengths[static_cast<std::size_t>(index)]; }
  /// Shows the document's four-bar (call only while it is one).
  void refresh();
  /// Sliders span a fixed range per document so that they do not jump while in use.
  void resetSliderRanges();

signals:
  /// After each edit: the refusal's reason, or nothing if it was applied.
  void edited(const std::optional<QString>& refusal);

private:
  void editLength(int index, double value, bool final);
  void editCouplerPoint();

  MechanismDocument* m_document;
  std::array<LengthEditor*, 4> m_lengths{};
  QCheckBox* m_hasCouplerPoint;
  LengthEditor* m_along;
  LengthEditor* m_across;
  int m_dragSerial = 0;  // separates consecutive slider drags into their own undo steps
};

}  // namespace linkwright::ui
