// PointSetView under X (xvfb-run, QT_QPA_PLATFORM=xcb): the rendered scene shows the deviation
// colours and the background, the mouse rotates and zooms the camera, setAfter changes the picture
// and resetCamera restores the initial camera. The rendered picture of the first test is saved as
// $METROFIT_TEST_OUT/pointsetview_block.png.
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QMouseEvent>
#include <QSet>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <QWheelEvent>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <vector>

#define METROFIT_TEST_QT_XVFB
#include "core/matching/probe_points.h"
#include "qtapp.h"
#include "widgets/matching/pointsetview.h"

namespace metrofit {
namespace {

using Vec3 = Eigen::Vector3d;

constexpr double kMaxDeviation = 0.05;  // mm

/// 200 points on the six faces of the block [0,100] x [0,60] x [0,40] (mm) with outward normals.
/// Deviation along the normal of point i: 0.05 * cos(2 pi i / 20), so exactly +-0.05 occur; the
/// measured points also carry a 0.02 mm tangential offset that is not a deviation.
ProbePointSet blockPoints() {
  struct Face {
    Vec3 origin, u, v, normal;
    int nu, nv;
  };
  const Face faces[] = {{{0, 0, 40}, {100, 0, 0}, {0, 60, 0}, {0, 0, 1}, 8, 5},   // top
                        {{0, 0, 0}, {100, 0, 0}, {0, 60, 0}, {0, 0, -1}, 8, 5},   // bottom
                        {{0, 0, 0}, {100, 0, 0}, {0, 0, 40}, {0, -1, 0}, 8, 4},   // front (y = 0)
                        {{0, 60, 0}, {100, 0, 0}, {0, 0, 40}, {0, 1, 0}, 8, 4},   // back
                        {{0, 0, 0}, {0, 60, 0}, {0, 0, 40}, {-1, 0, 0}, 7, 4},    // left (x = 0)
                        {{100, 0, 0}, {0, 60, 0}, {0, 0, 40}, {1, 0, 0}, 7, 4}};  // right
  ProbePointSet set;
  set.source = "synthetic block";
  set.hasNormals = true;
  for (const Face& f : faces) {
    for (int a = 0; a < f.nu; ++a) {
      for (int b = 0; b < f.nv; ++b) {
        const std::size_t i = set.points.size();
        ProbePoint p;
        p.id = "P" + std::to_string(i);
        p.surface = "face";
        p.nominal = f.origin + (a + 0.5) / f.nu * f.u + (b + 0.5) / f.nv * f.v;
        p.normal = f.normal;
        const double deviation =
            kMaxDeviation * std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / 20.0);
        p.measured = p.nominal + deviation * p.normal + 0.02 * f.u.normalized();
        set.points.push_back(p);
      }
    }
  }
  return set;
}

struct Rgb {
  int r, g, b;
};

bool near(QRgb pixel, Rgb colour, int tolerance) {
  return std::abs(qRed(pixel) - colour.r) <= tolerance && std::abs(qGreen(pixel) - colour.g) <= tolerance &&
         std::abs(qBlue(pixel) - colour.b) <= tolerance;
}

/// Pixels within `tolerance` (per channel) of `colour` inside `area`.
int countNear(const QImage& image, Rgb colour, int tolerance, const QRect& area) {
  int count = 0;
  const QRect r = area.intersected(image.rect());
  for (int y = r.top(); y <= r.bottom(); ++y) {
    for (int x = r.left(); x <= r.right(); ++x) {
      count += near(image.pixel(x, y), colour, tolerance) ? 1 : 0;
    }
  }
  return count;
}

int countDifferent(const QImage& a, const QImage& b) {
  EXPECT_EQ(a.size(), b.size());
  if (a.size() != b.size()) {
    return -1;
  }
  int count = 0;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      count +=
          near(a.pixel(x, y), {qRed(b.pixel(x, y)), qGreen(b.pixel(x, y)), qBlue(b.pixel(x, y))}, 8) ? 0 : 1;
    }
  }
  return count;
}

