#pragma once

class QThreadPool;

namespace linkwright::ui {

// The threads that run Linkwright's own background work: sweeps, force cycles, quality
// estimates and path searches.
//
// They are kept out of QThreadPool::globalInstance() on purpose. Qt's raster engine (Qt 6.4)
// splits a large fill into segments, runs them on the global pool and blocks the painting
// thread until all are done. Had our jobs taken the global pool's threads, a repaint of the
// window would wait behind a sweep that is still running.
QThreadPool* workerPool();  // GUI thread only

}  // namespace linkwright::ui
