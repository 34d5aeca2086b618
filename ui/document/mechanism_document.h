#pragma once
// The open document: owns the design (what is saved: any linkage), the undo stack, the motion
// state (the crank angle the canvas shows; on a time base, the instant, which sets the angle)
// and the solved results the views read, and the view settings the plots share (their x axis).
// Every view re-reads it when it emits changed(); views never solve anything themselves
// (docs/style.md, "Views only draw").
//
// Two grids: the analysis (crank range, gaps) uses the design's saved grid, as CSV export
// does; the displayed sweep spans the same crank angles (or times) with as many samples as the
// plots have pixels times the sampling quality, and computes only the quantities they show.
// In the designer (threading other than GuiThread) a drag's design grid is swept in a worker:
// the drag's design is accepted because it assembles at the crank angle shown, and the
// analysis's range and gaps follow when the grid lands (changed(Analysis)).

#include "ui/document/centres_at_pose.h"
#include "ui/document/display_sweeper.h"
#include "ui/document/edit_design_command.h"
#include "ui/document/quality_estimate.h"
#include "ui/document/quality_estimator.h"
#include "ui/document/sampling_quality.h"

#include "kinematics/analysis/advantage_sweep.h"
#include "kinematics/analysis/centrodes.h"
#include "kinematics/design/derived_design.h"
#include "kinematics/design/design.h"
#include "kinematics/model/recognise.h"
#include "kinematics/solve/pose.h"
#include "kinematics/solve/sweep.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <QTimer>
#include <QUndoStack>

#include <functional>
#include <optional>

namespace linkwright::ui {

/// What a changed() signal is about; views skip work that does not concern them.
enum class Change {
  Design = 0x1,     ///< the design and everything solved from it (sweep, analysis, pose)
  Motion = 0x2,     ///< only the crank angle and the pose at it
  Request = 0x4,    ///< the sweep was redone: other quantities or samples, or a worker's sweep landed
  File = 0x8,       ///< file name or modified flag
  Estimate = 0x10,  ///< the quality estimate was measured anew (qualityEstimate())
  PlotAxis = 0x20,  ///< what the plots' x axis shows (plotAxis())
  Analysis = 0x40,  ///< the crank range and gaps changed when a drag's grid landed from a worker
  Linkage = 0x80,   ///< another linkage took the design's place (replace(), or undo/redo of one): views fit it
};
Q_DECLARE_FLAGS(Changes, Change)
Q_DECLARE_OPERATORS_FOR_FLAGS(Changes)

/// What the plots' x axis shows: the time (s), which needs a time base, or the input (the
/// crank angle).
enum class PlotAxis { Time, Input };

class MechanismDocument : public QObject {
  Q_OBJECT
public:
  explicit MechanismDocument(QObject* parent = nullptr);

