// PointSetView: what the scene shows (all lengths in mm, in the point set's frame).
//
// - Nominal points q_i: small grey spheres.
// - Measured points, drawn at the exaggerated tip  t_i = q_i + k * v_i,  k = exaggeration (100x by
//   default), with the displacement
//       v_i = d_i * n_i   when the set has normals (d_i = (p_i - q_i) . n_i, the deviation along the
//                         nominal normal; tangential probe offsets are not errors and are not drawn),
//       v_i = p_i - q_i   otherwise (d_i = |p_i - q_i|).
//   A line joins q_i and t_i (the deviation vector); the tip sphere is coloured by d_i.
// - After matching (setAfter): tips t'_i = q'_i + k * v'_i with v'_i = d'_i * n_i (with normals; the
//   matching rotation is far too small to turn n_i visibly) or p_i - q'_i, coloured by d'_i. Display
//   Combined draws them solid while the "before" nominal points, tips and lines fade; Display::After
//   draws only the after state (the transformed nominal points in grey), Display::Before only the
//   before state.
// - Colour: Moreland's diverging cool-warm map (blue - light grey - red) over a symmetric range
//   [-r, r], r = max |d| of the shown states rounded up to 1, 2 or 5 x 10^n (or setColourRange),
//   shown by a scalar bar "deviation (mm)" in its own strip right of the scene (so it never covers
//   points). With a tolerance T > 0 the map has a tolerance band: green within [-T, T], light to dark
//   blue below -T, light to dark red above T, and points with |d| > T are drawn larger.
// - An axes marker (X red, Y green, Z blue) in the lower left corner follows the camera; a title at
//   the top, a caption at the bottom states the exaggeration. White background so that screenshots
//   print well.
#include "widgets/matching/pointsetview.h"

#include <QGuiApplication>
#include <QImage>
#include <QLabel>
#include <QLocale>
#include <QPointer>
#include <QResizeEvent>
#include <QSurfaceFormat>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkCamera.h>
#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkColorTransferFunction.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkScalarBarActorInternal.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <Eigen/Geometry>

#include "core/common/axis_ticks.h"
#include "core/common/numformat.h"
#include "core/matching/probe_points.h"
#include "widgets/common/palette.h"
#include "widgets/matching/vtkglwidget.h"

namespace metrofit {

/// A colour bar whose tick labels use the GUI locale's decimal separator: VTK formats them with
/// printf's LabelFormat in the C locale ("0.05" in a German window); the labels are made by
/// ConfigureTicks (called on every layout), and their '.' is replaced right after it.
class LocaleScalarBarActor : public vtkScalarBarActor {
 public:
  /// What vtkStandardNewMacro does (the macros end without ';', which -Wpedantic and clang-format
  /// both dislike).
  static LocaleScalarBarActor* New() {
    auto* actor = new LocaleScalarBarActor;
    actor->InitializeObjectBase();
    return actor;
  }
  char decimalPoint = '.';

 protected:
  void ConfigureTicks() override {
    vtkScalarBarActor::ConfigureTicks();
    if (decimalPoint == '.') return;
    for (vtkTextActor* label : this->P->TextActors) {
      if (label == nullptr || label->GetInput() == nullptr) continue;
      std::string text = label->GetInput();
      std::replace(text.begin(), text.end(), '.', decimalPoint);
      label->SetInput(text.c_str());
    }
  }
};

namespace {

using Vec3 = Eigen::Vector3d;

constexpr double kBackground[3] = {1.0, 1.0, 1.0};
/// A palette colour as VTK's RGB triple (widgets/common/palette.h: the deviation map of every view).
std::array<double, 3> rgbOf(const QColor& c) {
  return {c.redF(), c.greenF(), c.blueF()};
}
// Moreland, "Diverging Color Maps for Scientific Visualization" (ISVC 2009), cool-warm end points.
const std::array<double, 3> kColdEnd = rgbOf(palette::coldEnd());
const std::array<double, 3> kWarmEnd = rgbOf(palette::warmEnd());
constexpr double kNominalGrey[3] = {0.50, 0.50, 0.50};
constexpr double kTextColour[3] = {0.10, 0.10, 0.10};
constexpr double kFadedOpacity = 0.25;
constexpr double kNominalPointSize = 5.0;
constexpr double kMeasuredPointSize = 9.0;
constexpr double kOutOfTolerancePointSize = 15.0;
const std::array<double, 3> kToleranceGreen = rgbOf(palette::inTolerance());
const std::array<double, 3> kColdLight = rgbOf(palette::coldLight());
const std::array<double, 3> kWarmLight = rgbOf(palette::warmLight());
/// The scene takes the left part of the window, the scalar bar the strip right of it.
constexpr double kSceneWidth = 0.84;
/// Colour range used when every deviation is zero (1 µm).
constexpr double kMinimumRange = 1e-3;

vtkSmartPointer<vtkPolyData> makeVertices(const std::vector<Vec3>& positions,
                                          const std::vector<double>* scalars) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(positions.size()));
  vtkNew<vtkCellArray> verts;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const auto id = static_cast<vtkIdType>(i);
    points->SetPoint(id, positions[i].x(), positions[i].y(), positions[i].z());
    verts->InsertNextCell(1, &id);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(verts);
  if (scalars != nullptr) {
    vtkNew<vtkDoubleArray> values;
    values->SetName("deviation");
    values->SetNumberOfValues(static_cast<vtkIdType>(scalars->size()));
    for (std::size_t i = 0; i < scalars->size(); ++i) {
      values->SetValue(static_cast<vtkIdType>(i), (*scalars)[i]);
    }
    poly->GetPointData()->SetScalars(values);
  }
  return poly;
}

