#pragma once
// Reading and writing document files. Writes go through QSaveFile, so a failed save leaves
// the previous file intact; reads refuse missing, unreadable, corrupt and newer files with a
// message that names the file and the reason.

#include "kinematics/design/design.h"

#include <QString>

#include <functional>
#include <optional>
#include <string>

namespace linkwright::ui {

/// File dialog filters: Open takes `.linkwright` and `.json` documents alike; Save offers
/// `.linkwright` first, the extension the desktop's MIME type (packaging/linkwright-mime.xml)
/// opens in the designer, so a double-click does not claim every JSON file.
QString openDocumentFilter();
QString saveDocumentFilter();

/// `path` with `.linkwright` appended unless it ends in `.linkwright` or `.json` (any case): a
/// dot in the name ("0.0001", "arm v1.2") is no extension.
QString withDocumentSuffix(const QString& path);

/// Reads `path` into `design`; on failure returns the message and leaves `design` untouched.
std::optional<QString> loadDesignFile(const QString& path, kinematics::Design& design);

/// Writes `design` to `path` atomically; returns the message on failure.
std::optional<QString> saveDesignFile(const QString& path, const kinematics::Design& design);

/// Writes `bytes` to `path` through the core's one writer (kinematics/io/safe_file.h): whole or
/// not at all, a device or FIFO written through, a symlink's target written (every export uses it).
std::optional<QString> saveFileAtomically(const QString& path, const QByteArray& bytes);

/// Writes `path` through the same writer, `write` producing the file itself at the path it is
/// given (a temporary file beside `path`, renamed over it only if `write` returns nullopt; or
/// `path` itself when that is a device): for a library that writes a file by its name (FFmpeg's
/// muxers, which seek back in it). `write` returns why it failed, which the message quotes.
std::optional<QString> saveFileThrough(const QString& path,
                                       const std::function<std::optional<std::string>(const std::string&)>& write);

}  // namespace linkwright::ui
