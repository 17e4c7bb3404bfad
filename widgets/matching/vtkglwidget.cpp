#include "widgets/matching/vtkglwidget.h"

#include <QEnterEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QScopedValueRollback>
#include <QWheelEvent>
#include <cmath>

#include <vtkCommand.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLState.h>

namespace metrofit {

namespace {

/// One notch of a classic mouse wheel in QWheelEvent::angleDelta() units (1/8 degree).
constexpr int kWheelNotch = 120;

unsigned long pressEventFor(Qt::MouseButton button) {
  switch (button) {
    case Qt::LeftButton:
      return vtkCommand::LeftButtonPressEvent;
    case Qt::RightButton:
      return vtkCommand::RightButtonPressEvent;
    case Qt::MiddleButton:
      return vtkCommand::MiddleButtonPressEvent;
    default:
      return vtkCommand::NoEvent;
  }
}

unsigned long releaseEventFor(Qt::MouseButton button) {
  switch (button) {
    case Qt::LeftButton:
      return vtkCommand::LeftButtonReleaseEvent;
    case Qt::RightButton:
      return vtkCommand::RightButtonReleaseEvent;
    case Qt::MiddleButton:
      return vtkCommand::MiddleButtonReleaseEvent;
    default:
      return vtkCommand::NoEvent;
  }
}

}  // namespace

VtkGlWidget::VtkGlWidget(QWidget* parent) : QOpenGLWidget(parent) {
  // VTK renders into its own framebuffer; paintGL blits it into Qt's. No rendering before Qt has
  // created and made current the context (initializeGL).
  window_->SetReadyForRendering(false);
  window_->SetFrameBlitModeToNoBlit();
  window_->SetMultiSamples(0);
  window_->SetForceMaximumHardwareLineWidth(1);
  for (const unsigned long event :
       {vtkCommand::WindowMakeCurrentEvent, vtkCommand::WindowIsCurrentEvent, vtkCommand::WindowFrameEvent}) {
    windowObservers_.push_back(window_->AddObserver(event, this, &VtkGlWidget::onWindowEvent));
  }

  interactor_->SetRenderWindow(window_);
  interactor_->SetInteractorStyle(style_);
  interactor_->EnableRenderOff();
  renderObserver_ = interactor_->AddObserver(vtkCommand::RenderEvent, this, &VtkGlWidget::onInteractorRender);
  interactor_->Initialize();
}

VtkGlWidget::~VtkGlWidget() {
  // The base class destroys the context after this body: do not let its aboutToBeDestroyed signal
  // reach a half-destroyed object.
  if (QOpenGLContext* ctx = context()) {
    disconnect(ctx, nullptr, this, nullptr);
  }
  releaseVtkGraphics();
  interactor_->RemoveObserver(renderObserver_);
  for (const unsigned long id : windowObservers_) {
    window_->RemoveObserver(id);
  }
}

void VtkGlWidget::releaseVtkGraphics() {
  if (!glInitialized_) {
    return;
  }
  makeCurrent();
  window_->Finalize();
  window_->SetReadyForRendering(false);
  doneCurrent();
  glInitialized_ = false;
}

void VtkGlWidget::initializeGL() {
  window_->SetOwnContext(0);
  window_->SetReadyForRendering(true);
  window_->InitializeFromCurrentContext();
  // A new top-level window (reparenting) brings a new context: VTK's resources of the old one must
  // be released while it still exists.
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &VtkGlWidget::releaseVtkGraphics,
          Qt::DirectConnection);
  glInitialized_ = true;
}

void VtkGlWidget::resizeGL(int w, int h) {
  const double dpr = devicePixelRatioF();
  interactor_->UpdateSize(static_cast<int>(std::lround(w * dpr)), static_cast<int>(std::lround(h * dpr)));
}

void VtkGlWidget::paintGL() {
  if (!glInitialized_) {
    return;
  }
  QScopedValueRollback<bool> paintGuard(inPaint_, true);

  // Qt has changed the GL state behind VTK's cache: re-read it, render, restore Qt's state.
  vtkOpenGLState* state = window_->GetState();
  state->Reset();
  state->Push();
  state->vtkglDepthFunc(GL_LEQUAL);  // Qt leaves GL_LESS; VTK expects GL_LEQUAL
  window_->Render();
  state->Pop();

  if (QOpenGLContext::currentContext() != context()) {
    makeCurrent();
  }
  QOpenGLExtraFunctions* f = context()->extraFunctions();

  // VTK 9.1 has no SetDefaultFramebuffer: blit VTK's display framebuffer into the widget's FBO.
  f->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
  const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
  f->glDrawBuffers(1, &drawBuffer);
  const bool scissor = f->glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE;
  if (scissor) {
    state->vtkglDisable(GL_SCISSOR_TEST);
    f->glDisable(GL_SCISSOR_TEST);  // the scissor box clips glBlitFramebuffer
  }
  const double dpr = devicePixelRatioF();
  const int targetW = static_cast<int>(std::lround(width() * dpr));
  const int targetH = static_cast<int>(std::lround(height() * dpr));
  int* sourceSize = window_->GetRenderFramebuffer()->GetLastSize();
  window_->BlitDisplayFramebuffer(0, 0, 0, sourceSize[0], sourceSize[1], 0, 0, targetW, targetH,
                                  GL_COLOR_BUFFER_BIT, GL_LINEAR);

  // VTK leaves alpha at 0; force it to 1 or grabs show black fringes and the compositor blends.
  GLboolean colorMask[4];
  f->glGetBooleanv(GL_COLOR_WRITEMASK, colorMask);
  GLfloat clearColor[4];
  f->glGetFloatv(GL_COLOR_CLEAR_VALUE, clearColor);
  GLint viewport[4];
  f->glGetIntegerv(GL_VIEWPORT, viewport);
  f->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  f->glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  f->glViewport(0, 0, targetW, targetH);
  f->glClear(GL_COLOR_BUFFER_BIT);
  f->glColorMask(colorMask[0], colorMask[1], colorMask[2], colorMask[3]);
  f->glClearColor(clearColor[0], clearColor[1], clearColor[2], clearColor[3]);
  f->glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);

  if (scissor) {
    state->vtkglEnable(GL_SCISSOR_TEST);
    f->glEnable(GL_SCISSOR_TEST);
  }
}