  /// The current design; valid and assemblable somewhere, always.
  const kinematics::Design& design() const { return m_design; }
  /// What the core derived from the design (kinematics/design/derived_design.h): the
  /// document holds it and nothing else about the design, so nothing outlives its design.
  const kinematics::DerivedDesign& derived() const { return m_derived; }
  /// The design's four-bar, if its mechanism is one (read from its structure on each change).
  const std::optional<kinematics::FourBarStructure>& fourBar() const { return m_derived.fourBar; }
  /// The design's length unit ("mm").
  const std::string& lengthUnit() const { return m_design.mechanism.lengthUnit; }
  /// The design's mechanism, what the solver solves.
  const kinematics::Mechanism& mechanism() const { return m_design.mechanism; }
  /// Mobility, ranges and limits; crank range and gaps on the design's grid.
  const kinematics::DesignAnalysis& analysis() const { return m_derived.analysis; }
  /// The displayed cycle: the design's crank angles at displaySpec()'s samples, computing what
  /// request() asks for. The plots and the canvas's paths read it. While sweepPending(), it is
  /// the design's as it was a moment ago (same samples and columns, other lengths).
  const kinematics::SweepResult& sweep() const { return m_sweeper.result(); }
  /// A drag's edit is being swept in a worker (display_sweeper.h): slow sweeps (a Newton
  /// linkage at Precise) never hold up the GUI thread. changed(Request) follows when it lands.
  bool sweepPending() const { return m_sweeper.pending(); }
  /// Derived from sweep() on first ask and kept while it stays: the velocity ratio and the
  /// mechanical advantage at every sample (from its instant centres; empty where the core
  /// finds none), and the coupler's fixed and moving centrodes. Only a view that shows them
  /// asks, so a hidden one costs nothing; views draw these and compute nothing of their own.
  const std::optional<kinematics::AdvantageSeries>& ratios() const;
  const kinematics::Centrodes& centrodes() const;
  /// The instant centres at pose() and the coupler's frame there, derived on first ask and
  /// kept while the pose stays (the body model kept while the mechanism stays).
  const CentresAtPose& centresAtPose() const;
  /// A drag's design grid (the analysis's crank range and gaps) is being swept in a worker;
  /// analysis() holds the last grid's range and gaps meanwhile, and changed(Analysis) follows
  /// if the new ones differ.
  bool analysisPending() const { return m_grid.sweeper.pending(); }
  /// Blocks until a pending sweep and grid have landed, and announces them (exports, tests,
  /// benchmarks).
  void waitForSweep() {
    m_sweeper.waitForResult();
    m_grid.sweeper.waitForResult();
  }
  /// Where a drag's sweeps run: GuiThread (the default: every edit's sweeps are there at once),
  /// or Adaptive (the designer's: the displayed sweep in a worker once a sweep takes longer
  /// than DisplaySweeper::kWorkerAfterMs, the design's grid always), or Worker (both always).
  void setSweepThreading(DisplaySweeper::Threading threading) {
    m_sweeper.setThreading(threading);
    m_grid.sweeper.setThreading(threading == DisplaySweeper::Threading::GuiThread ? threading
                                                                                  : DisplaySweeper::Threading::Worker);
  }
  /// The grid of sweep(): the design's range, ω and α with displaySampleCount(quality(),
  /// displayWidth(), span) samples.
  const kinematics::SweepSpec& displaySpec() const { return m_displaySpec; }
  /// Wall time of the last computation of sweep(), ms.
  double sweepMilliseconds() const { return m_sweeper.milliseconds(); }
  /// How many sweeps the document has run (display, grid and validation ones): tests read it
  /// to show that an edit does each piece of work once.
  long sweepsRun() const { return m_sweepsRun; }
  /// The pose at crankAngle() (on a time base, at time(), with the law's ω and α), with
  /// velocities and accelerations.
  const kinematics::Pose& pose() const { return m_pose; }
  /// Status of pose(): Ok, or Singular at a toggle position.
  kinematics::PoseStatus poseStatus() const { return m_poseStatus; }

  /// Checks a candidate design with the core's deriveDesign: nullopt if it can be accepted,
  /// else the core's sentence for why not.
  std::optional<QString> validate(const kinematics::Design& design) const;

  /// Replaces the design through the undo stack. Consecutive edits with the same `mergeKey`
  /// merge into one undo step (a drag). `crankAngleAfter` (rad) also moves the
  /// crank, undoably (dragging B of a four-bar does). Returns the refusal reason, if refused:
  /// then nothing changes.
  std::optional<QString> edit(const kinematics::Design& design, const QString& description,
                              std::optional<MergeKey> mergeKey = std::nullopt,
                              std::optional<double> crankAngleAfter = std::nullopt);
  /// edit() for another linkage put in the design's place (an atlas cell, a cognate, a
  /// synthesised design), not a change of this one: it announces Change::Linkage, and so do
  /// the undo and redo that bring either linkage back, so that the views fit what they show.
  std::optional<QString> replace(const kinematics::Design& design, const QString& description);

  /// Replaces the design and the crank angle, or on a time base the instant, without touching
  /// the undo stack (the undo command calls it). Emits one changed(Design | Motion), with
  /// Linkage when `another` (the command replaced the linkage).
  void applyDesign(const DesignState& state, bool another = false);