vtkSmartPointer<vtkPolyData> makeSegments(const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(2 * static_cast<vtkIdType>(from.size()));
  vtkNew<vtkCellArray> lines;
  for (std::size_t i = 0; i < from.size(); ++i) {
    const auto first = 2 * static_cast<vtkIdType>(i);
    const vtkIdType ids[2] = {first, first + 1};
    points->SetPoint(ids[0], from[i].x(), from[i].y(), from[i].z());
    points->SetPoint(ids[1], to[i].x(), to[i].y(), to[i].z());
    lines->InsertNextCell(2, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetLines(lines);
  return poly;
}

void styleText(vtkTextProperty* text, int fontSize) {
  text->SetColor(kTextColour[0], kTextColour[1], kTextColour[2]);
  text->SetFontFamilyToArial();
  text->SetFontSize(fontSize);
  text->BoldOff();
  text->ItalicOff();
  text->ShadowOff();
}

/// One drawn set: spheres at the tips, optionally coloured by deviation, and the lines q -> tip.
struct MarkerLayer {
  vtkNew<vtkPolyDataMapper> pointMapper;
  vtkNew<vtkActor> points;
  vtkNew<vtkPolyDataMapper> lineMapper;
  vtkNew<vtkActor> lines;

  void init(vtkRenderer* renderer, double pointSize, vtkColorTransferFunction* colours,
            const double* lineColour) {
    points->SetMapper(pointMapper);
    vtkProperty* p = points->GetProperty();
    p->SetRepresentationToPoints();
    p->RenderPointsAsSpheresOn();
    p->SetPointSize(static_cast<float>(pointSize));
    // Ambient + diffuse = 1: the sphere centre shows the map colour exactly; the strong ambient part
    // keeps the sphere edges from turning dark, so small markers still read as their colour.
    p->SetAmbient(0.6);
    p->SetDiffuse(0.4);
    p->SetSpecular(0.0);
    if (colours != nullptr) {
      pointMapper->SetLookupTable(colours);
      pointMapper->UseLookupTableScalarRangeOn();
      pointMapper->SetScalarModeToUsePointData();
      pointMapper->SetColorModeToMapScalars();
      pointMapper->ScalarVisibilityOn();
    } else {
      pointMapper->ScalarVisibilityOff();
      p->SetColor(kNominalGrey[0], kNominalGrey[1], kNominalGrey[2]);
    }
    renderer->AddActor(points);
    if (lineColour != nullptr) {
      lines->SetMapper(lineMapper);
      lineMapper->ScalarVisibilityOff();
      lines->GetProperty()->SetColor(lineColour[0], lineColour[1], lineColour[2]);
      lines->GetProperty()->SetLineWidth(1.5f);
      lines->GetProperty()->LightingOff();
      renderer->AddActor(lines);
    }
  }

  void set(const std::vector<Vec3>& tips, const std::vector<double>* deviations,
           const std::vector<Vec3>* bases) {
    pointMapper->SetInputData(makeVertices(tips, deviations));
    points->SetVisibility(!tips.empty());
    if (bases != nullptr) {
      lineMapper->SetInputData(makeSegments(*bases, tips));
      lines->SetVisibility(!tips.empty());
    }
  }

  void hide() {
    points->VisibilityOff();
    lines->VisibilityOff();
  }

  void setOpacity(double opacity) {
    points->GetProperty()->SetOpacity(opacity);
    lines->GetProperty()->SetOpacity(opacity);
  }
};

constexpr double kBeforeLineColour[3] = {0.40, 0.40, 0.40};
constexpr double kAfterLineColour[3] = {0.10, 0.10, 0.10};

/// The CAD part (setSurface): its triangles, each coloured by the deviation measured there (cell
/// scalars through the view's colour map), light grey where nothing was measured (NaN), half
/// transparent so that the points behind it stay visible.
struct SurfaceLayer {
  vtkNew<vtkPolyDataMapper> mapper;
  vtkNew<vtkActor> actor;

  void init(vtkRenderer* renderer, vtkColorTransferFunction* colours) {
    actor->SetMapper(mapper);
    mapper->SetLookupTable(colours);
    mapper->UseLookupTableScalarRangeOn();
    mapper->SetScalarModeToUseCellData();
    mapper->SetColorModeToMapScalars();
    mapper->ScalarVisibilityOn();
    vtkProperty* p = actor->GetProperty();
    p->SetOpacity(0.55);
    p->SetAmbient(0.45);
    p->SetDiffuse(0.55);
    p->SetSpecular(0.0);
    actor->VisibilityOff();
    renderer->AddActor(actor);
  }

  void set(const std::vector<std::array<Vec3, 3>>& triangles, const std::vector<double>& deviations) {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> cells;
    vtkNew<vtkDoubleArray> scalars;
    scalars->SetName("deviation");
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      vtkIdType ids[3];
      for (int k = 0; k < 3; ++k) ids[k] = points->InsertNextPoint(triangles[t][k].data());
      cells->InsertNextCell(3, ids);
      scalars->InsertNextValue(t < deviations.size() ? deviations[t] : std::nan(""));
    }
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(points);
    poly->SetPolys(cells);
    poly->GetCellData()->SetScalars(scalars);
    mapper->SetInputData(poly);
    actor->SetVisibility(!triangles.empty());
  }
  void hide() { actor->VisibilityOff(); }
};

/// One drawn set: spheres at the tips coloured by deviation (the out-of-tolerance ones larger) and
/// the lines q -> tip.
struct TipLayer {
  MarkerLayer inside;   ///< spheres within tolerance (all of them without a tolerance) and the lines
  MarkerLayer outside;  ///< larger spheres out of tolerance (no lines)

  void init(vtkRenderer* renderer, vtkColorTransferFunction* colours, const double* lineColour) {
    inside.init(renderer, kMeasuredPointSize, colours, lineColour);
    outside.init(renderer, kOutOfTolerancePointSize, colours, nullptr);
  }
  void set(const std::vector<Vec3>& tips, const std::vector<double>& deviations,
           const std::vector<Vec3>& bases, double tolerance) {
    std::vector<Vec3> inTips, outTips;
    std::vector<double> inDev, outDev;
    for (std::size_t i = 0; i < tips.size(); ++i) {
      const bool out = tolerance > 0.0 && std::abs(deviations[i]) > tolerance;
      (out ? outTips : inTips).push_back(tips[i]);
      (out ? outDev : inDev).push_back(deviations[i]);
    }
    inside.set(inTips, &inDev, nullptr);
    inside.lineMapper->SetInputData(makeSegments(bases, tips));
    inside.lines->SetVisibility(!tips.empty());
    outside.set(outTips, &outDev, nullptr);
  }
  void hide() {
    inside.hide();
    outside.hide();
  }
  void setOpacity(double opacity) {
    inside.setOpacity(opacity);
    outside.setOpacity(opacity);
  }
};

/// The VTK scene; exists only when the process can render 3D.
struct PointSetScene {
  VtkGlWidget* gl = nullptr;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderer> barRenderer;
  vtkNew<vtkColorTransferFunction> colours;
  SurfaceLayer surface;
  MarkerLayer nominal;
  TipLayer before;
  TipLayer after;
  vtkNew<LocaleScalarBarActor> scalarBar;
  vtkNew<vtkTextActor> title;
  vtkNew<vtkTextActor> caption;
  vtkNew<vtkRenderer> axesRenderer;
  vtkNew<vtkAxesActor> axes;
  unsigned long startObserver = 0;
  bool planar = false;
  /// The framing depends on the window's aspect ratio, unknown until the first frame of a hidden
  /// or not yet laid out view: a reset is repeated once just before the next frame.
  bool cameraResetPending = false;
  int titleLines = 0;  ///< lines of the title; the caption starts below them
  /// Called after a pending reset was done (views sharing the camera repaint).
  std::function<void()> onCameraReset;

  explicit PointSetScene(QWidget* parent) : gl(new VtkGlWidget(parent)) {
    renderer->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
    renderer->SetViewport(0.0, 0.0, kSceneWidth, 1.0);
    barRenderer->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
    barRenderer->SetViewport(kSceneWidth, 0.0, 1.0, 1.0);
    barRenderer->InteractiveOff();
    colours->SetColorSpaceToDiverging();
    colours->SetNanColor(0.86, 0.86, 0.86);  // the part where nothing was measured
    surface.init(renderer, colours);
    nominal.init(renderer, kNominalPointSize, nullptr, nullptr);
    before.init(renderer, colours, kBeforeLineColour);
    after.init(renderer, colours, kAfterLineColour);
    nominal.hide();
    before.hide();
    after.hide();

    scalarBar->SetLookupTable(colours);
    const QString point = QLocale().decimalPoint();
    if (point.size() == 1 && point.at(0).unicode() < 128) scalarBar->decimalPoint = point.at(0).toLatin1();
    scalarBar->SetTitle(PointSetView::tr("deviation\n(mm)").toUtf8().constData());
    scalarBar->SetNumberOfLabels(5);
    scalarBar->SetLabelFormat("%.3g");
    scalarBar->SetMaximumNumberOfColors(256);
    scalarBar->SetOrientationToVertical();
    scalarBar->SetTextPositionToPrecedeScalarBar();  // labels left of the bar, away from the edge
    scalarBar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    scalarBar->GetPositionCoordinate()->SetValue(0.06, 0.06);
    scalarBar->SetWidth(0.88);
    scalarBar->SetHeight(0.80);
    scalarBar->SetMaximumWidthInPixels(130);
    scalarBar->SetBarRatio(0.3);
    scalarBar->SetVerticalTitleSeparation(6);
    scalarBar->UnconstrainedFontSizeOn();  // readable fixed sizes instead of sizes fitted to the box
    styleText(scalarBar->GetTitleTextProperty(), 14);
    styleText(scalarBar->GetLabelTextProperty(), 13);
    scalarBar->VisibilityOff();
    barRenderer->AddActor2D(scalarBar);

    title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    title->GetPositionCoordinate()->SetValue(0.015, 0.975);
    styleText(title->GetTextProperty(), 16);
    title->GetTextProperty()->BoldOn();
    title->GetTextProperty()->SetVerticalJustificationToTop();
    title->VisibilityOff();
    renderer->AddActor2D(title);

    caption->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    caption->GetPositionCoordinate()->SetValue(0.015, 0.975);
    styleText(caption->GetTextProperty(), 13);
    caption->GetTextProperty()->SetVerticalJustificationToTop();
    caption->VisibilityOff();
    renderer->AddActor2D(caption);

    // Axes marker: a second, non-interactive renderer in the lower left corner on layer 1 whose
    // camera copies the main camera's orientation before every frame.
    axesRenderer->SetViewport(0.0, 0.0, 0.18 * kSceneWidth, 0.22);
    axesRenderer->SetLayer(1);
    axesRenderer->InteractiveOff();
    axes->SetShaftTypeToCylinder();
    axes->SetTotalLength(1.0, 1.0, 1.0);
    for (vtkCaptionActor2D* label :
         {axes->GetXAxisCaptionActor2D(), axes->GetYAxisCaptionActor2D(), axes->GetZAxisCaptionActor2D()}) {
      styleText(label->GetCaptionTextProperty(), 14);
      label->GetCaptionTextProperty()->BoldOn();
    }
    axesRenderer->AddActor(axes);

    vtkGenericOpenGLRenderWindow* window = gl->renderWindow();
    window->SetNumberOfLayers(2);
    window->AddRenderer(renderer);
    window->AddRenderer(barRenderer);
    window->AddRenderer(axesRenderer);
    startObserver = renderer->AddObserver(vtkCommand::StartEvent, this, &PointSetScene::onStartRender);
  }

  ~PointSetScene() { renderer->RemoveObserver(startObserver); }
  PointSetScene(const PointSetScene&) = delete;
  PointSetScene& operator=(const PointSetScene&) = delete;

  /// Called by the main renderer before every frame.
  void onStartRender(vtkObject* /*caller*/, unsigned long /*eventId*/, void* /*callData*/) {
    if (cameraResetPending) {
      resetCamera();
      cameraResetPending = false;
      if (onCameraReset) onCameraReset();
    }
    const int* size = renderer->GetSize();
    if (size[1] > 0) {
      const double below = titleLines > 0 ? 6.0 + 21.0 * titleLines : 0.0;  // title: 16 pt lines
      caption->GetPositionCoordinate()->SetValue(0.015, 0.975 - below / size[1]);
    }
    vtkCamera* main = renderer->GetActiveCamera();
    renderer->ResetCameraClippingRange();  // a shared camera may have been moved from the other view
    double direction[3];
    main->GetDirectionOfProjection(direction);
    vtkCamera* camera = axesRenderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(-direction[0], -direction[1], -direction[2]);
    camera->SetViewUp(main->GetViewUp());
    axesRenderer->ResetCamera();
    camera->Zoom(1.5);  // ResetCamera fits the bounding sphere: too small for a corner marker
  }

  void setColourRange(double range, double tolerance) {
    colours->RemoveAllPoints();
    if (tolerance > 0.0 && tolerance < range) {
      // Tolerance band: green inside, a visible step to the light ends outside.
      const double step = 1e-6 * range;
      colours->AddRGBPoint(-range, kColdEnd[0], kColdEnd[1], kColdEnd[2]);
      colours->AddRGBPoint(-tolerance - step, kColdLight[0], kColdLight[1], kColdLight[2]);
      colours->AddRGBPoint(-tolerance, kToleranceGreen[0], kToleranceGreen[1], kToleranceGreen[2]);
      colours->AddRGBPoint(tolerance, kToleranceGreen[0], kToleranceGreen[1], kToleranceGreen[2]);
      colours->AddRGBPoint(tolerance + step, kWarmLight[0], kWarmLight[1], kWarmLight[2]);
      colours->AddRGBPoint(range, kWarmEnd[0], kWarmEnd[1], kWarmEnd[2]);
      colours->SetColorSpaceToRGB();
    } else if (tolerance > 0.0) {
      // Everything shown lies within the tolerance.
      colours->AddRGBPoint(-range, kToleranceGreen[0], kToleranceGreen[1], kToleranceGreen[2]);
      colours->AddRGBPoint(range, kToleranceGreen[0], kToleranceGreen[1], kToleranceGreen[2]);
      colours->SetColorSpaceToRGB();
    } else {
      colours->AddRGBPoint(-range, kColdEnd[0], kColdEnd[1], kColdEnd[2]);
      colours->AddRGBPoint(range, kWarmEnd[0], kWarmEnd[1], kWarmEnd[2]);
      colours->SetColorSpaceToDiverging();
    }
  }

  void resetCamera() {
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    if (planar) {
      camera->SetPosition(0.0, 0.0, 1.0);  // looking down on the XY plane
      camera->SetViewUp(0.0, 1.0, 0.0);
    } else {
      camera->SetPosition(1.0, -1.4, 0.9);  // isometric-like, Z up
      camera->SetViewUp(0.0, 0.0, 1.0);
    }
    renderer->ResetCamera();
    // ResetCamera fits the bounding sphere, which leaves a wide margin: zoom in by up to 1.2, as far
    // as the corners of the bounding box still fit the viewport (flat, wide parts seen obliquely
    // would otherwise be cut at the sides).
    double bounds[6];
    renderer->ComputeVisiblePropBounds(bounds);
    double zoom = 1.2;
    if (bounds[0] <= bounds[1]) {
      double focal[3], position[3], up[3], direction[3];
      camera->GetFocalPoint(focal);
      camera->GetPosition(position);
      camera->GetViewUp(up);
      camera->GetDirectionOfProjection(direction);
      const Vec3 f(focal[0], focal[1], focal[2]), d(direction[0], direction[1], direction[2]);
      const Vec3 u = Vec3(up[0], up[1], up[2]).normalized();
      const Vec3 r = d.cross(u).normalized();
      const double distance = (f - Vec3(position[0], position[1], position[2])).norm();
      const double halfHeight = distance * std::tan(0.5 * camera->GetViewAngle() * 3.14159265358979 / 180.0);
      const double aspect = std::max(renderer->GetTiledAspectRatio(), 1e-3);
      double maxX = 0.0, maxY = 0.0;
      for (int i = 0; i < 8; ++i) {
        const Vec3 corner(bounds[i & 1], bounds[2 + ((i >> 1) & 1)], bounds[4 + ((i >> 2) & 1)]);
        maxX = std::max(maxX, std::abs((corner - f).dot(r)));
        maxY = std::max(maxY, std::abs((corner - f).dot(u)));
      }
      if (maxX > 0.0) zoom = std::min(zoom, 0.95 * halfHeight * aspect / maxX);
      if (maxY > 0.0) zoom = std::min(zoom, 0.95 * halfHeight / maxY);
    }
    camera->Zoom(std::max(zoom, 0.2));
    renderer->ResetCameraClippingRange();
  }
};

}  // namespace

