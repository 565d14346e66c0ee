#include "views/scene/scene_view.h"

#include <QVTKOpenGLStereoWidget.h>
#include <QVTKOpenGLWindow.h>
#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkArrowSource.h>
#include <vtkAxesActor.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGlyph3D.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkLabeledDataMapper.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkOrientationMarkerWidget.h>
#include <vtkPointData.h>
#include <vtkPointPicker.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>
#include <QBackingStore>
#include <QEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QSurfaceFormat>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/geometry/mesh_placement.h"
#include "core/io/project_store.h"
#include "views/scene/scene_view_pipeline.h"

namespace mozzi {
namespace views {

void SceneView::prepareSurfaceFormat() {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLStereoWidget::defaultFormat());
}

SceneView::SceneView(QWidget* parent) : QWidget(parent), pipeline_(new Pipeline) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  // A native child window (a QOpenGLWindow in a container): VTK's frame goes
  // straight to its own window, so Qt does not compose the whole top-level
  // window for every animation frame (with software OpenGL that composition
  // cost as much as the render; docs/performance/scene.md). Grabs of a page
  // get the 3-D picture from paintEvent below.
  vtkWidget_ = new QVTKOpenGLStereoWidget(this);
  vtkWidget_->setObjectName(QStringLiteral("sceneVtkWidget"));
  vtkWidget_->installEventFilter(this);                          // events sent to the widget (tests)
  vtkWidget_->embeddedOpenGLWindow()->installEventFilter(this);  // the user's clicks
  layout->addWidget(vtkWidget_);
  Pipeline& p = *pipeline_;

  // No multisampling: with software OpenGL (Mesa llvmpipe) 8x MSAA multiplies
  // the fill cost of every frame by about eight; lines stay readable without it.
  p.window->SetMultiSamples(0);
  vtkWidget_->setRenderWindow(p.window);
  p.window->AddRenderer(p.renderer);
  // Light grey to white gradient: silhouettes and mode shapes read well on it in print too.
  p.renderer->GradientBackgroundOn();
  p.renderer->SetBackground(0.82, 0.85, 0.89);
  p.renderer->SetBackground2(1.0, 1.0, 1.0);

  p.marker->SetOrientationMarker(p.axes);
  p.marker->SetInteractor(p.window->GetInteractor());
  p.marker->SetViewport(0.0, 0.0, 0.18, 0.18);
  p.marker->SetEnabled(1);
  p.marker->InteractiveOff();

  p.meshMapper->SetInputData(p.mesh);
  p.meshActor->SetMapper(p.meshMapper);
  p.meshActor->GetProperty()->SetColor(0.11, 0.21, 0.34);
  p.meshActor->GetProperty()->SetLineWidth(2.0);
  p.nodeMapper->SetInputData(p.nodes);
  p.nodeActor->SetMapper(p.nodeMapper);
  p.nodeActor->GetProperty()->SetColor(0.90, 0.22, 0.27);
  p.nodeActor->GetProperty()->SetPointSize(7.0);
  p.nodeActor->GetProperty()->RenderPointsAsSpheresOn();
  p.renderer->AddActor(p.meshActor);
  p.renderer->AddActor(p.nodeActor);

  p.selectionMapper->SetInputData(p.selection);
  p.selectionActor->SetMapper(p.selectionMapper);
  p.selectionActor->GetProperty()->SetColor(1.0, 0.78, 0.0);
  p.selectionActor->GetProperty()->SetPointSize(13.0);
  p.selectionActor->GetProperty()->RenderPointsAsSpheresOn();
  p.selectionActor->PickableOff();
  p.renderer->AddActor(p.selectionActor);

