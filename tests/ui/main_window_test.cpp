// The whole window, offscreen: CSV export equals the CLI's output byte for byte, save → open
// reproduces the document, a corrupt file shows an error and changes nothing, examples load,
// presentation mode scales up, images export, and the DXF export equals the CLI's.

#include "ui/main_window.h"
#include "ui/canvas/coupler_path_item.h"
#include "ui/canvas/linkage_scene.h"
#include "ui/canvas/linkage_view.h"
#include "ui/document/mechanism_document.h"
#include "ui/message_banner.h"
#include "ui/panels/analysis_panel.h"
#include "ui/panels/dimensions_panel.h"
#include "ui/plots/force_chart_view.h"
#include "ui/plots/force_plot_panel.h"
#include "ui/plots/limit_markers.h"
#include "ui/plots/plot_axes.h"
#include "ui/plots/plot_panel.h"
#include "ui/plots/quality_bar.h"
#include "ui/plots/quantity_chart_view.h"
#include "ui/plots/quantity_selector.h"
#include "ui/settings.h"

#include "app/cli/cli.h"
#include "kinematics/analysis/link_drawing.h"
#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"

#include "tests/ui/support/read_file.h"

#include "tests/ui/support/four_bar_design.h"

#include "tests/support/catch.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QLegend>
#include <QMenu>
#include <QMenuBar>
#include <QScatterSeries>
#include <QTemporaryDir>
#include <QTest>
#include <QValueAxis>

#include <sstream>

using namespace linkwright;
using test::readAll;

namespace {

// The linkwright-cli command line that describes the same table as the design.
std::vector<std::string> cliArguments(const kinematics::Design& d) {
  using kinematics::formatDouble;
  const kinematics::FourBarStructure s = kinematics::asFourBar(d.mechanism).value();
  const auto& l = s.lengths;
  std::vector<std::string> args{"analyze",
                                "--fourbar",
                                formatDouble(l.frame) + "," + formatDouble(l.crank) + "," + formatDouble(l.coupler) +
                                    "," + formatDouble(l.rocker),
                                "--unit",
                                d.mechanism.lengthUnit,
                                "--branch",
                                s.branch == kinematics::Branch::Open ? "open" : "crossed",
                                "--omega",
                                formatDouble(d.omega),
                                "--alpha",
                                formatDouble(d.alpha),
                                "--from",
                                formatDouble(d.fromDeg),
                                "--to",
                                formatDouble(d.toDeg),
                                "--samples",
                                std::to_string(d.samples)};
  if (const auto p = kinematics::couplerPointOf(d.mechanism, s)) {
    args.push_back("--coupler-point");
    args.push_back(formatDouble(p->spec.along) + "," + formatDouble(p->spec.across));
  }
  return args;
}

}  // namespace

TEST_CASE("Export ▸ CSV is byte-identical to linkwright-cli analyze", "[ui][window][csv]") {
  ui::MainWindow window;
  kinematics::Design d = window.document()->design();
  d.mechanism =
      kinematics::withCouplerPoint(d.mechanism, *window.document()->fourBar(), kinematics::CouplerPointSpec{35.0, 20.0})
          .value();
  d.alpha = 0.25;
  d.samples = 181;
  REQUIRE_FALSE(window.document()->edit(d, "test").has_value());
  QTemporaryDir dir;
  const QString path = dir.filePath("table.csv");
  REQUIRE(window.exportCsv(path));
  std::ostringstream out, err;
  REQUIRE(cli::runCli(cliArguments(d), out, err) == 0);
  CHECK(readAll(path).toStdString() == out.str());
}

