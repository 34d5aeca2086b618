#pragma once
// The properties panel for forces: each link's mass (kg), centre of mass (along and across
// the link, in the length unit) and moment of inertia (kg·m²), each slider block's mass,
// gravity, a load torque on a link, a force on a slider or a link's point, and springs. It shows the
// design's values only; an unset centre or inertia reads as the core's default ("midpoint",
// "m·L²/12"). Every edit is a new design through MechanismDocument::edit, so it is undoable;
// an edit the core refuses (checkDesign names the field) changes nothing and is shown.

#include "kinematics/design/design.h"
#include "kinematics/dynamics/mass_properties.h"

#include <QString>
#include <QWidget>

#include <functional>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;

namespace linkwright::ui {

class MassTable;
class MechanismDocument;
class SpringsEditor;

class DynamicsPanel : public QWidget {
  Q_OBJECT
public:
  explicit DynamicsPanel(MechanismDocument* document, QWidget* parent = nullptr);

  /// Columns: link, mass, centre along, centre across, inertia; one row per mechanism link.
  MassTable* linkTable() const { return m_links; }
  /// Columns: slider, mass, inertia; one row per slider block (hidden when there is none).
  MassTable* sliderTable() const { return m_sliders; }
  QCheckBox* gravityBox() const { return m_gravity; }
  QDoubleSpinBox* gravitySpin() const { return m_g; }
  QComboBox* torqueLinkBox() const { return m_torqueLink; }
  QDoubleSpinBox* torqueSpin() const { return m_torque; }
  QComboBox* forceTargetBox() const { return m_forceTarget; }
  QDoubleSpinBox* forceXSpin() const { return m_forceX; }
  QDoubleSpinBox* forceYSpin() const { return m_forceY; }
  SpringsEditor* springsEditor() const { return m_springs; }
  /// Why the last edit was refused; empty after an accepted one.
  QString refusalMessage() const;

private:
  /// Where a point force may act: a link's point, or a slider block (link empty).
  struct ForceTarget {
    std::string link;
    std::string point;
    int guide = 0;
  };

  void refresh();
  void refreshTables();
  void refreshLoads();
  void editLink(int row, int column, std::optional<double> value, bool parsed);
  void editSlider(int row, int column, std::optional<double> value, bool parsed);
  void editGravity();
  void editTorque();
  void editForce();
  /// Applies `change` to a copy of the design's dynamics and submits it; shows a refusal.
  void submit(const QString& description, const std::function<void(kinematics::LinkageDynamics&)>& change);
  void refuse(const QString& reason);

  MechanismDocument* m_document;
  QLabel* m_refusal;
  MassTable* m_links;
  QGroupBox* m_sliderGroup;
  MassTable* m_sliders;
  QCheckBox* m_gravity;
  QDoubleSpinBox* m_g;
  QComboBox* m_torqueLink;
  QDoubleSpinBox* m_torque;
  QComboBox* m_forceTarget;
  QDoubleSpinBox* m_forceX;
  QDoubleSpinBox* m_forceY;
  QLabel* m_extraLoads;
  SpringsEditor* m_springs;
  std::vector<kinematics::SliderMass> m_sliderKeys;  // point and guide of each slider row
  std::vector<ForceTarget> m_targets;                // per force-target item after "none"
};

}  // namespace linkwright::ui
