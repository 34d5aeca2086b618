#include "app/cli/cli.h"

#include "app/cli/arguments.h"
#include "app/cli/commands.h"
#include "app/cli/exit_codes.h"

#include "kinematics/model/request_field.h"

#include <new>
#include <ostream>

namespace linkwright::cli {
namespace {

constexpr const char* kUsage = R"(Usage: linkwright-cli COMMAND [OPTIONS]

Planar linkage analysis (Linkwright's kinematics core, no GUI needed).

Commands:
  analyze    position, velocity and acceleration table of a linkage as CSV
  extremes   minimum and maximum of every column, refined between the samples
  classify   Grashof class, mobility, transmission angle, limit positions, time ratio
             (four-bars), quick return (shapers), mobility and assembly (any linkage)
  arm        a two-link arm's joint angles, rates and accelerations as its tip follows
             a straight line (CSV)
  centres    instant centres (Kennedy's circle diagram), velocity ratio and mechanical
             advantage at crank angles (four-bars, slider-cranks, shapers, six-bars)
  polygon    velocity and acceleration polygons at crank angles: each point's vector
             equation and its arrows, tip to tail, against the solver's exact values
  inversions a four-bar's (or slider-crank's) four inversions: the link grounded, the
             link driven, the textbook class
  accuracy   how far peaks read off N samples per turn are from the exact ones, and
             what each choice costs (CSV; optional SVG plot)
  dxf        the links as a DXF drawing at true size: plate outlines, pivot holes,
             one layer per link, the ground pivots (LibreCAD, QCAD, FreeCAD)
  report     a lab-report PDF: drawing, Grashof/mobility analysis, a table every
             30°, refined extremes, plots, forces (with masses)
  compare    another tool's table (SolidWorks Motion, MATLAB, Excel, NX) against the
             exact solution at its own crank angles or times: worst and rms deviation
             per column, the rows beyond a tolerance flagged
  machine    what a crank turn asks of the machine (needs masses): driving torque
             (mean, RMS, peak), power, energy fluctuation and flywheel, peak shaking
             force and moment, the motor's duty through a gearbox
  balance    counterweights that balance the shaking force (four-bars completely,
             slider-cranks in part), written as a new document, with the shaking,
             torque and bearing loads before and after
  cognates   a four-bar's two Roberts–Chebyshev cognates: the linkages whose coupler
             point traces the same curve, written as two documents, with their
             Grashof class, worst transmission angle and crank speeds
  tolerance  ± a tolerance on every length and pivot: a Monte-Carlo band of the output
             curves with the worst deviation per column, the first-order worst case
             and the exact sensitivities ∂y/∂p beside it
  optimise   a better linkage by one measure (peak |α| of a link, worst transmission
             angle, distance from a target path, RMS driving torque), its lengths in
             ranges, its pivots, Grashof class and branch kept; written as a document
  atlas      a grid of four-bars over link ratios and coupler points (Hrones–Nelson):
             each coupler curve classified (cusps, crunodes, symmetric, straight and
             circular runs, with where), filtered; one cell written as a document
  synthesize a linkage from the motion wanted: rocker swing and time ratio, slider or
             shaper stroke, function generator, coupler poses, coupler path; lists
             the candidates with their defects and writes the chosen one as a document
  examples   list the built-in examples
  --help [COMMAND], --version

)";

constexpr const char* kMechanismOptions = R"(Mechanism (one of):
  FILE.json           a Linkwright document (saved by the GUI; any linkage; see
                      docs/document_format.md); its speed and grid are the defaults
  --fourbar FRAME,CRANK,COUPLER,ROCKER
                      link lengths, positive, in the length unit (default mm).
                      Crank pivot O2 at the origin, rocker pivot O4 at (FRAME, 0).
  --example NAME      a built-in example (see 'linkwright-cli examples'): four-bars,
                      slider-crank, shaper, Whitworth, six-bars
  --unit NAME         length unit label used in the output (default mm; letters only).
                      Lengths are taken and reported in this unit.
  --branch open|crossed
                      assembly branch: open has sin(rocker angle − coupler angle) > 0
                      (default open, or the example's)
)";

constexpr const char* kAnalyzeOptions = R"(Speed and range (analyze, extremes):
  --rpm R | --omega W crank speed in rev/min or rad/s, CCW positive
                      (default: the example's; 1 rad/s for --fourbar)
  --alpha A           crank angular acceleration, rad/s² (default 0). ω and α are the
                      crank's instantaneous state at every listed angle.
  --from DEG          first crank angle, degrees CCW from the frame line (default 0)
  --to DEG            last crank angle, degrees (default 360)
  --step DEG | --samples N
                      angle step in degrees (default: the example's; 1 for --fourbar),
                      or N evenly spaced angles from --from to --to inclusive
  --coupler-point U,V add point P fixed on the coupler: U along B→C, V 90° CCW from it
  A linkage driven by a point on a path or a linear actuator (seed-arm, piston-driven,
  excavator-boom) takes --from, --to, --step, --rise and --omega/--alpha in its length
  unit (and per s, per s²): its input is the point's path position or the actuator's
  length; its first CSV column says which (tip_s_m, actuator_length_m).
Motion in time (analyze, extremes): instead of the angle grid, the crank follows a motion law;
  analyze's table gains a first column time_s, extremes are refined in time; ω and α are
  the law's at each instant. An example or document with a motion law follows it.
  --law constant      from --from degrees at --rpm / --omega
  --law ramp --ramp-time S
                      from rest at --from, constant acceleration to --rpm / --omega in S
                      seconds, then constant speed
  --law cycloidal|345 --rise DEG --duration S
                      a cycloidal or 3-4-5 polynomial rise of DEG from --from in S seconds
  --law-table FILE    a measured θ(t): a CSV whose first line names time_s and the angle
                      in _deg or _rad (time_s,crank_angle_deg), then at least four rows;
                      a C² cubic spline through them (a cubic is reproduced exactly)
  --from-time S, --to-time S
                      the times analysed (default: from 0, or the table's first time, to
                      the rise's end, the ramp and one turn, one turn, or the table's end)
  --step-time S | --samples N
                      time step, or N evenly spaced instants (default 361)
  --format csv|table  CSV (default) or an aligned table of the link columns, 4 decimals
  --forces            (analyze) add inverse dynamics from the masses and loads of the
                      document's "dynamics" or the example's (funsho-fourbar has them):
                      joint forces, the driver's torque or force, shaking force. The
                      length unit must be m, cm, mm, in or ft; the driver's rates are the
                      sweep's at every sample (a crank's ω and α, or its motion law's)
  -o, --output FILE   write the output to FILE (atomically) instead of standard output

Output: RFC 4180 CSV, '.' decimal point, round-trip precision. Columns carry units:
  crank_angle_deg, <link>_angle_deg, <link>_omega_rad_s, <link>_alpha_rad_s2 for links
  crank, coupler (B→C), rocker (O4→C); transmission_angle_deg; <point>_x_<unit>,
  _y_, _vx_<unit>_s, _vy_, _ax_<unit>_s2, _ay_ for points B, C (and P). Link angles are
  continuous over the sweep. At a toggle position the ω and α cells are empty.
With --forces, then (world frame, N and N·m, CCW positive): F_<joint>_x_N, _y_N and
  F_<joint>_N for each pin: the force on a link from the ground at a ground pivot, else
  from the link defined first (on the coupler from the crank at B, on the rocker from the
  coupler at C); N_<slider>_N and M_<slider>_Nm for each slider block: the normal force
  (along the guide direction turned 90° CCW) and couple on it from its guide; the driver's:
  T_drive_Nm, the motor torque on the crank; actuator_force_N, a linear actuator's axial
  force (positive pushing its ends apart); <point>_drive_fx_N, _fy_N and
  <point>_drive_force_N, the force on a point driven along a path (the guide's reaction
  included) and its part along the path (positive toward increasing s); for a path point
  at the tip of a two-link arm, <shoulder>_joint_torque_Nm and <elbow>_joint_torque_Nm, the
  motor torques that move the arm the same way with its tip free; shaking_x_N, shaking_y_N,
  shaking_N and shaking_moment_Nm, the linkage's force on its frame and that force's
  moment about the crank pivot (other drivers: the first ground point), with the motor's
  reaction. Cells are empty where the forces are undefined.
)";

constexpr const char* kClassifyOptions = R"(Classify options:
  --json              machine-readable output
)";

constexpr const char* kBalanceOptions =
    R"(balance options (FILE.json or --example NAME with masses; a four-bar or a slider-crank):
  -o, --output FILE     where to write the balanced design (required)
  --fraction K          slider-crank: the share of the reciprocating mass the crank's
                        counterweight balances, 0 to 1 (default 0.5)
  --radius R            each counterweight's distance from its pivot, in lengths of its
                        link, 0.1 to 10 (default 1)
  --spring A,B          instead, the linear spring from A to B that makes the RMS driving
                        torque least (any crank-driven linkage): each end LINK:POINT, a
                        point on that link's body, or a ground point alone (the frame)
  --spring-search LINK  instead, the spring from a point on LINK to a point on the frame,
                        both searched, that makes the RMS driving torque least; the two
                        points are added to the design as spring_link and spring_frame
  --json                one JSON object instead of the text: method, output, length_unit;
                        counterweights [{link, mass_kg, along, across}] with the turn's
                        before and after figures, or spring {first, second, stiffness_N_m,
                        free_length, preload_N} with rms_torque_before_Nm and _after_Nm
)";

constexpr const char* kAtlasOptions =
    R"(atlas options (a grid of four-bars, crank 1; see docs/atlas.md):
  --coupler R,...       coupler lengths in crank lengths (default 1.5,2,2.5,3)
  --rocker R,...        rocker lengths in crank lengths (default 1.5,2,2.5,3)
  --frame R,...         frame lengths in crank lengths (default 2,2.5,3); each ratio
                        from 0.001 to 1000, at most 64 values an axis
  --along U,...         P along B→C, in coupler lengths (default 0,0.5,1,1.5,2)
  --across V,...        P 90° CCW from B→C, in coupler lengths (default 0,0.5,1); each
                        within ±100. The grid (the five axes' product) is at most
                        100000 cells, about 4 minutes on one core at 360 samples
  --branch open|crossed the assembly branch each cell starts on (default open)
  --samples N           solver samples a curve, 36 to 100000 (default 360)
  --filter F,...        keep the cells whose curve has every feature named: cusp,
                        crunode, symmetric, straight, circular
  --json                one JSON object: cells, samples, tolerances (what each feature
                        is found to), atlas and matching; atlas [{cell,
                        coupler, rocker, frame, along, across, branch, class, crank,
                        crank_range_deg, size, cusps [{crank_deg, point, speed}],
                        crunodes [{point, crank_deg}], symmetry {point, axis_deg,
                        deviation}, straight {from_deg, to_deg, from, to, length,
                        deviation}, circular {from_deg, to_deg, centre, radius, turn_deg,
                        deviation}}] (null where a curve has none)
  -o, --output FILE.csv the kept cells as CSV (one row a cell; empty cells where a curve
                        has no such feature)
  --cell I              instead, write cell I (the table's first column) as a design
                        document to -o FILE.linkwright: a four-bar with its point P,
                        its grid a full turn or a rocking crank's range
  --crank L             with --cell: the design's crank length (default 1)
  --unit NAME           with --cell: its length unit (default mm)
Cells are numbered coupler slowest, then rocker, frame, along, across fastest, and each is
  written as it is classified (progress on a terminal). Points and
  sizes are in crank lengths, O2 at the origin and O4 on +x; angles are the crank's, in
  degrees. A crank that cannot turn fully rocks between its limits, and its curve is both
  branches' paths across the range (the classification's rules: docs/atlas.md).
)";

constexpr const char* kCognatesOptions =
    R"(cognates options (FILE.json, --example NAME or --fourbar FRAME,CRANK,COUPLER,ROCKER [--unit
NAME]: a four-bar with a point on its coupler; see docs/cognates.md):
  -o, --output PREFIX   write the cognates to PREFIX-1.linkwright and PREFIX-2.linkwright
                        (required), each a four-bar with its coupler point named P
  --coupler-point NAME  the point on the coupler whose curve they trace (default: the first)
  --coupler-point U,V   put P there first, U along B→C and V 90° CCW from it (as analyze)
  --json                one JSON object instead of the table (z, third_pivot, linkages
                        [{name, file, crank_pivot, rocker_pivot, lengths, class,
                        worst_transmission_deg, crank_turns_with, coupler_turns_with,
                        rocker_turns_with, crank_speed_ratio_min, crank_speed_ratio_max}])