  p.deformedCoords->SetNumberOfComponents(3);
  p.deformedPoints->SetDataTypeToDouble();
  p.deformedPoints->SetData(p.deformedCoords);
  p.deformed->SetPoints(p.deformedPoints);
  // Colours are given as RGB (direct scalars): VTK uploads them once and does
  // not map scalars again when a tick moves the points. The lookup table
  // makes them and draws the legend.
  p.colours->SetNumberOfComponents(3);
  p.colours->SetName("peak displacement colour");
  p.deformed->GetPointData()->SetScalars(p.colours);
  p.lut->SetHueRange(0.667, 0.0);  // blue (still) to red (largest)
  p.lut->SetNumberOfTableValues(256);
  p.lut->Build();
  p.deformedMapper->SetInputData(p.deformed);
  p.deformedMapper->SetScalarModeToUsePointData();
  p.deformedMapper->SetColorModeToDirectScalars();
  p.deformedActor->SetMapper(p.deformedMapper);
  p.deformedActor->GetProperty()->SetColor(0.11, 0.21, 0.34);
  p.deformedActor->GetProperty()->SetLineWidth(3.0);
  p.deformedActor->GetProperty()->SetPointSize(6.0);
  p.deformedActor->GetProperty()->RenderPointsAsSpheresOn();
  p.deformedActor->PickableOff();
  p.deformedActor->VisibilityOff();
  p.renderer->AddActor(p.deformedActor);

  p.legend->SetLookupTable(p.lut);
  p.legend->SetNumberOfLabels(5);
  p.legend->SetLabelFormat("%.3g");
  // Fixed font sizes (VTK scales them with the window's DPI), labels left of
  // the bar so nothing runs off the right edge of a narrow view.
  p.legend->UnconstrainedFontSizeOn();
  p.legend->GetTitleTextProperty()->SetFontSize(13);
  p.legend->GetLabelTextProperty()->SetFontSize(12);
  p.legend->SetTextPositionToPrecedeScalarBar();
  p.legend->SetPosition(0.86, 0.08);
  p.legend->SetWidth(0.12);
  p.legend->SetHeight(0.8);
  p.legend->SetBarRatio(0.25);
  p.legend->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
  p.legend->GetTitleTextProperty()->ShadowOff();
  p.legend->GetTitleTextProperty()->ItalicOff();
  p.legend->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
  p.legend->GetLabelTextProperty()->ShadowOff();
  p.legend->GetLabelTextProperty()->ItalicOff();
  p.legend->VisibilityOff();
  p.renderer->AddActor2D(p.legend);

  p.arrowVectors->SetNumberOfComponents(3);
  p.arrowVectors->SetName("displacement");
  p.arrowInput->GetPointData()->SetVectors(p.arrowVectors);
  p.arrow->SetTipResolution(12);
  p.arrow->SetShaftResolution(8);
  p.glyphs->SetSourceConnection(p.arrow->GetOutputPort());
  p.glyphs->SetInputData(p.arrowInput);
  p.glyphs->SetVectorModeToUseVector();
  p.glyphs->SetScaleModeToScaleByVector();
  p.glyphs->OrientOn();
  p.glyphs->SetScaleFactor(1.0);
  p.arrowMapper->SetInputConnection(p.glyphs->GetOutputPort());
  p.arrowMapper->ScalarVisibilityOff();
  p.arrowActor->SetMapper(p.arrowMapper);
  p.arrowActor->GetProperty()->SetColor(0.85, 0.33, 0.10);
  p.arrowActor->PickableOff();
  p.arrowActor->VisibilityOff();
  p.renderer->AddActor(p.arrowActor);

