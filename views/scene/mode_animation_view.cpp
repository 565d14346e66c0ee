#include "views/scene/mode_animation_view.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QSlider>
#include <QSplitter>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>

#include <qwt_plot_curve.h>
#include <qwt_text.h>

#include <memory>

#include "core/common/frf_display.h"
#include "core/common/plot_math.h"
#include "core/geometry/animation.h"
#include "core/io/gif_writer.h"
#include "views/common/dof_text.h"
#include "views/plots/interactive_plot.h"
#include "views/plots/vector_series.h"
#include "views/scene/scene_view.h"
#include "views/scene/screw_axis_layer.h"

namespace mozzi {
namespace views {

namespace geo = core::geometry;

namespace {
// Slider position p in [-100, 100] -> amplitude factor 10^(p/100): 0.1x to 10x.
double sliderFactor(int position) {
  return std::pow(10.0, position / 100.0);
}

std::vector<int> measuredRows(const geo::ShapeField& field) {
  std::vector<int> rows;
  for (std::size_t i = 0; i < field.source.size(); ++i)
    if (field.source[i] == geo::NodeSource::Measured) rows.push_back(static_cast<int>(i));
  return rows;
}

core::io::RgbImage toRgb(const QImage& image) {
  const QImage rgb = image.convertToFormat(QImage::Format_RGB888);
  core::io::RgbImage out;
  out.width = rgb.width();
  out.height = rgb.height();
  out.rgb.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 3);
  for (int y = 0; y < rgb.height(); ++y) {
    std::copy(rgb.constScanLine(y), rgb.constScanLine(y) + 3 * out.width,
              out.rgb.begin() + static_cast<std::ptrdiff_t>(3 * static_cast<std::size_t>(y) * out.width));
  }
  return out;
}
}  // namespace

ModeAnimationView::ModeAnimationView(QWidget* parent) : QWidget(parent) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);

  auto* controls = new QWidget(this);
  controls->setObjectName(QStringLiteral("animationControls"));
  auto* form = new QFormLayout(controls);
  shapeCombo_ = new QComboBox(controls);
  shapeCombo_->setObjectName(QStringLiteral("animationShapeCombo"));
  compareCombo_ = new QComboBox(controls);
  compareCombo_->setObjectName(QStringLiteral("animationCompareCombo"));
  shapeLabel_ = new QLabel(controls);
  compareLabel_ = new QLabel(controls);
  form->addRow(shapeLabel_, shapeCombo_);
  form->addRow(compareLabel_, compareCombo_);
  odsSpin_ = new QDoubleSpinBox(controls);
  odsSpin_->setObjectName(QStringLiteral("animationOdsSpin"));
  odsSpin_->setRange(0.0, 1e6);
  odsSpin_->setDecimals(2);
  odsSpin_->setSuffix(QStringLiteral(" Hz"));
  odsButton_ = new QPushButton(controls);
  odsButton_->setObjectName(QStringLiteral("animationOdsButton"));
  odsButton_->setEnabled(false);  // until an FRF set is given
  odsSpin_->setEnabled(false);
  auto* odsRow = new QHBoxLayout;
  odsRow->addWidget(odsSpin_, 1);
  odsRow->addWidget(odsButton_);
  odsLabel_ = new QLabel(controls);
  form->addRow(odsLabel_, odsRow);
  odsPlot_ = new InteractivePlot(controls);
  odsPlot_->setObjectName(QStringLiteral("animationOdsPlot"));
  odsPlot_->setMinimumHeight(controls->fontMetrics().height() * 11);
  odsCurve_ = new QwtPlotCurve;
  odsCurve_->setPen(QColor(31, 119, 180), 1.0);
  odsCurve_->attach(odsPlot_);
  odsPlot_->hide();  // until an FRF set is given
  form->addRow(odsPlot_);
  amplitudeSlider_ = new QSlider(Qt::Horizontal, controls);
  amplitudeSlider_->setObjectName(QStringLiteral("animationAmplitudeSlider"));
  amplitudeSlider_->setRange(-100, 100);
  amplitudeSlider_->setValue(0);
  amplitudeLabel_ = new QLabel(controls);
  form->addRow(amplitudeLabel_, amplitudeSlider_);
  speedSpin_ = new QDoubleSpinBox(controls);
  speedSpin_->setObjectName(QStringLiteral("animationSpeedSpin"));
  speedSpin_->setRange(0.05, 5.0);
  speedSpin_->setSingleStep(0.1);
  speedSpin_->setValue(speed_);
  speedLabel_ = new QLabel(controls);
  form->addRow(speedLabel_, speedSpin_);
  colourCheck_ = new QCheckBox(controls);
  colourCheck_->setObjectName(QStringLiteral("animationColourCheck"));
  colourCheck_->setChecked(true);
  undeformedCheck_ = new QCheckBox(controls);
  undeformedCheck_->setObjectName(QStringLiteral("animationUndeformedCheck"));
  undeformedCheck_->setChecked(true);
  arrowsCheck_ = new QCheckBox(controls);
  arrowsCheck_->setObjectName(QStringLiteral("animationArrowsCheck"));
  form->addRow(colourCheck_);
  form->addRow(undeformedCheck_);
  form->addRow(arrowsCheck_);
  screwCheck_ = new QCheckBox(controls);
  screwCheck_->setObjectName(QStringLiteral("animationScrewAxisCheck"));
  screwCheck_->setChecked(true);
  form->addRow(screwCheck_);
  playButton_ = new QPushButton(controls);
  playButton_->setObjectName(QStringLiteral("animationPlayButton"));
  playButton_->setCheckable(true);
  playButton_->setShortcut(Qt::Key_Space);
  form->addRow(playButton_);
  frameButton_ = new QPushButton(controls);
  frameButton_->setObjectName(QStringLiteral("animationFrameButton"));
  animationButton_ = new QPushButton(controls);
  animationButton_->setObjectName(QStringLiteral("animationExportButton"));
  form->addRow(frameButton_);
  form->addRow(animationButton_);
  // The controls scroll on their own: the 3-D view keeps the page's height
  // (the page fits a 1280x800 window at any scale, the shape stays in view).
  auto* controlsScroll = new QScrollArea(this);
  controlsScroll->setObjectName(QStringLiteral("animationControlsScroll"));
  controlsScroll->setFrameShape(QFrame::NoFrame);
  controlsScroll->setWidgetResizable(true);
  controlsScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  controlsScroll->setWidget(controls);
  const int controlsWidth = controls->fontMetrics().averageCharWidth() * 48;
  controls->setMaximumWidth(controlsWidth);
  controlsScroll->setMaximumWidth(controlsWidth + controlsScroll->verticalScrollBar()->sizeHint().width());
  // The width is set, not the minimum hint: the labels get their texts in
  // retranslate(), after this, and a hint taken now clipped the controls.
  controlsScroll->setMinimumWidth(controlsScroll->maximumWidth());
  layout->addWidget(controlsScroll);

  // The scenes, and under them what they show: the shape's frequency,
  // damping, nodes and Mozzi axis, the MAC of a comparison (below the
  // controls they were under the fold at 1280x800).
  auto* right = new QWidget(this);
  auto* rightLayout = new QVBoxLayout(right);
  rightLayout->setContentsMargins(0, 0, 0, 0);
  auto* splitter = new QSplitter(Qt::Horizontal, right);
  splitter_ = splitter;
  auto makeScene = [splitter](const char* name, QLabel*& title) {
    auto* box = new QWidget(splitter);
    auto* v = new QVBoxLayout(box);
    v->setContentsMargins(0, 0, 0, 0);
    title = new QLabel(box);
    title->setObjectName(QString::fromLatin1(name) + QStringLiteral("Title"));
    title->setAlignment(Qt::AlignCenter);
    auto* scene = new SceneView(box);
    scene->setObjectName(QString::fromLatin1(name));
    v->addWidget(title);
    v->addWidget(scene, 1);
    return scene;
  };
  scene_ = makeScene("animationScene", shapeTitle_);
  compare_ = makeScene("animationCompareScene", compareTitle_);
  splitter->setChildrenCollapsible(false);
  splitter->setSizes({500, 500});  // side by side: equal halves
  compare_->parentWidget()->hide();
  rightLayout->addWidget(splitter, 1);
  infoLabel_ = new QLabel(right);
  infoLabel_->setObjectName(QStringLiteral("animationInfo"));
  infoLabel_->setWordWrap(true);
  infoLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);  // the axis's numbers can be copied
  // Four lines kept: the 3-D view does not change height from mode to mode.
  infoLabel_->setMinimumHeight(infoLabel_->fontMetrics().lineSpacing() * 4);
  rightLayout->addWidget(infoLabel_);
  macLabel_ = new QLabel(right);
  macLabel_->setObjectName(QStringLiteral("animationMac"));
  macLabel_->setWordWrap(true);
  QFont big = macLabel_->font();
  big.setPointSizeF(big.pointSizeF() * 1.3);
  big.setBold(true);
  macLabel_->setFont(big);
  rightLayout->addWidget(macLabel_);
  layout->addWidget(right, 1);
  screwLayer_ = std::make_unique<ScrewAxisLayer>(scene_);

  wireControls();
  retranslate();
}