void VtkGlWidget::onWindowEvent(vtkObject* /*caller*/, unsigned long eventId, void* callData) {
  switch (eventId) {
    case vtkCommand::WindowMakeCurrentEvent: {
      // Never QOpenGLWidget::makeCurrent() here: it rebinds Qt's FBO while VTK sets up its own
      // (incomplete framebuffer, black frame).
      QOpenGLContext* ctx = context();
      if (ctx && QOpenGLContext::currentContext() != ctx) {
        ctx->makeCurrent(ctx->surface());
      }
      break;
    }
    case vtkCommand::WindowIsCurrentEvent: {
      bool* isCurrent = static_cast<bool*>(callData);
      *isCurrent = context() != nullptr && QOpenGLContext::currentContext() == context();
      break;
    }
    case vtkCommand::WindowFrameEvent:
      // A render started outside paintGL (by code calling Render() directly): show it.
      if (!inPaint_) {
        update();
      }
      break;
    default:
      break;
  }
}

void VtkGlWidget::onInteractorRender(vtkObject* /*caller*/, unsigned long /*eventId*/, void* /*callData*/) {
  update();
  emit interactorRendered();
}

void VtkGlWidget::setEventInformation(const QPointF& position, Qt::KeyboardModifiers modifiers, int repeat) {
  const double dpr = devicePixelRatioF();
  interactor_->SetEventInformationFlipY(
      static_cast<int>(std::lround(position.x() * dpr)), static_cast<int>(std::lround(position.y() * dpr)),
      (modifiers & Qt::ControlModifier) ? 1 : 0, (modifiers & Qt::ShiftModifier) ? 1 : 0, 0, repeat);
  interactor_->SetAltKey((modifiers & Qt::AltModifier) ? 1 : 0);
}

void VtkGlWidget::mousePressEvent(QMouseEvent* event) {
  const unsigned long vtkEvent = pressEventFor(event->button());
  if (vtkEvent == vtkCommand::NoEvent) {
    QOpenGLWidget::mousePressEvent(event);
    return;
  }
  setEventInformation(event->position(), event->modifiers());
  interactor_->InvokeEvent(vtkEvent, event);
  event->accept();
}

void VtkGlWidget::mouseDoubleClickEvent(QMouseEvent* event) {
  const unsigned long vtkEvent = pressEventFor(event->button());
  if (vtkEvent == vtkCommand::NoEvent) {
    QOpenGLWidget::mouseDoubleClickEvent(event);
    return;
  }
  setEventInformation(event->position(), event->modifiers(), 1);
  interactor_->InvokeEvent(vtkEvent, event);
  event->accept();
}

void VtkGlWidget::mouseMoveEvent(QMouseEvent* event) {
  setEventInformation(event->position(), event->modifiers());
  interactor_->InvokeEvent(vtkCommand::MouseMoveEvent, event);
  event->accept();
}

void VtkGlWidget::mouseReleaseEvent(QMouseEvent* event) {
  const unsigned long vtkEvent = releaseEventFor(event->button());
  if (vtkEvent == vtkCommand::NoEvent) {
    QOpenGLWidget::mouseReleaseEvent(event);
    return;
  }
  setEventInformation(event->position(), event->modifiers());
  interactor_->InvokeEvent(vtkEvent, event);
  event->accept();
}

void VtkGlWidget::wheelEvent(QWheelEvent* event) {
  // Touchpads deliver fractions of a notch: accumulate and send whole notches only.
  wheelAccumulator_ += event->angleDelta().y();
  setEventInformation(event->position(), event->modifiers());
  while (wheelAccumulator_ >= kWheelNotch) {
    interactor_->InvokeEvent(vtkCommand::MouseWheelForwardEvent, event);
    wheelAccumulator_ -= kWheelNotch;
  }
  while (wheelAccumulator_ <= -kWheelNotch) {
    interactor_->InvokeEvent(vtkCommand::MouseWheelBackwardEvent, event);
    wheelAccumulator_ += kWheelNotch;
  }
  event->accept();
}

void VtkGlWidget::enterEvent(QEnterEvent* event) {
  setEventInformation(event->position(), event->modifiers());
  interactor_->InvokeEvent(vtkCommand::EnterEvent, event);
  QOpenGLWidget::enterEvent(event);
}

void VtkGlWidget::leaveEvent(QEvent* event) {
  interactor_->InvokeEvent(vtkCommand::LeaveEvent, event);
  QOpenGLWidget::leaveEvent(event);
}

}  // namespace metrofit
