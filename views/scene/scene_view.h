#pragma once
// The 3-D work view: a VTK render window in a Qt widget with a ground grid and
// an orientation marker in the mesh's axes. Geometry and mode animation are
// added by the mesh and animation views built on top of it.

#include <QWidget>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/io/project_records.h"

class QVTKOpenGLNativeWidget;
class vtkRenderer;
class vtkOrientationMarkerWidget;

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
  // same order), lines as segments between node labels. Segments naming a
  // node the mesh lacks are skipped and counted. Replaces any mesh shown.
  void showMesh(const core::io::StoredMesh& mesh, const std::vector<core::Vector3>& globalPositions);
  void clearMesh();
  int meshPointCount() const { return meshPoints_; }
  int meshLineCount() const { return meshLines_; }
  int skippedLineCount() const { return skippedLines_; }

 private:
  QVTKOpenGLNativeWidget* vtkWidget_ = nullptr;
  struct Pipeline;
  Pipeline* pipeline_ = nullptr;
  int framesRendered_ = 0;
  int meshPoints_ = 0;
  int meshLines_ = 0;
  int skippedLines_ = 0;
};

}  // namespace views
}  // namespace mozzi
