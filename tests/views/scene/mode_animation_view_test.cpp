// Mode-shape animation driven as a user does. Checked against numbers worked
// here, independently of core::geometry: the VTK points of the deformed
// layer at a phase equal base + A Im(u e^{i theta}) to 1e-9 m (u the measured
// values, and the mean of the two neighbours for the free nodes halfway along
// the legs); the side-by-side view shows the MAC computed here from its
// definition; the ODS is the FRF column at the nearest line; PNG, GIF and PNG
// sequence exports read back. The speed test animates a 20,000-node mesh and
// reports frames per second. Screenshots: mode_animation*.png.
#include "views/scene/mode_animation_view.h"

#include <qwt_plot_curve.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QImageReader>
#include <QLabel>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <ctime>

#include "views/plots/interactive_plot.h"
#include "views/scene/scene_view.h"

using mozzi::core::Complex;
using mozzi::core::ComplexVector;
using mozzi::core::Dof;
using mozzi::core::Vector3;
using mozzi::core::io::MeshDocument;
using mozzi::views::ModeAnimationView;

namespace {

Dof dof(int node, mozzi::core::Direction d) {
  return Dof{node, d, false};
}

// A fork: two legs of five nodes 100 mm apart along z at x = 0 and y = 0 / 0.2,
// a crown line joining the tops. X is measured at nodes 1, 3, 5 (leg 1) and
// 6, 8, 10 (leg 2); 2, 4, 7, 9 sit halfway between measured nodes.
MeshDocument fork() {
  MeshDocument d;
  for (int leg = 0; leg < 2; ++leg)
    for (int k = 0; k < 5; ++k) {
      mozzi::core::io::StoredNode n;
      n.label = 1 + k + 5 * leg;
      n.position = Vector3(0.0, 0.2 * leg, 0.1 * k);
      d.mesh.nodes.push_back(n);
      if (k > 0) d.mesh.lines.push_back({n.label - 1, n.label});
    }
  d.mesh.lines.push_back({5, 10});
  return d;
}

const std::vector<int> kMeasured = {1, 3, 5, 6, 8, 10};

ModeAnimationView::Shape shape(const QString& name, double f, const std::vector<Complex>& x) {
  ModeAnimationView::Shape s;
  s.name = name;
  s.frequencyHz = f;
  s.dampingRatio = 0.012;
  for (int n : kMeasured) s.dofs.push_back(dof(n, mozzi::core::Direction::X));
  s.values = Eigen::Map<const ComplexVector>(x.data(), static_cast<Eigen::Index>(x.size()));
  return s;
}

// Mode 1: legs bend in phase; mode 2: complex, legs in quadrature; mode 3:
// mode 1 with the wheel (tips stiffened).
std::vector<ModeAnimationView::Shape> shapes() {
  return {shape(QStringLiteral("Mode 1"), 41.5, {0.0, 0.5, 1.0, 0.0, 0.5, 1.0}),
          shape(QStringLiteral("Mode 2"), 97.0,
                {0.0, Complex(0.4, 0.1), Complex(0.9, 0.3), 0.0, Complex(-0.1, 0.4), Complex(-0.3, 0.9)}),
          shape(QStringLiteral("Mode 1 with wheel"), 36.2, {0.05, 0.55, 0.8, 0.02, 0.45, 0.85})};
}

double macByDefinition(const ComplexVector& a, const ComplexVector& b) {
  const Complex ab = a.dot(b);  // a^H b
  return std::norm(ab) / (a.squaredNorm() * b.squaredNorm());
}

QString screenshotPath(const QString& name) {
  const QString folder = qEnvironmentVariable("MOZZI_SCREENSHOT_DIR", QDir::tempPath());
  QDir().mkpath(folder);
  QString file = name;
  if (qApp->devicePixelRatio() > 1.0) file.replace(QStringLiteral(".png"), QStringLiteral("@2x.png"));
  return QDir(folder).filePath(file);
}

}  // namespace

