#pragma once
// The Mozzi (instantaneous screw) axis of a shape drawn in a SceneView
// (thesis §1.5, notes.md closed forms): a thick line along the axis through
// the mesh and a label beside its upper end giving the pitch. The layer draws
// what it is given; the axis comes from core::stiffness (screw_axis.h) and the
// segment from core::stiffness::axisSegment.

#include <QString>
#include <utility>

#include "core/common/eigen_types.h"

class vtkActor;
class vtkBillboardTextActor3D;
class vtkLineSource;

namespace mozzi {
namespace views {

class SceneView;

class ScrewAxisLayer {
 public:
  explicit ScrewAxisLayer(SceneView* scene);
  ~ScrewAxisLayer();
  ScrewAxisLayer(const ScrewAxisLayer&) = delete;
  ScrewAxisLayer& operator=(const ScrewAxisLayer&) = delete;

  // Draws the segment from `from` to `to` [m, global] labelled `text` (shown
  // when the layer is visible); the scene is not rendered.
  void show(const core::Vector3& from, const core::Vector3& to, const QString& text);
  // No axis (the scene is not rendered).
  void clear();
  void setVisible(bool on);
  bool isVisible() const { return visible_; }
  bool hasAxis() const { return hasAxis_; }
  // The line's end points as VTK holds them, and the label's text.
  std::pair<core::Vector3, core::Vector3> endpoints() const;
  QString text() const { return text_; }

 private:
  void apply();

  SceneView* scene_;
  vtkLineSource* line_ = nullptr;
  vtkActor* actor_ = nullptr;
  vtkBillboardTextActor3D* label_ = nullptr;
  QString text_;
  bool visible_ = true;
  bool hasAxis_ = false;
};

}  // namespace views
}  // namespace mozzi
