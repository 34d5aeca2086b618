#include "ui/main_window.h"

#include "ui/animation/crank_animator.h"
#include "ui/canvas/force_arrows_item.h"
#include "ui/canvas/linkage_view.h"
#include "ui/classroom/atlas_window.h"
#include "ui/classroom/big_readout.h"
#include "ui/classroom/cognates_window.h"
#include "ui/classroom/inversion_cells.h"
#include "ui/classroom/inversions_window.h"
#include "ui/classroom/polygon_panel.h"
#include "ui/classroom/polygon_view.h"
#include "ui/colors.h"
#include "ui/compare/compare_dialog.h"
#include "ui/dialogs/attach_dyad_dialog.h"
#include "ui/dialogs/getting_started.h"
#include "ui/document/design_templates.h"
#include "ui/document/document_file.h"
#include "ui/document/force_results.h"
#include "ui/document/mechanism_document.h"
#include "ui/export/animation_dialog.h"
#include "ui/export/cycle_animation.h"
#include "ui/export/dxf_options_dialog.h"
#include "ui/export/report_options_dialog.h"
#include "ui/export/view_image.h"
#include "ui/message_banner.h"
#include "ui/number_text.h"
#include "ui/panels/analysis_panel.h"
#include "ui/panels/dimensions_panel.h"
#include "ui/panels/drive_panel.h"
#include "ui/panels/dynamics_panel.h"
#include "ui/panels/motion_panel.h"
#include "ui/plots/force_plot_panel.h"
#include "ui/plots/optimise_window.h"
#include "ui/plots/plot_panel.h"
#include "ui/plots/quality_bar.h"
#include "ui/plots/tolerance_window.h"
#include "ui/settings.h"
#include "ui/synthesis/synthesis_panel.h"
#include "ui/undo_keys.h"
#include "ui/wheel_guard.h"

#include "kinematics/design/design.h"
#include "kinematics/design/dyad_request.h"
#include "kinematics/design/examples.h"
#include "kinematics/dynamics/force_balance.h"
#include "kinematics/dynamics/machine_duty.h"
#include "kinematics/dynamics/spring_search.h"
#include "kinematics/io/bounded_read.h"
#include "kinematics/io/csv_writer.h"
#include "kinematics/io/dxf_export.h"
#include "kinematics/io/numeric_table_csv.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/recognise.h"
#include "kinematics/report/report_pdf.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDateTime>
#include <QDesktopServices>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QGraphicsView>
#include <QInputDialog>
#include <QKeySequence>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressDialog>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSpacerItem>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QToolBar>
#include <QUndoStack>
#include <QUrl>
#include <QVBoxLayout>

#include <sstream>