class ModeAnimationViewTest : public QObject {
  Q_OBJECT
 private slots:
  void vertexPositionsAtAPhaseAreShapeTimesScale();
  void sideBySideShowsTheMac();
  void odsIsTheFrfColumnAtTheNearestLine();
  void exportsFramesGifAndPngSequence();
  void twentyThousandNodesAnimateFast();
  void odsFollowsThePlotCursor();
  void odsOfARovingHammerSetMovesTheHammerPoints();
  void theShapeStaysInTheViewport();
};

void ModeAnimationViewTest::vertexPositionsAtAPhaseAreShapeTimesScale() {
  ModeAnimationView view;
  view.resize(1280, 800);
  view.show();
  QVERIFY(QTest::qWaitForWindowExposed(&view));
  QTRY_VERIFY(view.scene()->isReady());  // the 3-D window is a native child: exposed a moment later
  view.setMesh(fork());
  view.setShapes(shapes());
  QVERIFY(view.showShape(1));  // the complex mode
  const auto& s = view.shapes()[1];
  // u per node row (X only): measured values, free nodes the mean of their neighbours.
  std::vector<Complex> ux(10);
  for (std::size_t k = 0; k < kMeasured.size(); ++k) ux[static_cast<std::size_t>(kMeasured[k] - 1)] = s.values[k];
  ux[1] = 0.5 * (ux[0] + ux[2]);
  ux[3] = 0.5 * (ux[2] + ux[4]);
  ux[6] = 0.5 * (ux[5] + ux[7]);
  ux[8] = 0.5 * (ux[7] + ux[9]);
  const MeshDocument mesh = fork();
  const double amplitude = view.amplitude();
  QVERIFY(amplitude > 0.0);
  for (double theta : {0.0, 0.7, M_PI / 2, 2.5, 4.0}) {
    view.setPhase(theta);
    vtkPoints* points = view.scene()->deformedPoints();
    QCOMPARE(points->GetNumberOfPoints(), vtkIdType{10});
    for (vtkIdType i = 0; i < 10; ++i) {
      double p[3];
      points->GetPoint(i, p);
      const Vector3 base = mesh.mesh.nodes[static_cast<std::size_t>(i)].position;
      const double x = base.x() + amplitude * (ux[static_cast<std::size_t>(i)] * std::polar(1.0, theta)).imag();
      QVERIFY2(std::abs(p[0] - x) < 1e-9, qPrintable(QStringLiteral("node row %1 theta %2: %3 vs %4")
                                                         .arg(i)
                                                         .arg(theta)
                                                         .arg(p[0], 0, 'g', 17)
                                                         .arg(x, 0, 'g', 17)));
      QVERIFY(std::abs(p[1] - base.y()) < 1e-9);
      QVERIFY(std::abs(p[2] - base.z()) < 1e-9);
    }
  }
  // The largest displacement is 10 % of the fork's diagonal at factor 1; the
  // colour range runs from 0 to it.
  const double diagonal = std::hypot(0.2, 0.4);
  const double peak = std::abs(Complex(-0.3, 0.9));  // |u| of node 10, the largest
  QVERIFY(std::abs(amplitude - 0.1 * diagonal / peak) < 1e-12);
  QVERIFY(std::abs(view.scene()->colourRange().max - 0.1 * diagonal) < 1e-12);
  // Doubling the amplitude doubles the displacement.
  view.setAmplitudeFactor(2.0);
  QVERIFY(std::abs(view.amplitude() - 2 * amplitude) < 1e-15);
  const auto* field = view.field();
  QVERIFY(field);
  QCOMPARE(field->measuredNodes, 6);
  QCOMPARE(field->interpolatedNodes, 4);
  QVERIFY(view.findChild<QLabel*>(QStringLiteral("animationInfo"))->text().contains(QStringLiteral("97.00 Hz")));
}

