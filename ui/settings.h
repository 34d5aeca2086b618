#pragma once
// The one class that touches QSettings: window layout, units, the plots' sampling quality and
// recent files persist here.

#include "ui/document/sampling_quality.h"

#include <QByteArray>
#include <QSettings>
#include <QStringList>

namespace linkwright::ui {

class Settings {
public:
  Settings();

  QByteArray windowGeometry() const;
  void setWindowGeometry(const QByteArray& geometry);
  QByteArray windowState() const;
  void setWindowState(const QByteArray& state);

  /// true: angles in radians in the plots; false: degrees (the default).
  bool anglesInRadians() const;
  void setAnglesInRadians(bool radians);
  /// true: crank speed typed in rpm (the default); false: rad/s.
  bool speedInRpm() const;
  void setSpeedInRpm(bool rpm);
  /// The displayed sweep's sampling quality (Normal by default).
  SamplingQuality samplingQuality() const;
  void setSamplingQuality(SamplingQuality quality);

  /// Most recent first, at most kMaxRecentFiles, only files that still exist.
  QStringList recentFiles() const;
  void addRecentFile(const QString& path);

  static constexpr int kMaxRecentFiles = 8;

private:
  mutable QSettings m_settings;
};

}  // namespace linkwright::ui