Output: for the original and each cognate its ground pivots, lengths, Grashof class, worst
  transmission angle min(μ, 180° − μ) over the motion it makes in the original's cycle (its
  grid), and the speed its crank must turn at for the three to move together: cognate 2's
  crank turns with the original's crank (ω2, 1:1); cognate 1's with the original's coupler
  (ω3, which varies: its range over the cycle as a multiple of ω2). Cognate 2's document has
  the original's grid and speed; cognate 1's the range its crank sweeps in the cycle.
)";

constexpr const char* kCentresOptions =
    R"(Centres options (with the mechanism options; any linkage):
  --at DEG[,DEG...]   crank angle(s), degrees CCW from the frame line; repeatable
Output: every instant centre Iij of the linkage's bodies, numbered 1 frame, then in the
  order they are defined, each followed by the slider blocks pinned to it (a four-bar:
  2 crank, 3 coupler, 4 rocker; a shaper: 2 crank, 3 block, 4 rocker, 5 link, 6 ram), as (x, y) in the length unit or "at infinity" with a direction, each
  with the pin, slide or Kennedy lines that locate it ("not located" where Kennedy's
  theorem does not reach); for a crank and an output b jointed to the frame, the velocity
  ratio ωb/ω2 (sliding output: v/ω2, length unit per rad) and the ideal mechanical
  advantage Tb/T2 = ω2/ωb (sliding: F/T2 = ω2/v, per length unit), signed, infinite at a
  toggle.
)";

