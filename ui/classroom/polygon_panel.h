#pragma once
// The Polygons tab (issue 21, the classroom): the velocity or the acceleration polygon of the
// document's current pose drawn to a chosen scale (PolygonView), with Step / All / Reset to
// draw it one arrow at a time in the order a student would, the vector equations in solve
// order, and a table of each arrow's length on the drawing (cm), the value read off it at the
// scale, and the exact value beside it; then each point's image read off against the solver's
// velocity (acceleration) of that point: the check students make. It follows the crank while
// shown. The polygons come from the core (vector_polygon.h) at the document's solved pose;
// a linkage the core cannot draw them for shows the reason instead.

#include "kinematics/analysis/vector_polygon.h"

#include <QWidget>

#include <array>
#include <optional>

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace linkwright::ui {

class MechanismDocument;
class PolygonView;

class PolygonPanel : public QWidget {
  Q_OBJECT
public:
  explicit PolygonPanel(MechanismDocument* document, QWidget* parent = nullptr);

  /// Columns of table(): Step, Vector, Drawing (cm), Read off, Exact. Cells of the last three
  /// hold the unrounded number as Qt::UserRole data.
  enum Column { StepColumn, VectorColumn, DrawnColumn, ReadOffColumn, ExactColumn };

  /// Follows the document only while on screen; catches up when shown again.
  void setOnScreen(bool on);
  /// Shows the velocity (or acceleration) polygon.
  void setKind(kinematics::PolygonKind kind);
  kinematics::PolygonKind kind() const { return m_kind; }
  /// Polygon units per cm for the kind shown; 0 fits.
  void setChosenScale(double unitsPerCm);
  /// Step drawing: the next arrow, all arrows, none.
  void step();
  void showAll();
  void reset();
  void setPresentationScale(double scale);

  /// Both polygons at the document's pose, or nullopt with reason().
  const std::optional<kinematics::ClassroomPolygons>& polygons() const { return m_polygons; }
  /// Why there are no polygons (empty when there are).
  QString reason() const;
  PolygonView* view() const { return m_view; }
  QTableWidget* table() const { return m_table; }
  /// Rows of table() that are arrows (the rest are the image checks).
  int arrowRows() const { return m_arrowRows; }

private:
  QWidget* buildDrawingAndTable();
  void refresh();
  void showPolygon();
  void fillTable();
  void fillScales();
  void addRow(const QString& step, const QString& vector, double magnitude, const QString& tip);

  MechanismDocument* m_document;
  PolygonView* m_view;
  QComboBox* m_kindBox;
  QComboBox* m_scaleBox;
  QPushButton* m_stepButton;
  QLabel* m_stepText;
  QLabel* m_equations;
  QLabel* m_reasonLabel;
  QWidget* m_content;
  QTableWidget* m_table;
  std::optional<kinematics::ClassroomPolygons> m_polygons;
  QString m_reason;
  kinematics::PolygonKind m_kind = kinematics::PolygonKind::Velocity;
  std::array<double, 2> m_chosenScale{0.0, 0.0};  // per kind; 0 fits
  int m_arrowRows = 0;
  bool m_onScreen = true;
  bool m_stale = false;
};

}  // namespace linkwright::ui
