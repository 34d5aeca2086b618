#pragma once
// The sampling quality of the plots, with what it costs and what it buys on this design: a
// Draft / Normal / Precise box, then the samples per revolution and the measured sweep time,
// then the worst peak error read off those samples (measured by the document, see
// ui/document/quality_estimate.h), or why it cannot be measured. Shows, computes nothing.

#include "ui/document/mechanism_document.h"

#include <QWidget>

class QComboBox;
class QLabel;

namespace linkwright::ui {

class ReadoutLabel;

class QualityBar : public QWidget {
  Q_OBJECT
public:
  explicit QualityBar(MechanismDocument* document, QWidget* parent = nullptr);

  QComboBox* qualityBox() const { return m_box; }
  /// "380 samples/rev · sweep 0.42 ms"
  QString costText() const;
  /// "worst peak error 1.1 × 10⁻⁴", or "peak error not measurable: …"
  QString errorText() const;

  /// The text of a relative error: "1.1 × 10⁻⁴"; "< 10⁻¹⁵" below round-off.
  static QString formatRelative(double error);

signals:
  /// The user picked a quality (the document has it already).
  void qualityChosen(linkwright::ui::SamplingQuality quality);

protected:
  void changeEvent(QEvent* event) override;

private:
  void reserveErrorLines();
  void refreshCost();
  void refreshError();

  MechanismDocument* m_document;
  QComboBox* m_box;
  ReadoutLabel* m_cost;  // changes with every sweep: a drag must not re-lay out the window
  QLabel* m_error;
};

}  // namespace linkwright::ui
