// File ▸ Compare… (ui/compare/compare_dialog.h) on the thesis's Excel Table 7 (seed 000,
// tests/data/compare/): the mapping editor offers the core's quantities and units, Compare
// shows the core's comparison with the α4 typo rows highlighted, and a mapping the core refuses
// shows its sentence and leaves the last comparison as it was.

#include "ui/compare/compare_dialog.h"
#include "ui/compare/column_map_editor.h"
#include "ui/main_window.h"

#include "kinematics/compare/table_comparison.h"
#include "kinematics/design/design.h"

#include <catch2/catch.hpp>

#include <QComboBox>
#include <QLabel>
#include <QTableWidget>

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
