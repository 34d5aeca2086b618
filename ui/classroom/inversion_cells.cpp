#include "ui/classroom/inversion_cells.h"

#include "ui/colors.h"

#include "kinematics/analysis/inversions.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/recognise.h"

#include <QCoreApplication>

#include <array>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

QString tr(const char* text) { return QCoreApplication::translate("InversionCells", text); }

QString number(double value) { return QString::fromStdString(k::formatShort(value)); }

QString fromStd(std::string_view text) { return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size())); }

// The designer's colours of the original links; the frame, drawn grey while grounded, takes the
// palette's fourth colour when an inversion sets it moving.
QColor roleColor(k::LinkRole role) {
  switch (role) {
  case k::LinkRole::Crank: return linkColor(0);
  case k::LinkRole::Coupler: return linkColor(1);
  case k::LinkRole::Rocker: return linkColor(2);
  case k::LinkRole::Frame: break;
  }
  return linkColor(3);
}

// A cell's design: the inversion's mechanism at the source's crank speed, over a full turn of
// its grid (a crank that cannot turn fully rocks within it).
k::Design cellDesign(const k::Design& source, const std::string& kind, k::Mechanism mechanism) {
  k::Design d;
  d.kind = kind;
  d.mechanism = std::move(mechanism);
  d.omega = source.time || source.omega == 0.0 ? 1.0 : source.omega;
  d.samples = k::samplesEveryHalfDegree(d.fromDeg, d.toDeg);
  return d;
}

// The four-bar's loop, frame → crank → coupler → rocker, as in the core.
constexpr std::array<k::LinkRole, 4> kLoop{k::LinkRole::Frame, k::LinkRole::Crank, k::LinkRole::Coupler,
                                           k::LinkRole::Rocker};

int loopIndex(k::LinkRole role) { return static_cast<int>(role); }

InversionCell fourBarCell(const k::Design& source, const k::FourBarStructure& f, const k::FourBarInversion& inv) {
  InversionCell cell;
  cell.title = tr("Ground: %1").arg(fromStd(k::toString(inv.grounded)));
  cell.className = QString::fromStdString(inv.name);
  cell.detail =
      tr("drives the %1 (%2)")
          .arg(fromStd(k::toString(inv.driven)), inv.grashof.inputFullyRotates ? tr("turns fully") : tr("rocks"));
  // The inversion's crank, coupler and rocker are the original links the core went round the
  // loop to, from the grounded link through the driven one.
  const int g = loopIndex(inv.grounded);
  const int step = (loopIndex(inv.driven) - g + 4) % 4;  // 1 or 3: which way round
  const auto original = [&](int k) { return kLoop[static_cast<std::size_t>((g + step * k) % 4)]; };
  cell.linkColors = {roleColor(original(1)), roleColor(original(2)), roleColor(original(3))};
  // Its joints keep the names the designer gives them: the joint between two original links.
  const k::Mechanism& m = source.mechanism;
  const auto jointName = [&](k::LinkRole a, k::LinkRole b) {
    const auto is = [&](k::LinkRole x, k::LinkRole y) { return (a == x && b == y) || (a == y && b == x); };
    k::PointId id = f.c;
    if (is(k::LinkRole::Frame, k::LinkRole::Crank)) id = f.o2;
    else if (is(k::LinkRole::Crank, k::LinkRole::Coupler)) id = f.b;
    else if (is(k::LinkRole::Rocker, k::LinkRole::Frame)) id = f.o4;
    return m.points[id.index].name;
  };
  k::Mechanism inverted = inv.mechanism;
  inverted.points[k::fourbar::kO2.index].name = jointName(original(0), original(1));
  inverted.points[k::fourbar::kB.index].name = jointName(original(1), original(2));
  inverted.points[k::fourbar::kC.index].name = jointName(original(2), original(3));
  inverted.points[k::fourbar::kO4.index].name = jointName(original(3), original(0));
  cell.design = cellDesign(source, "four-bar", std::move(inverted));
  return cell;
}

