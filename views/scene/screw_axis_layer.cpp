#include "views/scene/screw_axis_layer.h"

#include <vtkActor.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkLineSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextProperty.h>
#include <algorithm>

#include "views/scene/scene_view.h"

namespace mozzi {
namespace views {

namespace {
// Magenta: apart from the displacement colours (blue to red) and the grey mesh.
constexpr double kColour[3] = {0.72, 0.05, 0.62};
}  // namespace

ScrewAxisLayer::ScrewAxisLayer(SceneView* scene) : scene_(scene) {
  line_ = vtkLineSource::New();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(line_->GetOutputPort());
  actor_ = vtkActor::New();
  actor_->SetMapper(mapper);
  actor_->GetProperty()->SetColor(kColour[0], kColour[1], kColour[2]);
  actor_->GetProperty()->SetLineWidth(4.0);
  actor_->GetProperty()->LightingOff();
  actor_->PickableOff();
  actor_->VisibilityOff();
  label_ = vtkBillboardTextActor3D::New();
  auto* style = label_->GetTextProperty();
  style->SetColor(kColour[0], kColour[1], kColour[2]);
  style->BoldOn();
  style->ShadowOff();
  style->SetFontSize(15);  // VTK scales text with the window's DPI itself
  style->SetBackgroundColor(1.0, 1.0, 1.0);
  style->SetBackgroundOpacity(0.85);
  style->SetJustificationToCentered();
  style->SetVerticalJustificationToBottom();
  label_->PickableOff();
  label_->VisibilityOff();
  scene_->renderer()->AddActor(actor_);
  scene_->renderer()->AddActor(label_);
}

ScrewAxisLayer::~ScrewAxisLayer() {
  if (auto* r = scene_->renderer()) {
    r->RemoveActor(actor_);
    r->RemoveActor(label_);
  }
  label_->Delete();
  actor_->Delete();
  line_->Delete();
}

void ScrewAxisLayer::show(const core::Vector3& from, const core::Vector3& to, const QString& text) {
  line_->SetPoint1(from.x(), from.y(), from.z());
  line_->SetPoint2(to.x(), to.y(), to.z());
  line_->Update();
  // VTK draws line widths in device pixels: as thick on a high-DPI screen.
  actor_->GetProperty()->SetLineWidth(4.0 * std::max(1.0, scene_->devicePixelRatioF()));
  // The label on the line, centred over it a third of the way from its middle
  // towards the upper end (+z, the screen's usual up): the segment spans the
  // drawn mesh, and at 80 % of the way a nearly level axis put the label's
  // text past the view's edge.
  const core::Vector3& top = to.z() >= from.z() ? to : from;
  const core::Vector3 at = 0.5 * (from + to) + 0.35 * (top - 0.5 * (from + to));
  label_->SetPosition(at.x(), at.y(), at.z());
  text_ = text;
  label_->SetInput(text.toUtf8().constData());
  hasAxis_ = true;
  apply();
  scene_->renderer()->ResetCameraClippingRange();
}

void ScrewAxisLayer::clear() {
  hasAxis_ = false;
  text_.clear();
  apply();
}

void ScrewAxisLayer::setVisible(bool on) {
  visible_ = on;
  apply();
}

void ScrewAxisLayer::apply() {
  actor_->SetVisibility(visible_ && hasAxis_);
  label_->SetVisibility(visible_ && hasAxis_);
}

std::pair<core::Vector3, core::Vector3> ScrewAxisLayer::endpoints() const {
  const double* a = line_->GetPoint1();
  const double* b = line_->GetPoint2();
  return {core::Vector3(a[0], a[1], a[2]), core::Vector3(b[0], b[1], b[2])};
}

}  // namespace views
}  // namespace mozzi
