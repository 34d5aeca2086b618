#pragma once
// The whole contents of a file the GUI tests wrote (a save, an export).

#include "tests/support/catch.h"

#include <QByteArray>
#include <QFile>
#include <QString>

namespace linkwright::test {

inline QByteArray readAll(const QString& path) {
  QFile f(path);
  REQUIRE(f.open(QIODevice::ReadOnly));
  return f.readAll();
}

}  // namespace linkwright::test