  // The hit marker in green: apart from the selection's amber and the nodes' red.
  p.hitNodeMapper->SetInputData(p.hitNode);
  p.hitNodeActor->SetMapper(p.hitNodeMapper);
  p.hitNodeActor->GetProperty()->SetColor(0.10, 0.62, 0.25);
  p.hitNodeActor->GetProperty()->SetPointSize(18.0);
  p.hitNodeActor->GetProperty()->RenderPointsAsSpheresOn();
  p.hitNodeActor->PickableOff();
  p.hitNodeActor->VisibilityOff();
  p.renderer->AddActor(p.hitNodeActor);
  p.hitArrowVector->SetNumberOfComponents(3);
  p.hitArrowVector->SetName("strike");
  p.hitArrowInput->GetPointData()->SetVectors(p.hitArrowVector);
  // Thicker than the shape arrows: one arrow, read at a glance from the rig.
  p.hitArrow->SetTipResolution(16);
  p.hitArrow->SetShaftResolution(12);
  p.hitArrow->SetShaftRadius(0.05);
  p.hitArrow->SetTipRadius(0.14);
  p.hitArrow->SetTipLength(0.3);
  p.hitGlyph->SetSourceConnection(p.hitArrow->GetOutputPort());
  p.hitGlyph->SetInputData(p.hitArrowInput);
  p.hitGlyph->SetVectorModeToUseVector();
  p.hitGlyph->SetScaleModeToScaleByVector();
  p.hitGlyph->OrientOn();
  p.hitArrowMapper->SetInputConnection(p.hitGlyph->GetOutputPort());
  p.hitArrowMapper->ScalarVisibilityOff();
  p.hitArrowActor->SetMapper(p.hitArrowMapper);
  p.hitArrowActor->GetProperty()->SetColor(0.10, 0.62, 0.25);
  p.hitArrowActor->PickableOff();
  p.hitArrowActor->VisibilityOff();
  p.renderer->AddActor(p.hitArrowActor);
  // The DOF in bold on a white plate, readable over lines and background alike.
  auto* hitTextStyle = p.hitText->GetTextProperty();
  hitTextStyle->SetColor(0.05, 0.45, 0.17);
  hitTextStyle->BoldOn();
  hitTextStyle->ShadowOff();
  hitTextStyle->SetBackgroundColor(1.0, 1.0, 1.0);
  hitTextStyle->SetBackgroundOpacity(0.85);
  hitTextStyle->SetFrame(1);
  hitTextStyle->SetFrameColor(0.10, 0.62, 0.25);
  hitTextStyle->SetJustificationToLeft();
  hitTextStyle->SetVerticalJustificationToBottom();
  p.hitText->PickableOff();
  p.hitText->VisibilityOff();
  p.renderer->AddActor(p.hitText);

  p.picker->PickFromListOn();
  p.picker->AddPickList(p.nodeActor);
  p.picker->SetTolerance(0.01);

  p.renderer->GetActiveCamera()->SetPosition(1.0, -1.5, 1.0);
  p.renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  p.renderer->ResetCamera();
  framedPose_ = cameraPose();
  retranslate();
}

SceneView::~SceneView() {
  delete pipeline_;
}

vtkRenderer* SceneView::renderer() const {
  return pipeline_->renderer;
}

