#pragma once
// The 3-D work view: a VTK render window in a Qt widget with a ground grid and
// an orientation marker in the mesh's axes. Geometry and mode animation are
// added by the mesh and animation views built on top of it.

#include <QWidget>

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

 private:
  QVTKOpenGLNativeWidget* vtkWidget_ = nullptr;
  struct Pipeline;
  Pipeline* pipeline_ = nullptr;
  int framesRendered_ = 0;
};

}  // namespace views
}  // namespace mozzi
