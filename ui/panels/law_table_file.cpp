#include "ui/panels/law_table_file.h"

#include "kinematics/io/bounded_read.h"
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
  const QString name = QFileInfo(path).fileName();
  // The core's one reader: a regular file of at most 64 MiB, the limit enforced while reading.
  const auto text = k::io::readFileBounded(path.toStdString(), k::io::kMaxLawTableBytes, "a table");
  if (!text) {
    const std::string& message = text.error().message;  // "PATH: why", the file named by its name here
    return tr("%1: %2").arg(name, QString::fromStdString(message.substr(path.toStdString().size() + 2)));
  }
  auto law = k::io::readLawTableCsv(*text, k::inputKind(mechanism), mechanism.lengthUnit);
  if (!law) return tr("%1: %2").arg(name, QString::fromStdString(law.error().message));
  return std::move(law).value();
}

}  // namespace linkwright::ui
