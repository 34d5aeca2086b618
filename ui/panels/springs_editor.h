#pragma once
// The dynamics panel's springs: a table of the design's springs (stiffness, free length and
// preload editable, each row named by its ends), Remove for the selected one, and a row that adds
// a spring between two chosen points (a point on a link, or a ground point on the frame), at
// 1000 N/m with its free length the ends' distance now, so it starts unloaded. Edits go through
// the panel's submit (one undoable design edit each; a refusal is shown by the panel).

#include "kinematics/dynamics/mass_properties.h"

#include <QGroupBox>

#include <functional>
#include <vector>

class QComboBox;
class QPushButton;

namespace linkwright::ui {

class MassTable;
class MechanismDocument;

class SpringsEditor : public QGroupBox {
  Q_OBJECT
public:
  using Submit = std::function<void(const QString&, const std::function<void(kinematics::LinkageDynamics&)>&)>;
  using Refuse = std::function<void(const QString&)>;

  SpringsEditor(MechanismDocument* document, Submit submit, Refuse refuse, QWidget* parent = nullptr);

  /// Shows the document's springs and the points their ends may go on.
  void refresh();

  /// Columns: spring, stiffness [N/m], free length [length unit], preload [N].
  MassTable* table() const { return m_table; }
  QComboBox* firstEndBox() const { return m_first; }
  QComboBox* secondEndBox() const { return m_second; }
  QPushButton* addButton() const { return m_add; }
  QPushButton* removeButton() const { return m_remove; }

  /// The stiffness a new spring starts with, N/m.
  static constexpr double kNewStiffness = 1000.0;

private:
  void edit(int row, int column, std::optional<double> value, bool parsed);
  void add();
  void removeSelected();

  MechanismDocument* m_document;
  Submit m_submit;
  Refuse m_refuse;
  MassTable* m_table;
  QComboBox* m_first;
  QComboBox* m_second;
  QPushButton* m_add;
  QPushButton* m_remove;
  std::vector<kinematics::SpringEnd> m_ends;  // per combo item
};

}  // namespace linkwright::ui