void SceneView::showMesh(const core::io::StoredMesh& mesh, const std::vector<core::Vector3>& globalPositions,
                         bool resetCamera) {
  Pipeline& p = *pipeline_;
  hideHitMarker();  // its node may be gone
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIntArray> labelArray;
  labelArray->SetName("label");
  std::unordered_map<int, vtkIdType> index;
  const std::size_t n = std::min(mesh.nodes.size(), globalPositions.size());
  labels_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& pos = globalPositions[i];
    const vtkIdType id = points->InsertNextPoint(pos[0], pos[1], pos[2]);
    index[mesh.nodes[i].label] = id;
    labels_[i] = mesh.nodes[i].label;
    labelArray->InsertNextValue(mesh.nodes[i].label);
    vertices->InsertNextCell(1, &id);
  }
  skippedLines_ = 0;
  meshLines_ = 0;
  meshFaces_ = 0;
  for (const auto& line : mesh.lines) {
    const auto a = index.find(line.nodeA);
    const auto b = index.find(line.nodeB);
    if (a == index.end() || b == index.end()) {
      ++skippedLines_;
      continue;
    }
    const vtkIdType ids[2] = {a->second, b->second};
    lines->InsertNextCell(2, ids);
    ++meshLines_;
  }
  for (const auto& face : mesh.faces) {
    vtkIdType ids[4];
    int count = 0;
    bool ok = true;
    for (int label : {face.nodeA, face.nodeB, face.nodeC, face.nodeD}) {
      if (label == 0 && count == 3) break;
      const auto it = index.find(label);
      if (it == index.end()) {
        ok = false;
        break;
      }
      ids[count++] = it->second;
    }
    if (!ok) {
      ++skippedLines_;
      continue;
    }
    polys->InsertNextCell(count, ids);
    ++meshFaces_;
  }
  p.mesh->Initialize();
  p.mesh->SetPoints(points);
  p.mesh->SetLines(lines);
  p.mesh->SetPolys(polys);
  p.nodes->Initialize();
  p.nodes->SetPoints(points);
  p.nodes->SetVerts(vertices);
  p.nodes->GetPointData()->AddArray(labelArray);
  p.mesh->Modified();
  p.nodes->Modified();
  // Faces are drawn light and translucent so lines and nodes stay readable.
  meshPoints_ = static_cast<int>(n);
  selected_.clear();
  p.selection->Initialize();
  clearShape();
  if (resetCamera) {
    this->resetCamera();
  } else {
    p.renderer->ResetCameraClippingRange();  // new nodes far away are not clipped
    render();
  }
}

std::array<double, 9> SceneView::cameraPose() const {
  std::array<double, 9> pose{};
  vtkCamera* camera = pipeline_->renderer->GetActiveCamera();
  camera->GetPosition(pose.data());
  camera->GetFocalPoint(pose.data() + 3);
  camera->GetViewUp(pose.data() + 6);
  return pose;
}

void SceneView::resetCamera() {
  frameDrawn();
  render();
}

void SceneView::frameDrawn() {
  std::array<double, 6> b = drawnBounds();
  if (b[0] <= b[1]) {
    pipeline_->renderer->ResetCamera(b.data());
  } else {
    pipeline_->renderer->ResetCamera();
  }
  framedPose_ = cameraPose();
}

void SceneView::reframeIfUntouched() {
  if (!cameraMovedSinceFraming()) resetCamera();
}

void SceneView::clearMesh() {
  showMesh({}, {});
}

void SceneView::setSelectedNodes(const std::vector<int>& labels) {
  selected_ = labels;
  Pipeline& p = *pipeline_;
  vtkNew<vtkCellArray> verts;
  std::unordered_map<int, vtkIdType> row;
  for (std::size_t i = 0; i < labels_.size(); ++i) row[labels_[i]] = static_cast<vtkIdType>(i);
  for (int label : labels) {
    const auto it = row.find(label);
    if (it != row.end()) verts->InsertNextCell(1, &it->second);
  }
  p.selection->Initialize();
  p.selection->SetPoints(p.mesh->GetPoints());
  p.selection->SetVerts(verts);
  p.selection->Modified();
  render();
}

void SceneView::hideHitMarker() {
  hitMarker_.reset();
  pipeline_->hitNodeActor->VisibilityOff();
  pipeline_->hitArrowActor->VisibilityOff();
  pipeline_->hitText->VisibilityOff();
}

std::optional<core::Vector3> SceneView::hitMarkerPosition() const {
  vtkPoints* points = pipeline_->hitNode->GetPoints();
  vtkCellArray* verts = pipeline_->hitNode->GetVerts();
  if (!hitMarker_ || !points || !verts || verts->GetNumberOfCells() != 1) return std::nullopt;
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  verts->InitTraversal();
  if (!verts->GetNextCell(count, ids) || count != 1) return std::nullopt;
  double at[3];
  points->GetPoint(ids[0], at);
  return core::Vector3(at[0], at[1], at[2]);
}

