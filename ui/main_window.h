#pragma once
// The designer window: canvas in the middle, dimensions / drive / motion / analysis panels on the left,
// plots on the right; File (New ▸ each kind of linkage), Edit (Attach dyad…), View, Examples
// and Help menus. The window wires widgets to
// the document; it computes nothing itself. Each file and export action has a dialog-free
// twin (openFile, saveTo, exportCsv, ...) that the menus call and the tests use.

#include "kinematics/analysis/link_drawing.h"
#include "kinematics/design/design.h"
#include "kinematics/report/report_pdf.h"

#include <QMainWindow>

#include <memory>
#include <optional>

class QAction;
class QMenu;
class QScrollArea;
class QSplitter;
class QTabWidget;

namespace linkwright::kinematics {
struct DyadRequest;
}

namespace linkwright::ui {

class AnalysisPanel;
class BigReadout;
class CrankAnimator;
class DimensionsPanel;
class DrivePanel;
class DynamicsPanel;
class ForceArrowsItem;
class ForcePlotPanel;
class ForceResults;
class LinkageView;
class MechanismDocument;
class MessageBanner;
class MotionPanel;
class PlotPanel;
class PolygonPanel;
class CompareDialog;
class CognatesWindow;
class ToleranceWindow;
class OptimiseWindow;
class AtlasWindow;
class InversionsWindow;
class Settings;
class SynthesisPanel;
struct AnimationSettings;

class MainWindow : public QMainWindow {
  Q_OBJECT
public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  MechanismDocument* document() const { return m_document; }
  LinkageView* canvas() const { return m_canvas; }
  PlotPanel* plots() const { return m_plots; }
  ForceResults* forces() const { return m_forces; }
  ForcePlotPanel* forcePlots() const { return m_forcePlots; }
  DimensionsPanel* dimensionsPanel() const { return m_dimensions; }
  DrivePanel* drivePanel() const { return m_drive; }
  MotionPanel* motionPanel() const { return m_motion; }
  AnalysisPanel* analysisPanel() const { return m_analysis; }
  SynthesisPanel* synthesisPanel() const { return m_synthesis; }
  PolygonPanel* polygonPanel() const { return m_polygons; }
  CrankAnimator* animator() const { return m_animator; }
  MessageBanner* banner() const { return m_banner; }