double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// End colours of the view's diverging map (Moreland's cool-warm) and its background.
constexpr Rgb kRedEnd{180, 4, 38};
constexpr Rgb kBlueEnd{59, 76, 192};
constexpr Rgb kWhite{255, 255, 255};
constexpr int kColourTolerance = 30;

class PointSetViewTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(PointSetView::canRender3D()) << "run under xvfb-run with QT_QPA_PLATFORM=xcb";
    view = std::make_unique<PointSetView>();
    view->resize(800, 600);
    view->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(view.get()));
    // The GL widget is private to the view: find it by its class (no OpenGLWidgets link needed).
    for (QWidget* child : view->findChildren<QWidget*>()) {
      if (child->inherits("QOpenGLWidget")) {
        gl = child;
      }
    }
    ASSERT_NE(gl, nullptr);
    points = blockPoints();
    view->setPoints(points);
  }

  void TearDown() override { view.reset(); }

  QImage render() {
    QCoreApplication::processEvents();
    return view->renderImage();
  }

  void sendMouse(QEvent::Type type, Qt::MouseButton button, QPoint at, Qt::MouseButtons held) {
    QMouseEvent event(type, QPointF(at), QPointF(gl->mapToGlobal(at)), button, held, Qt::NoModifier);
    QCoreApplication::sendEvent(gl, &event);
  }

  void drag(Qt::MouseButton button, QPoint from, QPoint to) {
    sendMouse(QEvent::MouseButtonPress, button, from, button);
    constexpr int kSteps = 5;
    for (int s = 1; s <= kSteps; ++s) {
      sendMouse(QEvent::MouseMove, Qt::NoButton, from + (to - from) * s / kSteps, button);
    }
    sendMouse(QEvent::MouseButtonRelease, button, to, Qt::NoButton);
    QCoreApplication::processEvents();
  }

  void wheel(int angleDelta) {
    const QPoint at = gl->rect().center();
    QWheelEvent event(QPointF(at), QPointF(gl->mapToGlobal(at)), QPoint(), QPoint(0, angleDelta),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(gl, &event);
    QCoreApplication::processEvents();
  }

  double cameraDistance() const { return distance(view->cameraPosition(), view->cameraFocalPoint()); }

  ProbePointSet points;
  std::unique_ptr<PointSetView> view;
  QWidget* gl = nullptr;
};

TEST_F(PointSetViewTest, SyntheticBlockShowsDeviationColoursOnLightBackground) {
  // The colours below rely on the deviations of the synthetic set spanning exactly [-0.05, 0.05].
  const std::vector<double> dev = points.deviations();
  ASSERT_EQ(dev.size(), 200u);
  EXPECT_NEAR(*std::max_element(dev.begin(), dev.end()), kMaxDeviation, 1e-12);
  EXPECT_NEAR(*std::min_element(dev.begin(), dev.end()), -kMaxDeviation, 1e-12);

  const QImage image = render();
  ASSERT_FALSE(image.isNull());
  const qreal dpr = gl->devicePixelRatioF();
  EXPECT_EQ(image.size(), gl->size() * dpr);

  const QString outDir = qEnvironmentVariable("METROFIT_TEST_OUT", QDir::tempPath());
  QDir().mkpath(outDir);
  EXPECT_TRUE(image.save(QDir(outDir).filePath("pointsetview_block.png")));

  const int w = image.width(), h = image.height();
  // Scene area: left of the scalar bar (x >= 0.86 w) and without the axes marker in the lower
  // left corner (its X and Z axes are red and blue as well).
  const QRect upperScene(0, 0, static_cast<int>(0.84 * w), static_cast<int>(0.76 * h));
  const QRect lowerScene(static_cast<int>(0.20 * w), static_cast<int>(0.76 * h), static_cast<int>(0.64 * w),
                         h - static_cast<int>(0.76 * h));
  const QRect scalarBar(static_cast<int>(0.86 * w), 0, w - static_cast<int>(0.86 * w), h);

  const int redInScene = countNear(image, kRedEnd, kColourTolerance, upperScene) +
                         countNear(image, kRedEnd, kColourTolerance, lowerScene);
  const int blueInScene = countNear(image, kBlueEnd, kColourTolerance, upperScene) +
                          countNear(image, kBlueEnd, kColourTolerance, lowerScene);
  // 20 points have |deviation| = 0.05 and more lie within the tolerance: each sphere is ~60 px.
  EXPECT_GE(redInScene, 100);
  EXPECT_GE(blueInScene, 100);
  EXPECT_GE(countNear(image, kRedEnd, kColourTolerance, scalarBar), 50);
  EXPECT_GE(countNear(image, kBlueEnd, kColourTolerance, scalarBar), 50);

  // Light background: most of the picture, and the top right corner in particular.
  EXPECT_TRUE(near(image.pixel(w - 3, 2), kWhite, 4));
  EXPECT_GT(countNear(image, kWhite, 4, image.rect()), w * h / 2);
  // Not uniform, and not just background and two colours.
  QSet<QRgb> distinct;
  for (int y = 0; y < h; y += 2) {
    for (int x = 0; x < w; x += 2) {
      distinct.insert(image.pixel(x, y));
    }
  }
  EXPECT_GT(distinct.size(), 50);

  // Grey nominal points and dark text/lines are there too.
  EXPECT_GE(countNear(image, {128, 128, 128}, 20, upperScene), 50);
  EXPECT_GE(countNear(image, {26, 26, 26}, 30, image.rect()), 50);
}