void SceneView::setHitMarker(std::optional<int> label, const core::Vector3& strike, const QString& text) {
  Pipeline& p = *pipeline_;
  hideHitMarker();
  hitText_ = text;
  vtkPoints* points = p.mesh->GetPoints();
  const auto it = label ? std::find(labels_.begin(), labels_.end(), *label) : labels_.end();
  if (it != labels_.end() && points) {
    hitMarker_ = label;
    double at[3];
    points->GetPoint(static_cast<vtkIdType>(it - labels_.begin()), at);
    // One vertex on the mesh's own points, as the selection draws them.
    vtkNew<vtkCellArray> vert;
    const vtkIdType row = static_cast<vtkIdType>(it - labels_.begin());
    vert->InsertNextCell(1, &row);
    p.hitNode->Initialize();
    p.hitNode->SetPoints(points);
    p.hitNode->SetVerts(vert);
    p.hitNodeActor->VisibilityOn();
    if (!text.isEmpty()) {
      // Up and right of the node by a few pixels, clear of the marker's dot.
      const double dpr = std::max(1.0, vtkWidget_->devicePixelRatioF());
      p.hitText->SetInput(text.toUtf8().constData());
      p.hitText->SetPosition(at);
      p.hitText->SetDisplayOffset(static_cast<int>(14 * dpr), static_cast<int>(10 * dpr));
      p.hitText->GetTextProperty()->SetFontSize(18);  // VTK scales text with the window's DPI itself
      p.hitText->VisibilityOn();
    }
    // The arrow: a quarter of the mesh's size, so it reads at any scale; its tip on the node.
    const double size = p.mesh->GetLength();  // the bounding box's diagonal
    const double norm = strike.norm();
    if (norm > 0.0 && size > 0.0) {
      const core::Vector3 v = strike / norm * (size / 4.0);
      vtkNew<vtkPoints> tail;
      tail->InsertNextPoint(at[0] - v.x(), at[1] - v.y(), at[2] - v.z());
      p.hitArrowVector->SetNumberOfTuples(1);
      p.hitArrowVector->SetTuple3(0, v.x(), v.y(), v.z());
      p.hitArrowInput->SetPoints(tail);
      p.hitArrowVector->Modified();
      p.hitArrowInput->Modified();
      p.hitArrowActor->VisibilityOn();
    }
  }
  // In an event of its own: the marker moves when a point is done, in the
  // same slot as the page's table, log and FRF updates; rendering there too
  // would lengthen that one GUI-thread stall (software OpenGL under load).
  if (!renderPending_) {
    renderPending_ = true;
    QTimer::singleShot(0, this, [this] {
      renderPending_ = false;
      render();
    });
  }
}

void SceneView::setLabelsVisible(bool visible) {
  Pipeline& p = *pipeline_;
  if (!p.labelActor) {
    if (!visible) return;
    p.labelMapper = vtkSmartPointer<vtkLabeledDataMapper>::New();
    p.labelMapper->SetInputData(p.nodes);
    p.labelMapper->SetLabelModeToLabelFieldData();
    p.labelMapper->SetFieldDataName("label");
    p.labelMapper->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
    p.labelMapper->GetLabelTextProperty()->SetFontSize(12);
    p.labelMapper->GetLabelTextProperty()->ShadowOff();
    p.labelMapper->GetLabelTextProperty()->BoldOff();
    p.labelActor = vtkSmartPointer<vtkActor2D>::New();
    p.labelActor->SetMapper(p.labelMapper);
    p.renderer->AddActor2D(p.labelActor);
  }
  p.labelActor->SetVisibility(visible ? 1 : 0);
  render();
}

std::optional<int> SceneView::nodeAt(const QPoint& widgetPos) const {
  if (labels_.empty()) return std::nullopt;
  const double ratio = vtkWidget_->devicePixelRatioF();
  const int height = static_cast<int>(vtkWidget_->height() * ratio);
  const double x = widgetPos.x() * ratio;
  const double y = height - 1 - widgetPos.y() * ratio;
  Pipeline& p = *pipeline_;
  if (!p.picker->Pick(x, y, 0.0, p.renderer)) return std::nullopt;
  const vtkIdType id = p.picker->GetPointId();
  if (id < 0 || id >= static_cast<vtkIdType>(labels_.size())) return std::nullopt;
  return labels_[static_cast<std::size_t>(id)];
}

