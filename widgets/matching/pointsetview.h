#pragma once
// 3D view of a probe point set (VTK embedded in a QOpenGLWidget as in ../shared/VTK-QT6.md):
// nominal points, measured points coloured by deviation, optional "after" state, axes, scalar bar;
// mouse: left-drag rotate, right-drag / wheel zoom, middle-drag pan. VTK stays behind the pimpl.
//
// Two views side by side show before and after matching: one in Display::Before, one in
// Display::After, with linkCamera() so that both show the workpiece from the same side; with a
// tolerance (setTolerance) the colour map gets a green tolerance band and out-of-tolerance points
// are drawn larger.
//
// VTK needs an X server (Debian's VTK has no EGL/OSMesa). When the Qt platform is not xcb (for
// example QT_QPA_PLATFORM=offscreen) the view shows a readable message instead of a 3D scene and
// never touches OpenGL, so offscreen GUI tests of windows containing it do not crash.
#include <QWidget>
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

class QImage;
class QSurfaceFormat;

namespace metrofit {
struct ProbePointSet;

class PointSetView : public QWidget {
  Q_OBJECT
 public:
  /// What the view draws once an after state is set (before that, always the before state).
  enum class Display {
    Combined,  ///< before faded, after solid (the default)
    Before,    ///< only the before state: nominal points and measured deviations
    After,     ///< only the after state: transformed nominal points and the deviations after matching
  };

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
  bool hasAfter() const;
  /// A part surface drawn with the points (a CAD nominal): triangles in the scene's coordinates, each
  /// coloured by its deviation (mm; NaN: not measured there, light grey), half transparent.
  void setSurface(const std::vector<std::array<std::array<double, 3>, 3>>& triangles,
                  const std::vector<double>& triangleDeviations);
  void clearSurface();
  std::size_t surfaceTriangles() const;
  void setDisplay(Display display);
  Display display() const;
  /// Deviation exaggeration for the drawn displacement vectors (default 100x).
  void setExaggeration(double factor);
  double exaggeration() const;
  /// Symmetric tolerance (mm): > 0 adds the tolerance band (green within +-tol) to the colour map
  /// and draws out-of-tolerance points larger; 0 (the default) shows the plain diverging map.
  void setTolerance(double toleranceMm);
  /// Colour range [-r, r] in mm; 0 (the default): automatic from the deviations shown.
  void setColourRange(double rangeMm);
  /// The colour range in use (mm).
  double colourRange() const;
  /// A title drawn at the top of the scene (e.g. "Before matching: 40 of 40 out of tolerance").
  void setTitle(const QString& title);
  void resetCamera();
  /// Shares `other`'s camera: rotating, zooming or panning either view moves both.
  void linkCamera(PointSetView* other);

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
