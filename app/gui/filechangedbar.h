#pragma once
// A bar above the pages that says the open project file was changed on disk by another program and
// offers to reload it (non-modal: work is never interrupted by a dialog).
#include <QFrame>

class QLabel;

namespace metrofit {

class FileChangedBar : public QFrame {
  Q_OBJECT
 public:
  explicit FileChangedBar(QWidget* parent = nullptr);

  /// Shows the bar for a file; `modified` adds that reloading discards unsaved changes.
  void showFor(const QString& fileName, bool modified);
  QString message() const;

 signals:
  void reloadRequested();

 private:
  QLabel* label_;
};

}  // namespace metrofit