bool SceneView::isLarge() const {
  return meshPoints_ > kLargeMeshNodes;
}

void SceneView::applyStyle() {
  Pipeline& p = *pipeline_;
  auto* mesh = p.meshActor->GetProperty();
  auto* nodes = p.nodeActor->GetProperty();
  auto* deformed = p.deformedActor->GetProperty();
  const bool large = isLarge();
  // VTK draws in device pixels: sizes follow the screen's scale (high DPI).
  const double dpr = std::max(1.0, vtkWidget_->devicePixelRatioF());
  p.selectionActor->GetProperty()->SetPointSize(13.0 * dpr);
  // Sphere-shaded dots and wide lines are drawn by geometry shaders, which
  // Mesa llvmpipe runs on the CPU: large meshes get plain dots and thin lines.
  nodes->SetRenderPointsAsSpheres(!large);
  deformed->SetRenderPointsAsSpheres(!large);
  deformed->SetLineWidth(large ? 1.0 : 3.0 * dpr);
  deformed->SetPointSize(6.0 * dpr);
  if (hasShape()) {
    // The undeformed mesh becomes a grey overlay (opaque for large meshes:
    // blending thousands of lines costs more than it shows).
    mesh->SetColor(0.62, 0.65, 0.69);
    mesh->SetOpacity(large ? 1.0 : 0.45);
    mesh->SetLineWidth(1.0);
    nodes->SetColor(0.55, 0.58, 0.62);
    nodes->SetPointSize(4.0 * dpr);
    // A large mesh's overlay waits for a pause: under software OpenGL its tens
    // of thousands of static lines cost about as much per frame as the moving
    // shape itself (docs/performance/scene.md).
    const bool overlay = undeformedVisible_ && !(large && animating_);
    p.meshActor->SetVisibility(overlay ? 1 : 0);
    p.nodeActor->SetVisibility(overlay && !large ? 1 : 0);
  } else {
    mesh->SetColor(0.11, 0.21, 0.34);
    mesh->SetOpacity(meshFaces_ > 0 ? 0.9 : 1.0);
    mesh->SetLineWidth(large ? 1.0 : 2.0 * dpr);
    nodes->SetColor(0.90, 0.22, 0.27);
    nodes->SetPointSize(large ? 3.0 : 7.0 * dpr);
    p.meshActor->VisibilityOn();
    p.nodeActor->VisibilityOn();
  }
}

bool SceneView::undeformedShown() const {
  return pipeline_->meshActor->GetVisibility() != 0;
}

void SceneView::setAnimating(bool on) {
  if (animating_ == on) return;
  animating_ = on;
  applyStyle();
  render();
}

void SceneView::setUndeformedVisible(bool on) {
  undeformedVisible_ = on;
  applyStyle();
  render();
}

void SceneView::setArrowsVisible(bool on) {
  arrowsVisible_ = on;
  pipeline_->arrowActor->SetVisibility(on && hasShape() && !arrowRows_.empty() ? 1 : 0);
  setPhase(phase_);
}

void SceneView::setLegendTitle(const QString& title) {
  pipeline_->legend->SetTitle(title.toUtf8().constData());
  render();
}

