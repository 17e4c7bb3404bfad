#include "app/gui/manual.h"

#include <QDesktopServices>
#include <QDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QPushButton>
#include <QTextBrowser>
#include <QTextDocument>
#include <QUrl>
#include <QVBoxLayout>

namespace metrofit {

namespace {
const QString kFirstPage = QStringLiteral("README.md");
}  // namespace

QStringList manualCandidates(const QString& appDir) {
  QStringList candidates;
  // The install layout (bin/ and share/doc/metrofit/ under one prefix): a package, /usr/local, a
  // prefix of the user's own.
  candidates << QDir::cleanPath(QDir(appDir).filePath(QStringLiteral(METROFIT_DOC_DIR_FROM_BIN)) +
                                QLatin1Char('/') + kFirstPage);
  candidates << QDir::cleanPath(QStringLiteral(METROFIT_INSTALL_DOC_DIR) + QLatin1Char('/') + kFirstPage);
  candidates << QDir::cleanPath(QStringLiteral(METROFIT_SOURCE_DOC_DIR) + QLatin1Char('/') + kFirstPage);
  candidates.removeDuplicates();
  return candidates;
}

QString findManual(const QString& appDir) {
  for (const QString& path : manualCandidates(appDir))
    if (QFileInfo(path).isFile()) return path;
  return {};
}

ManualWindow::ManualWindow(QWidget* parent) : QWidget(parent, Qt::Window), browser_(new QTextBrowser(this)) {
  setObjectName(QStringLiteral("manualWindow"));
  setWindowTitle(tr("Metrofit manual"));
  browser_->setObjectName(QStringLiteral("manualBrowser"));
  // Links between the documents open here (Markdown is rendered: QTextBrowser reads a ".md" source
  // as Markdown); links to the web in the user's browser.
  browser_->setOpenLinks(false);
  connect(browser_, &QTextBrowser::anchorClicked, this, [this](const QUrl& url) {
    const QUrl target = browser_->source().resolved(url);
    if (target.isLocalFile()) {
      browser_->setSource(target);
    } else {
      QDesktopServices::openUrl(target);
    }
  });

  auto* back = new QPushButton(tr("&Back"), this);
  auto* home = new QPushButton(tr("&Contents"), this);
  back->setEnabled(false);
  connect(back, &QPushButton::clicked, browser_, &QTextBrowser::backward);
  connect(home, &QPushButton::clicked, browser_, &QTextBrowser::home);
  connect(browser_, &QTextBrowser::backwardAvailable, back, &QPushButton::setEnabled);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(back);
  buttons->addWidget(home);
  buttons->addStretch(1);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(buttons);
  layout->addWidget(browser_, 1);
  resize(900, 700);
}

bool ManualWindow::openPage(const QString& path) {
  if (!QFileInfo(path).isFile()) return false;
  browser_->clearHistory();
  const QUrl url = QUrl::fromLocalFile(QFileInfo(path).absoluteFilePath());
  browser_->setSource(url);  // ".md": Markdown, else HTML
  return !browser_->document()->isEmpty();
}

}  // namespace metrofit
