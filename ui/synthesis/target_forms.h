#pragma once
// The input forms whose targets are positions on the canvas: motion generation (two or three
// coupler poses, each a point and an angle, and the two circle points at pose 1) and path
// generation (4 to 10 points, with a crank angle each when timing is prescribed, and how many
// starts to search from). Both keep their targets in a TargetTable, typed or picked on the
// canvas; angles are typed in degrees and handed to the core in radians.

#include "ui/synthesis/synthesis_forms.h"

#include <Eigen/Core>

class QCheckBox;
class QComboBox;
class QSpinBox;

namespace linkwright::ui {

class TargetTable;

class MotionForm : public ClosedForm {
  Q_OBJECT
public:
  explicit MotionForm(QWidget* parent = nullptr);
  kinematics::Result<ClosedFormRequest> request() const override;
  void load(const kinematics::SynthesisTargets& targets) override;
  void store(kinematics::SynthesisTargets& targets) const override;

  TargetTable* poses() const { return m_poses; }
  /// Appends a pose picked on the canvas (angle in rad); false if the table is full.
  bool appendPose(const Eigen::Vector2d& point, double angle);

private:
  void updateCentres();

  TargetTable* m_poses;
  QDoubleSpinBox* m_ax;
  QDoubleSpinBox* m_ay;
  QDoubleSpinBox* m_bx;
  QDoubleSpinBox* m_by;
  QDoubleSpinBox* m_centreA;
  QDoubleSpinBox* m_centreB;
  QCheckBox* m_fullTurn;
};

class PathForm : public ProblemForm {
  Q_OBJECT
public:
  explicit PathForm(QWidget* parent = nullptr);
  /// The search the fields describe, or why not (the message names the field).
  kinematics::Result<PathRequest> request() const;
  void load(const kinematics::SynthesisTargets& targets) override;
  void store(kinematics::SynthesisTargets& targets) const override;

  TargetTable* points() const { return m_points; }
  QCheckBox* timingBox() const { return m_timing; }
  QSpinBox* startsBox() const { return m_starts; }
  /// Appends a point picked on the canvas; false if the table is full.
  bool appendPoint(const Eigen::Vector2d& point);

private:
  TargetTable* m_points;
  QCheckBox* m_timing;
  QComboBox* m_reference;
  QSpinBox* m_starts;
  QCheckBox* m_fullTurn;
};

}  // namespace linkwright::ui
