#include "ui/panels/springs_editor.h"

#include "ui/document/mechanism_document.h"
#include "ui/panels/link_points.h"
#include "ui/panels/mass_table.h"
#include "ui/quiet_update.h"

#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>

#include <variant>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

QString endText(const k::SpringEnd& end) {
  return end.link.empty()
             ? SpringsEditor::tr("%1 on the frame").arg(QString::fromStdString(end.point))
             : SpringsEditor::tr("%1 on %2").arg(QString::fromStdString(end.point), QString::fromStdString(end.link));
}

// A name no spring of `springs` has: "spring", "spring2", …
std::string freeName(const std::vector<k::Spring>& springs) {
  const auto taken = [&](const std::string& name) {
    for (const k::Spring& s : springs)
      if (s.name == name) return true;
    return false;
  };
  std::string name = "spring";
  for (int n = 2; taken(name); ++n) name = "spring" + std::to_string(n);
  return name;
}

}  // namespace

SpringsEditor::SpringsEditor(MechanismDocument* document, Submit submit, Refuse refuse, QWidget* parent)
    : QGroupBox(tr("Springs"), parent), m_document(document), m_submit(std::move(submit)), m_refuse(std::move(refuse)),
      m_table(new MassTable({tr("Spring"), tr("Stiffness\n[N/m]"), tr("Free length"), tr("Preload\n[N]")})),
      m_first(new QComboBox), m_second(new QComboBox), m_add(new QPushButton(tr("Add spring"))),
      m_remove(new QPushButton(tr("Remove"))) {
  // The two ends one below the other: side by side they wanted 343 px, more than a projector's
  // side column has.
  auto* layout = new QGridLayout(this);
  layout->addWidget(m_table, 0, 0, 1, 2);
  layout->addWidget(new QLabel(tr("From")), 1, 0);
  layout->addWidget(m_first, 1, 1);
  layout->addWidget(new QLabel(tr("to")), 2, 0);
  layout->addWidget(m_second, 2, 1);
  auto* buttons = new QHBoxLayout;
  buttons->addStretch(1);
  buttons->addWidget(m_add);
  buttons->addWidget(m_remove);
  layout->addLayout(buttons, 3, 0, 1, 2);
  layout->setColumnStretch(1, 1);
  for (QComboBox* box : {m_first, m_second}) {
    box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    box->setMinimumContentsLength(6);
  }
  m_add->setToolTip(tr("A spring of %1 N/m between the two points, unloaded where they are now").arg(kNewStiffness));
  m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
  connect(m_table, &MassTable::cellEdited, this, &SpringsEditor::edit);
  connect(m_add, &QPushButton::clicked, this, &SpringsEditor::add);
  connect(m_remove, &QPushButton::clicked, this, &SpringsEditor::removeSelected);
  connect(m_table, &QTableWidget::itemSelectionChanged, this,
          [this] { m_remove->setEnabled(!m_table->selectedItems().isEmpty()); });
  refresh();
}

void SpringsEditor::refresh() {
  const k::Mechanism& m = m_document->mechanism();
  const std::vector<k::Spring>& springs = m_document->design().dynamics.loads.springs;
  m_table->setHeaderText(2, tr("Free length\n[%1]").arg(QString::fromStdString(m_document->lengthUnit())));
  QStringList names;
  std::vector<std::vector<MassTable::Cell>> cells;
  for (const k::Spring& s : springs) {
    names << tr("%1: %2 → %3").arg(QString::fromStdString(s.name), endText(s.first), endText(s.second));
    cells.push_back({{s.stiffness, {}, {}}, {s.freeLength, {}, {}}, {s.preload, {}, {}}});
  }
  m_table->setRows(names, cells);
  m_remove->setEnabled(!m_table->selectedItems().isEmpty());

  m_ends.clear();
  for (const LinkPoint& p : pointsOnLinks(m)) m_ends.push_back({p.link, p.point});
  for (const k::Point& p : m.points)
    if (std::holds_alternative<k::GroundPoint>(p.definition)) m_ends.push_back({"", p.name});
  QStringList items;
  for (const k::SpringEnd& end : m_ends) items << endText(end);
  for (QComboBox* box : {m_first, m_second}) {
    const QSignalBlocker block(box);
    const int kept = box->currentIndex();
    setComboItems(box, items);
    box->setCurrentIndex(kept >= 0 && kept < box->count() ? kept : 0);
  }
  if (m_second->currentIndex() == m_first->currentIndex() && m_second->count() > 1)
    m_second->setCurrentIndex(m_second->count() - 1);  // a frame point, unlike the first
  m_add->setEnabled(m_ends.size() > 1);
}

void SpringsEditor::edit(int row, int column, std::optional<double> value, bool parsed) {
  const std::vector<k::Spring>& springs = m_document->design().dynamics.loads.springs;
  if (row < 0 || static_cast<std::size_t>(row) >= springs.size()) return;
  if (!parsed || !value) {
    m_refuse(tr("A spring's %1 needs a number.")
                 .arg(column == 1   ? tr("stiffness")
                      : column == 2 ? tr("free length")
                                    : tr("preload")));
    refresh();
    return;
  }
  const auto index = static_cast<std::size_t>(row);
  m_submit(tr("Change spring %1").arg(QString::fromStdString(springs[index].name)), [&](k::LinkageDynamics& d) {
    k::Spring& s = d.loads.springs[index];
    (column == 1 ? s.stiffness : column == 2 ? s.freeLength : s.preload) = *value;
  });
}

void SpringsEditor::add() {
  const int a = m_first->currentIndex(), b = m_second->currentIndex();
  if (a < 0 || b < 0 || static_cast<std::size_t>(a) >= m_ends.size() || static_cast<std::size_t>(b) >= m_ends.size())
    return;
  const k::SpringEnd first = m_ends[static_cast<std::size_t>(a)], second = m_ends[static_cast<std::size_t>(b)];
  const k::Mechanism& m = m_document->mechanism();
  const auto& position = m_document->pose().position;
  const auto p = m.findPoint(first.point), q = m.findPoint(second.point);
  if (!p || !q || p->index >= position.size() || q->index >= position.size()) return;
  const double length = (position[q->index] - position[p->index]).norm();
  const std::string name = freeName(m_document->design().dynamics.loads.springs);
  // The undo step names the spring by its ends, as its row does ("Undo Add a spring from C to A").
  m_submit(
      tr("Add a spring from %1 to %2").arg(QString::fromStdString(first.point), QString::fromStdString(second.point)),
      [&](k::LinkageDynamics& d) {
        d.loads.springs.push_back({name, first, second, kNewStiffness, length, 0.0});
      });
}

void SpringsEditor::removeSelected() {
  const QList<QTableWidgetItem*> selected = m_table->selectedItems();
  if (selected.isEmpty()) return;
  const auto row = static_cast<std::size_t>(selected.front()->row());
  const std::vector<k::Spring>& springs = m_document->design().dynamics.loads.springs;
  if (row >= springs.size()) return;
  m_submit(tr("Remove spring %1").arg(QString::fromStdString(springs[row].name)), [&](k::LinkageDynamics& d) {
    d.loads.springs.erase(d.loads.springs.begin() + static_cast<std::ptrdiff_t>(row));
  });
}

}  // namespace linkwright::ui
