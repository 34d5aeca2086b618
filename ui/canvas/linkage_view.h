#pragma once
// The linkage canvas: a QGraphicsView over a LinkageScene in model units, y up (the view
// flips y). It draws a scale grid behind the linkage, zooms with the wheel about the cursor,
// pans by dragging the background (left or middle button), and turns drags of the points
// and of driven paths' vertices into document edits through the core (dragPoint, with a
// four-bar's frame-line rule, or dragPathVertex: design_drag.h), one undo step per drag. An edit the core or the document refuses
// changes nothing; the reason is shown next to the cursor and emitted as editRefused.
//
// Picking: in a pick mode (the synthesis panel collecting targets) a left click emits the
// model point clicked instead of dragging or panning; for a pose, press at the point, drag
// along the direction and release. The middle button still pans.
//
// Fitting: the view fits the drawing when first shown, on resize until the user zooms or
// pans, after fitToView(), and after a document reset (File ▸ New / Open / Examples, seen as
// one Design|File change). A region shown beside the drawing (the synthesis preview) joins what
// is fitted, and brings the view to it when it appears off screen.

#include "ui/canvas/drag_handles.h"
#include "ui/document/mechanism_document.h"

#include "kinematics/model/ids.h"

#include <QColor>
#include <QGraphicsView>
#include <QPixmap>
#include <QTransform>

#include <optional>
#include <vector>

namespace linkwright::ui {

class LinkageScene;

class LinkageView : public QGraphicsView {
  Q_OBJECT
public:
  explicit LinkageView(MechanismDocument* document, QWidget* parent = nullptr);

  /// The scene (model units, y up). Its sceneRect() is the drawing with a margin; draw it
  /// with renderLinkage(), which flips y, rather than QGraphicsScene::render().
  QGraphicsScene* linkageScene() const;
  /// Arrows of v and a at every moving point, to a scale fixed per design; hidden at a toggle.
  void setShowVelocityArrows(bool show);
  void setShowAccelerationArrows(bool show);
  /// Instant centres, Kennedy's lines and centrodes of a four-bar or slider-crank.
  void setShowInstantCentres(bool show);
  /// 1 normal; about 2 for presentation (thicker links, bigger pins and labels).
  void setPresentationScale(double factor);
  double presentationScale() const { return m_presentationScale; }
  /// Draws again in the current theme's colours (ui/colors.h), grid and background included.
  void refreshColors();

  /// Read-only: no handle is offered, so nothing can be dragged (a left drag pans); zoom and
  /// pan still work. For views of a document the user does not edit (the inversions).
  void setReadOnly(bool readOnly);
  bool isReadOnly() const { return m_readOnly; }
  /// Per link, the colour to draw it in (LinkageScene::setLinkColors); redraws at once.
  void setLinkColors(std::vector<QColor> colors);

  /// Screen pixels per model length unit at the current zoom.
  double pixelsPerUnit() const;
  /// Fits again if the view still follows the drawing (no zoom or pan since its last fit) and
  /// no gesture is under way: labels that came after the fit (the force arrows' magnitudes,
  /// whose forces land later) are then inside, as Ctrl+0 would have them.
  void refitIfFollowing();
  /// Distance between grid lines (model length units) at the current zoom.
  double gridSpacing() const;
  /// Paints the linkage without the grid into `target` (painter coordinates), y up, aspect
  /// ratio kept, centred: for image and SVG export.
  void renderLinkage(QPainter* painter, const QRectF& target) const;

  /// A region (scene units) to keep on screen beside the drawing, such as a synthesised
  /// candidate's preview; an empty rect clears it. It joins what fitToView() fits, and when it
  /// is not wholly in view the view fits the drawing and the region together.
  void setExtraRegion(const QRectF& region);
  /// The part of the scene the viewport shows (scene units).
  QRectF visibleRegion() const;

  /// What a left click does: drag and pan (None), or pick a point or a pose for the caller.
  enum class PickMode { None, Point, Pose };
  void setPickMode(PickMode mode);
  PickMode pickMode() const { return m_pickMode; }

public slots:
  /// Fits the drawing (every position over the cycle, the pivots, the coupler path, the
  /// crank's range) into the view with a margin.
  void fitToView();
  /// Zooms by `factor` (> 1 in) about the view's centre.
  void zoomBy(double factor);

signals:
  /// The scale changed (a fit or a zoom): pixels per scene unit.
  void pixelsPerUnitChanged(double pixelsPerUnit);
  void editRefused(const QString& reason);
  void statusMessage(const QString& text);
  /// Point mode: the model point clicked (length unit).
  void pointPicked(const QPointF& model);
  /// Pose mode: the model point pressed and the direction dragged from it (rad, CCW from +x;
  /// 0 for a click without a drag).
  void posePicked(const QPointF& model, double angle);

protected:
  void drawBackground(QPainter* painter, const QRectF& rect) override;
  void drawForeground(QPainter* painter, const QRectF& rect) override;
  void wheelEvent(QWheelEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void leaveEvent(QEvent* event) override;
  void showEvent(QShowEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

private:
  enum class Gesture { None, Pan, Drag, Pick };

  void onDocumentChanged(linkwright::ui::Changes what);
  QPointF sceneAt(const QPointF& viewportPos) const;
  std::optional<DragHandle> handleAt(const QPointF& viewportPos) const;
  void zoomAbout(const QPointF& viewportPos, double factor);
  void scrollByPixels(const QPointF& delta);
  void startDrag(const DragHandle& handle, const QPointF& viewportPos);
  void dragTo(const QPointF& viewportPos);
  void refuse(const QString& reason, const QPointF& viewportPos);
  void updateHover(const QPointF& viewportPos);
  void ensureSceneRect(bool force);
  // What a fit shows: the drawing and the extra region; and its size, for the zoom limits.
  QRectF fitBounds() const;
  double labelsFitScale(const QPointF& centre, const QSizeF& area) const;
  double fitSize() const;
  void finishPick(const QPointF& viewportPos);

  // The grid as last painted, in viewport pixels, and what it was painted for: a drag repaints
  // the linkage over it without drawing the grid's lines and labels again.
  struct GridCache {
    QPixmap pixmap;
    QTransform transform;
    QString unit;
    double textScale = 0.0;
  };

  MechanismDocument* m_document;
  LinkageScene* m_scene;
  GridCache m_grid;
  double m_presentationScale = 1.0;
  bool m_readOnly = false;
  QRectF m_extraRegion;  // scene units; null when none
  bool m_autoFit = true;
  Gesture m_gesture = Gesture::None;
  Qt::MouseButton m_gestureButton = Qt::NoButton;
  DragHandle m_dragHandle;
  QPointF m_grabOffset;     // handle minus pointer (scene units), fixed for one drag
  QPointF m_lastPointer;    // viewport pixels, last pan or drag position
  QPointF m_scrollResidue;  // sub-pixel remainder of programmatic scrolling
  int m_dragCount = 0;      // makes each drag its own undo step
  QString m_lastRefusal;
  std::optional<DragHandle> m_hover;
  PickMode m_pickMode = PickMode::None;
  QPointF m_pickStart;  // viewport pixels, where a pick was pressed
};

}  // namespace linkwright::ui
