#include "ui/export/view_image.h"

#include "ui/document/document_file.h"

#include <QBuffer>
#include <QFileInfo>
#include <QGraphicsView>
#include <QImage>
#include <QPainter>
#include <QSvgGenerator>

namespace linkwright::ui {

std::optional<QString> saveViewImage(QGraphicsView* view, const QString& path, const QString& title) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  const QSize size = view->viewport()->size();
  QByteArray bytes;
  QBuffer buffer(&bytes);
  buffer.open(QIODevice::WriteOnly);
  if (suffix == "svg") {
    QSvgGenerator svg;
    svg.setOutputDevice(&buffer);
    svg.setSize(size);
    svg.setViewBox(QRect(QPoint(0, 0), size));
    svg.setTitle(title);
    svg.setDescription(QObject::tr("Exported from Linkwright"));
    QPainter painter(&svg);
    view->render(&painter, QRectF(), view->viewport()->rect());
  } else if (suffix == "png") {
    // Twice the on-screen resolution, so the picture stays sharp in a printed report. The
    // device pixel ratio (not a painter scale) keeps pins, labels and cosmetic pens in
    // proportion with the drawing.
    QImage image(size * 2, QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(2.0);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    view->render(&painter, QRectF(QPointF(0, 0), QSizeF(size)), view->viewport()->rect());
    painter.end();
    image.save(&buffer, "PNG");
  } else {
    return QObject::tr("Cannot export %1: use a .png or .svg file name.").arg(QFileInfo(path).fileName());
  }
  return saveFileAtomically(path, bytes);
}

}  // namespace linkwright::ui
