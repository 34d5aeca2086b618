#pragma once
// One cell of the Inversions window: its title ("Ground: crank"), the textbook class, which
// link is driven, and the inversion drawn and animated: a document of its own holding the
// inversion's design, a read-only LinkageView on it and a CrankAnimator that plays it (rocking a
// crank that cannot turn fully). An inversion the core cannot build shows the core's note
// instead of a drawing.

#include "ui/classroom/inversion_cells.h"

#include <QFrame>

class QLabel;
class QStackedWidget;

namespace linkwright::ui {

class CrankAnimator;
class LinkageView;
class MechanismDocument;

class InversionCellPanel : public QFrame {
  Q_OBJECT
public:
  explicit InversionCellPanel(QWidget* parent = nullptr);

  /// Shows `cell`. The crank stays where it was when the cell shows the same kind of linkage
  /// again (the designer's lengths changed), within the new range.
  void setCell(const InversionCell& cell);

  /// Whether a linkage is drawn (else the note is shown).
  bool hasLinkage() const { return m_hasLinkage; }
  QString title() const;
  QString className() const;
  QString detail() const;
  QString note() const;
  MechanismDocument* document() const { return m_document; }
  LinkageView* view() const { return m_view; }
  CrankAnimator* animator() const { return m_animator; }

private:
  MechanismDocument* m_document;
  CrankAnimator* m_animator;
  LinkageView* m_view;
  QLabel* m_title;
  QLabel* m_class;
  QLabel* m_detail;
  QLabel* m_note;
  QStackedWidget* m_stack;
  bool m_hasLinkage = false;
};

}  // namespace linkwright::ui
