#pragma once
// View ▸ Cognates… (issue 46): the designer's four-bar and its two Roberts–Chebyshev cognates
// (kinematics/explore/cognates.h) drawn together on the coupler curve they share, moving with
// the designer's crank (its slider, Play, a drag) or with this window's Play, which turns the
// designer's crank; their figures side by side (Grashof class, worst transmission angle, how
// each crank must turn to move with the others); and Keep cognate 1 / 2, which make that
// cognate the design (one undoable edit). It follows the document: a new design rebuilds it, and
// a linkage with no cognates leaves it saying why, with nothing drawn from before. Not modal.

#include "kinematics/explore/cognates.h"

#include <QTimer>
#include <QWidget>

#include <array>
#include <optional>

class QLabel;
class QPushButton;

namespace linkwright::ui {

class CognatesView;
class MechanismDocument;

class CognatesWindow : public QWidget {
  Q_OBJECT
public:
  explicit CognatesWindow(MechanismDocument* document, QWidget* parent = nullptr);

  CognatesView* view() const { return m_view; }
  /// The figures of the three, or why there are no cognates.
  QString figuresText() const;
  QPushButton* keepButton(int cognate) const { return m_keep[static_cast<std::size_t>(cognate)]; }
  QPushButton* playButton() const { return m_play; }
  /// The cognates of the design now, if it has them.
  const std::optional<kinematics::CognateSet>& cognates() const { return m_set; }

  /// Steps the designer's crank by this much per frame of Play (rad).
  static constexpr double kStep = 0.04;

public slots:
  void togglePlay();

protected:
  void hideEvent(QHideEvent* event) override;

private:
  void rebuild();
  void followPose();
  void keep(int cognate);

  MechanismDocument* m_document;
  CognatesView* m_view;
  QLabel* m_figures;
  std::array<QPushButton*, 2> m_keep{};
  QPushButton* m_play;
  QTimer m_timer;
  std::optional<kinematics::CognateSet> m_set;
};

}  // namespace linkwright::ui
