#pragma once
// Saves what a QGraphicsView shows (the canvas, a chart) as PNG, or as SVG or PDF (vector: paths
// and text, no picture inside) for reports.
// The format follows the file's suffix.

#include <QString>

#include <optional>

class QGraphicsView;

namespace linkwright::ui {

/// Writes `view`'s visible contents to `path` (.png, .svg or .pdf). Returns the message on failure.
std::optional<QString> saveViewImage(QGraphicsView* view, const QString& path, const QString& title);

}  // namespace linkwright::ui
