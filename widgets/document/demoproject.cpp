#include "widgets/document/demoproject.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

#include "core/common/error.h"

namespace metrofit {
namespace {

[[noreturn]] void fail(const QString& file, const QString& what) {
  throw FileError(ErrorContext{file.toStdString(), 0, 0, {}}, what.toStdString());
}

void copyResource(const QString& resource, const QString& target) {
  QFile in(resource);
  if (!in.open(QIODevice::ReadOnly)) fail(resource, QStringLiteral("bundled demo file is missing"));
  const QByteArray content = in.readAll();
  // QSaveFile: atomic, and the copy gets normal permissions (QFile::copy would keep the resource's
  // read-only mode).
  QSaveFile out(target);
  if (!out.open(QIODevice::WriteOnly)) fail(target, QStringLiteral("cannot write: ") + out.errorString());
  if (out.write(content) != content.size()) {
    out.cancelWriting();
    fail(target, QStringLiteral("cannot write: ") + out.errorString());
  }
  if (!out.commit()) fail(target, QStringLiteral("cannot write: ") + out.errorString());
}

void makeFolder(const QString& path) {
  if (QFileInfo(path).isDir()) return;
  if (!QDir().mkpath(path)) fail(path, QStringLiteral("cannot create the folder"));
}

}  // namespace

QString extractDemoProject(const QString& dir) {
  const QString root = QDir(dir).absolutePath();
  const QString dataDir = root + QStringLiteral("/data");
  makeFolder(root);
  makeFolder(dataDir);
  const QDir data(QStringLiteral(":/demo/data"));
  const QStringList files = data.entryList(QDir::Files, QDir::Name);
  if (files.isEmpty()) fail(QStringLiteral(":/demo/data"), QStringLiteral("bundled demo data are missing"));
  for (const QString& name : files) copyResource(data.filePath(name), dataDir + QLatin1Char('/') + name);
  const QString project =
      root + QLatin1Char('/') + QFileInfo(QString::fromLatin1(kDemoProjectResource)).fileName();
  copyResource(QString::fromLatin1(kDemoProjectResource), project);
  return project;
}

namespace {
/// True when `dir` has no demo project file, or one equal to the bundled file.
bool demoFolderUnchanged(const QString& dir) {
  const QString name = QFileInfo(QString::fromLatin1(kDemoProjectResource)).fileName();
  QFile copy(QDir(dir).filePath(name));
  if (!copy.exists()) return true;
  QFile bundled(QString::fromLatin1(kDemoProjectResource));
  if (!copy.open(QIODevice::ReadOnly) || !bundled.open(QIODevice::ReadOnly)) return false;
  return copy.readAll() == bundled.readAll();
}
}  // namespace

QString demoFolderFor(const QString& base) {
  constexpr int kMaxCopies = 1000;
  if (demoFolderUnchanged(base)) return base;
  for (int n = 2; n < kMaxCopies; ++n) {
    const QString candidate = base + QStringLiteral("-%1").arg(n);
    if (demoFolderUnchanged(candidate)) return candidate;
  }
  return base + QStringLiteral("-%1").arg(kMaxCopies);
}

}  // namespace metrofit