  /// Crank angle in rad. Clamped into the assemblable range; on a time base, the law's angle
  /// at time() (unwrapped: a law may turn the crank many times).
  double crankAngle() const { return m_crankAngle; }
  /// Moves the crank. On a time base it moves to the instant nearest time() at which the law
  /// has the crank at `angle` (any turn), or where it comes nearest if it never does.
  void setCrankAngle(double angle);

  /// Whether the design's crank follows a motion law in time (Design::time).
  bool onTimeBase() const { return m_design.time.has_value(); }
  /// The instant shown, s, within the time base's [fromTime, toTime]; 0 without a time base.
  double time() const { return m_time; }
  /// Moves to instant `t` (s), clamped into the time base; ignored without one.
  void setTime(double t);

  /// The plots' x axis: the one chosen, except that without a time base it is the input.
  PlotAxis plotAxis() const { return onTimeBase() ? m_plotAxis : PlotAxis::Input; }
  /// The choice itself (Time by default: a design with a time base is plotted in time).
  PlotAxis chosenPlotAxis() const { return m_plotAxis; }
  void setPlotAxis(PlotAxis axis);

  /// Which quantities the sweep computes (plots ask only for what they show). Its Newton
  /// settings follow quality(); setRequest ignores the ones it is given.
  kinematics::SolveRequest request() const { return m_request; }
  void setRequest(const kinematics::SolveRequest& request);
  /// What the plots will ask for once they see a new mechanism (its curves and the selection
  /// they will have), so that a design change sweeps once, for that, instead of sweeping for
  /// the old request and again when the plots ask. Called by rebuild() with the new
  /// mechanism and its prepared (not yet solved) pose; ignored once `owner` is destroyed.
  using RequestSource = std::function<kinematics::SolveRequest(const kinematics::Mechanism&, const kinematics::Pose&)>;
  void setRequestSource(QObject* owner, RequestSource source);

  /// Samples per pixel and Newton tolerance of the displayed sweep (Normal by default).
  SamplingQuality quality() const { return m_quality; }
  void setQuality(SamplingQuality quality);
  /// Whether something on screen shows forces: then the sweep computes accelerations of every
  /// point and link whatever request() says (ForceResults solves the forces from it).
  void setForcesNeeded(bool needed);
  bool forcesNeeded() const { return m_forcesNeeded; }
  /// Width in pixels the displayed sweep is drawn across (the plots' plot area);
  /// kDefaultDisplayWidth until a plot reports one. Resweeps only if the sample count changes.
  double displayWidth() const { return m_displayWidth; }
  void setDisplayWidth(double pixels);

  /// The peak error the displayed sampling buys on this design. Measured after the design, the
  /// sample count or the quality changes, once they have stayed put for kEstimateSettleMs (a
  /// drag measures once, at its end), in a worker thread (quality_estimator.h), then announced
  /// with changed(Estimate); never during crank motion. Until then it holds the previous
  /// measurement and qualityEstimatePending().
  const QualityEstimate& qualityEstimate() const { return m_estimate; }
  bool qualityEstimatePending() const { return m_estimateTimer.isActive() || m_estimator.busy(); }
  /// Measures a pending estimate now, in this thread (and announces it): for exports and tests.
  void measureQualityNow();
  static constexpr int kEstimateSettleMs = 200;

  QUndoStack* undoStack() { return &m_undo; }

