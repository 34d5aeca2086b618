#include "ui/panels/law_table_file.h"

#include "kinematics/model/units.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QLocale>
#include <QTextStream>

#include <vector>

namespace linkwright::ui {
namespace {

// A measurement is far smaller; the bound keeps a wrong file (a device, an image) out.
constexpr qint64 kMaxTableBytes = 64 << 20;

QString tr(const char* text) { return QCoreApplication::translate("LawTableFile", text); }

}  // namespace

std::variant<kinematics::TableLaw, QString> readLawTableFile(const QString& path) {
  namespace k = kinematics;
  const QFileInfo info(path);
  const QString name = info.fileName();
  if (!info.isFile() || info.size() > kMaxTableBytes)
    return tr("%1 cannot be read as a table (a regular file of at most 64 MiB)").arg(name);
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
    return tr("%1 cannot be opened: %2").arg(name, file.errorString());
  QTextStream in(&file);
  const QString header = in.readLine().trimmed();
  const QStringList columns = header.split(QLatin1Char(','));
  const bool degrees = columns.size() == 2 && columns[1].trimmed().endsWith(QLatin1String("_deg"));
  const bool radians = columns.size() == 2 && columns[1].trimmed().endsWith(QLatin1String("_rad"));
  if (columns.value(0).trimmed() != QLatin1String("time_s") || !(degrees || radians))
    return tr("%1: the first line must name the columns time_s and the angle in _deg or _rad, e.g. "
              "time_s,crank_angle_deg (got '%2')")
        .arg(name, header);
  std::vector<double> time, angle;
  const QLocale c = QLocale::c();  // a CSV's numbers are written with a point, whatever the user's locale
  for (int line = 2; !in.atEnd(); ++line) {
    const QString row = in.readLine().trimmed();
    if (row.isEmpty()) continue;
    const QStringList cells = row.split(QLatin1Char(','));
    bool okTime = false, okAngle = false;
    const double t = cells.size() == 2 ? c.toDouble(cells[0].trimmed(), &okTime) : 0.0;
    const double q = cells.size() == 2 ? c.toDouble(cells[1].trimmed(), &okAngle) : 0.0;
    if (!okTime || !okAngle)
      return tr("%1 line %2: expected two numbers, time and angle (got '%3')").arg(name).arg(line).arg(row);
    time.push_back(t);
    angle.push_back(degrees ? k::degToRad(q) : q);
  }
  auto law = k::makeTableLaw(std::move(time), std::move(angle));
  if (!law) return tr("%1: %2").arg(name, QString::fromStdString(law.error().message));
  return std::move(law).value();
}

}  // namespace linkwright::ui
