#pragma once
// Private to widgets/matching: a QOpenGLWidget that drives a vtkGenericOpenGLRenderWindow (the
// approach of VTK's own Qt adapter, checked in /work/shared/VTK-QT6.md; Debian's GUISupportQt is
// built for Qt 5 and cannot be used).
//
// - VTK renders only inside paintGL(), into its own framebuffer, which is then blitted into the
//   widget's framebuffer object; alpha is cleared to 1 afterwards (VTK leaves 0, which shows as
//   black fringes in QWidget::grab and grabFramebuffer).
// - Mouse and wheel events become VTK interactor events for vtkInteractorStyleTrackballCamera
//   (left drag rotate, right drag / wheel zoom, middle drag pan). The interactor never renders
//   itself (EnableRenderOff); its RenderEvent calls update(), so a frame is painted by Qt.
// - Keys are not forwarded: the trackball style's key bindings (stereo, wireframe, pick, exit) do
//   not belong in a measurement view.
//
// Needs an X server (xcb) with OpenGL 3.2 core: QSurfaceFormat::setDefaultFormat must be set
// before the QApplication exists. Construct it only when PointSetView::canRender3D() is true.
#include <QOpenGLWidget>
#include <vector>

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>

class vtkObject;

namespace metrofit {

class VtkGlWidget : public QOpenGLWidget {
  Q_OBJECT
 public:
  explicit VtkGlWidget(QWidget* parent = nullptr);
  ~VtkGlWidget() override;

  vtkGenericOpenGLRenderWindow* renderWindow() const { return window_; }
  vtkGenericRenderWindowInteractor* interactor() const { return interactor_; }

 signals:
  /// The interactor asked for a frame (the user moved the camera): views sharing the camera repaint.
  void interactorRendered();

 protected:
  void initializeGL() override;
  void resizeGL(int w, int h) override;
  void paintGL() override;

  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void enterEvent(QEnterEvent* event) override;
  void leaveEvent(QEvent* event) override;

 private:
  void onWindowEvent(vtkObject* caller, unsigned long eventId, void* callData);
  void onInteractorRender(vtkObject* caller, unsigned long eventId, void* callData);
  /// Passes the position and modifiers of a Qt event to the interactor (VTK's y axis points up).
  void setEventInformation(const QPointF& position, Qt::KeyboardModifiers modifiers, int repeat = 0);
  void releaseVtkGraphics();

  vtkNew<vtkGenericOpenGLRenderWindow> window_;
  vtkNew<vtkGenericRenderWindowInteractor> interactor_;
  vtkNew<vtkInteractorStyleTrackballCamera> style_;
  std::vector<unsigned long> windowObservers_;
  unsigned long renderObserver_ = 0;
  int wheelAccumulator_ = 0;  ///< angleDelta not yet sent as whole notches
  bool glInitialized_ = false;
  bool inPaint_ = false;
};

}  // namespace metrofit