constexpr const char* kReportOptions =
    R"(Report options (with the mechanism options; on the input grid, or on the time base):
  -o, --output FILE.pdf
                      where to write the report (required; written whole or not at all)
  --at DEG            the input drawn on page 1, degrees for a crank, else the length
                      unit (default: the grid's start); on a time base a time in s
  --step DEG          the table's step, more than 0 and at most 360 for a crank (at most
                      the input's range for a linear driver); default 30, as the thesis;
                      on a time base seconds, at most the time span (default a twelfth)
  --paper a4|letter   paper size (default a4)
  --rates rad|deg     ω and α in rad/s and rad/s² (default, as the thesis and analyze) or
                      in deg/s and deg/s² (as SolidWorks Motion)
  --angles deg|rad    link and transmission angles in degrees (default) or radians; the
                      input (the table's first column) stays in degrees
Output: a PDF (vector drawing, selectable text, "page i of N"): page 1 the title, the
  linkage at --at with its link lengths and ground pivots, the Grashof class and mobility
  (as classify); then the table of link angles (--angles), ω and α (--rates), the same
  numbers as analyze's CSV at 4 decimals (ω, α times 180/π with --rates deg, angles
  times π/180 with --angles rad); the extremes refined between the grid's samples
  (as extremes); the joint forces and driving torque when the linkage has masses (as
  analyze --forces); the plots of θ, ω, α (and slider x, v, a) against the input.
)";