namespace linkwright::ui {

namespace k = kinematics;

namespace {
// Presentation mode: the window's text and every chart's text and lines grow by this much, a
// size a lecture hall reads from the back.
constexpr double kPresentationTextScale = 1.6;
}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_settings(std::make_unique<Settings>()), m_document(new MechanismDocument(this)),
      m_animator(new CrankAnimator(m_document, this)), m_banner(new MessageBanner(this)),
      m_canvas(new LinkageView(m_document, this)), m_plots(new PlotPanel(m_document, this)),
      m_dimensions(new DimensionsPanel(m_document, this)), m_drive(new DrivePanel(m_document, m_settings.get(), this)),
      m_motion(new MotionPanel(m_document, m_animator, this)), m_analysis(new AnalysisPanel(m_document, this)),
      m_forces(new ForceResults(m_document, this)), m_dynamicsPanel(new DynamicsPanel(m_document, this)),
      m_forcePlots(new ForcePlotPanel(m_document, m_forces, this)), m_forceArrows(new ForceArrowsItem) {
  setObjectName("MainWindow");
  m_normalFont = font();
  auto* side = new QWidget(this);
  // When a panel grows a row (a drag into a rocking crank adds "Not assembled"), the column
  // grows downward: only what moved is repainted, not every panel above it.
  side->setAttribute(Qt::WA_StaticContents);
  auto* sideLayout = new QVBoxLayout(side);
  sideLayout->setContentsMargins(0, 0, 0, 0);
  sideLayout->addWidget(m_dimensions);
  sideLayout->addWidget(m_drive);
  // Room at the bottom that a growing panel takes first: the column is laid out in its old
  // height before the scroll area makes it taller, and without this every panel would be
  // squeezed for that pass and moved back (the whole column repainted twice).
  constexpr int kGrowthRoomPx = 80;
  sideLayout->addSpacerItem(new QSpacerItem(0, kGrowthRoomPx, QSizePolicy::Minimum, QSizePolicy::Expanding));
  auto* scroll = new QScrollArea(this);
  scroll->setObjectName("SidePanel");
  m_sidePanel = scroll;
  scroll->setWidget(side);
  scroll->setWidgetResizable(true);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  new WheelGuard(scroll);        // the wheel scrolls the panels; it edits a control only once focused
  new UndoKeysToDocument(this);  // Ctrl+Z in a number field undoes the design, not the field's text
  // As wide as the panels need, plus the vertical scroll bar: never cut off on the right.
  scroll->setMinimumWidth(side->minimumSizeHint().width() + scroll->verticalScrollBar()->sizeHint().width() + 4);

  // The answers over the linkage, where they are seen without scrolling.
  auto* canvasColumn = new QWidget(this);
  auto* canvasLayout = new QVBoxLayout(canvasColumn);
  canvasLayout->setContentsMargins(0, 0, 0, 0);
  canvasLayout->setSpacing(2);
  canvasLayout->addWidget(m_analysis);
  canvasLayout->addWidget(m_canvas, 1);

  auto* splitter = new QSplitter(Qt::Horizontal, this);
  splitter->setObjectName("MainSplitter");
  splitter->addWidget(scroll);
  splitter->addWidget(canvasColumn);
  splitter->addWidget(buildAnalysisTabs());
  splitter->setStretchFactor(0, 0);
  splitter->setStretchFactor(1, 3);
  splitter->setStretchFactor(2, 2);
  splitter->setSizes({scroll->minimumWidth(), 620, 480});
  splitter->setChildrenCollapsible(false);

  auto* central = new QWidget(this);
  auto* layout = new QVBoxLayout(central);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(m_banner);
  m_bigReadout = new BigReadout(m_document, this);
  m_bigReadout->hide();
  layout->addWidget(m_bigReadout);
  layout->addWidget(splitter, 1);
  setCentralWidget(central);
  // The status bar is there from the start. QMainWindow makes it on the first message (the
  // first hover over a handle), and the window's content then shrinks by its height: every
  // widget moved and repainted at once, a visible jump and a 26 ms stall on the first drag.
  setStatusBar(new QStatusBar(this));

  // Play, step and the crank angle across the top: in sight at any height, and in presentation.
  auto* motionBar = new QToolBar(tr("Motion"), this);
  motionBar->setObjectName("MotionBar");
  motionBar->setMovable(false);
  motionBar->addWidget(m_motion);
  addToolBar(Qt::TopToolBarArea, motionBar);

  buildMenus();
  m_canvas->linkageScene()->addItem(m_forceArrows);
  m_forceArrows->setVisible(false);
  // Arrows that come after the canvas's fit (their forces land later) are fitted in, once.
  connect(m_forces, &ForceResults::changed, this, [this] {
    const bool shown = m_forceArrows->showsArrows();
    m_forceArrows->setForces(*m_document, *m_forces);
    if (!shown && m_forceArrows->showsArrows()) m_canvas->refitIfFollowing();
  });
  connect(m_canvas, &LinkageView::pixelsPerUnitChanged, this, [this](double s) {
    m_forceArrows->setCanvasSize(m_canvas->viewport()->size());
    m_forceArrows->setViewScale(s);
    m_forceArrows->setForces(*m_document, *m_forces);  // the arrows' lengths for the canvas's size
  });
  m_forceArrows->setViewScale(m_canvas->pixelsPerUnit());
  m_plots->setAngleUnit(m_settings->anglesInRadians() ? AngleUnit::Radians : AngleUnit::Degrees);
  m_forcePlots->setAngleUnit(m_settings->anglesInRadians() ? AngleUnit::Radians : AngleUnit::Degrees);
  m_bigReadout->setAngleUnit(m_plots->angleUnit());
  m_document->setQuality(m_settings->samplingQuality());
  connect(m_plots->qualityBar(), &QualityBar::qualityChosen, this,
          [this](SamplingQuality quality) { m_settings->setSamplingQuality(quality); });
  connect(m_canvas, &LinkageView::editRefused, this,
          [this](const QString& why) { statusBar()->showMessage(why, 5000); });
  connect(m_canvas, &LinkageView::statusMessage, this,
          [this](const QString& text) { statusBar()->showMessage(text, 3000); });
  connect(m_document, &MechanismDocument::changed, this, [this](Changes what) {
    if (what & (Change::File | Change::Design)) refreshTitle();
  });
  fitToScreen();
  // Qt moves and shrinks a saved geometry that would not fit the screen any more.
  restoreGeometry(m_settings->windowGeometry());
  restoreState(m_settings->windowState());
  newDocument(*k::designForExample("thesis-crank-rocker"), QStringLiteral("thesis-crank-rocker"));
}

namespace {

// `page` in a scroll area that takes none of its minimum size: a pane shorter or narrower than
// the page needs (a 768 px screen, presentation mode's larger text) scrolls, rather than the
// window growing past the screen or the page's controls being squeezed over each other.
QScrollArea* scrolled(QWidget* page, const QString& name, QWidget* parent) {
  auto* scroll = new QScrollArea(parent);
  scroll->setObjectName(name);
  scroll->setWidget(page);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  new WheelGuard(scroll);  // the wheel scrolls the page; it edits a control only once focused
  return scroll;
}

}  // namespace

// Kinematics plots, the forces view (masses and loads, torque and joint-force plots, polar
// load diagrams) and dimensional synthesis share the right-hand pane as tabs.
QWidget* MainWindow::buildAnalysisTabs() {
  auto* forces = new QSplitter(Qt::Vertical, this);
  m_forcesSplitter = forces;
  m_forceInputs = scrolled(m_dynamicsPanel, QStringLiteral("ForceInputs"), this);
  forces->addWidget(m_forceInputs);
  forces->addWidget(scrolled(m_forcePlots, QStringLiteral("ForcePlots"), this));
  forces->setStretchFactor(1, 1);
  forces->setChildrenCollapsible(false);
  m_tabs = new QTabWidget(this);
  m_tabs->setObjectName("AnalysisTabs");
  m_tabs->addTab(scrolled(m_plots, QStringLiteral("KinematicsPage"), this), tr("Kinematics"));
  m_tabs->addTab(forces, tr("Forces"));
  m_synthesis = new SynthesisPanel(m_document, m_canvas, this);
  m_tabs->addTab(scrolled(m_synthesis, QStringLiteral("SynthesisPage"), this), tr("Synthesis"));
  m_polygons = new PolygonPanel(m_document, this);
  m_tabs->addTab(scrolled(m_polygons, QStringLiteral("PolygonsPage"), this), tr("Polygons"));
  connect(m_tabs, &QTabWidget::currentChanged, this, &MainWindow::updateForcesNeeded);
  connect(m_tabs, &QTabWidget::currentChanged, this, &MainWindow::keepForceInputsShown);
  // The plots follow the document only while their tab is shown.
  const auto followTab = [this](int tab) {
    m_plots->setOnScreen(tab == 0);
    m_forcePlots->setOnScreen(tab == 1);
    m_polygons->setOnScreen(tab == 3);
  };
  connect(m_tabs, &QTabWidget::currentChanged, this, followTab);
  followTab(m_tabs->currentIndex());
  return m_tabs;
}

// Forces cost about ten times the kinematics: they are solved only while the Forces tab or
// the canvas's force arrows show them.
void MainWindow::updateForcesNeeded() {
  const bool arrows = m_forceArrowsAction != nullptr && m_forceArrowsAction->isChecked();
  const bool needed = arrows || m_tabs->currentIndex() == 1;
  m_document->setForcesNeeded(needed);  // first: the sweep then already has what forces need
  m_forces->setEnabled(needed);
  const bool shown = m_forceArrows->showsArrows();
  m_forceArrows->setVisible(arrows);
  if (!shown && m_forceArrows->showsArrows()) m_canvas->refitIfFollowing();
}

// The splitter keeps the masses' and loads' panel the height it had: at presentation mode's
// larger text that squeezed the Links table to its header. It gets what it needs, up to
// kForceInputsShare of the tab (the plots below keep the rest); beyond that it scrolls.
void MainWindow::keepForceInputsShown() {
  constexpr double kForceInputsShare = 0.55;
  QList<int> sizes = m_forcesSplitter->sizes();
  if (sizes.size() != 2) return;
  const int total = sizes[0] + sizes[1];
  const int needed = std::min(m_dynamicsPanel->minimumSizeHint().height() + 2 * m_forceInputs->frameWidth(),
                              static_cast<int>(kForceInputsShare * total));
  if (total <= 0 || sizes[0] >= needed) return;
  sizes[1] = total - needed;
  sizes[0] = needed;
  m_forcesSplitter->setSizes(sizes);
}

void MainWindow::fitToScreen() {
  // A window manager's title bar and borders, not known before the window is shown.
  constexpr QSize kFrameAllowance(8, 32);
  constexpr QSize kDefaultSize(1400, 880);
  const QRect room = screen()->availableGeometry();
  const QSize size = kDefaultSize.boundedTo(room.size() - kFrameAllowance);
  resize(size);
  move(room.topLeft() + QPoint((room.width() - size.width() - kFrameAllowance.width()) / 2,
                               (room.height() - size.height() - kFrameAllowance.height()) / 2));
}

void MainWindow::showForcesTab() { m_tabs->setCurrentIndex(1); }

void MainWindow::showPolygonsTab() { m_tabs->setCurrentIndex(3); }

void MainWindow::showForces() {
  showForcesTab();
  m_forceArrowsAction->setChecked(true);
}

MainWindow::~MainWindow() = default;

namespace {

// A window of the designer's own (inversions, cognates, tolerances, optimise, the atlas): made on first ask, then
// shown, raised and given the focus each time.
template <typename Window>
Window* showOwnWindow(Window*& window, MechanismDocument* document, QWidget* parent) {
  if (window == nullptr) window = new Window(document, parent);
  window->show();
  window->raise();
  window->activateWindow();
  return window;
}

}  // namespace

InversionsWindow* MainWindow::showInversions() {
  if (inversionsUnavailable(m_document->design())) return nullptr;
  return showOwnWindow(m_inversions, m_document, this);
}

CognatesWindow* MainWindow::showCognates() { return showOwnWindow(m_cognates, m_document, this); }

ToleranceWindow* MainWindow::showTolerances() { return showOwnWindow(m_tolerances, m_document, this); }

OptimiseWindow* MainWindow::showOptimise() { return showOwnWindow(m_optimise, m_document, this); }
AtlasWindow* MainWindow::showAtlas() { return showOwnWindow(m_atlas, m_document, this); }

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  buildNewMenu(file->addMenu(tr("&New")));
  file->addAction(tr("&Open…"), QKeySequence::Open, this, &MainWindow::open);
  m_recentMenu = file->addMenu(tr("Open &Recent"));
  file->addAction(tr("&Save"), QKeySequence::Save, this, &MainWindow::save);
  file->addAction(tr("Save &As…"), QKeySequence::SaveAs, this, &MainWindow::saveAs);
  file->addSeparator();
  QMenu* exportMenu = file->addMenu(tr("&Export"));
  exportMenu->addAction(tr("Table as &CSV…"), this, &MainWindow::exportCsvDialog);
  exportMenu->addAction(tr("&Image of the canvas or a plot…"), this, &MainWindow::exportImageDialog);
  exportMenu->addAction(tr("&Links as DXF…"), this, &MainWindow::exportDxfDialog);
  exportMenu->addAction(tr("&Animation…"), this, &MainWindow::exportAnimationDialog);
  file->addAction(tr("Co&mpare…"), this, &MainWindow::compareDialog);
  file->addSeparator();
  file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

