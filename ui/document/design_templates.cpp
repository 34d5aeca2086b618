#include "ui/document/design_templates.h"

#include "kinematics/model/recognise.h"

#include <QCoreApplication>

namespace linkwright::ui {

namespace k = kinematics;

namespace {
QString tr(const char* text) { return QCoreApplication::translate("DesignTemplates", text); }
}  // namespace

std::vector<DesignTemplate> designTemplates() {
  return {
      {tr("&Four-bar"), "four-bar", ""},
      {tr("&Slider-crank"), "slider-crank", "ls3-engine"},
      {tr("Crank-s&haper"), "shaper", "shaper"},
      {tr("&Whitworth quick return"), "whitworth", "whitworth"},
      {tr("Watt &I six-bar"), "watt-i", "watt-i"},
      {tr("Watt I&I six-bar"), "watt-ii", "watt-ii"},
      {tr("Stephenson I six-&bar"), "stephenson-i", "stephenson-i"},
      {tr("Stephenson III six-ba&r"), "stephenson-iii", "stephenson-iii"},
      {tr("Two-link &arm"), "two-link arm", "seed-arm"},
      {tr("&Piston-driven slider-crank"), "slider-crank", "piston-driven"},
      {tr("&Cylinder-driven boom"), "cylinder rocker", "excavator-boom"},
  };
}

k::Design templateDesign(const DesignTemplate& kind) {
  if (kind.example.empty()) return k::fourBarDesign(k::kThesisCrankRocker).value();
  // The templates name built-in examples, which always exist.
  return *k::designForExample(kind.example);
}

QString kindDisplayName(const k::Design& design) {
  // A four-bar is one however it was stored (a four-bar saved as a general linkage, say).
  if (k::asFourBar(design.mechanism, k::PointsOnLinks::AnyLink)) return tr("Four-bar");
  const std::string& kind = design.kind;
  for (const DesignTemplate& t : designTemplates())
    if (t.kind == kind) return QString(t.label).remove(QLatin1Char('&'));
  if (kind == "linkage" || kind.empty()) return tr("Linkage");
  // A kind without a template, as a name: "stephenson-iii-triad" → "Stephenson III triad".
  QStringList words = QString::fromStdString(kind).split(QLatin1Char('-'), Qt::SkipEmptyParts);
  static const QStringList kRoman{"i", "ii", "iii", "iv", "v", "vi"};
  for (QString& word : words)
    if (kRoman.contains(word)) word = word.toUpper();
  if (!words.isEmpty()) words.front()[0] = words.front()[0].toUpper();
  return words.join(QLatin1Char(' '));
}

}  // namespace linkwright::ui