constexpr const char* kDxfOptions =
    R"(Dxf options (with the mechanism options; any linkage; lengths in its length unit):
  -o, --output FILE.dxf
                      where to write the drawing (required; written whole or not at all)
  --at DEG            the input the links are drawn at: crank angle in degrees CCW from
                      +x, or a linear driver's position in the length unit (default:
                      where the design starts: its grid's first input or its motion law's
                      start; 0 for --fourbar)
  --hole D            pivot hole diameter, > 0 and less than the shortest distance
                      between two joints on one link (default a fifth of that
                      distance, to two significant digits)
  --width W           plate width, more than the hole diameter (default 2 × hole)
  --coupler-point U,V a four-bar's coupler point (as for analyze): drilled too
Output: a DXF R2000 file. Layer GROUND: each ground pivot as a hole with a centre
  cross. One layer per moving link, named after it (a plate made of several links
  takes its first link's name): the convex outline of circles of diameter W around
  every joint on it (a stadium for two joints), a hole of diameter D at each joint,
  and, on a slotted link, a slot D wide along it through the block's pin at this pose.
  One layer per slider block: a W × 2W rectangle along its guide with the pin's hole.
  $INSUNITS gives the unit (in 1, ft 2, mm 4, cm 5, m 6; other names 0, unitless).
  Coordinates: x right, y up, as the analyze table at the same input.
)";

constexpr const char* kPolygonOptions =
    R"(Polygon options (with the mechanism options; crank-driven linkages, see docs/classroom.md):
  --at DEG[,DEG...]   crank angle(s), degrees CCW from the frame line, within ±1e6;
                      repeatable
  --rpm R | --omega W crank speed in rev/min or rad/s, CCW positive, |ω| ≤ 1e6 rad/s
                      (default: the example's; 1 rad/s for --fourbar)
  --alpha A           crank angular acceleration, rad/s², |α| ≤ 1e12 (default: the
                      example's, else 0)
  --json              machine-readable output
Output, for the velocity polygon (length unit/s) and the acceleration polygon (length
  unit/s²), pole o at (0, 0): each point's equation in solve order (V_C = V_B + V_CB, with
  A^n normal, A^t tangential, A^c Coriolis, V_CC' the slide of C along a guide past C' the
  guide's point under it), where each side of it ends and the solver's value it must end
  on; then every arrow in drawing order: step, label, x, y, magnitude, angle (degrees CCW
  from +x) and what it is. Exit code 3 at a crank angle that cannot be assembled or is a
  toggle (rates, hence polygons, do not exist there).
Inversions options (with the mechanism options; four-bars and slider-cranks):
  --json              machine-readable output
Output: for each link held fixed in turn, the link driven (adjacent to it), the lengths
  as a four-bar (frame, crank, coupler, rocker), the class from Grashof's table
  (crank-rocker, double-crank, double-rocker, change point, triple-rocker) and whether
  the driven link turns fully; for a slider-crank: slider-crank, Whitworth or
  crank-shaper, oscillating or rotating cylinder, fixed piston (an offset guide's
  slotted inversions are named, not built).
)";

constexpr const char* kArmOptions =
    R"(Arm options (lengths in the length unit, default m; the shoulder is at the origin):
  --example seed-arm  seed 004's arm and path: --arm 0.3,0.2 --from-point 0.3,0
                      --to-point 0,0.3 --speed 2 --elbow down, 101 samples; options
                      given with it replace the example's values
  --arm UPPER,FOREARM shoulder-to-elbow and elbow-to-tip lengths, positive
  --from-point X,Y    where the tip starts
  --to-point X,Y      where it stops: a straight line at constant speed
  --speed V           tip speed, length unit per second, positive
  --samples N | --step-time S
                      N times evenly spaced from start to end inclusive (default 101,
                      at least 2), or every S seconds from 0 (the end is included when
                      the step lands on it)
  --elbow up|down     up (default): the elbow on the counter-clockwise side of the line
                      shoulder→tip (above it while the tip is to the right), so the
                      forearm angle minus the upper angle is in (−180°, 0°); down: the
                      mirror image. Run once with each to get both solutions.
  --unit NAME         length unit label (default m; letters only)
  --format csv|table  CSV (default) or an aligned table, 4 decimals
  -o, --output FILE   write the output to FILE (atomically) instead of standard output
Output: time_s, tip_x_<unit>, tip_y_<unit>, upper_angle_deg, forearm_angle_deg (absolute,
  CCW from +x, continuous along the path), upper_omega_rad_s, forearm_omega_rad_s,
  upper_alpha_rad_s2, forearm_alpha_rad_s2, elbow_x_<unit>, elbow_y_<unit>. Where the tip
  is out of reach the joint cells are empty (exit code 3, with the exact time ranges);
  where the arm is stretched out or folded the ω and α cells are empty (a note says so).
)";

