#include "app/gui/recentfiles.h"

#include <QFileInfo>
#include <QSettings>

namespace metrofit {
namespace {
QString key() {
  return QStringLiteral("recentFiles");
}
}  // namespace

QStringList recentFiles() {
  QSettings settings;
  const QStringList stored = settings.value(key()).toStringList();
  QStringList existing;
  for (const QString& path : stored) {
    if (QFileInfo(path).isFile() && !existing.contains(path)) existing << path;
  }
  while (existing.size() > kMaxRecentFiles) existing.removeLast();
  if (existing != stored) settings.setValue(key(), existing);
  return existing;
}

void addRecentFile(const QString& path) {
  const QString absolute = QFileInfo(path).absoluteFilePath();
  QStringList files = recentFiles();
  files.removeAll(absolute);
  files.prepend(absolute);
  while (files.size() > kMaxRecentFiles) files.removeLast();
  QSettings().setValue(key(), files);
}

void clearRecentFiles() {
  QSettings().remove(key());
}

}  // namespace metrofit