ModeAnimationView::~ModeAnimationView() = default;

void ModeAnimationView::wireControls() {
  timer_ = new QTimer(this);
  timer_->setSingleShot(true);
  connect(timer_, &QTimer::timeout, this, &ModeAnimationView::tick);
  connect(shapeCombo_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int i) {
    if (!filling_ && i >= 0) showShape(i);
  });
  connect(compareCombo_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int i) {
    if (!filling_) compareWith(i - 1);
  });
  connect(odsButton_, &QPushButton::clicked, this, [this] { showOds(odsSpin_->value()); });
  connect(odsPlot_, &InteractivePlot::cursorMoved, this, [this](double hz) {
    if (filling_) return;
    {
      QSignalBlocker block(odsSpin_);
      odsSpin_->setValue(hz);
    }
    showOds(hz);
  });
  connect(amplitudeSlider_, &QSlider::valueChanged, this, [this](int v) { setAmplitudeFactor(sliderFactor(v)); });
  connect(speedSpin_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) { setSpeed(v); });
  connect(colourCheck_, &QCheckBox::toggled, this, [this](bool on) {
    scene_->setColourByMagnitude(on);
    compare_->setColourByMagnitude(on);
  });
  connect(undeformedCheck_, &QCheckBox::toggled, this, [this](bool on) {
    scene_->setUndeformedVisible(on);
    compare_->setUndeformedVisible(on);
  });
  connect(arrowsCheck_, &QCheckBox::toggled, this, [this](bool on) {
    scene_->setArrowsVisible(on);
    compare_->setArrowsVisible(on);
  });
  connect(screwCheck_, &QCheckBox::toggled, this, [this](bool on) {
    screwLayer_->setVisible(on);
    scene_->render();
  });
  connect(playButton_, &QPushButton::toggled, this, [this](bool on) { on ? play() : pause(); });
  connect(frameButton_, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export a frame"), QString(), tr("PNG image (*.png)"));
    if (!path.isEmpty()) exportFrame(path);
  });
  connect(animationButton_, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export the animation"), QString(),
                                                      tr("Animated GIF (*.gif);;PNG sequence (*.png)"));
    if (!path.isEmpty()) exportAnimation(path, 25);
  });
}