constexpr const char* kAccuracyOptions = R"(Accuracy options (the speed-accuracy trade, measured; see docs/accuracy.md):
  --example NAME      measure one example (default: miranda-fourbar, ls3-engine, shaper,
                      watt-ii); the crank must turn fully
  --svg FILE          also draw worst peak error against samples per revolution
  -o, --output FILE   write the CSV to FILE (atomically)
  Rows: method samples (peaks read off N samples, exact ω, α), frames (ω, α by central
  differences between samples, as a frame-based motion study), refined (our extremes,
  refined between N samples), against peaks refined from 7200 samples (reference
  "refined"); then closed-form and newton-TOL (every RRR joint solved by Newton at
  tolerance TOL) at 360 samples, the Newton rows against the closed form at the same
  samples. time_us is the median of 5 runs on this machine. Rates' errors are relative,
  angles' in degrees.
)";

constexpr const char* kSynthesizeOptions =
    R"(Synthesize (linkwright-cli synthesize PROBLEM [OPTIONS]; see docs/synthesis.md). Angles in
degrees CCW from +x (for four-bars the frame line O2->O4 is +x); lengths in the length unit.
  swing --swing DEG --time-ratio Q (--rocker L | --frame L) [--count N]
                      crank-rockers whose rocker swings DEG (0 < DEG < 180) with time ratio
                      Q (slow stroke / quick stroke, 1 to 100), the rocker or frame length
                      fixed: N of the family (1 to 1000, default 11) and the best (largest
                      worst transmission angle within --max-ratio)
  slider --stroke S --time-ratio Q (--rod L | --offset E)
                      the offset slider-crank with stroke S and time ratio Q, the rod
                      length or the guide's offset E (any sign; 0 when Q = 1) fixed
  shaper --stroke S --time-ratio Q --crank L --link L [--guide-height H]
                      the crank-shaper with ram stroke S and time ratio Q (> 1), crank L,
                      link L from the lever to the ram; the ram's guide at height H
                      (default: mid-height of the lever tip's arc)
  function --function NAME --x0 A --x1 B --input-start DEG --input-span DEG
           --output-start DEG --output-span DEG [--frame L] [--points N | --at X,X,X...]
                      a four-bar whose rocker angle follows y = NAME(x) (log10, ln, exp,
                      sqrt, square, cube, reciprocal, sin, cos, tan; x in radians for the
                      last three) as its crank follows x over [A, B]: crank from the start
                      through the span, rocker likewise (spans nonzero, under 360).
                      Freudenstein's equation at N Chebyshev points (default 3, exact;
                      more: least squares) or at the given points (at least 3, increasing,
                      in [A, B]); frame length L (default 100). The error is the worst
                      output angle error over [A, B], degrees
  motion --pose X,Y,DEG (2 or 3 times) --circle-point X,Y --circle-point X,Y
         [--centre D --centre D] [--full-turn]
                      a four-bar whose coupler point is at X,Y with the coupler at DEG in
                      each pose. The circle points are the crank's, then the rocker's,
                      moving pivot where they are at pose 1; with three poses their
                      centre points (the ground pivots) follow (Burmester); with two, each
                      --centre D places one on its perpendicular bisector, D from the
                      chord's midpoint, positive to the left of pose 1 -> pose 2.
                      --full-turn: a motor turns the crank round (a crank that cannot is
                      a defect)
  path --target X,Y (4 to 10 times) [--timing DEG,DEG,... [--timing-from start|frame]]
       [--starts N] [--seed S] [--full-turn]
                      four-bars whose coupler point passes through the targets in order,
                      by Levenberg-Marquardt from N random starts (1 to 2000, default
                      400; seed S, default 19: a run repeats exactly); the best ten
                      distinct ones, best first. --timing: the crank angle at each target,
                      from a free start angle (default) or from the frame line. The error
                      is the worst distance to a target, in the length unit
  Common options:
  --unit NAME         length unit label (default mm; letters only)
  --min-transmission DEG
                      a worst transmission angle below DEG is a defect (0 to 90, default 40)
  --max-link L        a link longer than L is a defect (default: no bound)
  --max-ratio R       longest / shortest link above R is a defect (1 to 1e6, default 10)
  --json              the candidates as JSON instead of text
  --choose K          the candidate to write: its number in the list (default: the best)
  -o, --output FILE   write the chosen candidate as a Linkwright document (atomically);
                      'linkwright-cli analyze FILE' analyses it
Output: each candidate's link lengths, error (function: degrees), Grashof class, worst
  transmission angle over the motion it must make, and defects, each with its reason
  (not-grashof, branch, order, transmission, link-length); a candidate with a defect is
  listed and marked, never dropped. Then the chosen one's dimensions and figures.
)";

constexpr const char* kCompareOptions =
    R"(Compare (linkwright-cli compare FILE.json|--example NAME|--fourbar ... TABLE.csv --map MAP;