struct PointSetView::Impl {
  QLabel* message = nullptr;
  /// linkCamera: the view whose camera this one uses (it frames the shared camera), and the views
  /// that use this one's camera.
  QPointer<PointSetView> cameraMaster;
  std::vector<QPointer<PointSetView>> cameraFollowers;
  std::unique_ptr<PointSetScene> scene;

  // The data are kept also without a scene, so the view behaves the same with and without 3D.
  bool hasNormals = false;
  bool planar = false;
  std::vector<Vec3> nominal;
  std::vector<Vec3> normal;
  std::vector<Vec3> measured;
  std::vector<double> deviations;
  std::vector<std::array<Vec3, 3>> surface;
  std::vector<double> surfaceDeviations;
  bool hasAfter = false;
  std::vector<Vec3> afterNominal;
  std::vector<double> afterDeviations;
  double exaggeration = 100.0;
  double tolerance = 0.0;
  double fixedRange = 0.0;
  double usedRange = kMinimumRange;
  Display display = Display::Combined;
  std::string title;

  /// q + k * v (see the file comment).
  Vec3 tip(std::size_t i, const Vec3& base, double deviation) const {
    const Vec3 displacement = hasNormals ? Vec3(deviation * normal[i]) : Vec3(measured[i] - base);
    return base + exaggeration * displacement;
  }

