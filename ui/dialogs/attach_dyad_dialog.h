#pragma once
// Edit ▸ Attach dyad…: choose the dyad's kind (RRR, RRP, RPR, PRP), its new joint's name, its
// parents among the current points (or a new point on a link, or a new ground pivot), its
// lengths (pre-filled from the current pose so that it assembles), guides and branch. OK hands
// the request to `apply`; if that refuses, the dialog stays open with the reason and the
// document is unchanged.

#include "kinematics/design/dyad_request.h"

#include <QDialog>

#include <functional>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QLineEdit;

namespace linkwright::ui {

class GuideEditor;
class ParentEditor;

class AttachDyadDialog : public QDialog {
  Q_OBJECT
public:
  /// Applies a request; returns the refusal reason, or nullopt once it is done.
  using Apply = std::function<std::optional<QString>(const kinematics::DyadRequest&)>;

  /// For `mechanism` shown at `crankAngle` (rad).
  AttachDyadDialog(const kinematics::Mechanism& mechanism, double crankAngle, Apply apply, QWidget* parent = nullptr);

  /// The request the fields describe now.
  kinematics::DyadRequest request() const;
  /// Shows `request` in the fields (a new suggestion, or a test's).
  void setRequest(const kinematics::DyadRequest& request);
  QString errorText() const;

  void accept() override;

private:
  void kindChanged();
  void parentsChanged();
  void showKindFields();

  kinematics::Mechanism m_mechanism;
  double m_crankAngle;
  Apply m_apply;
  QComboBox* m_kind;
  QLineEdit* m_joint;
  QGroupBox* m_firstBox;
  QGroupBox* m_secondBox;
  ParentEditor* m_first;
  ParentEditor* m_second;
  QFormLayout* m_lengthsForm;
  QDoubleSpinBox* m_firstLength;
  QDoubleSpinBox* m_secondLength;
  QGroupBox* m_guideBox;
  QGroupBox* m_secondGuideBox;
  GuideEditor* m_guide;
  GuideEditor* m_secondGuide;
  QComboBox* m_branch;
  QLabel* m_error;
};

}  // namespace linkwright::ui
