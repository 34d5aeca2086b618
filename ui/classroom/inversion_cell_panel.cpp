#include "ui/classroom/inversion_cell_panel.h"

#include "ui/animation/crank_animator.h"
#include "ui/canvas/feasible_range_item.h"
#include "ui/canvas/linkage_scene.h"
#include "ui/canvas/linkage_view.h"
#include "ui/document/mechanism_document.h"

#include <QLabel>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace linkwright::ui {

namespace k = kinematics;

namespace {
constexpr int kMinimumDrawingWidthPx = 300;
constexpr int kMinimumDrawingHeightPx = 220;
}  // namespace

InversionCellPanel::InversionCellPanel(QWidget* parent)
    : QFrame(parent), m_document(new MechanismDocument(this)), m_animator(new CrankAnimator(m_document, this)),
      m_view(new LinkageView(m_document, this)), m_title(new QLabel(this)), m_class(new QLabel(this)),
      m_detail(new QLabel(this)), m_note(new QLabel(this)), m_stack(new QStackedWidget(this)) {
  setFrameShape(QFrame::StyledPanel);
  QFont bold = m_title->font();
  bold.setBold(true);
  bold.setPointSizeF(bold.pointSizeF() * 1.15);
  m_title->setFont(bold);
  m_class->setFont(bold);
  m_class->setTextFormat(Qt::PlainText);
  m_note->setTextFormat(Qt::PlainText);
  m_title->setObjectName("InversionTitle");
  m_class->setObjectName("InversionClass");
  m_detail->setObjectName("InversionDetail");
  m_note->setObjectName("InversionNote");
  m_note->setWordWrap(true);
  m_detail->setWordWrap(true);
  m_note->setAlignment(Qt::AlignCenter);
  m_note->setMargin(12);
  m_view->setReadOnly(true);
  // A cell is small: the crank's reach goes in the line above the drawing, not across it.
  static_cast<LinkageScene*>(m_view->linkageScene())->setRangeLabelShown(false);
  m_view->setMinimumSize(kMinimumDrawingWidthPx, kMinimumDrawingHeightPx);
  m_stack->addWidget(m_view);
  m_stack->addWidget(m_note);

  auto* heading = new QHBoxLayout;
  heading->addWidget(m_title);
  heading->addStretch();
  heading->addWidget(m_class);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(6, 6, 6, 6);
  layout->addLayout(heading);
  layout->addWidget(m_detail);
  layout->addWidget(m_stack, 1);
}

void InversionCellPanel::setCell(const InversionCell& cell) {
  m_title->setText(cell.title);
  m_class->setText(cell.className);
  m_detail->setText(cell.detail);
  std::optional<QString> refused;
  if (cell.design) refused = m_document->validate(*cell.design);
  if (!cell.design || refused) {
    m_animator->pause();
    m_hasLinkage = false;
    QString why = refused ? *refused : cell.note;
    if (!why.endsWith('.')) why += '.';
    m_note->setText(tr("Not drawn: %1").arg(why));
    m_stack->setCurrentWidget(m_note);
    return;
  }
  // The same linkage with new lengths goes on from where its crank was.
  const bool again = m_hasLinkage && m_document->design().kind == cell.design->kind &&
                     m_document->mechanism().points.size() == cell.design->mechanism.points.size();
  const double angle = m_document->crankAngle();
  m_view->setLinkColors(cell.linkColors);
  m_document->reset(*cell.design);
  const k::InputRange& range = m_document->analysis().inputRange;
  if (again) m_document->setCrankAngle(angle);
  else if (!range.fullRotation && !range.ranges.empty())  // a rocking crank starts mid-swing
    m_document->setCrankAngle(0.5 * (range.ranges.front().from + range.ranges.front().to));
  m_hasLinkage = true;
  const FeasibleRangeItem* reach = static_cast<LinkageScene*>(m_view->linkageScene())->feasibleRangeItem();
  if (reach->isVisible()) m_detail->setText(cell.detail + QStringLiteral("; ") + reach->labelText());
  m_note->clear();
  m_stack->setCurrentWidget(m_view);
}

QString InversionCellPanel::title() const { return m_title->text(); }

QString InversionCellPanel::className() const { return m_class->text(); }

QString InversionCellPanel::detail() const { return m_detail->text(); }

QString InversionCellPanel::note() const { return m_note->text(); }

}  // namespace linkwright::ui
