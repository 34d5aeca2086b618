#include "ui/document/document_file.h"

#include "kinematics/io/bounded_read.h"
#include "kinematics/io/document_json.h"
#include "kinematics/io/safe_file.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

namespace linkwright::ui {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("DocumentFile", text); }

// The core's sentence without what it starts with ("PATH: why" → "why"): the messages here
// name the file by its name.
QString whyOf(const std::string& message, const std::string& start) {
  const std::string lead = start + ": ";
  return QString::fromStdString(message.rfind(lead, 0) == 0 ? message.substr(lead.size()) : message);
}

}  // namespace

QString openDocumentFilter() { return tr("Linkwright documents (*.linkwright *.json);;All files (*)"); }

QString saveDocumentFilter() { return tr("Linkwright documents (*.linkwright);;JSON documents (*.json)"); }

QString withDocumentSuffix(const QString& path) {
  // Only a document's own suffix counts: in "0.0001" or "crank-rocker v1.2" the dot is part of
  // the name, which would otherwise be saved without one.
  const QString suffix = QFileInfo(path).suffix().toLower();
  return suffix == QStringLiteral("linkwright") || suffix == QStringLiteral("json") ? path : path + ".linkwright";
}

std::optional<QString> loadDesignFile(const QString& path, kinematics::Design& design) {
  const QString name = QFileInfo(path).fileName();
  if (!QFileInfo::exists(path)) return tr("Cannot open %1: the file does not exist.").arg(name);
  // The core's one reader: a regular file, its limit enforced while reading.
  const auto text =
      kinematics::io::readFileBounded(path.toStdString(), kinematics::io::kMaxDocumentBytes, "a Linkwright document");
  if (!text) return tr("Cannot open %1: %2.").arg(name, whyOf(text.error().message, path.toStdString()));
  const auto parsed = kinematics::io::readDocument(*text);
  if (!parsed) return tr("Cannot open %1: %2.").arg(name, QString::fromStdString(parsed.error().message));
  design = *parsed;
  return std::nullopt;
}

std::optional<QString> saveFileAtomically(const QString& path, const QByteArray& bytes) {
  // The core's one writer (kinematics/io/safe_file.h), as the CLI's outputs.
  const auto error = kinematics::io::writeFileSafely(
      path.toStdString(), std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
  if (!error) return std::nullopt;
  const QString why = whyOf(error->message, "cannot write " + path.toStdString());
  return tr("Cannot write %1: %2. The previous file, if any, is unchanged.").arg(QFileInfo(path).fileName(), why);
}

std::optional<QString> saveFileThrough(const QString& path,
                                       const std::function<std::optional<std::string>(const std::string&)>& write) {
  const auto error = kinematics::io::writeFileSafely(path.toStdString(), write);
  if (!error) return std::nullopt;
  const QString why = whyOf(error->message, "cannot write " + path.toStdString());
  return tr("Cannot write %1: %2. The previous file, if any, is unchanged.").arg(QFileInfo(path).fileName(), why);
}

std::optional<QString> saveDesignFile(const QString& path, const kinematics::Design& design) {
  return saveFileAtomically(path, QByteArray::fromStdString(kinematics::io::writeDocument(design)));
}

}  // namespace linkwright::ui