TEST_CASE("Export ▸ Links as DXF is byte-identical to linkwright-cli dxf at the crank angle shown",
          "[ui][window][dxf]") {
  ui::MainWindow window;
  const std::string example = GENERATE(std::string("thesis-crank-rocker"), std::string("ls3-engine"));
  CAPTURE(example);
  window.document()->reset(*kinematics::designForExample(example));
  window.document()->setCrankAngle(kinematics::degToRad(37.5));
  QTemporaryDir dir;
  const QString gui = dir.filePath("gui.dxf"), cli = dir.filePath("cli.dxf");
  kinematics::DrawingOptions options;
  options.holeDiameter = 3.0;
  options.plateWidth = 7.5;
  REQUIRE(window.exportDxf(gui, options));
  std::ostringstream out, err;
  REQUIRE(cli::runCli(
              {"dxf", "--example", example, "--at", "37.5", "--hole", "3", "--width", "7.5", "-o", cli.toStdString()},
              out, err) == 0);
  CHECK(readAll(gui) == readAll(cli));

  // A hole larger than a link allows is refused with the core's reason: no file, the banner says why.
  options.holeDiameter = 1e6;
  const QString refused = dir.filePath("refused.dxf");
  CHECK_FALSE(window.exportDxf(refused, options));
  CHECK_FALSE(QFile::exists(refused));
  CHECK(window.banner()->text().contains(QStringLiteral("hole")));
}

TEST_CASE("save then open in a new window reproduces the document", "[ui][window][file]") {
  QTemporaryDir dir;
  const QString path = dir.filePath("saved.json");
  kinematics::Design d;
  {
    ui::MainWindow window;
    d = testing::withLengths(window.document()->design(), {60.0, 21.5, 70.0, 45.0});
    d.mechanism =
        kinematics::withFourBarBranch(d.mechanism, *kinematics::asFourBar(d.mechanism), kinematics::Branch::Crossed);
    REQUIRE_FALSE(window.document()->edit(d, "test").has_value());
    CHECK(window.document()->isModified());
    REQUIRE(window.saveTo(path));
    CHECK_FALSE(window.document()->isModified());
    CHECK(window.windowTitle().startsWith("saved.json"));
  }
  ui::MainWindow other;
  REQUIRE(other.openFile(path));
  CHECK(other.document()->design() == d);
  CHECK(other.document()->filePath().endsWith("saved.json"));
  CHECK(other.document()->undoStack()->count() == 0);
}

TEST_CASE("opening a corrupt file shows an error and changes nothing", "[ui][window][file][errors]") {
  QTemporaryDir dir;
  const QString path = dir.filePath("broken.json");
  {
    QFile f(path);
    REQUIRE(f.open(QIODevice::WriteOnly));
    f.write("{ \"format\": \"linkwright\", \"version\": 1, \"mechanism\": { \"type\": ");
  }
  ui::MainWindow window;
  const kinematics::Design d = testing::withLengths(window.document()->design(), {60.0, 25.0, 70.0, 47.0});
  REQUIRE_FALSE(window.document()->edit(d, "test").has_value());
  const int undoSteps = window.document()->undoStack()->count();
  CHECK_FALSE(window.openFile(path));
  CHECK(window.document()->design() == d);
  CHECK(window.document()->undoStack()->count() == undoSteps);
  CHECK(window.banner()->isVisibleTo(&window));
  CHECK(window.banner()->text().contains("broken.json"));
  CHECK(window.banner()->text().contains("not valid JSON"));
}

TEST_CASE("the title names the example picked until the document is saved", "[ui][window][journey][file]") {
  ui::MainWindow window;
  CHECK(window.windowTitle().startsWith("thesis-crank-rocker (not saved)"));
  auto* shaper = window.findChild<QAction*>("example_shaper");
  REQUIRE(shaper != nullptr);
  shaper->trigger();  // Examples ▸ the crank-shaper, as the menu does
  CHECK(window.document()->design().kind == kinematics::designForExample("shaper")->kind);
  CHECK(window.windowTitle().startsWith("shaper (not saved)"));
  CHECK_FALSE(window.windowTitle().contains("Untitled"));
  window.newDocument(*kinematics::designForExample("watt-ii"));  // File ▸ New's path: no name given
  CHECK(window.windowTitle().startsWith(QString::fromStdString(window.document()->design().kind) + " (not saved)"));
  QTemporaryDir dir;
  REQUIRE(window.saveTo(dir.filePath("lecture.linkwright")));
  CHECK(window.windowTitle().startsWith("lecture.linkwright"));
}