TEST_F(PointSetViewTest, MouseRotatesAndZoomsTheCamera) {
  render();
  const auto position0 = view->cameraPosition();
  const auto focal0 = view->cameraFocalPoint();
  const double distance0 = cameraDistance();
  ASSERT_GT(distance0, 100.0);  // the block is ~120 mm across

  // Left drag: trackball rotation about the focal point.
  drag(Qt::LeftButton, {300, 300}, {420, 260});
  const auto position1 = view->cameraPosition();
  EXPECT_GT(distance(position1, position0), 0.1 * distance0);
  EXPECT_LT(distance(view->cameraFocalPoint(), focal0), 1e-6 * distance0);
  EXPECT_NEAR(cameraDistance(), distance0, 1e-6 * distance0);

  // Wheel forward zooms in, backward zooms out; the focal point stays.
  wheel(120);
  const double distanceIn = cameraDistance();
  EXPECT_LT(distanceIn, 0.95 * distance0);
  wheel(-240);
  EXPECT_GT(cameraDistance(), 1.05 * distanceIn);
  EXPECT_LT(distance(view->cameraFocalPoint(), focal0), 1e-6 * distance0);

  // Right drag upwards zooms in too.
  const double beforeRight = cameraDistance();
  drag(Qt::RightButton, {400, 350}, {400, 250});
  EXPECT_LT(cameraDistance(), 0.95 * beforeRight);

  // Middle drag pans: focal point and position move together.
  const auto focalBeforePan = view->cameraFocalPoint();
  const double beforePan = cameraDistance();
  drag(Qt::MiddleButton, {400, 300}, {300, 300});
  EXPECT_GT(distance(view->cameraFocalPoint(), focalBeforePan), 1.0);
  EXPECT_NEAR(cameraDistance(), beforePan, 1e-6 * beforePan);

  // The picture follows the camera.
  const QImage moved = render();
  view->resetCamera();
  EXPECT_GT(countDifferent(moved, render()), 1000);
}

