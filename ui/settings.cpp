#include "ui/settings.h"

#include <QFileInfo>

namespace linkwright::ui {

Settings::Settings() = default;

QByteArray Settings::windowGeometry() const { return m_settings.value("window/geometry").toByteArray(); }
void Settings::setWindowGeometry(const QByteArray& geometry) { m_settings.setValue("window/geometry", geometry); }
QByteArray Settings::windowState() const { return m_settings.value("window/state").toByteArray(); }
void Settings::setWindowState(const QByteArray& state) { m_settings.setValue("window/state", state); }

bool Settings::anglesInRadians() const { return m_settings.value("units/anglesInRadians", false).toBool(); }
void Settings::setAnglesInRadians(bool radians) { m_settings.setValue("units/anglesInRadians", radians); }
bool Settings::speedInRpm() const { return m_settings.value("units/speedInRpm", true).toBool(); }
void Settings::setSpeedInRpm(bool rpm) { m_settings.setValue("units/speedInRpm", rpm); }
SamplingQuality Settings::samplingQuality() const {
  return qualityFromKey(m_settings.value("plots/quality", qualityKey(SamplingQuality::Normal)).toString());
}
void Settings::setSamplingQuality(SamplingQuality quality) {
  m_settings.setValue("plots/quality", qualityKey(quality));
}

QStringList Settings::recentFiles() const {
  QStringList existing;
  for (const QString& path : m_settings.value("files/recent").toStringList())
    if (QFileInfo::exists(path)) existing << path;
  return existing;
}

void Settings::addRecentFile(const QString& path) {
  QStringList files = m_settings.value("files/recent").toStringList();
  const QString absolute = QFileInfo(path).absoluteFilePath();
  files.removeAll(absolute);
  files.prepend(absolute);
  while (files.size() > kMaxRecentFiles) files.removeLast();
  m_settings.setValue("files/recent", files);
}

}  // namespace linkwright::ui
