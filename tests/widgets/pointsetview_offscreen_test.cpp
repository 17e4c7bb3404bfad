// PointSetView without X (QT_QPA_PLATFORM=offscreen): no 3D, no OpenGL, a readable message, and
// every call is safe, so offscreen GUI tests of windows containing the view do not crash.
#include <gtest/gtest.h>

#include <QApplication>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <array>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/matching/probe_points.h"
#include "widgets/matching/pointsetview.h"

namespace metrofit {
namespace {

/// Owns the QApplication for the whole run and destroys it before main() returns (a function-local
/// static QApplication is destroyed after Qt's own globals and crashes at exit).
class QtApplicationEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    // This binary tests the view without X, whatever the environment says.
    qputenv("QT_QPA_PLATFORM", "offscreen");
    // As an application would do it: the 3D format is set whatever the platform turns out to be.
    QSurfaceFormat::setDefaultFormat(PointSetView::surfaceFormat());
    if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
      runtime_ = std::make_unique<QTemporaryDir>();  // mode 0700, as Qt wants it
      ASSERT_TRUE(runtime_->isValid());
      qputenv("XDG_RUNTIME_DIR", QFile::encodeName(runtime_->path()));
    }
    app_ = std::make_unique<QApplication>(argc_, argv_);
  }
  void TearDown() override {
    app_.reset();
    runtime_.reset();
  }

 private:
  int argc_ = 1;
  char name_[28] = "pointsetview_offscreen_test";
  char* argv_[2] = {name_, nullptr};
  std::unique_ptr<QTemporaryDir> runtime_;
  std::unique_ptr<QApplication> app_;
};

[[maybe_unused]] ::testing::Environment* const kQtEnvironment =
    ::testing::AddGlobalTestEnvironment(new QtApplicationEnvironment);

ProbePointSet threePoints() {
  ProbePointSet set;
  set.hasNormals = true;
  for (int i = 0; i < 3; ++i) {
    ProbePoint p;
    p.id = "P" + std::to_string(i);
    p.nominal = Eigen::Vector3d(10.0 * i, 0.0, 0.0);
    p.normal = Eigen::Vector3d(0.0, 0.0, 1.0);
    p.measured = p.nominal + Eigen::Vector3d(0.0, 0.0, 0.01 * (i - 1));
    set.points.push_back(p);
  }
  return set;
}

TEST(PointSetViewOffscreenTest, ShowsMessageInsteadOf3D) {
  ASSERT_EQ(QGuiApplication::platformName(), QStringLiteral("offscreen"));
  EXPECT_FALSE(PointSetView::canRender3D());

  PointSetView view;
  view.resize(640, 480);
  view.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));

  for (const QWidget* child : view.findChildren<QWidget*>()) {
    EXPECT_FALSE(child->inherits("QOpenGLWidget"));
  }
  auto* label = view.findChild<QLabel*>();
  ASSERT_NE(label, nullptr);
  EXPECT_TRUE(label->isVisible());
  EXPECT_TRUE(label->text().contains(QStringLiteral("X11 display")));
  EXPECT_TRUE(label->text().contains(QStringLiteral("xvfb-run")));

  // The label is what a screenshot of the window shows.
  const QImage grabbed = view.grab().toImage();
  EXPECT_FALSE(grabbed.isNull());

  EXPECT_TRUE(view.renderImage().isNull());
}

TEST(PointSetViewOffscreenTest, EveryCallIsSafeWithout3D) {
  PointSetView view;
  view.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
  const ProbePointSet set = threePoints();
  view.setPoints(set);
  view.setAfter({{0.0, 0.0, 0.0}, {10.0, 0.0, 0.0}, {20.0, 0.0, 0.0}}, {0.0, 0.001, -0.001});
  view.setExaggeration(50.0);
  view.clearAfter();
  view.resetCamera();
  EXPECT_TRUE(view.renderImage().isNull());
  const std::array<double, 3> origin{0.0, 0.0, 0.0};
  EXPECT_EQ(view.cameraPosition(), origin);
  EXPECT_EQ(view.cameraFocalPoint(), origin);
  // Argument checks do not depend on the platform.
  EXPECT_THROW(view.setAfter({{0.0, 0.0, 0.0}}, {0.0}), std::invalid_argument);
  EXPECT_THROW(view.setExaggeration(-1.0), std::invalid_argument);
}

}  // namespace
}  // namespace metrofit
