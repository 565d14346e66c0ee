#pragma once
// The 3-D work view: a VTK render window in a Qt widget with an orientation
// marker in the mesh's axes, and layers drawn over one mesh:
//   mesh       nodes (dots), trace lines, faces; the undeformed overlay while a
//              shape is shown
//   selection  highlighted nodes (the mesh editor's selection)
//   labels     node numbers
//   deformed   the mesh displaced by a shape, coloured by each node's peak
//              displacement over the cycle (set once per shape and amplitude)
//              with a legend
//   arrows     displacement arrows at the measured nodes
// Geometry and the shape arrays are built once (showMesh, setShape); each
// animation tick only sets the phase (STYLE 12): core::geometry computes the
// points from the two warp scales into the arrays VTK draws, then one render.

#include <QImage>
#include <QWidget>
#include <array>
#include <optional>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/geometry/animation.h"
#include "core/geometry/mode_shape.h"
#include "core/io/project_records.h"

class QVTKOpenGLStereoWidget;
namespace mozzi::core::io {
class ProjectStore;
}
class vtkRenderer;
class vtkPoints;

namespace mozzi {
namespace views {

class SceneView : public QWidget {
  Q_OBJECT
 public:
  explicit SceneView(QWidget* parent = nullptr);
  ~SceneView() override;

  vtkRenderer* renderer() const;
  // Renders once; the number of frames rendered so far (for tests and the status bar).
  void render();
  int framesRendered() const { return framesRendered_; }

  // Must run before the QApplication is created: VTK needs a default OpenGL
  // surface format of its own (STYLE 12).
  static void prepareSurfaceFormat();

  // Draws a mesh: nodes as dots at their global positions (one per mesh node,
  // same order), lines as segments and faces as polygons between node labels.
  // Segments and faces naming a node the mesh lacks are skipped and counted.
  // Replaces any mesh shown and clears the shape and the hit marker. `resetCamera` false keeps
  // the view (the editor redraws after each edit).
  void showMesh(const core::io::StoredMesh& mesh, const std::vector<core::Vector3>& globalPositions,
                bool resetCamera = true);
  void clearMesh();
  // Frames everything drawn and renders: the mesh and, with a shape shown,
  // every place the shape reaches over the cycle at the current amplitude
  // (drawnBounds). Done as well when a shape is set or its amplitude changes,
  // and when the view is resized, as long as the user has not moved the
  // camera since the last framing.
  void resetCamera();
  // Bounds (x min, x max, y min, y max, z min, z max; global axes) of the mesh
  // and of the deformed shape over a whole cycle at the current amplitude.
  std::array<double, 6> drawnBounds() const;
  int meshPointCount() const { return meshPoints_; }
  int meshLineCount() const { return meshLines_; }
  int meshFaceCount() const { return meshFaces_; }
  int skippedLineCount() const { return skippedLines_; }

  // Selection and labels.
  void setSelectedNodes(const std::vector<int>& labels);
  const std::vector<int>& selectedNodes() const { return selected_; }
  void setLabelsVisible(bool visible);
  // The hit marker: the node to strike next drawn large, with an arrow that
  // ends at it along `strike` (global axes; the hammer's direction of travel,
  // its length ignored; zero: the node alone) and `text` beside it (the
  // point's DOF; empty: no text). nullopt removes the marker. A label the
  // mesh lacks removes it too.
  void setHitMarker(std::optional<int> label, const core::Vector3& strike = core::Vector3::Zero(),
                    const QString& text = QString());
  std::optional<int> hitMarkerNode() const { return hitMarker_; }
  // Where the marker is drawn (global axes) and the text shown beside it.
  std::optional<core::Vector3> hitMarkerPosition() const;
  QString hitMarkerText() const { return hitMarker_ ? hitText_ : QString(); }
  // The node drawn nearest `widgetPos` (widget pixels), if one is within a few pixels.
  std::optional<int> nodeAt(const QPoint& widgetPos) const;