see docs/compare.md; with the mechanism options):
  TABLE.csv           the other tool's table: delimiter ',', ';' or tab (with ';' or tab
                      a decimal comma is read as a point); the lines before the first row
                      of numbers are its header; lines starting with # are skipped
  --map COLUMN=WHAT[:UNIT][:FLAG...],...
                      what each column holds; COLUMN counts from 1. One column is the x:
                        crank-angle[:deg|rad]  or  time[:s|ms|min]
                      the others are analyze's column names without their unit:
                        <link>_angle (deg|rad), <link>_omega (rad/s|deg/s|rpm),
                        <link>_alpha (rad/s2|deg/s2), transmission_angle, crank_angle,
                        <point>_x, _y (the length unit, or m|cm|mm|in|ft),
                        <point>_vx, _vy (unit/s), <point>_ax, _ay (unit/s2)
                      (a full name such as rocker_omega_rad_s brings its unit). Flags:
                        abs  the tool writes magnitudes (SolidWorks' |ω|, |α|)
                        neg  the tool's sign is the opposite of ours (CW positive)
                        rev  an angle measured from the link's other end (ours + 180°,
                             SolidWorks' "inner" rocker angle)
                      e.g. --map 2=time:s,3=coupler_angle:deg,4=rocker_angle:deg:rev
  --map auto          the mapping clear headers propose: theta2 (the crank angle),
                      theta3/4, omega3/4, alpha3/4 (coupler, rocker; ASCII or Greek), time,
                      analyze's names, each in the unit its header names, as (deg);
                      the report's map: line shows what was taken
  --offset auto|none|DEG
                      a constant crank-angle offset: rows are solved at their crank
                      angle + offset. auto (default): fitted within ±5° to the rows that
                      agree (cells beyond 3 tolerances left out, and listed), to the
                      position columns if any are mapped, else to all; zero unless it
                      halves the misfit; DEG: given, within ±5
  --tolerance PCT[,ABS]
                      a row is flagged when |deviation| > ABS + PCT % of the column's
                      span (max − min of its exact values); default 0.25 %, and ABS
                      each column's rounding (half a unit in its last printed digit)
  --rpm R | --omega W, --alpha A
                      the crank's speed at every row (default: the linkage's own)
  --from DEG          the crank angle at t = 0 of a time table (default: the linkage's
                      first grid angle)
  --json              the comparison as JSON, every row included
Output: the table, x, offset and tolerance used; per mapped column its worst deviation
  (value − exact, signed; angles across the nearest turn) and where, the rms, the
  tolerance and how many rows are flagged; then each flagged row: line, x, the crank
  angle solved at, value, exact value, deviation. Deviations are in the column's unit.
  Flagged rows are the comparison's answer, not an error: the exit code is 0 whenever it
  ran, 2 for a bad table, mapping or option.
)";

constexpr const char* kToleranceOptions =
    R"(tolerance options (FILE.json, --example NAME or --fourbar ...; its speed and grid are the
defaults, and --rpm, --omega, --alpha, --from, --to, --step and --samples change them; see
docs/tolerances.md):
  --tolerance T         ± T on every length and pivot coordinate, in the length unit
                        (required; 0 ≤ T < the shortest length)
  --tolerance-of "NAME=T,…"  a ± of their own for the dimensions named (as the output lists
                        them: "coupler length=0.02,O2 x=0.1"); the others take --tolerance
  --mc-samples N        Monte-Carlo samples, 1 to 100000 (default 1000), each a linkage
                        with every dimension uniform within ±T, swept over the grid
  --seed S              the samples' seed, a whole number (default 46): the same seed
                        gives the same study on every machine
  --at X                list every sensitivity at this one input (degrees, or the length
                        unit, or seconds on a time base) instead of the largest over the grid
  --json                the study as JSON: per column the worst deviation and where, the
                        first-order worst case Σ|∂y/∂p|·T and the sensitivities
  -o, --output FILE.csv the band: the input, then per column its nominal value and the
                        lowest and highest of the samples (low_NAME, high_NAME)
Output: per output column (each link's angle, ω and α, each moving point's x and y) the
  Monte-Carlo worst deviation from the nominal curve and the input where, the first-order
  worst case from the exact sensitivities (the chain rule through the solver, not finite
  differences), and the dimension the column is most sensitive to; samples that do not
  assemble at every input, or meet a toggle, are counted and left out of the band.
)";

constexpr const char* kOptimiseOptions =
    R"(optimise options (FILE.json or --example NAME; the design's own grid is the cycle every
objective is measured over; see docs/optimisation.md):
  --objective KIND      what to improve (required):
                          peak-alpha:LINK   the peak |α| of LINK over the cycle, lowered
                          transmission      the worst transmission angle, raised
                          path:TARGETS.csv  the distance of a point's path from the targets
                                            (x, y in the length unit, the first two columns),
                                            lowered
                          rms-torque        the RMS driving torque over a turn, lowered
                                            (needs the design's masses)
  --point NAME          the point whose path is compared (path; default P)
  --path-measure M      worst (default): the largest target's distance from the path;
                        rms: the root mean square of those distances
  --length-range PCT    each length within ±PCT % of its start, coordinates within ±PCT % of
                        the linkage's longest length (default 50, at most 95)
  --fix-pivots LIST     the ground pivots kept where they are: names, comma-separated, or
                        all (default) or none
  --seed S              the seed of the starts after the first (default 46): the same seed
                        gives the same design on every machine
  --evaluations N       designs measured in all, 10 to 1000000 (default 1500)
  --starts N            Nelder–Mead runs, the first from the design itself (default 4)
  --json                the result as JSON
  -o, --output FILE     where the optimised design is written (required)
Output: the objective before → after, the designs measured, what was kept (Grashof class,
  branch, assembly over the whole grid, ranges, fixed pivots) and each dimension's start,
  optimised value and range. The design is kept whole: its grid, speed and masses.
)";