void ModeAnimationView::setMesh(const core::io::MeshDocument& mesh) {
  pause();
  mesh_ = mesh;
  current_.reset();
  other_.reset();
  field_.reset();
  otherField_.reset();
  mac_.reset();
  screw_.reset();
  screwProblem_.clear();
  screwLayer_->clear();
  auto positions = geo::nodePoints(mesh_.mesh);
  if (positions) {
    std::vector<core::Vector3> points;
    for (Eigen::Index i = 0; i < positions->rows(); ++i) points.emplace_back(positions->row(i).transpose());
    scene_->showMesh(mesh_.mesh, points);
  } else {
    scene_->clearMesh();
    report(tr("Cannot place the mesh: %1").arg(QString::fromStdString(positions.error().describe())));
  }
  compareWith(-1);
  updateInfo();
}

void ModeAnimationView::setShapes(std::vector<Shape> shapes) {
  shapes_ = std::move(shapes);
  fillCombos();
}

void ModeAnimationView::fillCombos() {
  filling_ = true;
  shapeCombo_->clear();
  compareCombo_->clear();
  compareCombo_->addItem(tr("(none)"));
  for (const auto& s : shapes_) {
    const QString text = s.frequencyHz > 0.0 ? tr("%1 (%2 Hz)").arg(s.name).arg(s.frequencyHz, 0, 'f', 2) : s.name;
    shapeCombo_->addItem(text);
    compareCombo_->addItem(text);
  }
  shapeCombo_->setCurrentIndex(-1);
  filling_ = false;
}