  QMenu* report = menuBar()->addMenu(tr("&Report"));
  report->addAction(tr("&PDF…"), this, &MainWindow::exportReportDialog);

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
  redo->setShortcut(QKeySequence::Redo);
  edit->addAction(undo);
  edit->addAction(redo);
  edit->addSeparator();
  edit->addAction(tr("Attach &dyad…"), QKeySequence(Qt::CTRL | Qt::Key_D), this, &MainWindow::openAttachDyadDialog);
  edit->setToolTipsVisible(true);  // why Balance is disabled
  m_balanceAction = edit->addAction(tr("&Balance the shaking force"), this, &MainWindow::balanceShakingForce);
  m_springBalanceAction = edit->addAction(tr("Balance the torque by a &spring…"), this, &MainWindow::balanceBySpring);
  edit->addAction(tr("&Optimise…"), this, &MainWindow::showOptimise)
      ->setToolTip(tr("A better linkage by one measure (peak α, transmission angle, a path, the torque), its "
                      "lengths within ranges; accepted as one undoable edit"));
  const auto followBalance = [this] {
    const k::Design& d = m_document->design();
    const auto crank = k::checkCrankDriven(d.mechanism);
    m_springBalanceAction->setEnabled(!crank && !d.dynamics.empty());
    m_springBalanceAction->setToolTip(
        crank ? QString::fromStdString(crank->message)
        : d.dynamics.empty()
            ? tr("Give masses or loads first (Forces tab): a spring balances the torque they ask of the crank")
            : tr("The spring from a point on a link to a point on the frame, both searched, that makes the RMS "
                 "driving torque over a turn least"));
    const auto balance = k::balanceShakingForce(d.mechanism, d.dynamics);
    m_balanceAction->setEnabled(balance.ok() && !balance->counterweights.empty());
    m_balanceAction->setToolTip(!balance.ok()                     ? QString::fromStdString(balance.error().message)
                                : balance->counterweights.empty() ? tr("Its shaking force is balanced already")
                                                                  : QString::fromStdString(balance->method));
  };
  connect(m_document, &MechanismDocument::changed, this, [followBalance](Changes what) {
    if (what & Change::Design) followBalance();
  });
  followBalance();