TEST_CASE("the window starts on the thesis example and offers every example", "[ui][window]") {
  ui::MainWindow window;
  CHECK(window.document()->fourBar()->lengths == kinematics::FourBarLengths{60, 25, 70, 45});
  CHECK(window.document()->design().omega == Approx(kinematics::rpmToRadPerSec(10.0)));
  window.newDocument(*kinematics::designForExample("alvi-fourbar"));
  CHECK(window.document()->fourBar()->lengths == kinematics::FourBarLengths{80, 20, 66, 56});
  CHECK(window.document()->undoStack()->count() == 0);
}

TEST_CASE("the Examples menu names each example, its description in the tooltip", "[ui][window]") {
  ui::MainWindow window;
  QMenu* examples = nullptr;
  for (QAction* top : window.menuBar()->actions())
    if (top->text().remove(QLatin1Char('&')) == QStringLiteral("Examples")) examples = top->menu();
  REQUIRE(examples != nullptr);
  CHECK(examples->toolTipsVisible());
  for (const kinematics::Example& e : kinematics::examples()) {
    INFO(e.name);
    auto* action = window.findChild<QAction*>(QString::fromStdString("example_" + e.name));
    REQUIRE(action != nullptr);
    CHECK(examples->actions().contains(action));
    // The whole name, as --example and the window's title give it; a description cut short
    // ("…") told neither (issue 57).
    CHECK(action->text() == QString::fromStdString(e.name));
    CHECK(action->toolTip() == QString::fromStdString(e.description));
    CHECK(action->statusTip() == QString::fromStdString(e.description));
  }
}

TEST_CASE("canvas and plots export as PNG and SVG", "[ui][window][export]") {
  ui::MainWindow window;
  window.resize(1400, 880);
  window.show();
  QTemporaryDir dir;
  REQUIRE(window.exportCanvasImage(dir.filePath("canvas.png")));
  const QImage png(dir.filePath("canvas.png"));
  CHECK_FALSE(png.isNull());
  CHECK(png.width() > 100);
  REQUIRE(window.exportCanvasImage(dir.filePath("canvas.svg")));
  CHECK(readAll(dir.filePath("canvas.svg")).contains("<svg"));
  REQUIRE(window.exportPlotImage(0, dir.filePath("plot.svg")));
  CHECK(readAll(dir.filePath("plot.svg")).contains("<svg"));
  CHECK_FALSE(window.exportCanvasImage(dir.filePath("canvas.bmp")));
  CHECK(window.banner()->text().contains(".png, .svg or .pdf"));
}

TEST_CASE("presentation mode enlarges the fonts and can be left again", "[ui][window]") {
  ui::MainWindow window;
  const double normal = window.font().pointSizeF();
  // Qt Charts takes its fonts from the chart theme, not the window: read them off the charts.
  QChart* chart = window.plots()->chartView(ui::QuantityKind::Omega)->chart();
  const auto axisFont = [&] { return chart->axes(Qt::Vertical).front()->labelsFont(); };
  const auto size = [](const QFont& f) { return f.pixelSize() > 0 ? f.pixelSize() : f.pointSizeF(); };
  const double title = size(chart->titleFont()), labels = size(axisFont()), legend = size(chart->legend()->font());
  const ui::CurveItem* curve =
      window.plots()->chartView(ui::QuantityKind::Omega)->curveItem(ui::PlotQuantity::RockerOmega);
  REQUIRE(curve != nullptr);
  const double pen = curve->pen().widthF();
  QChart* force = window.forcePlots()->torqueChart()->chart();
  const double forceTitle = size(force->titleFont());
  window.setPresentationMode(true);
  CHECK(window.font().pointSizeF() > normal * 1.5);
  CHECK(size(chart->titleFont()) >= 1.5 * title);
  CHECK(size(axisFont()) >= 1.5 * labels);
  CHECK(size(chart->legend()->font()) >= 1.5 * legend);
  CHECK(curve->pen().widthF() >= 1.5 * pen);
  CHECK(size(force->titleFont()) >= 1.5 * forceTitle);
  window.setPresentationMode(false);
  CHECK(window.font().pointSizeF() == normal);
  CHECK(size(chart->titleFont()) == title);
  CHECK(size(axisFont()) == labels);
  CHECK(curve->pen().widthF() == pen);
}

