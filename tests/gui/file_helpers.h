#pragma once
// Small file helpers shared by the GUI tests that work on project and side files on disk.
#include <gtest/gtest.h>

#include <QDateTime>
#include <QFile>
#include <QString>
#include <string>

namespace metrofit::test {

/// The whole file, or "" when it cannot be read.
inline std::string readAll(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return {};
  return f.readAll().toStdString();
}

/// Sets a file's modification time (recovery compares the side file's time with the project's).
inline void setModified(const QString& path, const QDateTime& when) {
  QFile f(path);
  ASSERT_TRUE(f.open(QIODevice::ReadWrite)) << path.toStdString();
  ASSERT_TRUE(f.setFileTime(when, QFileDevice::FileModificationTime));
}

}  // namespace metrofit::test