  QMenu* view = menuBar()->addMenu(tr("&View"));
  view->addAction(tr("&Fit to view"), QKeySequence(Qt::CTRL | Qt::Key_0), m_canvas, &LinkageView::fitToView);
  QAction* play = view->addAction(tr("&Play / pause"), m_animator, &CrankAnimator::togglePlay);
  play->setShortcut(Qt::Key_Space);
  m_centresAction = view->addAction(tr("&Instant centres and centrodes"));
  m_centresAction->setCheckable(true);
  m_centresAction->setToolTip(
      tr("Kennedy's instant centres of a four-bar or slider-crank, and its coupler's centrodes"));
  connect(m_centresAction, &QAction::toggled, m_canvas, &LinkageView::setShowInstantCentres);
  QAction* velocity = view->addAction(tr("&Velocity arrows"));
  velocity->setCheckable(true);
  connect(velocity, &QAction::toggled, m_canvas, &LinkageView::setShowVelocityArrows);
  QAction* acceleration = view->addAction(tr("&Acceleration arrows"));
  acceleration->setCheckable(true);
  connect(acceleration, &QAction::toggled, m_canvas, &LinkageView::setShowAccelerationArrows);
  m_forceArrowsAction = view->addAction(tr("&Force arrows"));
  m_forceArrowsAction->setCheckable(true);
  connect(m_forceArrowsAction, &QAction::toggled, this, &MainWindow::updateForcesNeeded);
  view->addAction(tr("Forces and &masses"), QKeySequence(Qt::CTRL | Qt::Key_F), this, &MainWindow::showForcesTab);
  view->addAction(tr("Velocity and acceleration &polygons"), QKeySequence(Qt::CTRL | Qt::Key_G), this,
                  &MainWindow::showPolygonsTab);
  view->setToolTipsVisible(true);  // why Inversions… is disabled
  m_inversionsAction = view->addAction(tr("I&nversions…"), this, &MainWindow::showInversions);
  view->addAction(tr("&Cognates…"), this, &MainWindow::showCognates)
      ->setToolTip(tr("A four-bar's two Roberts–Chebyshev cognates, tracing its coupler curve with it"));
  view->addAction(tr("&Tolerances…"), this, &MainWindow::showTolerances)
      ->setToolTip(tr("How far the motion moves with every length and pivot made ± a tolerance"));
  view->addAction(tr("At&las…"), this, &MainWindow::showAtlas)
      ->setToolTip(tr("A grid of four-bars' coupler curves over link ratios and coupler points, classified; a "
                      "click makes one the design"));
  const auto followLinkage = [this] {
    const std::optional<QString> why = inversionsUnavailable(m_document->design());
    m_inversionsAction->setEnabled(!why);
    m_inversionsAction->setToolTip(
        why.value_or(tr("The linkage with each link grounded in turn, animated side by side")));
  };
  connect(m_document, &MechanismDocument::changed, this, [followLinkage](Changes what) {
    if (what & Change::Design) followLinkage();
  });
  followLinkage();
  QMenu* units = view->addMenu(tr("Angle &unit in plots"));
  auto* group = new QActionGroup(this);
  QAction* degrees = units->addAction(tr("&Degrees"));
  QAction* radians = units->addAction(tr("&Radians"));
  for (QAction* a : {degrees, radians}) {
    a->setCheckable(true);
    group->addAction(a);
  }
  (m_settings->anglesInRadians() ? radians : degrees)->setChecked(true);
  connect(radians, &QAction::toggled, this, [this](bool on) {
    m_settings->setAnglesInRadians(on);
    m_plots->setAngleUnit(on ? AngleUnit::Radians : AngleUnit::Degrees);
    m_forcePlots->setAngleUnit(on ? AngleUnit::Radians : AngleUnit::Degrees);
    m_bigReadout->setAngleUnit(on ? AngleUnit::Radians : AngleUnit::Degrees);
  });
  m_presentationAction = view->addAction(tr("Pr&esentation mode"));
  m_presentationAction->setCheckable(true);
  m_presentationAction->setShortcut(Qt::Key_F11);
  connect(m_presentationAction, &QAction::toggled, this, &MainWindow::setPresentationMode);
  // One key away in front of a class; presentation mode does not impose it.
  m_highContrastAction = view->addAction(tr("&High contrast"));
  m_highContrastAction->setCheckable(true);
  m_highContrastAction->setShortcut(Qt::Key_F12);
  connect(m_highContrastAction, &QAction::toggled, this, &MainWindow::setHighContrast);
  m_bigReadoutAction = view->addAction(tr("&Big read-out"));
  m_bigReadoutAction->setCheckable(true);
  m_bigReadoutAction->setShortcut(Qt::Key_F9);
  connect(m_bigReadoutAction, &QAction::toggled, m_bigReadout, &QWidget::setVisible);