TEST_CASE("presentation mode opens on every example, and only the bottom chart names the x axis", "[ui][window]") {
  // A linkage without limit positions (a slider-crank) once crashed here: Qt Charts re-laid out
  // a hidden, emptied scatter series (the limit points) against its stale points.
  namespace k = kinematics;
  for (const k::Example& example : k::examples()) {
    CAPTURE(example.name);
    ui::MainWindow window;
    window.newDocument(*k::designForExample(example.name));
    window.setPresentationMode(true);
    QList<ui::QuantityChartView*> shown;
    for (const auto kind : {ui::QuantityKind::Angle, ui::QuantityKind::Omega, ui::QuantityKind::Alpha,
                            ui::QuantityKind::Position, ui::QuantityKind::Velocity, ui::QuantityKind::Acceleration,
                            ui::QuantityKind::VelocityRatio, ui::QuantityKind::Advantage})
      if (!window.plots()->chartView(kind)->isHidden()) shown.append(window.plots()->chartView(kind));
    REQUIRE_FALSE(shown.isEmpty());
    const auto titled = [](ui::QuantityChartView* view) {
      return ui::plotAxes(view->chart())->titleShown(Qt::Horizontal);
    };
    for (ui::QuantityChartView* view : shown) CHECK(titled(view) == (view == shown.back()));
    // The limit points a slider-crank has none of stay hidden, out of the legend.
    const QScatterSeries* limits = window.plots()->limitMarkers()->points();
    CHECK(limits->isVisible() == (limits->count() > 0));
    window.setPresentationMode(false);
    for (ui::QuantityChartView* view : shown) CHECK(titled(view));
  }
}

TEST_CASE("presentation mode scales a slider-crank's charts after a four-bar's", "[ui][window]") {
  // The four-bar's limit markers, emptied while hidden, used to crash Qt Charts when scaled.
  ui::MainWindow window;
  window.newDocument(*kinematics::designForExample("ls3-engine"));
  QChart* chart = window.plots()->chartView(ui::QuantityKind::Position)->chart();
  const auto size = [](const QFont& f) { return f.pixelSize() > 0 ? f.pixelSize() : f.pointSizeF(); };
  const double title = size(chart->titleFont());
  REQUIRE(title > 0.0);
  window.setPresentationMode(true);
  CHECK(size(chart->titleFont()) >= 1.5 * title);
  window.setPresentationMode(false);
  CHECK(size(chart->titleFont()) == title);
}