QImage SceneView::grabFrame() {
  if (!isReady()) return QImage();
  render();
  // VTK's own frame, read from its render buffer (QOpenGLWindow's grab draws
  // the scene again in Qt's state, where VTK 9.1 lost the opaque mesh layers).
  vtkNew<vtkWindowToImageFilter> reader;
  reader->SetInput(pipeline_->window);
  reader->ReadFrontBufferOff();
  reader->ShouldRerenderOff();
  reader->SetInputBufferTypeToRGB();
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int size[3];
  image->GetDimensions(size);
  if (size[0] <= 0 || size[1] <= 0) return QImage();
  const auto* rgb = static_cast<const uchar*>(image->GetScalarPointer());
  // VTK's rows run bottom-up; mirrored() also makes the deep copy.
  return QImage(rgb, size[0], size[1], 3 * size[0], QImage::Format_RGB888).mirrored(false, true);
}

void SceneView::render() {
  // Before its window is first exposed VTK has no context to draw in; the
  // first expose draws the scene as it is then.
  if (!isReady()) return;
  pipeline_->window->Render();
  ++framesRendered_;
}

bool SceneView::eventFilter(QObject* watched, QEvent* event) {
  // A new size changes the view's aspect: framed again (after VTK has taken
  // the size) while the camera is where the last framing put it.
  if (watched == vtkWidget_ && event->type() == QEvent::Resize && !reframeQueued_) {
    reframeQueued_ = true;
    QTimer::singleShot(0, this, [this] {
      reframeQueued_ = false;
      reframeIfUntouched();
    });
  }
  if (watched == vtkWidget_ || watched == vtkWidget_->embeddedOpenGLWindow()) {
    if (event->type() == QEvent::MouseButtonPress) {
      auto* me = static_cast<QMouseEvent*>(event);
      if (me->button() == Qt::LeftButton) {
        pressPos_ = me->pos();
        pressed_ = true;
      }
    } else if (event->type() == QEvent::MouseButtonRelease && pressed_) {
      auto* me = static_cast<QMouseEvent*>(event);
      pressed_ = false;
      // A click, not a camera drag: at most a few pixels of travel.
      if (me->button() == Qt::LeftButton && (me->pos() - pressPos_).manhattanLength() <= 4) {
        if (const auto label = nodeAt(me->pos())) emit nodeClicked(*label, me->modifiers());
      }
    }
  }
  return QWidget::eventFilter(watched, event);
}

void SceneView::paintEvent(QPaintEvent* event) {
  // On screen the native 3-D window covers this widget. Painted into another
  // device (QWidget::grab of a page, Export Work Area as Image), the native
  // window is not part of the picture: paint its frame where it sits. On
  // screen Qt paints into the top-level's backing store; anything else is a grab.
  QPaintDevice* target = redirected(nullptr);
  QBackingStore* store = window()->backingStore();
  const bool grabbing = target && (!store || target != store->paintDevice());
  if (grabbing && vtkWidget_->isVisible() && isReady()) {
    QPainter painter(this);
    painter.drawImage(vtkWidget_->geometry(), grabFrame());
  }
  QWidget::paintEvent(event);
}

bool SceneView::isReady() const {
  return vtkWidget_->isValid();
}

void SceneView::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void SceneView::retranslate() {
  pipeline_->legend->SetTitle(tr("peak |u|").toUtf8().constData());
}

ShownMesh showStoredMesh(SceneView& scene, core::io::ProjectStore* store, qint64 specimenId) {
  ShownMesh shown;
  if (!store || specimenId == 0) {
    scene.clearMesh();
    return shown;
  }
  auto mesh = store->mesh(specimenId);
  if (!mesh) {
    scene.clearMesh();
    shown.problem = SceneView::tr("Cannot show the mesh: %1").arg(QString::fromStdString(mesh.error().describe()));
    return shown;
  }
  auto positions = core::geometry::globalNodePositions(*mesh);
  if (!positions || positions->empty()) {
    scene.clearMesh();
    if (!positions) {
      shown.problem =
          SceneView::tr("Cannot place the mesh: %1").arg(QString::fromStdString(positions.error().describe()));
    }
    return shown;
  }
  scene.showMesh(*mesh, *positions);
  shown.mesh = std::move(*mesh);
  return shown;
}

}  // namespace views
}  // namespace mozzi
