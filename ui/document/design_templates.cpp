#include "ui/document/design_templates.h"

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
  };
}

k::Design templateDesign(const DesignTemplate& kind) {
  if (kind.example.empty()) return k::FourBarDesign{};
  // The templates name built-in examples, which always exist.
  return *k::designForExample(kind.example);
}

QString kindDisplayName(const k::Design& design) {
  if (std::holds_alternative<k::FourBarDesign>(design)) return tr("Four-bar");
  const std::string& kind = std::get<k::MechanismDesign>(design).kind;
  for (const DesignTemplate& t : designTemplates())
    if (t.kind == kind) return QString(t.label).remove(QLatin1Char('&'));
  if (kind == "linkage" || kind.empty()) return tr("Linkage");
  return QString::fromStdString(kind);
}

QString exampleMenuText(const std::string& description, int maxChars) {
  QString text = QString::fromStdString(description);
  const qsizetype bracket = text.indexOf(QStringLiteral(" ("));
  if (bracket > 0) text.truncate(bracket);
  if (text.size() <= maxChars) return text;
  const qsizetype comma = text.lastIndexOf(QStringLiteral(", "), maxChars);
  text.truncate(comma > maxChars / 2 ? comma : maxChars);
  return text + QStringLiteral("…");
}

}  // namespace linkwright::ui
