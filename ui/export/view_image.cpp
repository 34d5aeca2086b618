#include "ui/export/view_image.h"

#include "ui/document/document_file.h"

#include <QBuffer>
#include <QFileInfo>
#include <QGraphicsView>
#include <QImage>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
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
  } else if (suffix == "pdf") {
    // Vector, as the SVG: one page the view's size at 96 px to the inch (1 px = 0.75 pt, Qt's
    // PDF pages being whole points), no margins. Paths stay paths and labels stay text
    // (selectable, embedded as a font subset); the canvas draws its grid as lines for it.
    QPdfWriter pdf(&buffer);
    pdf.setResolution(96);
    pdf.setPageLayout(QPageLayout(QPageSize(QSizeF(size) * 0.75, QPageSize::Point, {}, QPageSize::ExactMatch),
                                  QPageLayout::Portrait, QMarginsF()));
    pdf.setTitle(title);
    pdf.setCreator(QObject::tr("Linkwright"));
    QPainter painter(&pdf);
    painter.setRenderHint(QPainter::Antialiasing);
    view->render(&painter, QRectF(QPointF(0, 0), QSizeF(size)), view->viewport()->rect());
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
    return QObject::tr("Cannot export %1: use a .png, .svg or .pdf file name.").arg(QFileInfo(path).fileName());
  }
  return saveFileAtomically(path, bytes);
}

}  // namespace linkwright::ui