  buildExamplesMenu(menuBar()->addMenu(tr("E&xamples")));

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&Getting started"), QKeySequence::HelpContents, this, [this] {
    auto* dialog = new GettingStartedDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
  });
  help->addAction(tr("&Documentation online"), this,
                  [] { QDesktopServices::openUrl(QUrl(QString::fromLatin1(kDocumentationUrl))); });
  help->addSeparator();
  help->addAction(tr("&About Linkwright"), this, [this] {
    QMessageBox::about(this, tr("About Linkwright"),
                       tr("<b>Linkwright %1</b><p>Design and analysis of planar linkages (four-bars, slider-cranks, "
                          "quick returns, six-bars and whatever dyads you attach): exact positions, velocities and "
                          "accelerations, Grashof class, transmission angles, limit positions, time ratios.</p>")
                           .arg(QApplication::applicationVersion()));
  });
  refreshRecentFiles();
}

void MainWindow::buildNewMenu(QMenu* menu) {
  for (const DesignTemplate& kind : designTemplates()) {
    QAction* action = menu->addAction(kind.label, this, [this, kind] {
      if (maybeSave()) newDocument(templateDesign(kind));
    });
    if (kind.example.empty()) action->setShortcut(QKeySequence::New);
  }
}

void MainWindow::buildExamplesMenu(QMenu* menu) {
  menu->setToolTipsVisible(true);
  const auto addExample = [this, menu](const std::string& name, const std::string& description) {
    // The name, as the CLI's --example and the window's title give it; what it is, which does
    // not fit a menu, in the tooltip and the status bar.
    QAction* action = menu->addAction(QString::fromStdString(name), this, [this, name] {
      if (maybeSave()) newDocument(*k::designForExample(name), QString::fromStdString(name));
    });
    action->setObjectName(QString::fromStdString("example_" + name));
    action->setToolTip(QString::fromStdString(description));
    action->setStatusTip(QString::fromStdString(description));
  };
  const std::vector<k::Example> examples = k::examples();
  menu->addSection(tr("Four-bars"));
  for (const k::Example& e : examples)
    if (k::asFourBar(e.mechanism)) addExample(e.name, e.description);
  menu->addSection(tr("Slider-cranks, quick returns and six-bars"));
  for (const k::Example& e : examples)
    if (!k::asFourBar(e.mechanism)) addExample(e.name, e.description);
}

std::optional<QString> MainWindow::attachDyad(const kinematics::DyadRequest& request) {
  const auto attached = kinematics::attachToDesign(m_document->design(), request);
  if (!attached) return QString::fromStdString(attached.error().message);
  return m_document->edit(*attached, tr("Attach %1").arg(QString::fromStdString(request.joint)));
}

void MainWindow::openAttachDyadDialog() {
  m_animator->pause();
  AttachDyadDialog dialog(
      m_document->mechanism(), m_document->crankAngle(),
      [this](const kinematics::DyadRequest& request) { return attachDyad(request); }, this);
  dialog.exec();
}

void MainWindow::newDocument(const k::Design& design, const QString& name) {
  m_unsavedName = name.isEmpty() ? QString::fromStdString(design.kind) : name;
  const auto example = name.isEmpty() ? std::nullopt : k::findExample(name.toStdString());
  m_unsavedDescription = example ? example->description : std::string();
  m_animator->pause();
  m_plots->clearComparison();  // another tool's rows belong to the linkage they were compared with
  m_document->reset(design);
  m_canvas->fitToView();
  m_banner->hide();
}

bool MainWindow::openFile(const QString& path) {
  k::Design design;
  if (auto why = loadDesignFile(path, design)) {
    showError(*why);
    return false;
  }
  // A well-formed file may still describe a linkage that never assembles.
  if (auto why = m_document->validate(design)) {
    showError(tr("Cannot open %1: %2").arg(QFileInfo(path).fileName(), *why));
    return false;
  }
  m_animator->pause();
  m_plots->clearComparison();
  m_document->reset(design, QFileInfo(path).absoluteFilePath());
  m_canvas->fitToView();
  m_settings->addRecentFile(path);
  refreshRecentFiles();
  m_banner->hide();
  statusBar()->showMessage(tr("Opened %1").arg(QFileInfo(path).fileName()), 3000);
  return true;
}

bool MainWindow::saveTo(const QString& path) {
  if (auto why = saveDesignFile(path, m_document->design())) {
    showError(*why);
    return false;
  }
  m_document->setFilePath(QFileInfo(path).absoluteFilePath());
  m_document->markSaved();
  m_settings->addRecentFile(path);
  refreshRecentFiles();
  statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), 3000);
  return true;
}

bool MainWindow::exportCsv(const QString& path) {
  // The full table at the design's grid, whatever the plots show: the CLI's columns exactly.
  const auto result = k::sweep(m_document->mechanism(), k::designSweepSpec(m_document->design()), {true, true});
  std::ostringstream csv;
  k::io::writeSweepCsv(csv, m_document->mechanism(), result.value());
  if (auto why = saveFileAtomically(path, QByteArray::fromStdString(csv.str()))) {
    showError(*why);
    return false;
  }
  statusBar()->showMessage(tr("Exported %1").arg(QFileInfo(path).fileName()), 3000);
  return true;
}

bool MainWindow::exportDxf(const QString& path, const k::DrawingOptions& options) {
  if (auto why =
          k::io::exportLinkDrawingDxf(m_document->mechanism(), m_document->pose(), options, path.toStdString())) {
    showError(tr("DXF not written: %1").arg(QString::fromStdString(why->message)));
    return false;
  }
  statusBar()->showMessage(tr("Exported %1").arg(QFileInfo(path).fileName()), 3000);
  return true;
}

