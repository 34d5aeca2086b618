#pragma once
// The side panel where a four-bar's lengths are typed or slid: frame, crank, coupler, rocker,
// and the coupler point's offsets (other linkages have the dimensions panel instead). Every change goes through the document (validated, undoable); a
// refused change shows why and the editors snap back to the document's values.

#include <QWidget>

#include <array>

class QCheckBox;
class QLabel;

namespace linkwright::ui {

class LengthEditor;
class MechanismDocument;
enum class Change;

class LengthsPanel : public QWidget {
  Q_OBJECT
public:
  explicit LengthsPanel(MechanismDocument* document, QWidget* parent = nullptr);

  /// The editor of frame (0), crank (1), coupler (2), rocker (3).
  LengthEditor* lengthEditor(int index) const { return m_lengths[static_cast<std::size_t>(index)]; }
  /// The message shown when the last edit was refused (empty if it was accepted).
  QString refusalMessage() const;

private:
  void refresh();
  void resetSliderRanges();
  void editLength(int index, double value, bool final);
  void editCouplerPoint();
  void showRefusal(const QString& reason);

  MechanismDocument* m_document;
  std::array<LengthEditor*, 4> m_lengths{};
  QCheckBox* m_hasCouplerPoint;
  LengthEditor* m_along;
  LengthEditor* m_across;
  QLabel* m_message;
  int m_dragSerial = 0;
  bool m_hadFourBar = true;  // separates consecutive slider drags into their own undo steps
};

}  // namespace linkwright::ui
