#include "ui/panels/law_table_file.h"

#include "kinematics/io/law_table_csv.h"
#include "kinematics/model/driver.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

namespace linkwright::ui {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("LawTableFile", text); }

}  // namespace

std::variant<kinematics::TableLaw, QString> readLawTableFile(const QString& path,
                                                             const kinematics::Mechanism& mechanism) {
  namespace k = kinematics;
  const QFileInfo info(path);
  const QString name = info.fileName();
  if (!info.isFile() || info.size() > static_cast<qint64>(k::io::kMaxLawTableBytes))
    return tr("%1 cannot be read as a table (a regular file of at most 64 MiB)").arg(name);
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return tr("%1 cannot be opened: %2").arg(name, file.errorString());
  const QByteArray text = file.readAll();
  auto law = k::io::readLawTableCsv(std::string_view(text.constData(), static_cast<std::size_t>(text.size())),
                                    k::inputKind(mechanism), mechanism.lengthUnit);
  if (!law) return tr("%1: %2").arg(name, QString::fromStdString(law.error().message));
  return std::move(law).value();
}

}  // namespace linkwright::ui