  // --- shapes ---------------------------------------------------------------
  // Shows `u` (one row per mesh node, global axes) on the mesh: builds the
  // deformed layer once. `arrowNodes` are the mesh-node rows that get arrows
  // (usually the measured ones). Errors when the row count differs from the mesh.
  bool setShape(const core::geometry::NodeDisplacements& u, const std::vector<int>& arrowNodes = {});
  void clearShape();
  bool hasShape() const { return shapeRows_ > 0; }
  // Amplitude A: displacement drawn = A x shape (see core/geometry/animation.h).
  void setAmplitude(double amplitude);
  double amplitude() const { return amplitude_; }
  // Sets the phase theta [rad], updates the deformed points, renders once.
  void setPhase(double theta);
  double phase() const { return phase_; }
  void setColourByMagnitude(bool on);
  void setUndeformedVisible(bool on);
  // The animation is playing. A large mesh (see kLargeMeshNodes) shows its
  // undeformed overlay only while paused.
  void setAnimating(bool on);
  bool isAnimating() const { return animating_; }
  // The undeformed mesh is drawn (as the overlay while a shape is shown).
  bool undeformedShown() const;
  void setArrowsVisible(bool on);
  void setLegendTitle(const QString& title);
  core::geometry::ColourRange colourRange() const { return colourRange_; }
  // The VTK points of the deformed layer (tests read the vertex positions).
  vtkPoints* deformedPoints() const;

  // The rendered picture at the widget's size (device pixels).
  QImage grabFrame();
  // The 3-D window has its OpenGL context: it draws, and grabs of it (and of
  // the page holding it) show the picture. False until the window is first
  // exposed, a moment after its top-level window is shown.
  bool isReady() const;

 signals:
  // A click (press and release without dragging) on a node.
  void nodeClicked(int label, Qt::KeyboardModifiers modifiers);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;
  void changeEvent(QEvent* event) override;
  void paintEvent(QPaintEvent* event) override;

 private:
  void updateColourRange();
  void retranslate();
  // The camera as the last framing left it (position, focal point, view up).
  std::array<double, 9> cameraPose() const;
  bool cameraMovedSinceFraming() const { return cameraPose() != framedPose_; }
  void reframeIfUntouched();
  // resetCamera() without the render, for callers that render next.
  void frameDrawn();
  void hideHitMarker();
  // Meshes above this many nodes are drawn for speed (thin lines, plain dots,
  // no dots on the deformed shape, opaque overlay shown only while paused):
  // see applyStyle().
  static constexpr int kLargeMeshNodes = 5000;
  bool isLarge() const;
  void applyStyle();

  QVTKOpenGLStereoWidget* vtkWidget_ = nullptr;
  struct Pipeline;
  Pipeline* pipeline_ = nullptr;
  int framesRendered_ = 0;
  int meshPoints_ = 0;
  int meshLines_ = 0;
  int meshFaces_ = 0;
  int skippedLines_ = 0;
  std::vector<int> labels_;  // node label per mesh point
  std::vector<int> selected_;
  std::optional<int> hitMarker_;
  QString hitText_;
  bool renderPending_ = false;  // a deferred render of the hit marker is queued
  // Shape state: base points and the two parts of the shape, split once.
  core::geometry::NodePoints base_, re_, im_;
  core::geometry::NodeDisplacements shape_;
  std::vector<int> arrowRows_;
  Eigen::Index shapeRows_ = 0;
  double amplitude_ = 1.0;
  double phase_ = 0.0;
  bool colourByMagnitude_ = true;
  bool undeformedVisible_ = true;
  bool animating_ = false;
  bool arrowsVisible_ = false;
  core::geometry::ColourRange colourRange_;
  QPoint pressPos_;
  bool pressed_ = false;
  std::array<double, 9> framedPose_{};
  bool reframeQueued_ = false;
};

// The stored mesh of a specimen shown in `scene`: read from the project,
// placed in global axes and drawn; the scene is cleared when the specimen has
// no mesh or it cannot be read or placed (`problem` then says why, translated;
// empty for a specimen without a mesh or no project).
struct ShownMesh {
  std::optional<core::io::StoredMesh> mesh;
  QString problem;
};
ShownMesh showStoredMesh(SceneView& scene, core::io::ProjectStore* store, qint64 specimenId);

}  // namespace views
}  // namespace mozzi