void ModeAnimationView::setFrfSet(std::shared_ptr<const core::FrfMatrix> set, const QString& name) {
  frf_ = std::move(set);
  frfName_ = name;
  const bool hasLines = frf_ && frf_->lineCount() > 0;
  odsButton_->setEnabled(hasLines);
  odsSpin_->setEnabled(hasLines);
  odsPlot_->hide();
  if (!hasLines) return;
  const core::FrfMatrix& frf = *frf_;
  odsSpin_->setRange(frf.frequencyHz[0], frf.frequencyHz[frf.lineCount() - 1]);
  // The modes of the set's specimen (the shapes without a mesh of their own):
  // the guide opens on them, the spin box on the first; Home shows the whole
  // set.
  double firstMode = std::numeric_limits<double>::infinity(), lastMode = -firstMode;
  for (const Shape& s : shapes_) {
    if (s.mesh || !(s.frequencyHz >= frf.frequencyHz[0] && s.frequencyHz <= frf.frequencyHz[frf.lineCount() - 1]))
      continue;
    firstMode = std::min(firstMode, s.frequencyHz);
    lastMode = std::max(lastMode, s.frequencyHz);
  }
  const bool modesInSet = firstMode <= lastMode;
  odsSpin_->setValue(modesInSet ? firstMode : frf.frequencyHz[frf.lineCount() / 2]);
  // The guide curve: the sum of |H| over every FRF of the set in dB, the
  // Identification page's backdrop, whose peaks (the modes) show which
  // frequencies are worth a look. Not the FRFs of one reference alone: on a
  // roving-hammer set that is one hammer point, perhaps one that barely
  // moves; not their complex sum, in which an antisymmetric mode cancels.
  auto sum = core::frfMagnitudeSum(frf, core::pickFrfs(frf, {}));
  if (!sum) return;
  auto x = std::make_shared<const core::Vector>(frf.frequencyHz);
  auto y =
      std::make_shared<const core::Vector>(core::frfViewValues(sum->cast<core::Complex>(), core::FrfView::MagnitudeDb));
  odsCurve_->setData(new VectorSeries(x, y));
  odsPlot_->setYFloor(core::kMagnitudeFloorDb);
  odsPlot_->show();
  odsPlot_->autoscale();
  if (modesInSet) {
    // A quarter of the modes' span on either side (at least 10 % of the first
    // mode's frequency), within the set.
    const double margin = std::max(0.25 * (lastMode - firstMode), 0.1 * firstMode);
    odsPlot_->setAxisScale(QwtPlot::xBottom, std::max(frf.frequencyHz[0], firstMode - margin),
                           std::min(frf.frequencyHz[frf.lineCount() - 1], lastMode + margin));
    odsPlot_->autoscaleY();
  }
  filling_ = true;  // the cursor marks the spin box's frequency; no ODS yet
  odsPlot_->setCursor(odsSpin_->value());
  filling_ = false;
}

