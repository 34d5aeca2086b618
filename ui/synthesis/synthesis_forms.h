#pragma once
// The input forms of the closed-form problems: crank-rocker for a rocker swing and time ratio,
// slider-crank and crank-shaper for a stroke and time ratio, and the function generator. Each
// reads its fields into the core's request (degrees to radians here, lengths in the document's
// unit); checks that need the form's own knowledge (a function's domain, a span in degrees)
// are made here, every other one by the core.

#include "ui/synthesis/problem_form.h"
#include "ui/synthesis/synthesis_solve.h"

class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace linkwright::ui {

/// A form whose problem solves in closed form, as the user types.
class ClosedForm : public ProblemForm {
  Q_OBJECT
public:
  using ProblemForm::ProblemForm;
  /// The request the fields describe, or why not (an Error whose message names the field).
  virtual kinematics::Result<ClosedFormRequest> request() const = 0;
};

class CrankRockerForm : public ClosedForm {
  Q_OBJECT
public:
  explicit CrankRockerForm(QWidget* parent = nullptr);
  kinematics::Result<ClosedFormRequest> request() const override;
  void load(const kinematics::SynthesisTargets& targets) override;
  void store(kinematics::SynthesisTargets& targets) const override;

  QDoubleSpinBox* swingBox() const { return m_swing; }
  QDoubleSpinBox* timeRatioBox() const { return m_timeRatio; }
  /// 0: the rocker's length is fixed, 1: the frame's.
  QComboBox* scaleBox() const { return m_scale; }
  QDoubleSpinBox* lengthBox() const { return m_length; }
  QSpinBox* countBox() const { return m_count; }

private:
  QDoubleSpinBox* m_swing;
  QDoubleSpinBox* m_timeRatio;
  QComboBox* m_scale;
  QDoubleSpinBox* m_length;
  QSpinBox* m_count;
};

class SliderCrankForm : public ClosedForm {
  Q_OBJECT
public:
  explicit SliderCrankForm(QWidget* parent = nullptr);
  kinematics::Result<ClosedFormRequest> request() const override;
  void load(const kinematics::SynthesisTargets& targets) override;
  void store(kinematics::SynthesisTargets& targets) const override;

private:
  QDoubleSpinBox* m_stroke;
  QDoubleSpinBox* m_timeRatio;
  QComboBox* m_choice;
  QDoubleSpinBox* m_value;
};

class ShaperForm : public ClosedForm {
  Q_OBJECT
public:
  explicit ShaperForm(QWidget* parent = nullptr);
  kinematics::Result<ClosedFormRequest> request() const override;
  void load(const kinematics::SynthesisTargets& targets) override;
  void store(kinematics::SynthesisTargets& targets) const override;

private:
  QDoubleSpinBox* m_stroke;
  QDoubleSpinBox* m_timeRatio;
  QDoubleSpinBox* m_crank;
  QDoubleSpinBox* m_link;
};

class FunctionForm : public ClosedForm {
  Q_OBJECT
public:
  explicit FunctionForm(QWidget* parent = nullptr);
  kinematics::Result<ClosedFormRequest> request() const override;
  void load(const kinematics::SynthesisTargets& targets) override;
  void store(kinematics::SynthesisTargets& targets) const override;

  QComboBox* functionBox() const { return m_function; }

private:
  QComboBox* m_function;
  QDoubleSpinBox* m_x0;
  QDoubleSpinBox* m_x1;
  QDoubleSpinBox* m_inputStart;
  QDoubleSpinBox* m_inputSpan;
  QDoubleSpinBox* m_outputStart;
  QDoubleSpinBox* m_outputSpan;
  QDoubleSpinBox* m_frame;
  QSpinBox* m_points;
};

}  // namespace linkwright::ui
