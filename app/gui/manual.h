#pragma once
// Help › Manual (F1): the documentation installed with the program (docs/README.md, its index, and
// the documents it links, in share/doc/metrofit), shown in a window of its own that renders the
// Markdown and follows the links between the documents; links to the web open in the browser. A
// program run from its build folder shows the documents of the source tree instead.
#include <QString>
#include <QStringList>
#include <QWidget>

class QTextBrowser;

namespace metrofit {

/// Where the manual's first page is looked for, in this order: the documentation folder next to the
/// program (`appDir`/../share/doc/metrofit, the layout of every install), the configured install
/// folder, then the source tree's docs folder (a build folder).
QStringList manualCandidates(const QString& appDir);
/// The first candidate that exists; empty when there is none.
QString findManual(const QString& appDir);

/// A window showing the manual: one per main window, raised again by F1.
class ManualWindow : public QWidget {
  Q_OBJECT
 public:
  explicit ManualWindow(QWidget* parent = nullptr);
  /// Shows the page `path` (a Markdown or HTML file); false when it cannot be read.
  bool openPage(const QString& path);
  QTextBrowser* browser() const { return browser_; }

 private:
  QTextBrowser* browser_;
};

}  // namespace metrofit