InversionSet fourBarSet(const k::Design& source, const k::FourBarStructure& f) {
  InversionSet set;
  const auto inversions = k::fourBarInversions(f.lengths, f.branch, source.mechanism.lengthUnit);
  if (!inversions) {
    set.unavailable = QString::fromStdString(inversions.error().message);
    return set;
  }
  const k::GrashofReport g = k::classifyGrashof(f.lengths);
  set.heading =
      tr("Four-bar chain: frame %1, crank %2, coupler %3, rocker %4 %5. S + L = %6, P + Q = %7: %8.")
          .arg(number(f.lengths.frame), number(f.lengths.crank), number(f.lengths.coupler), number(f.lengths.rocker),
               QString::fromStdString(source.mechanism.lengthUnit), number(g.sPlusL), number(g.pPlusQ))
          .arg(g.category == k::GrashofClass::TripleRocker  ? tr("non-Grashof")
               : g.category == k::GrashofClass::ChangePoint ? tr("change point")
                                                            : tr("Grashof"));
  for (const k::FourBarInversion& inv : *inversions) set.cells.push_back(fourBarCell(source, f, inv));
  return set;
}

InversionCell sliderCrankCell(const k::Design& source, const k::SliderCrankInversion& inv) {
  InversionCell cell;
  cell.title = tr("Ground: %1").arg(fromStd(k::toString(inv.grounded)));
  cell.className = QString::fromStdString(inv.name);
  cell.detail = tr("drives the %1 (%2)")
                    .arg(QString::fromStdString(inv.driven), inv.driverTurnsFully ? tr("turns fully") : tr("rocks"));
  cell.note = QString::fromStdString(inv.note);
  if (!inv.mechanism) return cell;
  // The core names the links after the original ones; the old frame is a guide or a cylinder.
  for (const k::Link& link : inv.mechanism->links)
    cell.linkColors.push_back(link.name == "crank" ? roleColor(k::LinkRole::Crank)
                              : link.name == "rod" ? roleColor(k::LinkRole::Coupler)
                                                   : roleColor(k::LinkRole::Frame));
  cell.design = cellDesign(source, "slider-crank inversion", *inv.mechanism);
  return cell;
}

InversionSet sliderCrankSet(const k::Design& source, const k::SliderCrankGeometry& g) {
  InversionSet set;
  const auto inversions = k::sliderCrankInversions(g, source.mechanism.lengthUnit);
  if (!inversions) {
    set.unavailable = QString::fromStdString(inversions.error().message);
    return set;
  }
  set.heading =
      tr("Slider-crank chain: crank %1, rod %2, offset %3 %4.")
          .arg(number(g.crank), number(g.rod), number(g.offset), QString::fromStdString(source.mechanism.lengthUnit));
  for (const k::SliderCrankInversion& inv : *inversions) set.cells.push_back(sliderCrankCell(source, inv));
  return set;
}

}  // namespace

std::optional<QString> inversionsUnavailable(const k::Design& design) {
  const k::Mechanism& m = design.mechanism;
  if (k::asFourBar(m, k::PointsOnLinks::AnyLink)) return std::nullopt;
  if (const auto s = k::asSliderCrank(m, k::PointsOnLinks::AnyLink); s && k::sliderCrankGeometry(m, *s))
    return std::nullopt;
  return tr("Inversions are shown for four-bars and slider-cranks only; this linkage is a %1.")
      .arg(QString::fromStdString(design.kind));
}

InversionSet inversionSet(const k::Design& design) {
  const k::Mechanism& m = design.mechanism;
  if (const auto f = k::asFourBar(m, k::PointsOnLinks::AnyLink)) return fourBarSet(design, *f);
  if (const auto s = k::asSliderCrank(m, k::PointsOnLinks::AnyLink))
    if (const auto g = k::sliderCrankGeometry(m, *s)) return sliderCrankSet(design, *g);
  InversionSet set;
  set.unavailable = *inversionsUnavailable(design);
  return set;
}

}  // namespace linkwright::ui