TEST_CASE("typing a length in the panel updates the badge and the plotted series as the core says", "[ui][window]") {
  ui::MainWindow window;
  auto* frame = window.dimensionsPanel()->editor(kinematics::ParameterSlot::FrameLength);
  REQUIRE(frame != nullptr);
  frame->setFocus();
  frame->selectAll();
  QTest::keyClicks(frame, "20");
  QTest::keyClick(frame, Qt::Key_Return);
  REQUIRE(window.document()->fourBar()->lengths.frame == 20.0);
  CHECK(window.analysisPanel()->grashofText().contains("Triple-rocker"));
  // The rocker's ω curve now holds exactly the new sweep's values at its assembled samples.
  const auto& sweep = window.document()->sweep();
  const ui::CurveItem* curve =
      window.plots()->chartView(ui::QuantityKind::Omega)->curveItem(ui::PlotQuantity::RockerOmega);
  REQUIRE(curve != nullptr);
  REQUIRE_FALSE(curve->runs().isEmpty());
  const QList<QPointF> plotted = curve->runs().front();
  REQUIRE_FALSE(plotted.isEmpty());
  std::size_t first = 0;
  while (!sweep.ok(first)) ++first;
  CHECK(plotted.front().x() == Approx(kinematics::radToDeg(sweep.inputAngle[first])));
  CHECK(plotted.front().y() ==
        Approx(kinematics::radToDeg(sweep.linkOmega[kinematics::fourbar::kRocker.index][first])));
}

TEST_CASE("the quality box sets the plots' sampling, states its cost and error, and is remembered",
          "[ui][window][quality]") {
  // Whatever happens here, later windows start on Normal again.
  struct Restore {
    ~Restore() { ui::Settings().setSamplingQuality(ui::SamplingQuality::Normal); }
  } restore;
  ui::Settings().setSamplingQuality(ui::SamplingQuality::Normal);
  {
    ui::MainWindow window;
    window.resize(1400, 880);
    window.show();
    REQUIRE(QTest::qWaitForWindowExposed(&window));
    window.settle();
    ui::QualityBar* bar = window.plots()->qualityBar();
    CHECK(bar->qualityBox()->currentIndex() == static_cast<int>(ui::SamplingQuality::Normal));
    bar->qualityBox()->setCurrentIndex(static_cast<int>(ui::SamplingQuality::Draft));
    window.settle();
    const ui::MechanismDocument& doc = *window.document();
    CHECK(doc.quality() == ui::SamplingQuality::Draft);
    CHECK(doc.request().newton.tolerance == 1e-6);
    CHECK(bar->costText().contains(QStringLiteral("samples/rev · sweep")));
    REQUIRE(doc.qualityEstimate().error.has_value());
    CHECK(bar->errorText() == QStringLiteral("worst peak error ") +
                                  ui::QualityBar::formatRelative(doc.qualityEstimate().error->worstRate()));
  }
  CHECK(ui::Settings().samplingQuality() == ui::SamplingQuality::Draft);
  ui::MainWindow again;
  CHECK(again.document()->quality() == ui::SamplingQuality::Draft);
  CHECK(again.plots()->qualityBar()->qualityBox()->currentIndex() == static_cast<int>(ui::SamplingQuality::Draft));
}

TEST_CASE("with every plot unticked the sweep has positions only and the canvas still draws the coupler path",
          "[ui][window][quality]") {
  ui::MainWindow window;
  window.resize(1400, 880);
  window.show();
  REQUIRE(QTest::qWaitForWindowExposed(&window));
  window.newDocument(*kinematics::designForExample("miranda-fourbar"));
  window.settle();
  for (const ui::PlotCurve& c : window.plots()->curves())
    window.plots()->selector()->checkBox(c.quantity)->setChecked(false);
  const ui::MechanismDocument& doc = *window.document();
  CHECK_FALSE(doc.request().velocities);
  CHECK_FALSE(doc.request().accelerations);
  CHECK(doc.sweep().linkOmega.empty());
  CHECK(doc.sweep().velocity.empty());
  const auto& scene = dynamic_cast<const ui::LinkageScene&>(*window.canvas()->linkageScene());
  const ui::CouplerPathItem* path = scene.pathItem(kinematics::fourbar::kCouplerPoint);
  REQUIRE(path != nullptr);
  CHECK(path->isVisible());
  CHECK(path->path().elementCount() == static_cast<int>(doc.sweep().size()));
  // The analysis panel's figures are closed form or on the design's grid: still there.
  CHECK(window.analysisPanel()->grashofText().contains(QStringLiteral("Crank-rocker")));
}
