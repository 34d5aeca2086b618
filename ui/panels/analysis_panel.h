#pragma once
// What the linkage is. For a four-bar: a Grashof badge (class, S+L against P+Q, which link is
// shortest), the transmission angle now and over the cycle, the rocker's limit positions and
// the time ratio. For any other linkage: its kind, the transmission angle at each dyad joint,
// a quick return's time ratio and stroke, and the crank angles where it cannot be assembled.
// Always the mobility and the crank's range. All numbers come from the document; rows that
// do not apply are hidden. Shown in two columns over the canvas (the window's answers strip).

#include <QHash>
#include <QWidget>

class QGridLayout;
class QHBoxLayout;
class QLabel;

namespace linkwright::ui {

class MechanismDocument;
class ReadoutLabel;

class AnalysisPanel : public QWidget {
  Q_OBJECT
public:
  explicit AnalysisPanel(MechanismDocument* document, QWidget* parent = nullptr);

  QString grashofText() const;
  QString transmissionNowText() const;
  QString timeRatioText() const;
  QString strokeText() const;
  QString notAssembledText() const;
  QString mobilityText() const;

private:
  void refreshDesign();
  QGridLayout* addColumn(QHBoxLayout* strip);
  void addRow(QGridLayout* grid, const QString& name, QWidget* field);
  void showRow(QWidget* field, bool shown);
  void refreshFourBar();
  void refreshLinkage();
  void refreshMotion();

  MechanismDocument* m_document;
  QGridLayout* m_left;                // what the linkage is
  QGridLayout* m_right;               // how it moves
  QHash<QWidget*, QLabel*> m_labels;  // each value's row label
  QLabel* m_badge;
  ReadoutLabel* m_sums;
  QLabel* m_mobility;
  ReadoutLabel* m_range;
  ReadoutLabel* m_transmissionNow;
  ReadoutLabel* m_transmissionRange;
  ReadoutLabel* m_limits;
  ReadoutLabel* m_timeRatio;
  ReadoutLabel* m_stroke;
  ReadoutLabel* m_notAssembled;
  QLabel* m_warning;
};

}  // namespace linkwright::ui