void ModeAnimationViewTest::sideBySideShowsTheMac() {
  ModeAnimationView view;
  view.resize(1280, 800);
  view.show();
  QVERIFY(QTest::qWaitForWindowExposed(&view));
  QTRY_VERIFY(view.scene()->isReady());  // the 3-D window is a native child: exposed a moment later
  view.setMesh(fork());
  view.setShapes(shapes());
  QVERIFY(view.showShape(0));
  QVERIFY(view.compareWith(2));
  QVERIFY(view.compareScene()->isVisible());
  const double expected = macByDefinition(view.shapes()[0].values, view.shapes()[2].values);
  QVERIFY(view.mac().has_value());
  QVERIFY(std::abs(*view.mac() - expected) < 1e-12);
  const QString text = view.findChild<QLabel*>(QStringLiteral("animationMac"))->text();
  QCOMPARE(text, QStringLiteral("MAC %1 (6 shared DOFs)").arg(expected, 0, 'f', 3));
  QVERIFY2(text.startsWith(QStringLiteral("MAC 0.98")), qPrintable(text));  // same mode, stiffer tip
  QVERIFY(view.compareScene()->width() > 300);                              // really beside it, not squeezed to nothing
  // Switching the left shape recomputes the MAC against the new one.
  QVERIFY(view.showShape(1));
  QVERIFY(std::abs(*view.mac() - macByDefinition(view.shapes()[1].values, view.shapes()[2].values)) < 1e-12);
  QVERIFY(view.showShape(0));
  view.findChild<QCheckBox*>(QStringLiteral("animationArrowsCheck"))->setChecked(true);
  view.setPhase(M_PI / 2);
  QVERIFY(view.findChild<QLabel*>(QStringLiteral("animationScene") + QStringLiteral("Title"))->text() ==
          QStringLiteral("Mode 1"));
  QTRY_VERIFY(view.compareScene()->isReady());
  QVERIFY(view.grab().save(screenshotPath(QStringLiteral("mode_animation_side_by_side.png"))));
  QVERIFY(view.compareWith(-1));
  QVERIFY(!view.mac().has_value());
  QVERIFY(!view.compareScene()->isVisible());
}

// An FRF set on the fork's measured X DOFs, 0-200 Hz in 1 Hz lines, reference node 5.
static mozzi::core::FrfMatrix forkFrf() {
  mozzi::core::FrfMatrix frf;
  frf.frequencyHz = mozzi::core::Vector::LinSpaced(201, 0.0, 200.0);
  for (int n : kMeasured) frf.responses.push_back(dof(n, mozzi::core::Direction::X));
  frf.references = {dof(5, mozzi::core::Direction::X)};
  mozzi::core::ComplexMatrix h(201, 6);
  for (int k = 0; k < 201; ++k)
    for (int o = 0; o < 6; ++o) h(k, o) = Complex(std::cos(0.01 * k * (o + 1)), std::sin(0.02 * k)) * double(o % 3);
  frf.h = {h};
  return frf;
}

void ModeAnimationViewTest::odsIsTheFrfColumnAtTheNearestLine() {
  ModeAnimationView view;
  view.setMesh(fork());
  const mozzi::core::FrfMatrix frf = forkFrf();
  const mozzi::core::ComplexMatrix& h = frf.h[0];
  view.setFrfSet(std::make_shared<const mozzi::core::FrfMatrix>(frf), QStringLiteral("fork-a.uff"));
  QVERIFY(view.showOds(41.4));  // nearest line 41 Hz
  const double amplitude = view.amplitude();
  view.setPhase(M_PI / 2);  // sin = 1, cos = 0: displacement = A Re(u)
  double p[3];
  view.scene()->deformedPoints()->GetPoint(4, p);  // node 5 = response 3
  QVERIFY(std::abs(p[0] - amplitude * h(41, 2).real()) < 1e-9);
  QVERIFY(view.findChild<QLabel*>(QStringLiteral("animationInfo"))->text().contains(QStringLiteral("41.00 Hz")));
}

