// File ▸ Compare… (ui/compare/compare_dialog.h) on the thesis's Excel Table 7 (seed 000,
// tests/data/compare/): the mapping editor offers the core's quantities and units, Compare
// shows the core's comparison with the α4 typo rows highlighted, and a mapping the core refuses
// shows its sentence and leaves the last comparison as it was.

#include "ui/compare/compare_dialog.h"
#include "ui/colors.h"
#include "ui/compare/column_map_editor.h"
#include "ui/main_window.h"
#include "ui/plots/hover_readout.h"
#include "ui/plots/plot_panel.h"
#include "ui/plots/quantity_chart_view.h"

#include "kinematics/compare/table_comparison.h"
#include "kinematics/design/design.h"

#include "tests/support/catch.h"

#include <QChart>
#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QScatterSeries>
#include <QTableWidget>
#include <QValueAxis>

#include <cmath>
#include <fstream>
#include <sstream>

namespace k = linkwright::kinematics;
namespace kc = linkwright::kinematics::compare;
using linkwright::ui::CompareDialog;

namespace {

const char* kTable = LINKWRIGHT_TEST_DATA "/compare/thesis_excel_table7.tsv";
const char* kMap = "1=crank-angle:deg,2=coupler_angle:deg,3=rocker_angle:deg,7=rocker_alpha:rad/s2";

k::io::NumericTable excelTable() {
  std::ifstream file(kTable);
  std::stringstream text;
  text << file.rdbuf();
  return *k::io::readNumericTable(text.str());
}

int highlighted(const QTableWidget* table) {
  int n = 0;
  for (int row = 0; row < table->rowCount(); ++row) n += table->item(row, 0)->background().style() != Qt::NoBrush;
  return n;
}

}  // namespace

TEST_CASE("Compare on the thesis Excel table highlights the 8 α4 typo rows", "[ui][compare]") {
  const k::Design thesis = *k::designForExample("thesis-crank-rocker");
  CompareDialog dialog(thesis, excelTable(), kTable);
  // Each column of the table has a row; the units follow the quantity chosen.
  REQUIRE(dialog.mapEditor()->rowCount() == 7);
  // The headers ("Angle, θ_2 , deg", "… α_4 , rad/s ²") propose the whole mapping to start from.
  const auto proposed = dialog.mapEditor()->mapping();
  REQUIRE(proposed);
  CHECK(kc::formatColumnMap(*proposed) ==
        "1=crank-angle:deg,2=coupler_angle:deg,3=rocker_angle:deg,4=coupler_omega:rad/s,5=rocker_omega:rad/s,"
        "6=coupler_alpha:rad/s2,7=rocker_alpha:rad/s2");
  dialog.mapEditor()->setMapping(*kc::parseColumnMap(kMap, thesis.mechanism));
  const auto mapping = dialog.mapEditor()->mapping();
  REQUIRE(mapping);
  CHECK(kc::formatColumnMap(*mapping) == kMap);
  auto* unit = qobject_cast<QComboBox*>(dialog.mapEditor()->cellWidget(6, 3));
  REQUIRE(unit != nullptr);
  CHECK(unit->count() == 2);  // rad/s2, deg/s2
  REQUIRE(dialog.compare());
  const kc::Comparison& c = *dialog.comparison();
  // The dialog shows the core's numbers, and opens on the column with flagged rows.
  const auto core = kc::compareTable(thesis.mechanism, kc::compareDriveFor(thesis), excelTable(), *mapping);
  REQUIRE(core);
  CHECK(c.offsetDeg == core->offsetDeg);
  CHECK(dialog.summaryTable()->rowCount() == 3);
  CHECK(dialog.summaryTable()->item(2, 7)->text() == "8");
  CHECK(dialog.rowsTable()->rowCount() == 13);
  CHECK(highlighted(dialog.rowsTable()) == 8);
  CHECK(dialog.messageLabel()->isHidden());
}

TEST_CASE("a mapping the core refuses shows why and keeps the last comparison", "[ui][compare]") {
  const k::Design thesis = *k::designForExample("thesis-crank-rocker");
  CompareDialog dialog(thesis, excelTable(), kTable);
  dialog.mapEditor()->setMapping(*kc::parseColumnMap(kMap, thesis.mechanism));
  REQUIRE(dialog.compare());
  // A second x column.
  qobject_cast<QComboBox*>(dialog.mapEditor()->cellWidget(1, 2))->setCurrentIndex(2);
  CHECK_FALSE(dialog.compare());
  CHECK_FALSE(dialog.messageLabel()->isHidden());
  CHECK(dialog.messageLabel()->text().contains("both the x"));
  CHECK(dialog.summaryTable()->rowCount() == 3);
  // Nothing compared but the x.
  dialog.mapEditor()->setMapping(*kc::parseColumnMap("1=crank-angle", thesis.mechanism));
  CHECK_FALSE(dialog.compare());
  CHECK(dialog.messageLabel()->text().contains("no quantity mapped"));
  CHECK(dialog.comparison()->columns.size() == 3);
}