  /// Starts afresh on `design` (File ▸ New, Examples, Open), clearing undo history. The
  /// design must be valid (a template, an example or a file the reader accepted).
  void reset(const kinematics::Design& design, const QString& filePath = {});
  QString filePath() const { return m_filePath; }
  void setFilePath(const QString& path);
  bool isModified() const { return !m_undo.isClean(); }
  void markSaved();

signals:
  void changed(linkwright::ui::Changes what);

private:
  // edit() and replace(): `another` marks the command as a change of linkage.
  std::optional<QString> push(const kinematics::Design& design, const QString& description,
                              std::optional<MergeKey> mergeKey, std::optional<double> crankAngleAfter, bool another);
  // rebuild: mechanism, sweep, analysis, pose from m_design; resweep: the sweep only (request
  // or sampling changed). SweepNow::No lets an edit's sweep go to a worker (display_sweeper.h).
  enum class SweepNow : bool { No, Yes };
  void rebuild(SweepNow now);
  void resweep(SweepNow now = SweepNow::Yes);
  void solvePoseNow();  // pose at m_crankAngle, or at m_time on a time base
  void clampMotion();   // m_time into the time base and the crank angle with it, or the angle into the range
  kinematics::SweepSpec wantedDisplaySpec() const;
  // Degrees of crank angle the displayed sweep spans: the grid's, or the law's travel; 0 for
  // a linear input.
  double displaySpanDeg() const;
  void scheduleEstimate();
  void measureQuality();  // the timer's: it is no longer active when it fires
  // The estimate when there is nothing to measure (a time base, a linear input), else none.
  std::optional<QualityEstimate> unmeasuredEstimate() const;
  QualityEstimator::Input estimateInput() const;
  void adoptEstimate(const QualityEstimate& estimate);
  // Sweeps `design`'s own grid, positions only (what validation and the analysis read), into
  // m_grid, now: a drag sweeps it on every move, into the same memory.
  const kinematics::SweepResult& sweepGrid(const kinematics::Design& design) const;
  kinematics::SolveRequest gridRequest() const;
  // What validate() derived for `design`, if it is the last one accepted; taken once.
  std::optional<kinematics::DerivedDesign> takeAccepted(const kinematics::Design& design);
  // Whether `design`'s grid would be swept in a worker: a drag's (the samples and structure
  // of the grid shown), where the threading is not GuiThread; never on a time base.
  bool gridDeferred(const kinematics::Design& design) const;
  // Whether `design` assembles at the crank angle shown: such a drag's design is valid (it
  // assembles somewhere), checked without sweeping its grid.
  bool assemblesAtInstant(const kinematics::Design& design) const;
  // A worker's grid landed: the design is derived anew from it, and the crank is clamped
  // into its range; announced only if the range or gaps changed.
  void adoptGridAnalysis();

  // The grid last swept; the derived state validate() accepted and the design and Newton
  // settings it was accepted for, until that design is applied, so that applying it derives
  // nothing again.
  struct DesignGrid {
    DisplaySweeper sweeper;  // its result() is the grid
    struct Accepted {
      kinematics::Design design;
      kinematics::NewtonSettings newton;
      kinematics::DerivedDesign derived;
    };
    std::optional<Accepted> accepted;
  };

  kinematics::Design m_design;
  kinematics::DerivedDesign m_derived;
  DisplaySweeper m_sweeper;
  // What ratios() and centrodes() derived, and from which sweep (DisplaySweeper::serial).
  mutable std::optional<kinematics::AdvantageSeries> m_ratios;
  mutable std::uint64_t m_ratiosSerial = 0;
  mutable kinematics::Centrodes m_centrodes;
  mutable std::uint64_t m_centrodesSerial = 0;
  std::uint64_t m_poseSerial = 0;  // grows with each pose solved
  mutable CentresAtPose m_centresAtPose;
  mutable std::uint64_t m_centresSerial = 0;
  mutable std::optional<kinematics::Mechanism> m_centreModelFor;
  mutable std::optional<kinematics::Result<kinematics::CentreModel>> m_centreModel;
  kinematics::SweepSpec m_displaySpec;
  mutable long m_sweepsRun = 0;
  mutable DesignGrid m_grid;
  QPointer<QObject> m_requestOwner;
  RequestSource m_requestSource;
  SamplingQuality m_quality = SamplingQuality::Normal;
  double m_displayWidth = kDefaultDisplayWidth;
  QualityEstimate m_estimate;
  QTimer m_estimateTimer;
  QualityEstimator m_estimator;
  kinematics::Pose m_pose;
  mutable kinematics::Pose m_candidatePose;  // assemblesAtInstant's, reused
  kinematics::PoseStatus m_poseStatus = kinematics::PoseStatus::Ok;
  kinematics::SolveRequest m_request{true, true};
  bool m_forcesNeeded = false;
  double m_crankAngle = 0.0;
  double m_time = 0.0;
  PlotAxis m_plotAxis = PlotAxis::Time;
  QUndoStack m_undo;
  QString m_filePath;
};

}  // namespace linkwright::ui