void ModeAnimationViewTest::exportsFramesGifAndPngSequence() {
  QTemporaryDir dir;
  ModeAnimationView view;
  view.resize(1280, 800);
  view.show();
  QVERIFY(QTest::qWaitForWindowExposed(&view));
  QTRY_VERIFY(view.scene()->isReady());  // the 3-D window is a native child: exposed a moment later
  view.setMesh(fork());
  view.setShapes(shapes());
  QVERIFY(view.showShape(0));
  const QString png = dir.filePath(QStringLiteral("frame.png"));
  QVERIFY(view.exportFrame(png));
  const QImage frame(png);
  QVERIFY(!frame.isNull());
  const QSize sceneSize = view.scene()->size() * view.devicePixelRatioF();
  QCOMPARE(frame.size(), sceneSize);
  QVERIFY(frame.save(screenshotPath(QStringLiteral("mode_animation_frame.png"))));

  view.setSpeed(1.0);
  const QString gif = dir.filePath(QStringLiteral("mode1.gif"));
  QCOMPARE(view.exportAnimation(gif, 25), 25);  // one cycle at 1 cycle/s, 25 frames/s
  QImageReader reader(gif);
  QVERIFY2(reader.canRead(), qPrintable(reader.errorString()));
  QCOMPARE(reader.imageCount(), 25);
  const QImage first = reader.read();
  QCOMPARE(reader.nextImageDelay(), 40);  // ms, known once a frame is read
  QCOMPARE(first.size(), sceneSize);
  // The GIF frame is the rendered frame at theta = 0 within the palette's
  // step and the dither (a 6 x 7 x 6 cube: at most 51 per channel, so the
  // average over a block stays within 26).
  view.setPhase(0.0);
  const QImage rendered = view.scene()->grabFrame().convertToFormat(QImage::Format_RGB32);
  const QImage decoded = first.convertToFormat(QImage::Format_RGB32);
  double worst = 0.0;
  for (int by = 0; by + 8 <= decoded.height(); by += 64)
    for (int bx = 0; bx + 8 <= decoded.width(); bx += 64) {
      double diff[3] = {0, 0, 0};
      for (int y = by; y < by + 8; ++y)
        for (int x = bx; x < bx + 8; ++x) {
          const QColor a = rendered.pixelColor(x, y), b = decoded.pixelColor(x, y);
          diff[0] += a.red() - b.red();
          diff[1] += a.green() - b.green();
          diff[2] += a.blue() - b.blue();
        }
      for (double d : diff) worst = std::max(worst, std::abs(d) / 64.0);
    }
  QVERIFY2(worst < 26.0, qPrintable(QString::number(worst)));

  const QString sequence = dir.filePath(QStringLiteral("mode1.png"));
  view.setSpeed(2.5);
  QCOMPARE(view.exportAnimation(sequence, 25), 10);
  QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("mode1_25fps_0000.png"))));
  QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("mode1_25fps_0009.png"))));
  QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("mode1_25fps_0010.png"))));
}