bool ModeAnimationView::present(SceneView* scene, const Shape& shape, std::optional<geo::ShapeField>& field,
                                double& autoAmplitude) {
  const core::io::MeshDocument& doc = shape.mesh ? *shape.mesh : mesh_;
  auto spread = geo::shapeField(doc, shape.dofs, shape.values);
  if (!spread) {
    report(tr("Cannot show %1: %2").arg(shape.name, QString::fromStdString(spread.error().describe())));
    return false;
  }
  auto base = geo::nodePoints(doc.mesh);
  if (!base) {
    report(tr("Cannot show %1: %2").arg(shape.name, QString::fromStdString(base.error().describe())));
    return false;
  }
  auto amplitude = geo::autoAmplitude(*base, spread->u);
  if (!amplitude) {
    report(tr("Cannot show %1: %2").arg(shape.name, QString::fromStdString(amplitude.error().describe())));
    return false;
  }
  if (shape.mesh) {
    std::vector<core::Vector3> points;
    for (Eigen::Index i = 0; i < base->rows(); ++i) points.emplace_back(base->row(i).transpose());
    scene->showMesh(doc.mesh, points);
  } else if (scene->meshPointCount() != static_cast<int>(doc.mesh.nodes.size())) {
    std::vector<core::Vector3> points;
    for (Eigen::Index i = 0; i < base->rows(); ++i) points.emplace_back(base->row(i).transpose());
    scene->showMesh(doc.mesh, points);
  }
  autoAmplitude = *amplitude;
  scene->setAmplitude(autoAmplitude * amplitudeFactor_);
  if (!scene->setShape(spread->u, measuredRows(*spread))) {
    report(tr("Cannot show %1: the mesh and the shape differ in node count").arg(shape.name));
    return false;
  }
  scene->setColourByMagnitude(colourCheck_->isChecked());
  scene->setUndeformedVisible(undeformedCheck_->isChecked());
  scene->setArrowsVisible(arrowsCheck_->isChecked());
  scene->setLegendTitle(tr("peak |u|"));
  field = std::move(spread).value();
  return true;
}

bool ModeAnimationView::showShape(int index) {
  if (index < 0 || index >= static_cast<int>(shapes_.size())) {
    report(tr("No shape %1.").arg(index + 1));
    return false;
  }
  if (!present(scene_, shapes_[static_cast<std::size_t>(index)], field_, autoAmplitude_)) return false;
  current_ = shapes_[static_cast<std::size_t>(index)];
  updateScrewAxis(*current_);
  filling_ = true;
  shapeCombo_->setCurrentIndex(index);
  filling_ = false;
  if (other_) {
    // Recompute the MAC against the new left shape.
    auto pair = geo::macOnCommonDofs(current_->dofs, current_->values, other_->dofs, other_->values);
    mac_.reset();
    if (pair) {
      mac_ = pair->mac;
      macDofs_ = pair->commonDofs;
    }
  }
  updateInfo();
  return true;
}

bool ModeAnimationView::compareWith(int index) {
  if (index < 0) {
    other_.reset();
    otherField_.reset();
    mac_.reset();
    compare_->clearShape();
    compare_->parentWidget()->hide();
    filling_ = true;
    compareCombo_->setCurrentIndex(0);
    filling_ = false;
    updateInfo();
    return true;
  }
  if (index >= static_cast<int>(shapes_.size())) return false;
  const Shape& shape = shapes_[static_cast<std::size_t>(index)];
  if (!compare_->parentWidget()->isVisible()) {
    compare_->parentWidget()->show();
    const int half = std::max(1, splitter_->width() / 2);
    splitter_->setSizes({half, half});  // a hidden widget comes back with no width otherwise
  }
  if (!present(compare_, shape, otherField_, otherAutoAmplitude_)) return false;
  other_ = shape;
  filling_ = true;
  compareCombo_->setCurrentIndex(index + 1);
  filling_ = false;
  mac_.reset();
  if (current_) {
    auto pair = geo::macOnCommonDofs(current_->dofs, current_->values, other_->dofs, other_->values);
    if (pair) {
      mac_ = pair->mac;
      macDofs_ = pair->commonDofs;
    } else {
      report(tr("No MAC: %1").arg(QString::fromStdString(pair.error().describe())));
    }
  }
  compare_->setPhase(scene_->phase());
  updateInfo();
  return true;
}

