#include "views/scene/scene_view.h"

#include <QSurfaceFormat>
#include <QVBoxLayout>
#include <QVTKOpenGLNativeWidget.h>
#include <vtkAxesActor.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkOrientationMarkerWidget.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

namespace mozzi {
namespace views {

struct SceneView::Pipeline {
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkAxesActor> axes;
  vtkNew<vtkOrientationMarkerWidget> marker;
};

void SceneView::prepareSurfaceFormat() { QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat()); }

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

  pipeline_->renderer->GetActiveCamera()->SetPosition(1.0, -1.5, 1.0);
  pipeline_->renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  pipeline_->renderer->ResetCamera();
}

SceneView::~SceneView() { delete pipeline_; }

vtkRenderer* SceneView::renderer() const { return pipeline_->renderer; }

void SceneView::render() {
  pipeline_->window->Render();
  ++framesRendered_;
}

}  // namespace views
}  // namespace mozzi