bool MainWindow::exportAnimation(const QString& path, const AnimationSettings& settings, bool showProgress) {
  m_animator->pause();  // the export moves the crank itself, and puts it back
  std::unique_ptr<QProgressDialog> progress;
  if (showProgress) {
    progress =
        std::make_unique<QProgressDialog>(tr("Rendering the animation…"), tr("Cancel"), 0, settings.frames, this);
    progress->setWindowModality(Qt::WindowModal);
    progress->setMinimumDuration(500);
  }
  const auto report = [&progress](int done, int) {
    if (!progress) return true;
    progress->setValue(done);
    return !progress->wasCanceled();
  };
  if (auto why = exportCycleAnimation(*m_document, *m_canvas, path, settings, report)) {
    showError(*why);
    return false;
  }
  statusBar()->showMessage(tr("Exported %1").arg(QFileInfo(path).fileName()), 3000);
  return true;
}

bool MainWindow::exportCanvasImage(const QString& path) {
  if (auto why = saveViewImage(m_canvas, path, tr("Linkwright linkage"))) {
    showError(*why);
    return false;
  }
  return true;
}

bool MainWindow::exportPlotImage(int index, const QString& path) {
  const QList<QGraphicsView*> views = m_plots->graphicsViews();
  if (index < 0 || index >= views.size()) return false;
  if (auto why = saveViewImage(views[index], path, m_plots->chartTitle(index))) {
    showError(*why);
    return false;
  }
  return true;
}

void MainWindow::settle() {
  m_plots->reportPlotWidth();
  m_document->measureQualityNow();
}

void MainWindow::setShowInstantCentres(bool show) { m_centresAction->setChecked(show); }

void MainWindow::setPresentationMode(bool on) {
  if (on == m_presentation) return;
  m_presentation = on;
  QFont big = m_normalFont;
  big.setPointSizeF(m_normalFont.pointSizeF() * kPresentationTextScale);
  setFont(on ? big : m_normalFont);
  m_canvas->setPresentationScale(on ? 2.0 : 1.0);
  m_forceArrows->setPresentationScale(on ? 2.0 : 1.0);
  m_plots->setPresentationScale(on ? kPresentationTextScale : 1.0);
  m_forcePlots->setPresentationScale(on ? kPresentationTextScale : 1.0);
  m_polygons->setPresentationScale(on ? kPresentationTextScale : 1.0);
  m_bigReadout->setPresentationScale(on ? kPresentationTextScale : 1.0);
  // The read-out comes with presentation mode, and goes as it was before.
  if (on) m_bigReadoutBeforePresentation = m_bigReadoutAction->isChecked();
  m_bigReadoutAction->setChecked(on || m_bigReadoutBeforePresentation);
  // The class watches the linkage and the plots; Space, the arrows' menu and F11 still work.
  m_sidePanel->setVisible(!on);
  if (m_presentationAction->isChecked() != on) m_presentationAction->setChecked(on);
  // Back where it was: a window manager that forgets the size would leave the window too
  // narrow for the side panel, the canvas and the plots together.
  if (on) m_geometryBeforePresentation = saveGeometry();
  on ? showFullScreen() : showNormal();
  if (!on) restoreGeometry(m_geometryBeforePresentation);
  keepForceInputsShown();
  m_canvas->fitToView();
}

void MainWindow::setHighContrast(bool on) {
  if (on == highContrast()) return;
  setTheme(on ? Theme::HighContrast : Theme::Normal);
  if (m_highContrastAction->isChecked() != on) m_highContrastAction->setChecked(on);
  m_canvas->refreshColors();
  m_plots->refreshColors();
  m_forcePlots->refreshColors();
  m_bigReadout->refreshColors();
  m_polygons->view()->update();  // it reads colors() as it paints
}

bool MainWindow::highContrast() const { return theme() == Theme::HighContrast; }

void MainWindow::setShowBigReadout(bool show) { m_bigReadoutAction->setChecked(show); }

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!maybeSave()) {
    event->ignore();
    return;
  }
  m_settings->setWindowGeometry(saveGeometry());
  m_settings->setWindowState(saveState());
  event->accept();
}

void MainWindow::refreshRecentFiles() {
  m_recentMenu->clear();
  const QStringList files = m_settings->recentFiles();
  for (const QString& path : files)
    m_recentMenu
        ->addAction(QFileInfo(path).fileName(), this,
                    [this, path] {
                      if (maybeSave()) openFile(path);
                    })
        ->setStatusTip(path);
  m_recentMenu->setEnabled(!files.isEmpty());
}

void MainWindow::refreshTitle() {
  const QString path = m_document->filePath();
  // A document not saved yet is named after what it was started from, so a lecture's window
  // says which example it shows.
  const QString name = path.isEmpty() ? tr("%1 (not saved)").arg(m_unsavedName) : QFileInfo(path).fileName();
  setWindowTitle(tr("%1[*] — Linkwright").arg(name));
  setWindowModified(m_document->isModified());
}

bool MainWindow::save() {
  if (m_document->filePath().isEmpty()) return saveAs();
  return saveTo(m_document->filePath());
}

bool MainWindow::saveAs() {
  const QString path =
      QFileDialog::getSaveFileName(this, tr("Save linkage"), m_document->filePath(), saveDocumentFilter());
  if (path.isEmpty()) return false;
  return saveTo(withDocumentSuffix(path));
}

void MainWindow::open() {
  if (!maybeSave()) return;
  const QString path = QFileDialog::getOpenFileName(this, tr("Open linkage"), QString(), openDocumentFilter());
  if (!path.isEmpty()) openFile(path);
}

void MainWindow::exportCsvDialog() {
  QString path = QFileDialog::getSaveFileName(this, tr("Export table"), QString(), tr("CSV tables (*.csv)"));
  if (path.isEmpty()) return;
  if (QFileInfo(path).suffix().isEmpty()) path += ".csv";
  exportCsv(path);
}