bool ModeAnimationView::showOds(double frequencyHz) {
  if (!frf_) {
    report(tr("Open an FRF set to see operating deflection shapes."));
    return false;
  }
  auto ods = geo::operatingDeflectionShape(*frf_, frequencyHz);
  if (!ods) {
    report(tr("No ODS: %1").arg(QString::fromStdString(ods.error().describe())));
    return false;
  }
  Shape shape;
  shape.name = tr("ODS at %1 Hz, driven at %2 (%3)").arg(ods->lineHz, 0, 'f', 2).arg(dofText(ods->drivenAt), frfName_);
  if (!odsPlot_->isHidden()) {
    filling_ = true;  // the cursor on the line used, without showing the ODS twice
    odsPlot_->setCursor(ods->lineHz);
    filling_ = false;
  }
  shape.dofs = ods->dofs;
  shape.values = ods->values;
  if (!present(scene_, shape, field_, autoAmplitude_)) return false;
  current_ = shape;
  updateScrewAxis(shape);
  updateInfo();
  return true;
}

void ModeAnimationView::updateScrewAxis(const Shape& shape) {
  screw_.reset();
  screwProblem_.clear();
  screwLayer_->clear();
  const core::io::MeshDocument& doc = shape.mesh ? *shape.mesh : mesh_;
  auto readings = geo::shapeReadings(doc, shape.dofs, shape.values);
  auto points = geo::nodePoints(doc.mesh);
  if (!readings || !points) {
    screwProblem_ = QString::fromStdString((!readings ? readings.error() : points.error()).message);
  } else {
    auto axis = core::stiffness::screwAxisFromReadingPhasors(readings->points, readings->directions, readings->values);
    if (!axis) {
      screwProblem_ = QString::fromStdString(axis.error().message);
    } else {
      screw_ = std::move(axis).value();
      // Through the mesh: the stretch nearest its centre, as long as the mesh
      // is wide, so it stays inside the sphere the camera frames.
      const core::Vector3 lo = points->colwise().minCoeff().transpose(), hi = points->colwise().maxCoeff().transpose();
      const double half = 0.5 * std::max((hi - lo).norm(), 1e-3);
      const auto ends = core::stiffness::axisSegment(*screw_, 0.5 * (lo + hi), half);
      screwLayer_->show(ends.from, ends.to, tr("Mozzi axis, pitch %1 m/rad").arg(screw_->pitch, 0, 'g', 3));
    }
  }
  screwLayer_->setVisible(screwCheck_->isChecked());
  scene_->render();
}

QString ModeAnimationView::macText() const {
  if (!mac_) return QString();
  return tr("MAC %1 (%2 shared DOFs)").arg(*mac_, 0, 'f', 3).arg(macDofs_);
}

void ModeAnimationView::setAmplitudeFactor(double factor) {
  amplitudeFactor_ = factor;
  applyAmplitude();
}

void ModeAnimationView::applyAmplitude() {
  if (scene_->hasShape()) scene_->setAmplitude(autoAmplitude_ * amplitudeFactor_);
  if (compare_->hasShape()) compare_->setAmplitude(otherAutoAmplitude_ * amplitudeFactor_);
}

double ModeAnimationView::amplitude() const {
  return scene_->amplitude();
}

void ModeAnimationView::setSpeed(double cyclesPerSecond) {
  if (!(cyclesPerSecond > 0.0)) return;
  // Keep the phase continuous when the speed changes while playing.
  if (isPlaying()) {
    phaseOffset_ = scene_->phase();
    clock_.restart();
  }
  speed_ = cyclesPerSecond;
  if (std::abs(speedSpin_->value() - cyclesPerSecond) > 1e-12) speedSpin_->setValue(cyclesPerSecond);
}

void ModeAnimationView::play() {
  if (playing_) return;
  playing_ = true;
  phaseOffset_ = scene_->phase();
  clock_.start();
  fpsClock_.start();
  fpsTicks_ = 0;
  {
    QSignalBlocker block(playButton_);
    playButton_->setChecked(true);
  }
  retranslate();
  scene_->setAnimating(true);
  compare_->setAnimating(true);
  timer_->start(0);
}

void ModeAnimationView::pause() {
  if (playing_) {
    timer_->stop();
    if (fpsClock_.isValid() && fpsClock_.elapsed() > 0) fps_ = 1000.0 * fpsTicks_ / fpsClock_.elapsed();
  }
  playing_ = false;
  scene_->setAnimating(false);
  compare_->setAnimating(false);
  {
    QSignalBlocker block(playButton_);
    playButton_->setChecked(false);
  }
  retranslate();
}

