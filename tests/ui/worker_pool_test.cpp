// Linkwright's background jobs run on threads of their own (ui/document/worker_pool.h). Qt 6.4's raster
// engine splits a large fill into segments, runs them on Qt's global thread pool and waits for
// them: with every worker busy, a paint still finishes.
#include "ui/document/worker_pool.h"

#include <QImage>
#include <QPainter>
#include <QSemaphore>
#include <QThreadPool>

#include "tests/support/catch.h"

#include <chrono>
#include <future>

namespace {

// Paints what the raster engine fills in parallel: an antialiased disc hundreds of rows high.
void paintLargeDisc() {
  QImage image(800, 800, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::white);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setPen(Qt::NoPen);
  painter.setBrush(QColor(40, 120, 200, 180));
  painter.drawEllipse(QPointF(400.0, 400.0), 390.0, 390.0);
}

}  // namespace

TEST_CASE("a paint finishes while every worker thread is busy", "[ui][worker]") {
  QThreadPool* workers = linkwright::ui::workerPool();
  REQUIRE(workers == linkwright::ui::workerPool());  // one pool for every job
  CHECK(workers != QThreadPool::globalInstance());

  // Every worker held, as by sweeps still running.
  QSemaphore started, release;
  const int busy = workers->maxThreadCount();
  for (int i = 0; i < busy; ++i)
    workers->start([&] {
      started.release();
      release.acquire();
    });
  REQUIRE(started.tryAcquire(busy, 10000));

  // Painted off the GUI thread, so that a paint held up fails the test instead of hanging it.
  auto painted = std::async(std::launch::async, paintLargeDisc);
  const bool finished = painted.wait_for(std::chrono::seconds(20)) == std::future_status::ready;
  release.release(busy);
  workers->waitForDone();
  CHECK(finished);
}
