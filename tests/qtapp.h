#pragma once
// A QApplication for the offscreen GUI and widget tests, created once in a GoogleTest environment (gtest_main
// is linked, so there is no main() of our own). The tests are written for the offscreen platform (no X
// server, the 3D view shows its fallback), so the environment sets it whatever the caller's environment says.
// Settings go to a private temporary folder, so tests never see or change the user's recent files or
// language; XDG_RUNTIME_DIR gets a private folder when it is not set.
#include <gtest/gtest.h>

#include <QApplication>
#include <QFile>
#include <QSettings>
#include <QTemporaryDir>
#include <clocale>
#include <memory>

// Tests that run under xvfb-run and render VTK views define METROFIT_TEST_QT_XVFB before including
// this header: the platform the test executor set (xcb) is kept, and VTK's OpenGL surface format is
// made the default before the QApplication exists (VTK-QT6.md).
#ifdef METROFIT_TEST_QT_XVFB
#include <QSurfaceFormat>

#include "widgets/matching/pointsetview.h"
#endif

namespace metrofit::test {

class QtApplicationEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
#ifdef METROFIT_TEST_QT_XVFB
    QSurfaceFormat::setDefaultFormat(PointSetView::surfaceFormat());
#else
    qputenv("QT_QPA_PLATFORM", "offscreen");
#endif
    settings_ = std::make_unique<QTemporaryDir>();
    ASSERT_TRUE(settings_->isValid());
    if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
      runtime_ = std::make_unique<QTemporaryDir>();  // created with mode 0700
      ASSERT_TRUE(runtime_->isValid());
      qputenv("XDG_RUNTIME_DIR", QFile::encodeName(runtime_->path()));
    }
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings_->path());
    QCoreApplication::setOrganizationName(QStringLiteral("MetrofitTest"));
    QCoreApplication::setApplicationName(QStringLiteral("metrofit-gui-test"));
    app_ = std::make_unique<QApplication>(argc_, argv_);
    // The locale test matrix (tests/CMakeLists.txt, LOCALES): QApplication has just set the C locale
    // from LC_ALL; a locale that is not installed would leave "C" and pass the test unnoticed.
    const QByteArray wanted = qgetenv("LC_ALL");
    if (!wanted.isEmpty() && wanted != "C" && wanted != "POSIX") {
      const char* numeric = std::setlocale(LC_NUMERIC, nullptr);
      ASSERT_TRUE(numeric != nullptr && QByteArray(numeric) == wanted)
          << "LC_ALL=" << wanted.constData() << " but the process runs in " << (numeric ? numeric : "?")
          << ": the locale is not installed (packaging/install-deps.sh generates de_DE.UTF-8 and "
             "pl_PL.UTF-8)";
    }
  }
  void TearDown() override {
    app_.reset();
    settings_.reset();
    runtime_.reset();
  }

 private:
  int argc_ = 1;
  char name_[20] = "metrofit-gui-test";
  char* argv_[2] = {name_, nullptr};
  std::unique_ptr<QTemporaryDir> settings_;
  std::unique_ptr<QTemporaryDir> runtime_;
  std::unique_ptr<QApplication> app_;
};

inline ::testing::Environment* const kQtApplicationEnvironment =
    ::testing::AddGlobalTestEnvironment(new QtApplicationEnvironment);

}  // namespace metrofit::test