bool ModeAnimationView::isPlaying() const {
  return playing_;
}

void ModeAnimationView::setPhase(double theta) {
  pause();
  scene_->setPhase(theta);
  if (compare_->hasShape()) compare_->setPhase(theta);
}

void ModeAnimationView::setFrameInterval(int milliseconds) {
  frameInterval_ = std::max(0, milliseconds);
}

double ModeAnimationView::measuredFps() const {
  if (isPlaying() && fpsClock_.isValid() && fpsClock_.elapsed() > 0) return 1000.0 * fpsTicks_ / fpsClock_.elapsed();
  return fps_;
}

void ModeAnimationView::tick() {
  if (!isPlaying()) return;
  // theta from the elapsed time only: a slow frame skips phase, it never slows the mode.
  const double theta = std::fmod(phaseOffset_ + geo::animationPhase(clock_.nsecsElapsed() * 1e-9, speed_), 2.0 * M_PI);
  scene_->setPhase(theta);
  if (compare_->hasShape() && compare_->isVisible()) compare_->setPhase(theta);
  ++ticks_;
  ++fpsTicks_;
  timer_->start(frameInterval_);  // re-armed after the render: ticks never pile up
}

bool ModeAnimationView::exportFrame(const QString& path) {
  QImage image = scene_->grabFrame();
  if (compare_->hasShape() && compare_->isVisible()) {
    const QImage right = compare_->grabFrame();
    QImage both(image.width() + right.width(), std::max(image.height(), right.height()), QImage::Format_RGB32);
    both.fill(Qt::white);
    QPainter painter(&both);
    painter.drawImage(0, 0, image);
    painter.drawImage(image.width(), 0, right);
    painter.end();
    image = both;
  }
  if (image.isNull() || !image.save(path, "PNG")) {
    report(tr("Cannot write %1.").arg(path));
    return false;
  }
  report(tr("Frame written to %1.").arg(path));
  return true;
}

int ModeAnimationView::exportAnimation(const QString& path, int framesPerSecond) {
  if (!scene_->hasShape()) {
    report(tr("Choose a shape to export."));
    return 0;
  }
  if (framesPerSecond <= 0 || framesPerSecond > 100) {
    report(tr("The frame rate must be 1 to 100 frames per second."));
    return 0;
  }
  pause();
  // One cycle at the current speed.
  const int frames = std::clamp(static_cast<int>(std::lround(framesPerSecond / speed_)), 8, 400);
  const core::Vector phases = geo::framePhases(frames);
  const QFileInfo info(path);
  const bool gif = info.suffix().compare(QLatin1String("gif"), Qt::CaseInsensitive) == 0;
  std::vector<core::io::RgbImage> images;
  for (int k = 0; k < frames; ++k) {
    scene_->setPhase(phases[k]);
    if (compare_->hasShape() && compare_->isVisible()) compare_->setPhase(phases[k]);
    QImage image = scene_->grabFrame();
    if (gif) {
      images.push_back(toRgb(image));
    } else {
      const QString name = info.dir().filePath(
          QString::fromStdString(geo::frameFileName(info.completeBaseName().toStdString(), framesPerSecond, k)));
      if (!image.save(name, "PNG")) {
        report(tr("Cannot write %1.").arg(name));
        return 0;
      }
    }
  }
  if (gif) {
    core::io::GifOptions options;
    options.delayCentiseconds = static_cast<int>(std::lround(100.0 / framesPerSecond));
    if (auto r = core::io::writeAnimatedGif(path.toStdString(), images, options); !r) {
      report(tr("Cannot write %1: %2").arg(path, QString::fromStdString(r.error().message)));
      return 0;
    }
  }
  report(tr("%n frame(s) written.", nullptr, frames));
  return frames;
}

