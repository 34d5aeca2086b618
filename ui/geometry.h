#pragma once
// The one place where core vectors meet Qt points. Model coordinates have y up; the canvas
// view flips y, so no conversion here changes a sign.

#include <Eigen/Core>

#include <QPointF>

namespace linkwright::ui {

inline QPointF toQt(const Eigen::Vector2d& v) { return {v.x(), v.y()}; }
inline Eigen::Vector2d toEigen(const QPointF& p) { return {p.x(), p.y()}; }

}  // namespace linkwright::ui
