#pragma once
// Saves what a QGraphicsView shows (the canvas, a chart) as PNG, or as SVG for reports.
// The format follows the file's suffix.

#include <QString>

#include <optional>

class QGraphicsView;

namespace linkwright::ui {

/// Writes `view`'s visible contents to `path` (.png or .svg). Returns the message on failure.
std::optional<QString> saveViewImage(QGraphicsView* view, const QString& path, const QString& title);

}  // namespace linkwright::ui