constexpr const char* kExitCodes = R"(Exit codes:
  0  success
  1  the output file could not be written, or memory ran out (the old file is kept)
  2  bad usage or input: unknown option, malformed or invalid value (the message names it);
     --forces for a linkage without masses, or with a length unit forces cannot convert
  3  the linkage cannot be assembled over the requested range (rows that assemble are
     still written; the message gives the ranges that do not and the range that does);
     for arm: the tip path leaves the workspace (the message gives the exact times);
     for centres, dxf and report: a requested input cannot be assembled; for polygon: a crank
     angle cannot be assembled or is a toggle; for cognates: the four-bar at its grid's
     start, where they are built; for synthesize path: no
     start found a four-bar that assembles at every target

Examples:
  linkwright-cli analyze --fourbar 60,25,70,45 --rpm 10 --step 30
  linkwright-cli analyze --example funsho-fourbar --forces --step 30
  linkwright-cli arm --example seed-arm --format table
  linkwright-cli centres --example thesis-crank-rocker --at 0,90
  linkwright-cli dxf --example thesis-crank-rocker --at 30 --hole 2 -o links.dxf
  linkwright-cli report --example thesis-crank-rocker --step 30 -o report.pdf
  linkwright-cli compare --example thesis-crank-rocker solidworks.csv \
      --map 2=time:s,3=coupler_omega:deg/s:abs,4=rocker_omega:deg/s:abs
  linkwright-cli polygon --example thesis-crank-rocker --at 30
  linkwright-cli inversions --fourbar 60,25,70,45
  linkwright-cli machine --example funsho-fourbar --cs 0.02 --gear-ratio 10 --efficiency 0.9
  linkwright-cli balance --example funsho-fourbar -o balanced.linkwright
  linkwright-cli cognates --example thesis-crank-rocker --coupler-point 35,20 -o thesis
  linkwright-cli tolerance --example thesis-crank-rocker --tolerance 0.05 --json
  linkwright-cli optimise --example thesis-crank-rocker --objective peak-alpha:rocker -o better.linkwright
  linkwright-cli atlas --coupler 2.5 --rocker 2.5 --frame 2 --along 2 --across 0 --filter straight
  linkwright-cli atlas --cell 17 -o cell.linkwright
  linkwright-cli synthesize swing --swing 60 --time-ratio 1.3 --rocker 50 -o design.json
)";

// A request's options, read off its fields (kinematics/model/request_field.h): the option, then
// its help, unit, range and default, wrapped under one another.
std::string requestOptionsText(const std::string& heading, const std::vector<kinematics::RequestField>& fields) {
  constexpr std::size_t kIndent = 24, kWidth = 100;
  std::string text = heading + "\n";
  for (const auto& field : fields) {
    std::string line = "  " + kinematics::fieldName(field, kinematics::FrontEnd::Cli) +
                       (field.kind == kinematics::RequestField::Kind::Count ? " N" : " X");
    line += line.size() + 2 <= kIndent ? std::string(kIndent - line.size(), ' ') : "\n" + std::string(kIndent, ' ');
    std::size_t column = line.size() - line.rfind('\n') - 1;
    std::size_t begin = 0;
    const std::string help = kinematics::helpText(field);
    while (begin < help.size()) {
      std::size_t end = help.find(' ', begin);
      if (end == std::string::npos) end = help.size();
      const std::string word = help.substr(begin, end - begin);
      if (column > kIndent && column + 1 + word.size() > kWidth) {
        line += "\n" + std::string(kIndent, ' ');
        column = kIndent;
      } else if (column > kIndent) {
        line += ' ';
        ++column;
      }
      line += word;
      column += word.size();
      begin = end + 1;
    }
    text += line + "\n";
  }
  return text + "  --json                one JSON object, SI units, each figure's relative error estimate under\n" +
         std::string(kIndent, ' ') + "\"accuracy\"\n";
}

}  // namespace

