#include "ui/document/document_file.h"

#include "kinematics/io/document_json.h"
#include "kinematics/io/safe_file.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

namespace linkwright::ui {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("DocumentFile", text); }

// Documents are a few hundred bytes; anything this large is not one of ours.
constexpr qint64 kMaxDocumentBytes = 16 * 1024 * 1024;

}  // namespace

QString openDocumentFilter() { return tr("Linkwright documents (*.linkwright *.json);;All files (*)"); }

QString saveDocumentFilter() { return tr("Linkwright documents (*.linkwright);;JSON documents (*.json)"); }

QString withDocumentSuffix(const QString& path) {
  return QFileInfo(path).suffix().isEmpty() ? path + ".linkwright" : path;
}

std::optional<QString> loadDesignFile(const QString& path, kinematics::Design& design) {
  const QString name = QFileInfo(path).fileName();
  QFile file(path);
  if (!file.exists()) return tr("Cannot open %1: the file does not exist.").arg(name);
  if (!file.open(QIODevice::ReadOnly)) return tr("Cannot open %1: %2.").arg(name, file.errorString());
  if (file.size() > kMaxDocumentBytes)
    return tr("Cannot open %1: it is too large to be a Linkwright document.").arg(name);
  const QByteArray bytes = file.readAll();
  const auto parsed =
      kinematics::io::readDocument(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
  if (!parsed) return tr("Cannot open %1: %2.").arg(name, QString::fromStdString(parsed.error().message));
  design = *parsed;
  return std::nullopt;
}

std::optional<QString> saveFileAtomically(const QString& path, const QByteArray& bytes) {
  // The core's one writer (kinematics/io/safe_file.h), as the CLI's outputs.
  const auto error = kinematics::io::writeFileSafely(
      path.toStdString(), std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
  if (!error) return std::nullopt;
  const std::string& message = error->message;  // "cannot write PATH: WHY"
  const QString why = QString::fromStdString(message.substr(message.rfind(": ") + 2));
  return tr("Cannot write %1: %2. The previous file, if any, is unchanged.").arg(QFileInfo(path).fileName(), why);
}

std::optional<QString> saveDesignFile(const QString& path, const kinematics::Design& design) {
  return saveFileAtomically(path, QByteArray::fromStdString(kinematics::io::writeDocument(design)));
}

}  // namespace linkwright::ui
