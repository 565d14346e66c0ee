// The deformed layer of SceneView: a shape's arrays built once, the phase
// per tick, the colours per amplitude, and the box the shape sweeps (what
// the camera frames).
#include <vtkCamera.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <algorithm>
#include <cmath>

#include "views/scene/scene_view.h"
#include "views/scene/scene_view_pipeline.h"

namespace mozzi {
namespace views {

bool SceneView::setShape(const core::geometry::NodeDisplacements& u, const std::vector<int>& arrowNodes) {
  Pipeline& p = *pipeline_;
  vtkPoints* meshPoints = p.mesh->GetPoints();
  const Eigen::Index n = meshPoints ? meshPoints->GetNumberOfPoints() : 0;
  if (u.rows() != n || n == 0) return false;
  // Built once per shape: base points, Re and Im parts, the deformed layer's
  // arrays, colours and cells. Ticks only write into deformedCoords.
  base_.resize(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    double xyz[3];
    meshPoints->GetPoint(i, xyz);
    base_.row(i) << xyz[0], xyz[1], xyz[2];
  }
  shape_ = u;
  re_ = core::geometry::realPart(u);
  im_ = core::geometry::imagPart(u);
  shapeRows_ = n;
  p.deformedCoords->SetNumberOfTuples(n);
  p.colours->SetNumberOfTuples(n);
  p.deformed->SetLines(p.mesh->GetLines());
  p.deformed->SetPolys(p.mesh->GetPolys());
  // Large meshes: the lines show the nodes; per-node dots would double the
  // vertex work of every frame under software OpenGL.
  if (isLarge()) {
    p.deformed->SetVerts(nullptr);
  } else {
    p.deformed->SetVerts(p.nodes->GetVerts());
  }
  arrowRows_.clear();
  for (int row : arrowNodes)
    if (row >= 0 && row < n) arrowRows_.push_back(row);
  vtkNew<vtkPoints> arrowPoints;
  arrowPoints->SetDataTypeToDouble();
  arrowPoints->SetNumberOfPoints(static_cast<vtkIdType>(arrowRows_.size()));
  for (std::size_t k = 0; k < arrowRows_.size(); ++k)
    arrowPoints->SetPoint(static_cast<vtkIdType>(k), base_.row(arrowRows_[k]).data());
  p.arrowInput->SetPoints(arrowPoints);
  p.arrowVectors->SetNumberOfTuples(static_cast<vtkIdType>(arrowRows_.size()));
  p.deformedActor->SetVisibility(1);
  p.legend->SetVisibility(colourByMagnitude_ ? 1 : 0);
  p.arrowActor->SetVisibility(arrowsVisible_ && !arrowRows_.empty() ? 1 : 0);
  applyStyle();
  updateColourRange();
  // The whole cycle in view: framed when the shape comes (the mesh was framed
  // alone when it was drawn), unless the user has moved the camera since.
  if (!cameraMovedSinceFraming()) frameDrawn();
  setPhase(phase_);
  return true;
}

void SceneView::clearShape() {
  Pipeline& p = *pipeline_;
  shapeRows_ = 0;
  shape_.resize(0, 3);
  base_.resize(0, 3);
  re_.resize(0, 3);
  im_.resize(0, 3);
  arrowRows_.clear();
  p.deformedActor->VisibilityOff();
  p.legend->VisibilityOff();
  p.arrowActor->VisibilityOff();
  applyStyle();
}

std::array<double, 6> SceneView::drawnBounds() const {
  std::array<double, 6> b{};
  pipeline_->mesh->GetBounds(b.data());
  if (!hasShape()) return b;
  // Each coordinate of a node moves as A (sin t Re u + cos t Im u): at most
  // A |(Re u, Im u)| either side of where it rests.
  for (Eigen::Index i = 0; i < shapeRows_; ++i) {
    for (int c = 0; c < 3; ++c) {
      const double reach = std::abs(amplitude_) * std::hypot(re_(i, c), im_(i, c));
      b[2 * c] = std::min(b[2 * c], base_(i, c) - reach);
      b[2 * c + 1] = std::max(b[2 * c + 1], base_(i, c) + reach);
    }
  }
  return b;
}

void SceneView::setAmplitude(double amplitude) {
  amplitude_ = amplitude;
  if (!hasShape()) return;
  updateColourRange();
  if (!cameraMovedSinceFraming()) frameDrawn();
  setPhase(phase_);
}

void SceneView::setPhase(double theta) {
  phase_ = theta;
  if (!hasShape()) {
    render();
    return;
  }
  Pipeline& p = *pipeline_;
  const auto scales = core::geometry::warpScales(amplitude_, theta);
  // One fused loop into the array VTK draws; the colours stay as they are.
  core::geometry::deformPoints(base_.data(), re_.data(), im_.data(), shapeRows_, scales,
                               p.deformedCoords->GetPointer(0));
  p.deformedCoords->Modified();
  p.deformedPoints->Modified();
  if (p.arrowActor->GetVisibility()) {
    double* v = p.arrowVectors->GetPointer(0);
    for (std::size_t k = 0; k < arrowRows_.size(); ++k) {
      const Eigen::Index r = arrowRows_[k];
      for (int c = 0; c < 3; ++c) v[3 * k + c] = scales.re * re_(r, c) + scales.im * im_(r, c);
    }
    p.arrowVectors->Modified();
    p.arrowInput->Modified();
  }
  render();
}

void SceneView::updateColourRange() {
  colourRange_ = core::geometry::colourRange(shape_, amplitude_);
  Pipeline& p = *pipeline_;
  p.lut->SetTableRange(colourRange_.min, colourRange_.max);
  // Each node's colour: its peak displacement over the cycle through the
  // legend's table (once per shape and amplitude, not per tick).
  const core::Vector values = core::geometry::colourValues(shape_, amplitude_);
  if (p.colours->GetNumberOfTuples() != values.size()) p.colours->SetNumberOfTuples(values.size());
  unsigned char* rgb = p.colours->GetPointer(0);
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    const unsigned char* c = p.lut->MapValue(values[i]);
    rgb[3 * i] = c[0];
    rgb[3 * i + 1] = c[1];
    rgb[3 * i + 2] = c[2];
  }
  p.colours->Modified();
}

void SceneView::setColourByMagnitude(bool on) {
  colourByMagnitude_ = on;
  Pipeline& p = *pipeline_;
  p.deformedMapper->SetScalarVisibility(on ? 1 : 0);
  p.legend->SetVisibility(on && hasShape() ? 1 : 0);
  render();
}

vtkPoints* SceneView::deformedPoints() const {
  return pipeline_->deformedPoints;
}

}  // namespace views
}  // namespace mozzi
