#pragma once
// The list of recently opened projects, most recent first, kept in QSettings ("recentFiles").
#include <QString>
#include <QStringList>

namespace metrofit {

inline constexpr int kMaxRecentFiles = 8;

/// The recent files that still exist (files that are gone are dropped from the stored list).
QStringList recentFiles();
/// Puts a file at the top of the list (at most kMaxRecentFiles are kept).
void addRecentFile(const QString& path);
void clearRecentFiles();

}  // namespace metrofit