void MainWindow::exportDxfDialog() {
  // The core's defaults for this linkage pre-fill the dialog (and say why there are none).
  const auto drawing = k::linkDrawing(m_document->mechanism(), m_document->pose(), {});
  if (!drawing) {
    showError(tr("DXF not written: %1").arg(QString::fromStdString(drawing.error().message)));
    return;
  }
  DxfOptionsDialog options(drawing->holeDiameter, drawing->plateWidth, QString::fromStdString(m_document->lengthUnit()),
                           this);
  if (options.exec() != QDialog::Accepted) return;
  QString path = QFileDialog::getSaveFileName(this, tr("Export links as DXF"), QString(), tr("DXF drawings (*.dxf)"));
  if (path.isEmpty()) return;
  if (QFileInfo(path).suffix().isEmpty()) path += ".dxf";
  exportDxf(path, options.options());
}

void MainWindow::exportAnimationDialog() {
  m_animator->pause();
  const CycleFrames cycle = cycleFrames(*m_document, AnimationSettings::kMinFrames);
  const QString what = cycle.inTime    ? tr("the time base, from its start to its end")
                       : cycle.rocking ? tr("the input's range, there and back (it cannot turn fully)")
                                       : tr("one turn of the crank");
  AnimationDialog dialog(m_canvas->viewport()->size(), what, this);
  if (dialog.exec() != QDialog::Accepted) return;
  QString path = QFileDialog::getSaveFileName(this, tr("Export animation"), QString(), dialog.fileFilter());
  if (path.isEmpty()) return;
  // The format chosen, unless the name given ends in another one's suffix.
  if (!animationFormatOf(path)) path += "." + dialog.suffix();
  exportAnimation(path, dialog.settings(), true);
}

bool MainWindow::exportReport(const QString& path, double at, double step, k::report::Paper paper,
                              const k::report::ReportUnits& units) {
  const k::Design& design = m_document->design();
  const k::Mechanism& m = design.mechanism;
  k::report::ReportRequest request;
  // Named as the window's title names it: the file, else the example it was started from.
  const bool saved = !m_document->filePath().isEmpty();
  k::report::setReportHeading(request,
                              (saved ? QFileInfo(m_document->filePath()).fileName() : m_unsavedName).toStdString(),
                              saved ? std::string() : m_unsavedDescription, design.kind);
  request.date = QDateTime::currentDateTimeUtc().date().toString(Qt::ISODate).toStdString();
  request.grid = k::designSweepSpec(design);
  // On a time base both are seconds. Else a step is a difference of inputs: the display unit's
  // scale without its origin.
  request.tableStep = design.time ? step : k::inputFromDisplay(m, step) - k::inputFromDisplay(m, 0.0);
  request.drawAt = design.time ? at : k::inputFromDisplay(m, at);
  request.units = units;
  const auto content = k::report::buildReport(m, design.dynamics, request);
  const std::optional<k::Error> why = content ? k::report::writeReportPdf(*content, paper, path.toStdString())
                                              : std::optional<k::Error>(content.error());
  if (why) {
    showError(tr("Report not written: %1").arg(QString::fromStdString(why->message)));
    return false;
  }
  statusBar()->showMessage(tr("Wrote %1").arg(QFileInfo(path).fileName()), 3000);
  return true;
}

void MainWindow::exportReportDialog() {
  const k::Design& design = m_document->design();
  const k::Mechanism& m = design.mechanism;
  const bool crank = k::inputKind(m) == k::InputKind::Angle;
  // On a time base the pose drawn and the table's step are times.
  const auto& time = design.time;
  const double at = time ? m_document->time() : k::inputDisplayValue(m, m_document->crankAngle());
  const double maxStep = time ? time->toTime - time->fromTime : crank ? 360.0 : design.toDeg - design.fromDeg;
  const QString unit = time ? QStringLiteral("s") : QString::fromStdString(k::inputUnit(m));
  ReportOptionsDialog options(at, maxStep, unit, this);
  // Angles, ω and α in the unit the plots show them in.
  const bool radians = m_plots->angleUnit() == AngleUnit::Radians;
  options.setUnits({radians ? k::report::AngleUnit::Radians : k::report::AngleUnit::Degrees,
                    radians ? k::report::RateUnit::Radians : k::report::RateUnit::Degrees});
  if (options.exec() != QDialog::Accepted) return;
  QString path = QFileDialog::getSaveFileName(this, tr("Lab report as PDF"), QString(), tr("PDF documents (*.pdf)"));
  if (path.isEmpty()) return;
  if (QFileInfo(path).suffix().isEmpty()) path += ".pdf";
  exportReport(path, options.at(), options.step(), options.paper(), options.units());
}

void MainWindow::compareDialog() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Compare with a table from another tool"), QString(),
                                                    tr("Tables (*.csv *.txt *.tsv);;All files (*)"));
  if (!path.isEmpty()) openCompareTable(path);
}

CompareDialog* MainWindow::openCompareTable(const QString& path) {
  // The core's one reader: a regular file of at most 64 MiB, the limit enforced while reading.
  const auto text = k::io::readFileBounded(path.toStdString(), k::io::kMaxNumericTableBytes, "a table");
  if (!text) {
    showError(QString::fromStdString(text.error().message));
    return nullptr;
  }
  const auto table = k::io::readNumericTable(*text);
  if (!table) {
    showError(tr("%1: %2").arg(QFileInfo(path).fileName(), QString::fromStdString(table.error().message)));
    return nullptr;
  }
  auto* dialog = new CompareDialog(m_document->design(), *table, path, this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &CompareDialog::plotOverlayChanged, this,
          [this, name = QFileInfo(path).completeBaseName()](const std::optional<k::compare::Comparison>& c) {
            if (c) m_plots->setComparison(*c, name);
            else m_plots->clearComparison();
          });
  dialog->show();
  return dialog;
}