TEST_CASE("the compared rows are drawn over the plots, the α4 typo rows in red, until unticked", "[ui][compare]") {
  using namespace linkwright::ui;
  const k::Design thesis = *k::designForExample("thesis-crank-rocker");
  MainWindow window;
  window.newDocument(thesis);
  CompareDialog* dialog = window.openCompareTable(kTable);
  REQUIRE(dialog != nullptr);
  dialog->mapEditor()->setMapping(*kc::parseColumnMap(kMap, thesis.mechanism));
  REQUIRE(dialog->compare());
  const kc::Comparison& c = *dialog->comparison();
  PlotPanel* plots = window.plots();
  REQUIRE(plots->hasComparison());

  // α4: one marker a row, at the crank angle it was solved at, the 8 typo rows filled red.
  QuantityChartView* alphaChart = plots->chartView(QuantityKind::Alpha);
  QScatterSeries* alpha = alphaChart->overlaySeries(PlotQuantity::RockerAlpha);
  REQUIRE(alpha != nullptr);
  CHECK(alpha->isVisible());
  CHECK(alpha->name() == "thesis_excel_table7");
  const kc::ColumnComparison& alphaColumn = c.columns[2];
  REQUIRE(alpha->count() == static_cast<int>(alphaColumn.rows.size()));
  int red = 0;
  for (int i = 0; i < alpha->count(); ++i) {
    const kc::RowComparison& row = alphaColumn.rows[static_cast<std::size_t>(i)];
    // At the angle solved at (the fitted offset included), moved by a turn into the axis's range.
    CHECK(std::remainder(alpha->at(i).x() - row.inputDeg, 360.0) == Approx(0.0).margin(1e-9));
    CHECK(alpha->at(i).x() >= alphaChart->xAxis()->min());
    CHECK(alpha->at(i).x() <= alphaChart->xAxis()->max());
    CHECK(alpha->at(i).y() == Approx(k::radToDeg(row.restated)).margin(1e-9));  // deg/s², as the chart
    const auto config = alpha->pointConfiguration(i);
    const bool filledRed = config.value(QXYSeries::PointConfiguration::Color).value<QColor>() == colors().flaggedRow;
    CHECK(filledRed == row.flagged);
    red += filledRed;
  }
  CHECK(red == 8);
  // The value axis covers every row, the typo's too.
  for (const QPointF& p : alpha->points()) {
    CHECK(p.y() >= alphaChart->yAxis()->min());
    CHECK(p.y() <= alphaChart->yAxis()->max());
  }

  // The angle chart has θ3's and θ4's markers, and one legend entry naming the table (a
  // legend marker reads as visible only once its legend is laid out on screen).
  window.show();
  QCoreApplication::processEvents();
  QChart* angles = plots->chartView(QuantityKind::Angle)->chart();
  int listed = 0;
  for (QLegendMarker* marker : angles->legend()->markers())
    listed += marker->isVisible() && marker->label() == "thesis_excel_table7";
  CHECK(listed == 1);
  // θ4 agrees everywhere: each marker lies on the exact curve's sample at the same angle.
  QScatterSeries* theta = plots->chartView(QuantityKind::Angle)->overlaySeries(PlotQuantity::RockerAngle);
  REQUIRE(theta != nullptr);
  const QList<QPointF> curve = plots->chartView(QuantityKind::Angle)->samples(PlotQuantity::RockerAngle);
  int onCurve = 0;
  for (const QPointF& marker : theta->points())
    for (qsizetype j = 1; j < curve.size(); ++j)
      if (curve[j - 1].x() <= marker.x() && marker.x() <= curve[j].x()) {
        const double t = (marker.x() - curve[j - 1].x()) / (curve[j].x() - curve[j - 1].x());
        const double y = curve[j - 1].y() + t * (curve[j].y() - curve[j - 1].y());
        CHECK(marker.y() == Approx(y).margin(c.columns[1].tolerance + 0.01));  // + the chord's error
        ++onCurve;
        break;
      }
  CHECK(onCurve == theta->count());

  // Hovering a marker reads the row out.
  emit alpha->hovered(alpha->at(1), true);
  CHECK(plots->hoverReadout()->text().contains("line"));
  CHECK(plots->hoverReadout()->text().contains("beyond the tolerance"));

  // In radians the markers move with the curves.
  plots->setAngleUnit(AngleUnit::Radians);
  alpha = plots->chartView(QuantityKind::Alpha)->overlaySeries(PlotQuantity::RockerAlpha);
  REQUIRE(alpha != nullptr);
  CHECK(alpha->at(3).x() == Approx(k::degToRad(alphaColumn.rows[3].inputDeg)).margin(1e-12));
  CHECK(alpha->at(3).y() == Approx(alphaColumn.rows[3].restated).margin(1e-12));

  // The markers are outlined in their curve's colour, in the theme drawn with.
  window.setHighContrast(true);
  const QScatterSeries* outlined = plots->chartView(QuantityKind::Angle)->overlaySeries(PlotQuantity::RockerAngle);
  REQUIRE(outlined != nullptr);
  CHECK(outlined->pen().color() == paletteOf(Theme::HighContrast).links[k::fourbar::kRocker.index]);
  window.setHighContrast(false);
  outlined = plots->chartView(QuantityKind::Angle)->overlaySeries(PlotQuantity::RockerAngle);
  REQUIRE(outlined != nullptr);
  CHECK(outlined->pen().color() == paletteOf(Theme::Normal).links[k::fourbar::kRocker.index]);

  // Unticked, they go; ticked, they come back; another linkage clears them.
  dialog->drawOnPlotsBox()->setChecked(false);
  CHECK_FALSE(plots->hasComparison());
  CHECK(plots->chartView(QuantityKind::Alpha)->overlaySeries(PlotQuantity::RockerAlpha) == nullptr);
  dialog->drawOnPlotsBox()->setChecked(true);
  CHECK(plots->chartView(QuantityKind::Alpha)->overlaySeries(PlotQuantity::RockerAlpha) != nullptr);
  window.newDocument(*k::designForExample("alvi-fourbar"));
  CHECK_FALSE(plots->hasComparison());
  CHECK(plots->chartView(QuantityKind::Alpha)->overlaySeries(PlotQuantity::RockerAlpha) == nullptr);
}