std::string helpText(const std::string& topic) {
  std::string text = kUsage;
  const bool sweeps = topic.empty() || topic == "analyze" || topic == "extremes";
  if (sweeps || topic == "classify" || topic == "centres" || topic == "polygon" || topic == "inversions" ||
      topic == "dxf" || topic == "report" || topic == "compare" || topic == "tolerance")
    text += kMechanismOptions;
  if (sweeps) text += std::string("\n") + kAnalyzeOptions;
  if (topic.empty() || topic == "classify") text += std::string("\n") + kClassifyOptions;
  if (topic.empty() || topic == "centres") text += std::string("\n") + kCentresOptions;
  if (topic.empty() || topic == "polygon" || topic == "inversions") text += std::string("\n") + kPolygonOptions;
  if (topic.empty() || topic == "dxf") text += std::string("\n") + kDxfOptions;
  if (topic.empty() || topic == "report") text += std::string("\n") + kReportOptions;
  if (topic.empty() || topic == "compare") text += std::string("\n") + kCompareOptions;
  if (topic.empty() || topic == "arm") text += std::string(topic.empty() ? "\n" : "") + kArmOptions;
  if (topic.empty() || topic == "accuracy") text += std::string("\n") + kAccuracyOptions;
  if (topic.empty() || topic == "machine")
    text += "\n" + requestOptionsText(
                       "machine options (FILE.json or --example NAME with masses; one full turn from "
                       "its grid's start):",
                       requestFieldsOf(Command::Machine));
  if (topic.empty() || topic == "balance") text += std::string("\n") + kBalanceOptions;
  if (topic.empty() || topic == "cognates") text += std::string("\n") + kCognatesOptions;
  if (topic.empty() || topic == "tolerance") text += std::string("\n") + kToleranceOptions;
  if (topic.empty() || topic == "optimise") text += std::string("\n") + kOptimiseOptions;
  if (topic.empty() || topic == "atlas") text += std::string("\n") + kAtlasOptions;
  if (topic.empty() || topic == "synthesize") text += std::string("\n") + kSynthesizeOptions;
  return text + "\n" + kExitCodes;
}

namespace {

int runCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const kinematics::Result<Invocation> parsed = parseArguments(args);
  if (!parsed) {
    err << "linkwright-cli: " << parsed.error().message << "\n";
    return toInt(ExitCode::BadInput);
  }
  const Invocation& inv = *parsed;
  switch (inv.command) {
  case Command::Help:
    if (!inv.helpTopic.empty() && inv.helpTopic != "analyze" && inv.helpTopic != "classify" &&
        inv.helpTopic != "extremes" && inv.helpTopic != "arm" && inv.helpTopic != "centres" &&
        inv.helpTopic != "polygon" && inv.helpTopic != "inversions" && inv.helpTopic != "dxf" &&
        inv.helpTopic != "report" && inv.helpTopic != "compare" && inv.helpTopic != "accuracy" &&
        inv.helpTopic != "synthesize" && inv.helpTopic != "machine" && inv.helpTopic != "balance" &&
        inv.helpTopic != "cognates" && inv.helpTopic != "tolerance" && inv.helpTopic != "optimise" &&
        inv.helpTopic != "atlas" && inv.helpTopic != "examples" && inv.helpTopic != "linkwright-cli") {
      err << "linkwright-cli: no help for '" << inv.helpTopic
          << "' (commands: analyze, extremes, classify, arm, centres, polygon, inversions, accuracy, dxf, report, "
             "compare, machine, balance, cognates, tolerance, optimise, atlas, synthesize, examples)\n";
      return toInt(ExitCode::BadInput);
    }
    out << helpText(inv.helpTopic == "linkwright-cli" || inv.helpTopic == "examples" ? "" : inv.helpTopic);
    return toInt(ExitCode::Success);
  case Command::Version: out << "linkwright-cli " << LINKWRIGHT_VERSION << "\n"; return toInt(ExitCode::Success);
  case Command::Examples: return toInt(runExamples(out));
  case Command::Analyze: return toInt(runAnalyze(inv, out, err));
  case Command::Classify: return toInt(runClassify(inv, out, err));
  case Command::Extremes: return toInt(runExtremes(inv, out, err));
  case Command::Arm: return toInt(runArm(inv, out, err));
  case Command::Centres: return toInt(runCentres(inv, out, err));
  case Command::Polygon: return toInt(runPolygon(inv, out, err));
  case Command::Inversions: return toInt(runInversions(inv, out, err));
  case Command::Accuracy: return toInt(runAccuracy(inv, out, err));
  case Command::Dxf: return toInt(runDxf(inv, out, err));
  case Command::Report: return toInt(runReport(inv, out, err));
  case Command::Compare: return toInt(runCompare(inv, out, err));
  case Command::Synthesize: return toInt(runSynthesize(inv, out, err));
  case Command::Machine: return toInt(runMachine(inv, out, err));
  case Command::Balance: return toInt(runBalance(inv, out, err));
  case Command::Cognates: return toInt(runCognates(inv, out, err));
  case Command::Tolerance: return toInt(runTolerance(inv, out, err));
  case Command::Optimise: return toInt(runOptimise(inv, out, err));
  case Command::Atlas: return toInt(runAtlas(*inv.atlas, out, err));
  }
  return toInt(ExitCode::BadInput);
}

}  // namespace

int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  // Memory runs out on a machine smaller than the job (a table of 10⁷ rows read whole, a
  // synthesis of many starts): a sentence and exit 1, never an abort. The one writer has then
  // left any output file as it was.
  try {
    const int code = runCommand(args, out, err);
    // A full disk or a closed pipe behind `> file` shows only here, when the last buffer is
    // written: every command's results are then incomplete, whatever it returned.
    out << std::flush;
    if (!out) {
      err << "linkwright-cli: cannot write the standard output (is the disk full?); what was written is "
             "incomplete\n";
      return toInt(ExitCode::IoError);
    }
    return code;
  } catch (const std::bad_alloc&) {
    err << "linkwright-cli: out of memory: this machine cannot hold what the command needs (try fewer samples, "
           "rows or starts); no output file was changed\n";
    return toInt(ExitCode::IoError);
  }
}

}  // namespace linkwright::cli
