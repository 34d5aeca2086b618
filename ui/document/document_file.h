#pragma once
// Reading and writing document files. Writes go through QSaveFile, so a failed save leaves
// the previous file intact; reads refuse missing, unreadable, corrupt and newer files with a
// message that names the file and the reason.

#include "kinematics/model/mechanism_design.h"

#include <QString>

#include <optional>

namespace linkwright::ui {

/// Reads `path` into `design`; on failure returns the message and leaves `design` untouched.
std::optional<QString> loadDesignFile(const QString& path, kinematics::Design& design);

/// Writes `design` to `path` atomically; returns the message on failure.
std::optional<QString> saveDesignFile(const QString& path, const kinematics::Design& design);

/// Writes `bytes` to `path` atomically (CSV and SVG exports use it too).
std::optional<QString> saveFileAtomically(const QString& path, const QByteArray& bytes);

} // namespace linkwright::ui
