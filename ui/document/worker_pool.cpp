#include "ui/document/worker_pool.h"

#include <QCoreApplication>
#include <QPointer>
#include <QThreadPool>

namespace linkwright::ui {

QThreadPool* workerPool() {
  // Owned by the application, as Qt's global pool is: deleting it waits for the jobs still
  // running, before the application and the objects they read are gone. Called from the GUI
  // thread only.
  static QPointer<QThreadPool> pool;
  if (pool.isNull()) pool = new QThreadPool(QCoreApplication::instance());
  return pool;
}

}  // namespace linkwright::ui
