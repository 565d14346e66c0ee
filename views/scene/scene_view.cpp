#include "views/scene/scene_view.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <QSurfaceFormat>
#include <QVBoxLayout>

#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkOrientationMarkerWidget.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <algorithm>
#include <unordered_map>

namespace mozzi {
namespace views {

struct SceneView::Pipeline {
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkAxesActor> axes;
  vtkNew<vtkOrientationMarkerWidget> marker;
  vtkNew<vtkPolyData> mesh;
  vtkNew<vtkPolyDataMapper> meshMapper;
  vtkNew<vtkActor> meshActor;
  vtkNew<vtkActor> nodeActor;
  vtkNew<vtkPolyDataMapper> nodeMapper;
  vtkNew<vtkPolyData> nodes;
};

void SceneView::prepareSurfaceFormat() {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
}

SceneView::SceneView(QWidget* parent) : QWidget(parent), pipeline_(new Pipeline) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  vtkWidget_ = new QVTKOpenGLNativeWidget(this);
  vtkWidget_->setObjectName(QStringLiteral("sceneVtkWidget"));
  layout->addWidget(vtkWidget_);

  vtkWidget_->setRenderWindow(pipeline_->window);
  pipeline_->window->AddRenderer(pipeline_->renderer);
  // Light grey to white gradient: silhouettes and mode shapes read well on it in print too.
  pipeline_->renderer->GradientBackgroundOn();
  pipeline_->renderer->SetBackground(0.82, 0.85, 0.89);
  pipeline_->renderer->SetBackground2(1.0, 1.0, 1.0);

  pipeline_->marker->SetOrientationMarker(pipeline_->axes);
  pipeline_->marker->SetInteractor(pipeline_->window->GetInteractor());
  pipeline_->marker->SetViewport(0.0, 0.0, 0.18, 0.18);
  pipeline_->marker->SetEnabled(1);
  pipeline_->marker->InteractiveOff();

  pipeline_->meshMapper->SetInputData(pipeline_->mesh);
  pipeline_->meshActor->SetMapper(pipeline_->meshMapper);
  pipeline_->meshActor->GetProperty()->SetColor(0.11, 0.21, 0.34);
  pipeline_->meshActor->GetProperty()->SetLineWidth(2.0);
  pipeline_->nodeMapper->SetInputData(pipeline_->nodes);
  pipeline_->nodeActor->SetMapper(pipeline_->nodeMapper);
  pipeline_->nodeActor->GetProperty()->SetColor(0.90, 0.22, 0.27);
  pipeline_->nodeActor->GetProperty()->SetPointSize(7.0);
  pipeline_->nodeActor->GetProperty()->RenderPointsAsSpheresOn();
  pipeline_->renderer->AddActor(pipeline_->meshActor);
  pipeline_->renderer->AddActor(pipeline_->nodeActor);

  pipeline_->renderer->GetActiveCamera()->SetPosition(1.0, -1.5, 1.0);
  pipeline_->renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  pipeline_->renderer->ResetCamera();
}

SceneView::~SceneView() {
  delete pipeline_;
}

vtkRenderer* SceneView::renderer() const {
  return pipeline_->renderer;
}

void SceneView::showMesh(const core::io::StoredMesh& mesh, const std::vector<core::Vector3>& globalPositions) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkCellArray> lines;
  std::unordered_map<int, vtkIdType> index;
  const std::size_t n = std::min(mesh.nodes.size(), globalPositions.size());
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = globalPositions[i];
    const vtkIdType id = points->InsertNextPoint(p[0], p[1], p[2]);
    index[mesh.nodes[i].label] = id;
    vertices->InsertNextCell(1, &id);
  }
  skippedLines_ = 0;
  meshLines_ = 0;
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
  pipeline_->mesh->SetPoints(points);
  pipeline_->mesh->SetLines(lines);
  pipeline_->nodes->SetPoints(points);
  pipeline_->nodes->SetVerts(vertices);
  pipeline_->mesh->Modified();
  pipeline_->nodes->Modified();
  meshPoints_ = static_cast<int>(n);
  pipeline_->renderer->ResetCamera();
  render();
}

void SceneView::clearMesh() {
  showMesh({}, {});
}

void SceneView::render() {
  pipeline_->window->Render();
  ++framesRendered_;
}

}  // namespace views
}  // namespace mozzi
