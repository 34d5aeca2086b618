#pragma once
// What the linkage is: a Grashof badge (class, S+L against P+Q, which link is shortest), the
// mobility, the transmission angle now and over the cycle, the rocker's limit positions, the
// time ratio, and the crank's assemblable range. All numbers come from the document.

#include <QWidget>

class QLabel;

namespace linkwright::ui {

class MechanismDocument;

class AnalysisPanel : public QWidget {
  Q_OBJECT
public:
  explicit AnalysisPanel(MechanismDocument* document, QWidget* parent = nullptr);

  QString grashofText() const;
  QString transmissionNowText() const;

private:
  void refreshDesign();
  void refreshMotion();

  MechanismDocument* m_document;
  QLabel* m_badge;
  QLabel* m_sums;
  QLabel* m_mobility;
  QLabel* m_range;
  QLabel* m_transmissionNow;
  QLabel* m_transmissionRange;
  QLabel* m_limits;
  QLabel* m_timeRatio;
  QLabel* m_warning;
};

} // namespace linkwright::ui