  /// Starts a new document on `design` (File ▸ New, Examples). Until it is saved, the title
  /// calls it `name` (the example's name), or the design's kind when `name` is empty.
  void newDocument(const kinematics::Design& design, const QString& name = {});
  /// Attaches a dyad to the current linkage, undoably (Edit ▸ Attach dyad… without the
  /// dialog). Returns the reason if the core or the document refuses; then nothing changes.
  std::optional<QString> attachDyad(const kinematics::DyadRequest& request);
  /// Opens a document; on failure shows why in the banner and changes nothing.
  bool openFile(const QString& path);
  /// Saves to `path` (atomically) and makes it the document's file.
  bool saveTo(const QString& path);
  /// Writes the design's full table, byte-identical to `linkwright-cli analyze`.
  bool exportCsv(const QString& path);
  /// Writes the links as a DXF drawing at the current pose (kinematics/io/dxf_export.h); on a
  /// refusal (a hole too large for a link, …) shows the core's reason and writes nothing.
  bool exportDxf(const QString& path, const kinematics::DrawingOptions& options);
  /// Writes an animated GIF of the canvas over one cycle (ui/export/cycle_animation.h) and
  /// puts the crank back; `showProgress` offers a cancellable progress dialog. On failure
  /// shows why in the banner and writes nothing.
  bool exportAnimation(const QString& path, const AnimationSettings& settings, bool showProgress = false);
  /// Writes the lab-report PDF (kinematics/report/, as `linkwright-cli report`): drawn at input
  /// `at`, a table row every `step` (both in the input's display unit: degrees for a crank, or
  /// seconds on a time base); on a refusal shows the core's reason and writes nothing.
  bool exportReport(const QString& path, double at, double step, kinematics::report::Paper paper,
                    const kinematics::report::ReportUnits& units = {});
  /// File ▸ Compare… on `path`, a table from another tool: opens the comparison dialog on it
  /// (not modal; it closes itself). On a file that cannot be read or holds no numbers, shows
  /// why in the banner and returns nullptr.
  CompareDialog* openCompareTable(const QString& path);
  /// Writes the canvas as PNG or SVG.
  bool exportCanvasImage(const QString& path);
  /// Writes plot `index` (0 angles, 1 ω, 2 α) as PNG or SVG.
  bool exportPlotImage(int index, const QString& path);
  /// Does now what waits for the window to settle: the plots report their width (the sweep
  /// follows it) and the document measures the quality estimate. For a screenshot or a test.
  void settle();
  /// View ▸ Inversions…: shows (and raises) the window of the linkage's four inversions, made
  /// once and kept; nullptr, changing nothing, when the linkage is neither a four-bar nor a
  /// slider-crank (the action is disabled then, its tooltip saying why).
  InversionsWindow* showInversions();
  /// View ▸ Cognates…: shows (and raises) the window of the four-bar's cognates.
  CognatesWindow* showCognates();
  /// View ▸ Tolerances…: shows (and raises) the window of the design's tolerance study.
  ToleranceWindow* showTolerances();
  /// Edit ▸ Optimise…: shows (and raises) the window that optimises the design by one measure.
  OptimiseWindow* showOptimise();
  /// View ▸ Atlas…: shows (and raises) the coupler-curve atlas window.
  AtlasWindow* showAtlas();
  QAction* inversionsAction() const { return m_inversionsAction; }
  QAction* balanceAction() const { return m_balanceAction; }
  QAction* springBalanceAction() const { return m_springBalanceAction; }
  /// View ▸ Instant centres and centrodes, as if chosen from the menu.
  void setShowInstantCentres(bool show);
  /// Large fonts and lines, full screen, side panels hidden: for the lecture hall.
  void setPresentationMode(bool on);
  bool presentationMode() const { return m_presentation; }
  /// View ▸ High contrast (--high-contrast): black on white, darker link colours, thicker grid
  /// axes (ui/colors.h); the canvas and every chart are drawn again in it.
  void setHighContrast(bool on);
  bool highContrast() const;
  /// View ▸ Big read-out: the input and the main outputs in large type above the canvas and
  /// the plots (ui/classroom/big_readout.h). Presentation mode shows it while it lasts.
  void setShowBigReadout(bool show);
  BigReadout* bigReadout() const { return m_bigReadout; }
  /// Shows the Forces tab and the canvas's force arrows (linkwright --forces).
  void showForces();
  /// The size a new window opens at (1400×880), made to fit the available geometry of the
  /// screen the window is on, frame included, and the window placed inside it: on a 1366×768
  /// laptop it opened 34 px and 112 px past the screen's edges.
  void fitToScreen();

protected:
  void closeEvent(QCloseEvent* event) override;

private:
  void buildMenus();
  void buildNewMenu(QMenu* menu);
  void buildExamplesMenu(QMenu* menu);
  void openAttachDyadDialog();
  void balanceShakingForce();
  void balanceBySpring();
  QWidget* buildAnalysisTabs();
  void updateForcesNeeded();
  void showForcesTab();
  void keepForceInputsShown();
  void showPolygonsTab();
  void refreshRecentFiles();
  void refreshTitle();
  bool save();
  bool saveAs();
  void open();
  void exportCsvDialog();
  void exportImageDialog();
  void exportDxfDialog();
  void exportAnimationDialog();
  void exportReportDialog();
  void compareDialog();
  bool maybeSave();
  void showError(const QString& message);

  std::unique_ptr<Settings> m_settings;
  MechanismDocument* m_document;
  CrankAnimator* m_animator;
  MessageBanner* m_banner;
  LinkageView* m_canvas;
  PlotPanel* m_plots;
  DimensionsPanel* m_dimensions;
  DrivePanel* m_drive;
  MotionPanel* m_motion;
  AnalysisPanel* m_analysis;
  ForceResults* m_forces;
  DynamicsPanel* m_dynamicsPanel;
  ForcePlotPanel* m_forcePlots;
  ForceArrowsItem* m_forceArrows;  // owned by the canvas's scene
  SynthesisPanel* m_synthesis = nullptr;
  PolygonPanel* m_polygons = nullptr;
  QTabWidget* m_tabs = nullptr;
  QAction* m_forceArrowsAction = nullptr;
  QWidget* m_sidePanel = nullptr;
  QMenu* m_recentMenu = nullptr;
  QAction* m_centresAction = nullptr;
  QAction* m_presentationAction = nullptr;
  QAction* m_highContrastAction = nullptr;
  QAction* m_bigReadoutAction = nullptr;
  BigReadout* m_bigReadout = nullptr;
  bool m_bigReadoutBeforePresentation = false;  // the toggle's state, put back on leaving
  QByteArray m_geometryBeforePresentation;      // the window's, put back on leaving
  QSplitter* m_forcesSplitter = nullptr;        // the masses and loads over the force plots
  QScrollArea* m_forceInputs = nullptr;         // the masses and loads, scrolled when the tab is short
  QAction* m_inversionsAction = nullptr;
  QAction* m_balanceAction = nullptr;
  QAction* m_springBalanceAction = nullptr;
  InversionsWindow* m_inversions = nullptr;
  CognatesWindow* m_cognates = nullptr;
  ToleranceWindow* m_tolerances = nullptr;
  OptimiseWindow* m_optimise = nullptr;
  AtlasWindow* m_atlas = nullptr;
  bool m_presentation = false;
  QString m_unsavedName;             ///< what the title calls a document not saved yet
  std::string m_unsavedDescription;  ///< the example's description, when it was started from one
  QFont m_normalFont;
};

}  // namespace linkwright::ui
