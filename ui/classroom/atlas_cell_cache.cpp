#include "ui/classroom/atlas_cell_cache.h"

#include "ui/document/worker_pool.h"

#include <QPromise>
#include <QtConcurrent>

namespace linkwright::ui {

namespace k = kinematics;

AtlasCellCache::AtlasCellCache(QObject* parent) : QObject(parent) {}

// A job still running holds only its own copies; it is told to stop and waited for, so no
// thread outlives the cache that started it.
AtlasCellCache::~AtlasCellCache() {
  cancel();
  for (QFuture<k::AtlasCell>& job : m_cancelled) job.waitForFinished();
}

AtlasCellCache::Key AtlasCellCache::keyOf(const k::AtlasCellKey& key) {
  const k::FourBarLengths& l = key.lengths;
  return {l.frame,    l.crank, l.coupler, l.rocker, key.point.along, key.point.across, static_cast<int>(key.branch),
          key.samples};
}

const k::AtlasCell* AtlasCellCache::find(const k::AtlasCellKey& key) const {
  const auto found = m_cells.find(keyOf(key));
  return found == m_cells.end() ? nullptr : &found->second;
}

void AtlasCellCache::cancel() {
  if (!m_pending) return;
  m_pending->cancel->store(true);
  // Its watcher goes with it, so nothing it still finds is delivered; later, as this may run
  // inside the watcher's own signal.
  m_cancelled.push_back(m_pending->watcher->future());
  retire();
  // Jobs that have ended need not be kept.
  std::erase_if(m_cancelled, [](const QFuture<k::AtlasCell>& job) { return job.isFinished(); });
}

void AtlasCellCache::request(const std::vector<k::AtlasCellKey>& keys) {
  cancel();
  std::vector<k::AtlasCellKey> missing;
  for (const k::AtlasCellKey& key : keys)
    if (!find(key)) missing.push_back(key);
  if (missing.empty()) {
    emit finished();
    return;
  }
  auto flag = std::make_shared<std::atomic<bool>>(false);
  auto job = QtConcurrent::run(workerPool(), [missing, flag](QPromise<k::AtlasCell>& promise) {
    for (const k::AtlasCellKey& key : missing) {
      if (flag->load() || promise.isCanceled()) return;
      auto cell = k::computeAtlasCell(key, flag.get());
      if (cell) {
        promise.addResult(std::move(cell).value());
      } else if (cell.error().code != k::ErrorCode::Cancelled) {
        // Lengths a linkage may not have (the axes' bounds keep them out): shown as a cell with
        // no curve rather than one computed for ever.
        k::AtlasCell none;
        none.key = key;
        none.motion = k::CrankMotion::NeverAssembles;
        promise.addResult(std::move(none));
      }
    }
  });
  auto watcher = std::make_unique<QFutureWatcher<k::AtlasCell>>();
  connect(watcher.get(), &QFutureWatcherBase::resultReadyAt, this, &AtlasCellCache::deliver);
  connect(watcher.get(), &QFutureWatcherBase::finished, this, [this] {
    retire();
    emit finished();
  });
  watcher->setFuture(job);
  m_pending = std::make_unique<Pending>(Pending{std::move(flag), std::move(watcher)});
}

void AtlasCellCache::retire() {
  if (!m_pending) return;
  QFutureWatcher<k::AtlasCell>* watcher = m_pending->watcher.release();
  watcher->disconnect(this);
  watcher->setParent(this);  // deleted with the cache if no event loop runs again
  watcher->deleteLater();
  m_pending.reset();
}

void AtlasCellCache::deliver(int index) {
  if (!m_pending) return;
  k::AtlasCell cell = m_pending->watcher->resultAt(index);
  const auto [at, inserted] = m_cells.insert_or_assign(keyOf(cell.key), std::move(cell));
  emit cellReady(at->second);
}

}  // namespace linkwright::ui
