#pragma once
// The set-up the page tests share: the bundled demo project extracted to a temporary folder and
// loaded into a ProjectDocument, optionally edited first (editDemo), and page grabs for people to
// look at ($METROFIT_TEST_OUT/<folder>/<name>.png, nothing when the variable is not set).
#include <gtest/gtest.h>

#include <QDir>
#include <QSize>
#include <QString>
#include <QTemporaryDir>
#include <QWidget>

#include "core/project/project.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"

namespace metrofit::test {

class DemoDocumentTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    project_ = extractDemoProject(dir_.path());
    Project p = loadProject(project_.toStdString());
    if (editDemo(p)) {
      project_ = dir_.filePath(QStringLiteral("edited.metrofit"));
      saveProject(p, project_.toStdString());
    }
    document_.load(project_);
  }

  /// Changes the demo project before it is loaded; true: it was changed (saved as edited.metrofit
  /// next to the demo's data and loaded from there).
  virtual bool editDemo(Project& /*project*/) { return false; }

  /// Saves a grab of `page` (resized to `size`) to $METROFIT_TEST_OUT/<folder>/<name>.png.
  static void grab(QWidget& page, const QString& folder, const QString& name, const QSize& size) {
    const QString out = qEnvironmentVariable("METROFIT_TEST_OUT");
    if (out.isEmpty()) return;
    const QString dir = QDir(out).filePath(folder);
    QDir().mkpath(dir);
    page.resize(size);
    page.grab().save(QDir(dir).filePath(name + QStringLiteral(".png")));
  }

  QTemporaryDir dir_;
  QString project_;  ///< the project file loaded
  ProjectDocument document_;
};

}  // namespace metrofit::test