void ModeAnimationView::updateInfo() {
  QString info;
  if (current_ && field_) {
    info = current_->name;
    if (current_->frequencyHz > 0.0) info += tr(": %1 Hz").arg(current_->frequencyHz, 0, 'f', 2);
    if (current_->dampingRatio >= 0.0) info += tr(", zeta %1 %").arg(100.0 * current_->dampingRatio, 0, 'f', 2);
    info += QLatin1Char('\n') + tr("%1 measured, %2 slaved, %3 interpolated, %4 still nodes")
                                    .arg(field_->measuredNodes)
                                    .arg(field_->slavedNodes)
                                    .arg(field_->interpolatedNodes)
                                    .arg(field_->stillNodes);
    if (screw_) {
      const auto& u = screw_->direction;
      const auto& p = screw_->point;
      info +=
          QLatin1Char('\n') + tr("Mozzi (screw) axis: pitch %1 m/rad, direction (%2, %3, %4), through (%5, %6, %7) m")
                                  .arg(screw_->pitch, 0, 'g', 3)
                                  .arg(u.x(), 0, 'f', 3)
                                  .arg(u.y(), 0, 'f', 3)
                                  .arg(u.z(), 0, 'f', 3)
                                  .arg(p.x(), 0, 'f', 4)
                                  .arg(p.y(), 0, 'f', 4)
                                  .arg(p.z(), 0, 'f', 4);
      if (screw_->lowConfidence)
        info += QLatin1Char(' ') + tr("(low confidence: %1)").arg(QString::fromStdString(screw_->note));
    } else if (!screwProblem_.isEmpty()) {
      info += QLatin1Char('\n') + tr("No Mozzi axis: %1").arg(screwProblem_);
    }
  } else {
    info = tr("Choose a mode to animate.");
  }
  infoLabel_->setText(info);
  shapeTitle_->setText(current_ ? current_->name : QString());
  compareTitle_->setText(other_ ? other_->name : QString());
  macLabel_->setText(macText());
  macLabel_->setVisible(!macLabel_->text().isEmpty());
}

void ModeAnimationView::report(const QString& text) {
  emit message(text);
  infoLabel_->setToolTip(text);
}

void ModeAnimationView::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) {
    retranslate();
    fillCombos();
    updateInfo();
  }
  QWidget::changeEvent(event);
}

void ModeAnimationView::retranslate() {
  shapeLabel_->setText(tr("Shape"));
  compareLabel_->setText(tr("Beside it"));
  odsLabel_->setText(tr("ODS at"));
  odsButton_->setText(tr("Show"));
  odsButton_->setToolTip(tr("Operating deflection shape of the FRF set at the line nearest this frequency"));
  odsPlot_->setToolTip(tr("Click (or use the arrow keys) to animate the operating deflection shape at that frequency"));
  // Axis titles in the controls' own font: Qwt's default bold title is too
  // large for a plot this small.
  for (const auto& [axis, text] : {std::pair<int, QString>{QwtPlot::xBottom, tr("Frequency [Hz]")},
                                   std::pair<int, QString>{QwtPlot::yLeft, tr("sum of |H| [dB]")}}) {
    QwtText title(text);
    title.setFont(odsPlot_->font());
    odsPlot_->setAxisTitle(axis, title);
  }
  amplitudeLabel_->setText(tr("Amplitude"));
  amplitudeSlider_->setToolTip(tr("0.1x to 10x the automatic amplitude (largest displacement 10 % of the mesh)"));
  speedLabel_->setText(tr("Cycles/s"));
  colourCheck_->setText(tr("Colour by displacement"));
  undeformedCheck_->setText(tr("Undeformed overlay"));
  arrowsCheck_->setText(tr("Arrows at measured nodes"));
  screwCheck_->setText(tr("Mozzi (screw) axis"));
  screwCheck_->setToolTip(
      tr("The screw axis of the rigid motion fitted to the shape's measured translations, with its "
         "pitch (thesis §1.5)"));
  playButton_->setText(isPlaying() ? tr("Pause (Space)") : tr("Play (Space)"));
  frameButton_->setText(tr("Export frame…"));
  animationButton_->setText(tr("Export animation…"));
  animationButton_->setToolTip(tr("One cycle as an animated GIF or numbered PNG files (25 frames/s)"));
}

}  // namespace views
}  // namespace mozzi
