#pragma once
// The atlas window's cells (kinematics/explore/coupler_atlas.h), computed on a worker thread and
// kept by their key, so a grid asked for again (a filter, a scroll, the same ratios typed back)
// is drawn at once. One request runs at a time: a new one, or the cache's end, cancels the one
// before (its std::atomic<bool>), and a cancelled job's results are never delivered. Each cell
// arrives as it is done, on the GUI thread.

#include "kinematics/explore/coupler_atlas.h"

#include <QFuture>
#include <QFutureWatcher>
#include <QObject>

#include <atomic>
#include <map>
#include <memory>
#include <tuple>
#include <vector>

namespace linkwright::ui {

class AtlasCellCache : public QObject {
  Q_OBJECT
public:
  explicit AtlasCellCache(QObject* parent = nullptr);
  ~AtlasCellCache() override;

  /// Computes, in the background and in this order, those of `keys` not held yet; cancels the
  /// request before. Emits cellReady for each as it is done, then finished.
  void request(const std::vector<kinematics::AtlasCellKey>& keys);
  /// Stops the running request (its cells done so far are kept).
  void cancel();
  /// The cell of `key`, if it has been computed.
  const kinematics::AtlasCell* find(const kinematics::AtlasCellKey& key) const;
  /// True while a request runs.
  bool busy() const { return m_pending != nullptr; }
  /// Cells held.
  std::size_t size() const { return m_cells.size(); }

signals:
  void cellReady(const kinematics::AtlasCell& cell);
  void finished();

private:
  using Key = std::tuple<double, double, double, double, double, double, int, std::size_t>;
  static Key keyOf(const kinematics::AtlasCellKey& key);
  void deliver(int index);
  void retire();  // forgets the running request's watcher, deleting it later

  struct Pending {
    std::shared_ptr<std::atomic<bool>> cancel;
    std::unique_ptr<QFutureWatcher<kinematics::AtlasCell>> watcher;
  };
  std::unique_ptr<Pending> m_pending;
  std::vector<QFuture<kinematics::AtlasCell>> m_cancelled;  // waited for at the end only
  std::map<Key, kinematics::AtlasCell> m_cells;
};

}  // namespace linkwright::ui