void ModeAnimationViewTest::twentyThousandNodesAnimateFast() {
  // A 200 x 100 plate, 5 mm pitch, trace lines both ways (39,700 segments),
  // Z measured at one node in ten along each direction (200 nodes), the rest
  // interpolated.
  const int nx = 200, ny = 100;
  MeshDocument plate;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      mozzi::core::io::StoredNode n;
      n.label = 1 + i + nx * j;
      n.position = Vector3(0.005 * i, 0.005 * j, 0.0);
      plate.mesh.nodes.push_back(n);
      if (i > 0) plate.mesh.lines.push_back({n.label - 1, n.label});
      if (j > 0) plate.mesh.lines.push_back({n.label - nx, n.label});
    }
  ModeAnimationView::Shape s;
  s.name = QStringLiteral("Plate mode (1,1)");
  s.frequencyHz = 120.0;
  std::vector<Complex> values;
  for (int j = 0; j < ny; j += 10)
    for (int i = 0; i < nx; i += 10) {
      s.dofs.push_back(dof(1 + i + nx * j, mozzi::core::Direction::Z));
      values.push_back(std::sin(M_PI * i / (nx - 1)) * std::sin(M_PI * j / (ny - 1)));
    }
  s.values = Eigen::Map<const ComplexVector>(values.data(), static_cast<Eigen::Index>(values.size()));
  ModeAnimationView view;
  view.resize(1280, 800);
  view.show();
  QVERIFY(QTest::qWaitForWindowExposed(&view));
  QTRY_VERIFY(view.scene()->isReady());  // the 3-D window is a native child: exposed a moment later
  QElapsedTimer setup;
  setup.start();
  view.setMesh(plate);
  view.setShapes({s});
  QVERIFY(view.showShape(0));
  const qint64 setupMs = setup.elapsed();
  QCOMPARE(view.scene()->deformedPoints()->GetNumberOfPoints(), vtkIdType{20000});
  {  // Where a frame's time goes: the VTK render, then Qt composing the window.
    static int renders = 0;
    vtkNew<vtkCallbackCommand> counter;
    counter->SetCallback([](vtkObject*, unsigned long, void*, void*) { ++renders; });
    view.scene()->renderer()->GetRenderWindow()->AddObserver(vtkCommand::EndEvent, counter);
    double a = 0, b = 0;
    for (int k = 0; k < 10; ++k) {
      const std::clock_t c0 = std::clock();
      view.scene()->setPhase(0.3 * k);
      const std::clock_t c1 = std::clock();
      QCoreApplication::processEvents();
      const std::clock_t c2 = std::clock();
      a += double(c1 - c0);
      b += double(c2 - c1);
    }
    qInfo("per frame: setPhase (deform + VTK render) %.1f ms CPU, Qt composition %.1f ms CPU (%d renders for 10)",
          100.0 * a / CLOCKS_PER_SEC, 100.0 * b / CLOCKS_PER_SEC, renders);
    view.scene()->renderer()->GetRenderWindow()->RemoveObserver(counter);
  }
  view.setFrameInterval(0);  // as fast as it goes
  view.setSpeed(1.0);
  QVERIFY(view.scene()->undeformedShown());
  view.play();
  // Above 5,000 nodes the overlay waits for a pause (it costs as much per
  // frame as the moving shape under llvmpipe; docs/performance/scene.md).
  QVERIFY(view.scene()->isAnimating());
  QVERIFY(!view.scene()->undeformedShown());
  QTest::qWait(500);  // warm-up (shader compilation, first uploads)
  view.pause();
  const int ticksBefore = view.ticks();
  const std::clock_t cpuBefore = std::clock();
  view.play();
  QTest::qWait(4000);
  view.pause();
  const double cpuSeconds = double(std::clock() - cpuBefore) / CLOCKS_PER_SEC;
  const int frames = view.ticks() - ticksBefore;
  const double fps = view.measuredFps();
  const double cpuMsPerFrame = 1000.0 * cpuSeconds / std::max(frames, 1);
  // Process CPU time covers the GUI thread and llvmpipe's rasterizer threads.
  qInfo(
      "20,000-node mesh: %.1f frames/s wall (%.1f ms per frame), %.1f ms CPU per frame, %d frames; "
      "shape set-up %lld ms",
      fps, 1000.0 / fps, cpuMsPerFrame, frames, static_cast<long long>(setupMs));
  QVERIFY(!view.scene()->isAnimating());
  QVERIFY(view.scene()->undeformedShown());  // paused: the overlay is back
  QVERIFY(view.grab().save(screenshotPath(QStringLiteral("mode_animation_20k.png"))));
  // Issue 21 asks for 30 frames per second under llvmpipe on the 2-core
  // machine, i.e. at most 33 ms per frame. Measured at 1280 x 800 while
  // playing: 18-19 ms of CPU per frame (GUI thread and llvmpipe's two
  // rasterizer threads together) under a load of 9, against 43-44 ms before
  // the native 3-D window, the colours set once and the overlay waiting for
  // a pause (docs/performance/scene.md). The
  // wall rate depends on what else the machine runs, so the guard is on CPU
  // time, with room for a loaded machine (CPU time per frame grows under
  // contention too): 75 ms. The overlay's return while playing is checked
  // above by state, not by time.
  QVERIFY2(cpuMsPerFrame <= 75.0, qPrintable(QStringLiteral("%1 ms CPU per frame").arg(cpuMsPerFrame)));
}

