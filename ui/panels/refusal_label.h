#pragma once
// Under an editing panel: why the last edit was not applied ("Not applied: duration must be
// positive…"), in red, hidden once an edit goes through. The panels that edit the design
// through MechanismDocument::edit share it, so a refusal reads the same everywhere.

#include <QLabel>

#include <optional>

namespace linkwright::ui {

class RefusalLabel : public QLabel {
  Q_OBJECT
public:
  explicit RefusalLabel(QWidget* parent = nullptr);

  /// Shows "Not applied: <refusal>", or hides the label when there is none.
  void showOutcome(const std::optional<QString>& refusal);
  /// The refusal shown; empty when hidden.
  QString refusal() const;
};

}  // namespace linkwright::ui