  void rebuild() {
    const bool showBefore = !hasAfter || display != Display::After;
    const bool showAfter = hasAfter && display != Display::Before;
    double maxAbs = 0.0;
    if (showBefore)
      for (const double v : deviations) maxAbs = std::max(maxAbs, std::abs(v));
    if (showAfter)
      for (const double v : afterDeviations) maxAbs = std::max(maxAbs, std::abs(v));
    if (tolerance > 0.0) maxAbs = std::max(maxAbs, 2.0 * tolerance);  // the band stays readable
    usedRange = fixedRange > 0.0 ? fixedRange : (maxAbs > 0.0 ? ticks::niceCeil(maxAbs) : kMinimumRange);
    if (!scene) {
      return;
    }
    if (surface.empty())
      scene->surface.hide();
    else
      scene->surface.set(surface, surfaceDeviations);
    if (showBefore) {
      std::vector<Vec3> tips(nominal.size());
      for (std::size_t i = 0; i < nominal.size(); ++i) {
        tips[i] = tip(i, nominal[i], deviations[i]);
      }
      scene->nominal.set(nominal, nullptr, nullptr);
      scene->before.set(tips, deviations, nominal, tolerance);
    } else {
      scene->nominal.set(afterNominal, nullptr, nullptr);
      scene->before.hide();
    }
    if (showAfter) {
      std::vector<Vec3> afterTips(afterNominal.size());
      for (std::size_t i = 0; i < afterNominal.size(); ++i) {
        afterTips[i] = tip(i, afterNominal[i], afterDeviations[i]);
      }
      scene->after.set(afterTips, afterDeviations, afterNominal, tolerance);
    } else {
      scene->after.hide();
    }
    // Combined: the nominal points belong to the before state; faded they no longer hide the after
    // tips, which lie close to them when the matching is good.
    const bool fade = showBefore && showAfter;
    scene->nominal.setOpacity(fade ? kFadedOpacity : 1.0);
    scene->before.setOpacity(fade ? kFadedOpacity : 1.0);
    scene->setColourRange(usedRange, tolerance);
    scene->scalarBar->SetVisibility(!nominal.empty());
    const QLocale locale;
    QString text = PointSetView::tr("grey: nominal points; coloured: measured, deviation vectors x%1")
                       .arg(locale.toString(exaggeration, 'g', 4));
    if (fade) {
      text +=
          QLatin1Char('\n') + PointSetView::tr("after matching: solid; before (nominal and measured): faded");
    }
    if (!surface.empty())
      text += QLatin1Char('\n') + PointSetView::tr(
                                      "the part: coloured as the nearest probed point, light grey where "
                                      "none is near");
    if (tolerance > 0.0) {
      text += QLatin1Char('\n') + PointSetView::tr("green: within ±%1 mm; large: out of tolerance")
                                      .arg(locale.toString(tolerance, 'g', 4));
    }
    scene->caption->SetInput(text.toUtf8().constData());
    scene->caption->SetVisibility(!nominal.empty());
    scene->title->SetInput(title.c_str());
    scene->title->SetVisibility(!title.empty());
    // The caption goes below the title (placed in pixels before each frame, onStartRender).
    scene->titleLines =
        title.empty() ? 0 : static_cast<int>(std::count(title.begin(), title.end(), '\n')) + 1;
    scene->gl->update();
  }
};