void MainWindow::exportImageDialog() {
  // Which image first: the canvas, one plot, or all of them (each plot beside the canvas's
  // file). It wrote all four files without asking.
  const QList<QGraphicsView*> views = m_plots->graphicsViews();
  QStringList sources{tr("Canvas")};
  QList<int> plotOf{-1};
  for (int i = 0; i < views.size(); ++i) {
    if (views[i]->isHidden()) continue;  // a chart with nothing ticked is not shown, so not exported
    sources << tr("Plot: %1").arg(m_plots->chartTitle(i));
    plotOf << i;
  }
  sources << tr("Canvas and every plot shown");
  bool chosen = false;
  const QString source = QInputDialog::getItem(this, tr("Export image"), tr("Image of:"), sources, 0, false, &chosen);
  if (!chosen) return;
  const auto choice = sources.indexOf(source);
  QString selected;
  const QString path =
      QFileDialog::getSaveFileName(this, tr("Export image"), QString(),
                                   tr("PNG image (*.png);;SVG drawing (*.svg);;PDF drawing (*.pdf)"), &selected);
  if (path.isEmpty()) return;
  QString withSuffix = path;
  if (QFileInfo(path).suffix().isEmpty())
    withSuffix += selected.contains("svg") ? ".svg" : selected.contains("pdf") ? ".pdf" : ".png";
  const QFileInfo info(withSuffix);
  if (choice > 0 && choice < plotOf.size()) {
    if (exportPlotImage(plotOf[choice], withSuffix))
      statusBar()->showMessage(tr("Exported %1").arg(info.fileName()), 5000);
    return;
  }
  if (!exportCanvasImage(withSuffix)) return;
  if (choice == 0) {
    statusBar()->showMessage(tr("Exported %1").arg(info.fileName()), 5000);
    return;
  }
  int exported = 0;
  for (int i = 1; i < plotOf.size(); ++i) {
    const QString plotPath =
        info.path() + "/" + info.completeBaseName() + QString("-plot%1.").arg(plotOf[i] + 1) + info.suffix();
    if (!exportPlotImage(plotOf[i], plotPath)) return;
    ++exported;
  }
  statusBar()->showMessage(tr("Exported the canvas and %1 plots beside %2").arg(exported).arg(info.fileName()), 5000);
}

bool MainWindow::maybeSave() {
  if (!m_document->isModified()) return true;
  const auto answer = QMessageBox::question(this, tr("Unsaved changes"), tr("Save the changes to this linkage first?"),
                                            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
  if (answer == QMessageBox::Save) return save();
  return answer == QMessageBox::Discard;
}

void MainWindow::balanceShakingForce() {
  k::Design design = m_document->design();
  const auto balance = k::balanceShakingForce(design.mechanism, design.dynamics);
  if (!balance || balance->counterweights.empty()) return;  // the action is disabled then
  const k::LinkageDynamics before = design.dynamics;
  design.dynamics = balance->balanced;
  if (const auto why = m_document->edit(design, tr("Balance the shaking force"))) {
    showError(*why);
    return;
  }
  // The forces from before, dashed beside the new ones until the design changes again.
  m_forcePlots->setBefore(m_document->design(), before);
  // What the balance gained and cost over a turn, as the CLI's balance says it.
  const k::SweepSpec turn = k::designTurn(design);
  const auto was = k::machineDuty(design.mechanism, before, turn, {});
  const auto is = k::machineDuty(design.mechanism, design.dynamics, turn, {});
  if (!was || !is) return;
  const auto change = [](double a, double b, const QString& unit) {
    return tr("%1 → %2 %3").arg(numberText(a, 'g', 4), numberText(b, 'g', 4), unit);
  };
  statusBar()->showMessage(tr("Balanced (Ctrl+Z undoes): shaking force peak %1, shaking moment peak %2, driving "
                              "torque RMS %3, bearing load peak %4; the Forces tab shows before dashed")
                               .arg(change(was->shakingForcePeak, is->shakingForcePeak, tr("N")),
                                    change(was->shakingMomentPeak, is->shakingMomentPeak, tr("N·m")),
                                    change(was->rmsTorque, is->rmsTorque, tr("N·m")),
                                    change(was->bearingLoadPeak, is->bearingLoadPeak, tr("N"))),
                           20000);
}

void MainWindow::balanceBySpring() {
  k::Design design = m_document->design();
  QStringList links;
  for (const k::Link& link : design.mechanism.links) links << QString::fromStdString(link.name);
  bool chosen = false;
  const QString link = QInputDialog::getItem(this, tr("Balance the torque by a spring"),
                                             tr("The spring's moving end goes on link:"), links, 0, false, &chosen);
  if (!chosen) return;
  const auto found =
      k::searchSpringBalance(design.mechanism, design.dynamics, k::designTurn(design), link.toStdString());
  if (!found) {
    showError(QString::fromStdString(found.error().message));
    return;
  }
  const k::LinkageDynamics before = design.dynamics;
  design.mechanism = found->mechanism;
  design.dynamics = found->balance.balanced;
  if (const auto why = m_document->edit(design, tr("Balance the torque by a spring on %1").arg(link))) {
    showError(*why);
    return;
  }
  m_forcePlots->setBefore(m_document->design(), before);
  const k::SpringBalance& b = found->balance;
  statusBar()->showMessage(
      tr("Spring %1 N/m from %2 on %3 to %4 on the frame (Ctrl+Z undoes): driving torque RMS %5 → %6 N·m%7; the "
         "Forces tab shows before dashed")
          .arg(numberText(b.spring.stiffness, 'g', 4), QString::fromStdString(b.spring.first.point), link,
               QString::fromStdString(b.spring.second.point), numberText(b.rmsBefore, 'g', 4),
               numberText(b.rmsAfter, 'g', 4), found->atBound ? tr(" (an end is at the search's edge)") : QString()),
      20000);
}

void MainWindow::showError(const QString& message) { m_banner->showMessage(message, MessageBanner::Kind::Error); }

}  // namespace linkwright::ui