void ModeAnimationViewTest::odsFollowsThePlotCursor() {
  ModeAnimationView view;
  view.resize(1280, 800);
  view.show();
  QVERIFY(QTest::qWaitForWindowExposed(&view));
  view.setMesh(fork());
  QVERIFY(view.odsPlot()->isHidden());  // no FRF set yet
  const mozzi::core::FrfMatrix frf = forkFrf();
  view.setFrfSet(std::make_shared<const mozzi::core::FrfMatrix>(frf), QStringLiteral("fork-a.uff"));
  QVERIFY(view.odsPlot()->isVisible());
  QVERIFY(!view.scene()->hasShape());  // the set alone shows nothing yet
  // The curve is the sum of |H| over the set's FRFs in dB, line by line.
  auto* curve = dynamic_cast<QwtPlotCurve*>(view.odsPlot()->itemList(QwtPlotItem::Rtti_PlotCurve).value(0));
  QVERIFY(curve);
  QCOMPARE(static_cast<Eigen::Index>(curve->dataSize()), frf.lineCount());
  const double sum80 = frf.h[0].row(80).cwiseAbs().sum();
  QVERIFY(std::abs(curve->sample(80).y() - 20.0 * std::log10(sum80)) < 1e-9);
  // Placing the cursor (as a click does) animates the ODS at the nearest line.
  view.odsPlot()->setCursor(120.3);
  QVERIFY(view.scene()->hasShape());
  QVERIFY2(view.findChild<QLabel*>(QStringLiteral("animationInfo"))->text().contains(QStringLiteral("120.00 Hz")),
           qPrintable(view.findChild<QLabel*>(QStringLiteral("animationInfo"))->text()));
  QCOMPARE(view.odsPlot()->cursor().value_or(-1.0), 120.0);  // moved onto the line used
  const double amplitude = view.amplitude();
  view.setPhase(M_PI / 2);  // sin = 1, cos = 0: displacement = A Re(u)
  double p[3];
  view.scene()->deformedPoints()->GetPoint(4, p);  // node 5 = response 3
  QVERIFY(std::abs(p[0] - amplitude * frf.h[0](120, 2).real()) < 1e-9);
  // Stepping the cursor with the keys moves the ODS one line on.
  view.odsPlot()->stepCursor(1);
  QVERIFY(view.findChild<QLabel*>(QStringLiteral("animationInfo"))->text().contains(QStringLiteral("121.00 Hz")));
  QVERIFY(view.grab().save(screenshotPath(QStringLiteral("mode_animation_ods.png"))));
}

// The same FRFs measured the other way round: one accelerometer at 5:+X, the
// hammer roved over the six points. The guide sums every FRF, the ODS moves the
// hammer points (reciprocity) with the values of the column above, and the
// shape says where it is driven. A set taken away disables the ODS again.
void ModeAnimationViewTest::odsOfARovingHammerSetMovesTheHammerPoints() {
  ModeAnimationView view;
  view.resize(1280, 800);
  view.show();
  QVERIFY(QTest::qWaitForWindowExposed(&view));
  view.setMesh(fork());
  const mozzi::core::FrfMatrix column = forkFrf();
  const mozzi::core::FrfMatrix roving = column.transposed();
  QCOMPARE(roving.referenceCount(), Eigen::Index(6));
  view.setFrfSet(std::make_shared<const mozzi::core::FrfMatrix>(roving), QStringLiteral("fork-hammer.uff"));
  auto* curve = dynamic_cast<QwtPlotCurve*>(view.odsPlot()->itemList(QwtPlotItem::Rtti_PlotCurve).value(0));
  QVERIFY(curve);
  const double sum80 = column.h[0].row(80).cwiseAbs().sum();  // every FRF of the set, not reference 0's alone
  QVERIFY(std::abs(curve->sample(80).y() - 20.0 * std::log10(sum80)) < 1e-9);
  QVERIFY(view.showOds(41.4));
  const QString info = view.findChild<QLabel*>(QStringLiteral("animationInfo"))->text();
  QVERIFY2(info.contains(QStringLiteral("41.00 Hz")) && info.contains(QStringLiteral("5:+X")), qPrintable(info));
  const double amplitude = view.amplitude();
  view.setPhase(M_PI / 2);
  double p[3];
  view.scene()->deformedPoints()->GetPoint(4, p);  // node 5 = hammer point 3
  QVERIFY(std::abs(p[0] - amplitude * column.h[0](41, 2).real()) < 1e-9);
  auto* button = view.findChild<QPushButton*>(QStringLiteral("animationOdsButton"));
  QVERIFY(button && button->isEnabled());
  view.setFrfSet(nullptr, {});
  QVERIFY(!button->isEnabled());
  QVERIFY(view.odsPlot()->isHidden());
  QVERIFY(!view.showOds(41.4));
}