TEST_F(PointSetViewTest, AfterStateChangesImageAndResetCameraRestoresView) {
  const QImage before = render();
  const auto position0 = view->cameraPosition();
  const auto focal0 = view->cameraFocalPoint();

  // After matching: nominal shifted by 0.01 mm along x, deviations a tenth of before.
  std::vector<std::array<double, 3>> transformed;
  std::vector<double> devAfter;
  const std::vector<double> dev = points.deviations();
  for (std::size_t i = 0; i < points.points.size(); ++i) {
    const Vec3& q = points.points[i].nominal;
    transformed.push_back({q.x() + 0.01, q.y(), q.z()});
    devAfter.push_back(0.1 * dev[i]);
  }
  view->setAfter(transformed, devAfter);
  const QImage after = render();
  EXPECT_GT(countDifferent(before, after), 500);
  const QString outDir = qEnvironmentVariable("METROFIT_TEST_OUT", QDir::tempPath());
  QDir().mkpath(outDir);
  EXPECT_TRUE(after.save(QDir(outDir).filePath("pointsetview_block_after.png")));
  // The red end of the map is gone from the scene at full strength once the "before" fades.
  const QRect scene(0, 0, static_cast<int>(0.84 * after.width()), static_cast<int>(0.76 * after.height()));
  EXPECT_LT(countNear(after, kRedEnd, kColourTolerance, scene),
            countNear(before, kRedEnd, kColourTolerance, scene) / 4);
  // setAfter does not move the camera.
  EXPECT_LT(distance(view->cameraPosition(), position0), 1e-9);

  // Wrong sizes are rejected.
  EXPECT_THROW(view->setAfter({{0.0, 0.0, 0.0}}, {0.0}), std::invalid_argument);

  view->clearAfter();
  EXPECT_LE(countDifferent(before, render()), 20);

  // Exaggeration changes the drawn displacements.
  view->setExaggeration(300.0);
  EXPECT_GT(countDifferent(before, render()), 500);
  EXPECT_THROW(view->setExaggeration(0.0), std::invalid_argument);
  view->setExaggeration(100.0);

  drag(Qt::LeftButton, {250, 250}, {500, 380});
  wheel(240);
  ASSERT_GT(distance(view->cameraPosition(), position0), 1.0);
  view->resetCamera();
  const double d0 = distance(position0, focal0);
  EXPECT_LT(distance(view->cameraPosition(), position0), 1e-6 * d0);
  EXPECT_LT(distance(view->cameraFocalPoint(), focal0), 1e-6 * d0);
  EXPECT_LE(countDifferent(before, render()), 20);
}

// The report renders the view into an image without showing it on screen.
TEST(PointSetViewHiddenTest, RendersWithoutBeingShown) {
  ASSERT_TRUE(PointSetView::canRender3D());
  PointSetView view;
  view.resize(640, 480);
  view.setPoints(blockPoints());
  const QImage image = view.renderImage();
  ASSERT_FALSE(image.isNull());
  EXPECT_EQ(image.size(), QSize(640, 480));
  const QString outDir = qEnvironmentVariable("METROFIT_TEST_OUT", QDir::tempPath());
  QDir().mkpath(outDir);
  EXPECT_TRUE(image.save(QDir(outDir).filePath("pointsetview_hidden.png")));
  EXPECT_GE(countNear(image, kRedEnd, kColourTolerance, image.rect()), 100);
  EXPECT_GE(countNear(image, kBlueEnd, kColourTolerance, image.rect()), 100);
  EXPECT_GT(countNear(image, kWhite, 4, image.rect()), image.width() * image.height() / 2);
}

// A view that never rendered is destroyed cleanly; so is one destroyed right after its first frame.
TEST(PointSetViewHiddenTest, DestroysCleanly) {
  { PointSetView neverShown; }
  {
    PointSetView view;
    view.setPoints(blockPoints());
    view.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
    EXPECT_FALSE(view.renderImage().isNull());
  }
}

// Moving the view to another top-level window (a floating dock) gives it a new GL context.
TEST(PointSetViewHiddenTest, RendersAfterMovingToAnotherWindow) {
  QWidget first;
  QWidget second;
  auto* view = new PointSetView(&first);
  view->resize(400, 300);
  view->setPoints(blockPoints());
  first.resize(400, 300);
  first.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&first));
  ASSERT_FALSE(view->renderImage().isNull());

  view->setParent(&second);
  view->show();
  second.resize(400, 300);
  second.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&second));
  const QImage image = view->renderImage();
  ASSERT_FALSE(image.isNull());
  EXPECT_GE(countNear(image, kRedEnd, kColourTolerance, image.rect()), 50);
  EXPECT_GE(countNear(image, kBlueEnd, kColourTolerance, image.rect()), 50);
}

}  // namespace
}  // namespace metrofit
