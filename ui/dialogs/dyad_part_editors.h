#pragma once
// The two compound fields of the Attach dyad dialog: a parent picker (an existing point, a
// new point on a link at along/across, or a new ground pivot at x, y) and a guide editor (on
// the ground through x, y, or on a link at along/across, with its angle).

#include "kinematics/design/dyad_request.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace linkwright::ui {

class ParentEditor : public QWidget {
  Q_OBJECT
public:
  explicit ParentEditor(QWidget* parent = nullptr);

  /// Lists `mechanism`'s points and links (length unit in the suffixes) and shows `choice`.
  void setChoices(const kinematics::Mechanism& mechanism, const kinematics::ParentChoice& choice);
  kinematics::ParentChoice choice() const;

signals:
  void changed();

private:
  void showFields();

  QComboBox* m_source;
  QComboBox* m_link;
  QDoubleSpinBox* m_a;  // along or x
  QDoubleSpinBox* m_b;  // across or y
  QLabel* m_aLabel;
  QLabel* m_bLabel;
  QLabel* m_linkLabel;
  std::size_t m_points = 0;
};

class GuideEditor : public QWidget {
  Q_OBJECT
public:
  explicit GuideEditor(QWidget* parent = nullptr);

  void setGuide(const kinematics::Mechanism& mechanism, const kinematics::Guide& guide);
  kinematics::Guide guide() const;

signals:
  void changed();

private:
  void showLabels();

  QComboBox* m_body;
  QDoubleSpinBox* m_a;
  QDoubleSpinBox* m_b;
  QDoubleSpinBox* m_angle;
  QLabel* m_aLabel;
  QLabel* m_bLabel;
};

}  // namespace linkwright::ui