PointSetView::PointSetView(QWidget* parent) : QWidget(parent), d(std::make_unique<Impl>()) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  if (canRender3D()) {
    d->scene = std::make_unique<PointSetScene>(this);
    layout->addWidget(d->scene->gl);
  } else {
    d->message = new QLabel(tr("3D view needs an X11 display (run under xvfb-run for headless use)"), this);
    d->message->setAlignment(Qt::AlignCenter);
    d->message->setWordWrap(true);
    layout->addWidget(d->message);
  }
  setMinimumSize(200, 150);
}

PointSetView::~PointSetView() = default;

bool PointSetView::canRender3D() {
  if (qobject_cast<QGuiApplication*>(QCoreApplication::instance()) == nullptr) {
    return false;
  }
  if (QGuiApplication::platformName() != QLatin1String("xcb")) {
    return false;
  }
  return !qEnvironmentVariableIsEmpty("DISPLAY");
}

QSurfaceFormat PointSetView::surfaceFormat() {
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 2);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  return format;
}

void PointSetView::setPoints(const ProbePointSet& points) {
  const std::size_t n = points.points.size();
  d->hasNormals = points.hasNormals;
  d->planar = points.planar;
  d->nominal.resize(n);
  d->normal.resize(n);
  d->measured.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    d->nominal[i] = points.points[i].nominal;
    d->normal[i] = points.points[i].normal;
    d->measured[i] = points.points[i].measured;
  }
  d->deviations = points.deviations();
  d->hasAfter = false;
  d->afterNominal.clear();
  d->afterDeviations.clear();
  d->rebuild();
  resetCamera();
}

