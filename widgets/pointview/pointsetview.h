#pragma once
// 3D view of a probe point set (VTK embedded in a QOpenGLWidget as in ../shared/VTK-QT6.md):
// nominal points, measured points coloured by deviation, optional "after" state, axes, scalar bar;
// mouse: left-drag rotate, right-drag / wheel zoom, middle-drag pan. VTK stays behind the pimpl.
//
// VTK needs an X server (Debian's VTK has no EGL/OSMesa). When the Qt platform is not xcb (for
// example QT_QPA_PLATFORM=offscreen) the view shows a readable message instead of a 3D scene and
// never touches OpenGL, so offscreen GUI tests of windows containing it do not crash.
#include <QWidget>
#include <array>
#include <memory>
#include <vector>

class QImage;
class QSurfaceFormat;

namespace metrofit {
struct ProbePointSet;

class PointSetView : public QWidget {
  Q_OBJECT
 public:
  explicit PointSetView(QWidget* parent = nullptr);
  ~PointSetView() override;

  /// True when this process can show the 3D scene (xcb platform with a display).
  static bool canRender3D();
  /// The OpenGL format the 3D scene needs (OpenGL 3.2 core profile, 24-bit depth). Pass it to
  /// QSurfaceFormat::setDefaultFormat() before the QApplication is constructed.
  static QSurfaceFormat surfaceFormat();

  /// Points before matching: nominal q (grey) and measured p coloured by deviation.
  void setPoints(const ProbePointSet& points);
  /// Optional state after matching: the transformed nominal points and their deviations (mm).
  void setAfter(const std::vector<std::array<double, 3>>& transformedNominal,
                const std::vector<double>& deviationsAfter);
  void clearAfter();
  /// Deviation exaggeration for the drawn displacement vectors (default 100x).
  void setExaggeration(double factor);
  void resetCamera();

  /// Camera position and focal point (for tests and for saving the view).
  std::array<double, 3> cameraPosition() const;
  std::array<double, 3> cameraFocalPoint() const;
  /// Renders the current scene into an image of the widget's size (empty image without 3D).
  QImage renderImage();

 private:
  struct Impl;
  std::unique_ptr<Impl> d;
};

}  // namespace metrofit
