#pragma once
// Under an editing panel: why the last edit was not applied ("Not applied: duration must be
// positive…"), in red, hidden once an edit goes through. The panels that edit the design
// through MechanismDocument::edit share it, so a refusal reads the same everywhere. A refusal
// is about the design it was made for: once that design is replaced (an accepted edit, undo,
// redo, another example, File ▸ New or Open) the label hides.

#include <QLabel>

#include <optional>

namespace linkwright::ui {

class MechanismDocument;

class RefusalLabel : public QLabel {
  Q_OBJECT
public:
  /// Refusals of edits to `document`'s design.
  RefusalLabel(const MechanismDocument* document, QWidget* parent);

  /// Shows "Not applied: <refusal>", or hides the label when there is none.
  void showOutcome(const std::optional<QString>& refusal);
  /// The refusal shown; empty when hidden.
  QString refusal() const;
};

}  // namespace linkwright::ui