void PointSetView::setAfter(const std::vector<std::array<double, 3>>& transformedNominal,
                            const std::vector<double>& deviationsAfter) {
  if (transformedNominal.size() != d->nominal.size() || deviationsAfter.size() != d->nominal.size()) {
    throw std::invalid_argument("PointSetView::setAfter: " + std::to_string(transformedNominal.size()) +
                                " transformed nominal points and " + std::to_string(deviationsAfter.size()) +
                                " deviations for a set of " + std::to_string(d->nominal.size()) + " points");
  }
  d->afterNominal.resize(transformedNominal.size());
  for (std::size_t i = 0; i < transformedNominal.size(); ++i) {
    d->afterNominal[i] = Vec3(transformedNominal[i][0], transformedNominal[i][1], transformedNominal[i][2]);
  }
  d->afterDeviations = deviationsAfter;
  d->hasAfter = true;
  d->rebuild();
}

void PointSetView::setSurface(const std::vector<std::array<std::array<double, 3>, 3>>& triangles,
                              const std::vector<double>& triangleDeviations) {
  d->surface.resize(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      d->surface[t][k] = Vec3(triangles[t][k][0], triangles[t][k][1], triangles[t][k][2]);
  d->surfaceDeviations = triangleDeviations;
  d->rebuild();
  resetCamera();
}

void PointSetView::clearSurface() {
  d->surface.clear();
  d->surfaceDeviations.clear();
  d->rebuild();
}

std::size_t PointSetView::surfaceTriangles() const {
  return d->surface.size();
}

void PointSetView::clearAfter() {
  d->hasAfter = false;
  d->afterNominal.clear();
  d->afterDeviations.clear();
  d->rebuild();
}

bool PointSetView::hasAfter() const {
  return d->hasAfter;
}

void PointSetView::setDisplay(Display display) {
  d->display = display;
  d->rebuild();
}

PointSetView::Display PointSetView::display() const {
  return d->display;
}

void PointSetView::setExaggeration(double factor) {
  if (!std::isfinite(factor) || factor <= 0.0) {
    throw std::invalid_argument("PointSetView::setExaggeration: factor must be positive and finite, got " +
                                num::toString(factor));
  }
  d->exaggeration = factor;
  d->rebuild();
}

double PointSetView::exaggeration() const {
  return d->exaggeration;
}

void PointSetView::setTolerance(double toleranceMm) {
  if (!std::isfinite(toleranceMm) || toleranceMm < 0.0) {
    throw std::invalid_argument("PointSetView::setTolerance: tolerance must be >= 0 and finite, got " +
                                num::toString(toleranceMm));
  }
  d->tolerance = toleranceMm;
  d->rebuild();
}

void PointSetView::setColourRange(double rangeMm) {
  if (!std::isfinite(rangeMm) || rangeMm < 0.0) {
    throw std::invalid_argument("PointSetView::setColourRange: range must be >= 0 and finite, got " +
                                num::toString(rangeMm));
  }
  d->fixedRange = rangeMm;
  d->rebuild();
}

double PointSetView::colourRange() const {
  return d->usedRange;
}

void PointSetView::setTitle(const QString& title) {
  d->title = title.toStdString();
  d->rebuild();
}

void PointSetView::resetCamera() {
  if (!d->scene) {
    return;
  }
  if (d->cameraMaster) {
    d->cameraMaster->resetCamera();  // one framing for the shared camera: the master's
    return;
  }
  d->scene->planar = d->planar;
  d->scene->resetCamera();
  d->scene->cameraResetPending = true;
  d->scene->gl->update();
}

void PointSetView::linkCamera(PointSetView* other) {
  if (other == nullptr || other == this || !d->scene || !other->d->scene) {
    return;
  }
  d->scene->renderer->SetActiveCamera(other->d->scene->renderer->GetActiveCamera());
  VtkGlWidget* mine = d->scene->gl;
  VtkGlWidget* theirs = other->d->scene->gl;
  connect(mine, &VtkGlWidget::interactorRendered, theirs, qOverload<>(&QWidget::update));
  connect(theirs, &VtkGlWidget::interactorRendered, mine, qOverload<>(&QWidget::update));
  d->cameraMaster = other;
  other->d->cameraFollowers.emplace_back(this);
  other->d->scene->onCameraReset = [master = other] {
    for (const QPointer<PointSetView>& f : master->d->cameraFollowers) {
      if (f && f->d->scene)
        QMetaObject::invokeMethod(f->d->scene->gl, qOverload<>(&QWidget::update), Qt::QueuedConnection);
    }
  };
  mine->update();
}

std::array<double, 3> PointSetView::cameraPosition() const {
  std::array<double, 3> out{0.0, 0.0, 0.0};
  if (d->scene) {
    d->scene->renderer->GetActiveCamera()->GetPosition(out.data());
  }
  return out;
}

std::array<double, 3> PointSetView::cameraFocalPoint() const {
  std::array<double, 3> out{0.0, 0.0, 0.0};
  if (d->scene) {
    d->scene->renderer->GetActiveCamera()->GetFocalPoint(out.data());
  }
  return out;
}

QImage PointSetView::renderImage() {
  if (!d->scene) {
    return QImage();
  }
  VtkGlWidget* gl = d->scene->gl;
  if (!gl->isVisible()) {
    // A hidden view (a report rendering it off screen) is neither laid out nor sent resize
    // events: lay it out and deliver the resize, which creates the GL context and sizes VTK.
    layout()->activate();
    QResizeEvent resize(gl->size(), QSize());
    QCoreApplication::sendEvent(gl, &resize);
    gl->setAttribute(Qt::WA_PendingResizeEvent, false);
  }
  return gl->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
}

}  // namespace metrofit