int main(int argc, char** argv) {
  mozzi::views::SceneView::prepareSurfaceFormat();
  QApplication app(argc, argv);
  ModeAnimationViewTest test;
  return QTest::qExec(&test, argc, argv);
}

// Every deformed point over a cycle is projected inside the 3-D viewport
// (VTK's world to display transform): after the shape is shown, after a
// resize to a tall narrow view, and at three times the amplitude; once the
// user has turned the camera, a resize leaves it where the user put it.
void ModeAnimationViewTest::theShapeStaysInTheViewport() {
  ModeAnimationView view;
  view.resize(1280, 800);
  view.show();
  QVERIFY(QTest::qWaitForWindowExposed(&view));
  QTRY_VERIFY(view.scene()->isReady());
  view.setMesh(fork());
  view.setShapes(shapes());
  QVERIFY(view.showShape(1));
  mozzi::views::SceneView* scene = view.scene();
  auto outside = [&] {
    QTest::qWait(50);  // the reframing queued by a resize
    vtkRenderer* renderer = scene->renderer();
    const int* size = renderer->GetSize();
    int out = 0;
    for (int k = 0; k < 16; ++k) {
      view.setPhase(k * M_PI / 8.0);
      vtkPoints* points = scene->deformedPoints();
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
        double p[3], d[3];
        points->GetPoint(i, p);
        renderer->SetWorldPoint(p[0], p[1], p[2], 1.0);
        renderer->WorldToDisplay();
        renderer->GetDisplayPoint(d);
        if (d[0] < 0.0 || d[0] > size[0] || d[1] < 0.0 || d[1] > size[1]) ++out;
      }
    }
    return out;
  };
  QCOMPARE(outside(), 0);
  view.resize(700, 900);  // the scene narrower than tall
  // The native 3-D window gets its new size from the X server, later than the
  // widget under load: the framing is checked once it has.
  QTRY_COMPARE_WITH_TIMEOUT(outside(), 0, 3000);
  view.setAmplitudeFactor(3.0);
  QCOMPARE(outside(), 0);
  // The box the shape sweeps holds every deformed point.
  const auto b = scene->drawnBounds();
  for (int k = 0; k < 8; ++k) {
    view.setPhase(k * M_PI / 4.0);
    vtkPoints* points = scene->deformedPoints();
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
      double p[3];
      points->GetPoint(i, p);
      for (int c = 0; c < 3; ++c) QVERIFY(p[c] >= b[2 * c] - 1e-12 && p[c] <= b[2 * c + 1] + 1e-12);
    }
  }
  // A camera the user moved stays.
  scene->renderer()->GetActiveCamera()->Azimuth(30.0);
  double before[3], after[3];
  scene->renderer()->GetActiveCamera()->GetPosition(before);
  view.resize(900, 700);
  QTest::qWait(50);
  scene->renderer()->GetActiveCamera()->GetPosition(after);
  for (int c = 0; c < 3; ++c) QCOMPARE(after[c], before[c]);
}

#include "mode_animation_view_test.moc"
