#include "ui/dialogs/attach_dyad_dialog.h"

#include "ui/dialogs/dyad_part_editors.h"
#include "ui/number_box.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

QGroupBox* boxAround(QWidget* content, QWidget* parent) {
  auto* box = new QGroupBox(parent);
  auto* layout = new QVBoxLayout(box);
  layout->addWidget(content);
  return box;
}

}  // namespace

AttachDyadDialog::AttachDyadDialog(const k::Mechanism& mechanism, double crankAngle, Apply apply, QWidget* parent)
    : QDialog(parent), m_mechanism(mechanism), m_crankAngle(crankAngle), m_apply(std::move(apply)),
      m_kind(new QComboBox(this)), m_joint(new QLineEdit(this)), m_first(new ParentEditor(this)),
      m_second(new ParentEditor(this)), m_firstLength(new NumberBox(this)), m_secondLength(new NumberBox(this)),
      m_guide(new GuideEditor(this)), m_secondGuide(new GuideEditor(this)), m_branch(new QComboBox(this)),
      m_error(new QLabel(this)) {
  setWindowTitle(tr("Attach dyad"));
  auto* layout = new QVBoxLayout(this);
  auto* top = new QFormLayout;
  m_kind->addItem(tr("RRR: two links, three pins"));
  m_kind->addItem(tr("RRP: a link and a slider"));
  m_kind->addItem(tr("RPR: a slotted link on a block"));
  m_kind->addItem(tr("PRP: a pin joining two sliders"));
  top->addRow(tr("Dyad"), m_kind);
  top->addRow(tr("New joint"), m_joint);
  layout->addLayout(top);
  m_firstBox = boxAround(m_first, this);
  m_secondBox = boxAround(m_second, this);
  m_guideBox = boxAround(m_guide, this);
  m_secondGuideBox = boxAround(m_secondGuide, this);
  for (QGroupBox* box : {m_firstBox, m_secondBox, m_guideBox, m_secondGuideBox}) layout->addWidget(box);
  m_lengthsForm = new QFormLayout;
  const QString unit = QStringLiteral(" ") + QString::fromStdString(mechanism.lengthUnit);
  for (QDoubleSpinBox* box : {m_firstLength, m_secondLength}) {
    box->setRange(1e-6, 1e9);
    box->setDecimals(4);
    box->setSuffix(unit);
  }
  m_lengthsForm->addRow(tr("Length 1"), m_firstLength);
  m_lengthsForm->addRow(tr("Length 2"), m_secondLength);
  m_branch->addItems({tr("Open"), tr("Crossed")});
  m_lengthsForm->addRow(tr("Branch"), m_branch);
  layout->addLayout(m_lengthsForm);
  m_error->setWordWrap(true);
  m_error->setStyleSheet("color: #b00020;");
  m_error->hide();
  layout->addWidget(m_error);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  layout->addWidget(buttons);
  connect(buttons, &QDialogButtonBox::accepted, this, &AttachDyadDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(m_kind, &QComboBox::currentIndexChanged, this, &AttachDyadDialog::kindChanged);
  // New parents or a new guide: lengths that assemble at the current pose again.
  for (ParentEditor* e : {m_first, m_second})
    connect(e, &ParentEditor::changed, this, &AttachDyadDialog::parentsChanged);
  connect(m_guide, &GuideEditor::changed, this, &AttachDyadDialog::parentsChanged);
  setRequest(kinematics::suggestDyad(m_mechanism, m_crankAngle, kinematics::DyadKind::Rrr));
}

kinematics::DyadRequest AttachDyadDialog::request() const {
  kinematics::DyadRequest r;
  r.kind = static_cast<kinematics::DyadKind>(m_kind->currentIndex());
  r.joint = m_joint->text().trimmed().toStdString();
  r.first = m_first->choice();
  r.second = m_second->choice();
  r.firstLength = m_firstLength->value();
  r.secondLength = m_secondLength->value();
  r.guide = m_guide->guide();
  r.secondGuide = m_secondGuide->guide();
  r.branch = m_branch->currentIndex() == 0 ? k::Branch::Open : k::Branch::Crossed;
  return r;
}

void AttachDyadDialog::setRequest(const kinematics::DyadRequest& r) {
  {
    const QSignalBlocker block(m_kind);
    m_kind->setCurrentIndex(static_cast<int>(r.kind));
  }
  m_joint->setText(QString::fromStdString(r.joint));
  m_first->setChoices(m_mechanism, r.first);
  m_second->setChoices(m_mechanism, r.second);
  m_guide->setGuide(m_mechanism, r.guide);
  m_secondGuide->setGuide(m_mechanism, r.secondGuide);
  m_firstLength->setValue(r.firstLength);
  m_secondLength->setValue(r.secondLength);
  m_branch->setCurrentIndex(r.branch == k::Branch::Open ? 0 : 1);
  showKindFields();
}

QString AttachDyadDialog::errorText() const { return m_error->isHidden() ? QString() : m_error->text(); }

void AttachDyadDialog::accept() {
  if (const auto why = m_apply(request())) {
    m_error->setText(tr("Not attached: %1").arg(*why));
    m_error->show();
    return;
  }
  QDialog::accept();
}

void AttachDyadDialog::kindChanged() {
  setRequest(
      kinematics::suggestDyad(m_mechanism, m_crankAngle, static_cast<kinematics::DyadKind>(m_kind->currentIndex())));
  m_error->hide();
}

void AttachDyadDialog::parentsChanged() {
  kinematics::DyadRequest r = request();
  kinematics::fillLengths(m_mechanism, m_crankAngle, r);
  const QSignalBlocker a(m_firstLength), b(m_secondLength);
  m_firstLength->setValue(r.firstLength);
  m_secondLength->setValue(r.secondLength);
}

void AttachDyadDialog::showKindFields() {
  const auto kind = static_cast<kinematics::DyadKind>(m_kind->currentIndex());
  const bool rrr = kind == kinematics::DyadKind::Rrr, rrp = kind == kinematics::DyadKind::Rrp,
             rpr = kind == kinematics::DyadKind::Rpr, prp = kind == kinematics::DyadKind::Prp;
  m_firstBox->setVisible(!prp);
  m_firstBox->setTitle(rpr ? tr("Pivot of the slotted link") : rrp ? tr("The rod's other end") : tr("First parent"));
  m_secondBox->setVisible(rrr || rpr);
  m_secondBox->setTitle(rpr ? tr("The slot slides on a block at") : tr("Second parent"));
  m_guideBox->setVisible(rrp || prp);
  m_guideBox->setTitle(prp ? tr("First guide") : tr("Guide of the slider"));
  m_secondGuideBox->setVisible(prp);
  m_secondGuideBox->setTitle(tr("Second guide"));
  m_lengthsForm->setRowVisible(m_firstLength, !prp);
  m_lengthsForm->setRowVisible(m_secondLength, rrr);
  m_lengthsForm->setRowVisible(m_branch, rrr || rrp);
  auto* firstLabel = qobject_cast<QLabel*>(m_lengthsForm->labelForField(m_firstLength));
  if (firstLabel != nullptr) firstLabel->setText(rrr ? tr("to first parent") : rrp ? tr("rod") : tr("slotted link"));
  if (auto* l = qobject_cast<QLabel*>(m_lengthsForm->labelForField(m_secondLength))) l->setText(tr("to second parent"));
  adjustSize();
}

}  // namespace linkwright::ui
