#pragma once
// Mode-shape animation: any identified or imported mode (or the operating
// deflection shape of an FRF set at a cursor frequency) animated on its mesh,
// with amplitude and speed, colour by displacement magnitude with a legend,
// the undeformed overlay, arrows at the measured nodes, and a second mode side
// by side with the MAC of the two. Exports a PNG frame, an animated GIF or a
// numbered PNG sequence. The geometry is built once per shape; a single-shot
// timer, re-armed after each render, sets the phase from the elapsed time
// (STYLE 12). Numbers come from core::geometry (mode_shape.h, animation.h).

#include <QElapsedTimer>
#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

#include "core/common/dof.h"
#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/geometry/mode_shape.h"
#include "core/io/mesh_document.h"
#include "core/stiffness/screw_axis.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;
class QSplitter;
class QTimer;
class QwtPlotCurve;

namespace mozzi {
namespace views {

class InteractivePlot;
class SceneView;
class ScrewAxisLayer;

class ModeAnimationView : public QWidget {
  Q_OBJECT
 public:
  // A shape to animate: a mode (frequency, damping) or any DOF vector.
  struct Shape {
    QString name;                // "Mode 2", "fork A with wheel, mode 1"
    double frequencyHz = 0.0;    // 0 when not a mode
    double dampingRatio = -1.0;  // viscous zeta; < 0 when not a mode
    std::vector<core::Dof> dofs;
    core::ComplexVector values;
    // The mesh it was measured on, when not the view's mesh (side-by-side of
    // two specimens, thesis Figure 32).
    std::optional<core::io::MeshDocument> mesh;
  };

  explicit ModeAnimationView(QWidget* parent = nullptr);
  ~ModeAnimationView() override;

  void setMesh(const core::io::MeshDocument& mesh);
  void setShapes(std::vector<Shape> shapes);
  const std::vector<Shape>& shapes() const { return shapes_; }
  // FRF set for the operating deflection shape (reference 0 of the set);
  // shared, not copied (ProjectModel::frfSet keeps it for other pages).
  void setFrfSet(std::shared_ptr<const core::FrfMatrix> set, const QString& name);

  // Shows shape `index` (left scene); false with message() when it cannot.
  bool showShape(int index);
  // Shows shape `index` beside it and the MAC of the two; -1 hides the second scene.
  bool compareWith(int index);
  // Shows the ODS at the FRF line nearest `frequencyHz` in the left scene.
  bool showOds(double frequencyHz);
  // The sum of |H| over every FRF of the set (dB) under the controls: placing
  // its cursor (a click, or the arrow keys) shows the ODS at that frequency.
  // Hidden until an FRF set is given.
  InteractivePlot* odsPlot() const { return odsPlot_; }
  std::optional<double> mac() const { return mac_; }
  QString macText() const;

  // Amplitude: factor x the automatic amplitude (largest displacement 10 % of
  // the mesh size).
  void setAmplitudeFactor(double factor);
  double amplitude() const;  // A of the left scene
  void setSpeed(double cyclesPerSecond);
  double speed() const { return speed_; }
  void play();
  void pause();
  bool isPlaying() const;
  // Pauses and shows the phase theta [rad] in both scenes.
  void setPhase(double theta);
  // Timer interval [ms] between a render and the next tick (0: as fast as the
  // event loop allows, for the speed test).
  void setFrameInterval(int milliseconds);
  // Frames per second over the last playing period.
  double measuredFps() const;
  int ticks() const { return ticks_; }

  SceneView* scene() const { return scene_; }
  SceneView* compareScene() const { return compare_; }
  const core::geometry::ShapeField* field() const { return field_ ? &*field_ : nullptr; }

  // The Mozzi (screw) axis of the shown shape (thesis §1.5): the rigid twist
  // fitted to its measured translations (core::geometry::shapeReadings,
  // core::stiffness::screwAxisFromReadingPhasors), drawn through the mesh with
  // its pitch; the check box shows or hides it. None when the readings do not
  // determine a rigid motion (screwAxisProblem() says why).
  const std::optional<core::stiffness::ScrewAxis>& screwAxis() const { return screw_; }
  QString screwAxisProblem() const { return screwProblem_; }
  ScrewAxisLayer* screwAxisLayer() const { return screwLayer_.get(); }
  QCheckBox* screwAxisCheck() const { return screwCheck_; }

  bool exportFrame(const QString& path);
  // One cycle at the current speed, `framesPerSecond` frames a second: an
  // animated GIF when `path` ends in .gif, otherwise PNG files named
  // <stem>_<fps>fps_<nnnn>.png beside `path`. Returns the number of frames.
  int exportAnimation(const QString& path, int framesPerSecond);

 signals:
  void message(const QString& text);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  bool present(SceneView* scene, const Shape& shape, std::optional<core::geometry::ShapeField>& field,
               double& autoAmplitude);
  void tick();
  void applyAmplitude();
  void updateInfo();
  void retranslate();
  void report(const QString& text);
  void fillCombos();
  void wireControls();
  void updateScrewAxis(const Shape& shape);

  core::io::MeshDocument mesh_;
  std::vector<Shape> shapes_;
  std::shared_ptr<const core::FrfMatrix> frf_;
  QString frfName_;
  std::optional<Shape> current_;
  std::optional<Shape> other_;
  std::optional<core::geometry::ShapeField> field_;
  std::optional<core::geometry::ShapeField> otherField_;
  double autoAmplitude_ = 1.0;
  double otherAutoAmplitude_ = 1.0;
  double amplitudeFactor_ = 1.0;
  double speed_ = 0.5;
  std::optional<double> mac_;
  int macDofs_ = 0;

  SceneView* scene_ = nullptr;
  SceneView* compare_ = nullptr;
  QSplitter* splitter_ = nullptr;
  QComboBox* shapeCombo_ = nullptr;
  QComboBox* compareCombo_ = nullptr;
  QDoubleSpinBox* odsSpin_ = nullptr;
  QPushButton* odsButton_ = nullptr;
  InteractivePlot* odsPlot_ = nullptr;
  QwtPlotCurve* odsCurve_ = nullptr;
  QSlider* amplitudeSlider_ = nullptr;
  QDoubleSpinBox* speedSpin_ = nullptr;
  QCheckBox* colourCheck_ = nullptr;
  QCheckBox* undeformedCheck_ = nullptr;
  QCheckBox* arrowsCheck_ = nullptr;
  QCheckBox* screwCheck_ = nullptr;
  std::unique_ptr<ScrewAxisLayer> screwLayer_;
  std::optional<core::stiffness::ScrewAxis> screw_;
  QString screwProblem_;
  QPushButton* playButton_ = nullptr;
  QPushButton* frameButton_ = nullptr;
  QPushButton* animationButton_ = nullptr;
  QLabel* infoLabel_ = nullptr;
  QLabel* macLabel_ = nullptr;
  QLabel* compareTitle_ = nullptr;
  QLabel* shapeTitle_ = nullptr;
  QLabel* odsLabel_ = nullptr;
  QLabel* amplitudeLabel_ = nullptr;
  QLabel* speedLabel_ = nullptr;
  QLabel* compareLabel_ = nullptr;
  QLabel* shapeLabel_ = nullptr;

  QTimer* timer_ = nullptr;
  QElapsedTimer clock_;
  double phaseOffset_ = 0.0;  // phase at the moment play() started
  int frameInterval_ = 15;
  int ticks_ = 0;
  QElapsedTimer fpsClock_;
  int fpsTicks_ = 0;
  double fps_ = 0.0;
  bool filling_ = false;
  bool playing_ = false;
};

}  // namespace views
}  // namespace mozzi
