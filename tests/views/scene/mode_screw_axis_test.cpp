// The Mozzi (screw) axis of a mode in the Mode Animation page's 3-D scene
// (issue 22; thesis §1.5). A project holds a mesh measured triaxially at
// eight nodes and a modal result whose modes are rigid screw motions about
// axes chosen here (direction u, a point q, pitch h, a complex common phase):
// the page must draw, for the selected mode, a line whose end points lie on
// that axis (1e-9 m), label it with that pitch, hide it with its check box,
// follow the selected mode, and say why a mode measured along one direction
// only has no axis. Independent source: the analytic motion
//   d(p) = theta u x (p - q) + h theta u,
// written into the stored mode shape. Screenshot: mode_screw_axis (and @2x
// under QT_SCALE_FACTOR=2).
#include <QApplication>
#include <QCheckBox>
#include <QLabel>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <tuple>

#include "core/io/project_store.h"
#include "views/common/project_model.h"
#include "views/scene/mode_animation_page.h"
#include "views/scene/mode_animation_view.h"
#include "views/scene/scene_view.h"
#include "views/scene/screw_axis_layer.h"
#include "views/screenshot.h"

using mozzi::core::Complex;
using mozzi::core::Dof;
using mozzi::core::Vector3;
namespace io = mozzi::core::io;
using mozzi::views::ModeAnimationPage;
using mozzi::views::ProjectModel;

namespace {

struct Screw {
  Vector3 u, q;
  double h;  // [m/rad]
  double distance(const Vector3& p) const { return (p - q).cross(u).norm(); }
};

// A frame-like cage: four nodes at z = 0 and four at z = 0.4 m, joined by lines.
const Vector3 kNodes[] = {{0, 0, 0},         {0.3, 0, 0},       {0.3, 0.2, 0},     {0, 0.2, 0},
                          {0.05, 0.02, 0.4}, {0.25, 0.02, 0.4}, {0.25, 0.18, 0.4}, {0.05, 0.18, 0.4}};

io::StoredMesh cage() {
  io::StoredMesh m;
  for (int i = 0; i < 8; ++i) {
    io::StoredNode n;
    n.label = i + 1;
    n.position = kNodes[i];
    m.nodes.push_back(n);
  }
  for (int i = 0; i < 4; ++i) {
    m.lines.push_back({i + 1, (i + 1) % 4 + 1});
    m.lines.push_back({i + 5, (i + 1) % 4 + 5});
    m.lines.push_back({i + 1, i + 5});
  }
  return m;
}

// The mode of a rigid screw motion, theta = 0.01 rad, times e^{i phase}; `dirs`
// the measured directions (1 = X .. 3 = Z).
io::StoredMode mode(const Screw& s, double phase, double f, std::vector<Dof>& dofs, int dirs = 3) {
  io::StoredMode m;
  m.frequencyHz = f;
  m.dampingRatio = 0.01;
  std::vector<Complex> v;
  dofs.clear();
  for (int i = 0; i < 8; ++i) {
    const Vector3 d = 0.01 * s.u.cross(kNodes[i] - s.q) + s.h * 0.01 * s.u;
    for (int k = 0; k < 3; ++k) {
      dofs.push_back(Dof{i + 1, static_cast<mozzi::core::Direction>(k + 1), false});
      v.push_back(k < dirs ? d(k) * std::polar(1.0, phase) : Complex(0.0));
    }
  }
  m.shape = Eigen::Map<const mozzi::core::ComplexVector>(v.data(), static_cast<Eigen::Index>(v.size()));
  return m;
}

}  // namespace

class ModeScrewAxisTest : public QObject {
  Q_OBJECT
 private slots:
  void theSelectedModesScrewAxisIsDrawnWithItsPitch() {
    QTemporaryDir dir;
    ProjectModel model;
    QVERIFY(model.create(dir.filePath(QStringLiteral("screw.mozzi"))).ok());
    auto& store = *model.store();
    auto specimen = store.addSpecimen("cage", "frame", "eight triaxial nodes");
    QVERIFY(specimen.ok());
    QVERIFY(store.setMesh(*specimen, cage()).ok());
    const Screw bend{Vector3(0.2, 0.1, 1.0).normalized(), Vector3(0.1, 0.05, 0.2), 0.05};
    const Screw tors{Vector3(1.0, 0.0, 0.1).normalized(), Vector3(0.0, 0.1, 0.3), -0.02};
    io::ModalTable table;
    table.modes.push_back(mode(bend, 0.3, 26.0, table.dofs));
    table.modes.push_back(mode(tors, -1.2, 60.0, table.dofs));
    // The third mode: only X measured (Y and Z zero would be readings too, so
    // keep X alone in a table of its own).
    io::ModalTable xOnly;
    xOnly.modes.push_back(mode(bend, 0.0, 80.0, xOnly.dofs, 3));
    std::vector<Dof> xs;
    mozzi::core::ComplexVector xv(8);
    for (int i = 0; i < 8; ++i) {
      xs.push_back(xOnly.dofs[static_cast<std::size_t>(3 * i)]);
      xv(i) = xOnly.modes[0].shape(3 * i);
    }
    xOnly.dofs = xs;
    xOnly.modes[0].shape = xv;
    io::ModalResultInfo info;
    info.specimenId = *specimen;
    info.name = "rigid screws";
    info.method = "analytic";
    info.modeCount = 2;
    auto id = store.addModalResult(info, table);
    QVERIFY(id.ok());
    info.name = "X only";
    info.modeCount = 1;
    QVERIFY(store.addModalResult(info, xOnly).ok());

    ModeAnimationPage page(&model, *id);
    page.resize(1280, 800);
    page.show();
    QVERIFY(QTest::qWaitForWindowExposed(&page));
    auto* view = page.view();
    QTRY_VERIFY(view->scene()->isReady());
    QVERIFY(view->showShape(0));
    auto* layer = view->screwAxisLayer();
    for (const auto& [index, screw, name] :
         {std::tuple<int, Screw, const char*>{0, bend, "mode 1"}, {1, tors, "mode 2"}}) {
      QVERIFY(view->showShape(index));
      QVERIFY2(view->screwAxis().has_value(), qPrintable(view->screwAxisProblem()));
      QVERIFY(layer->hasAxis() && layer->isVisible());
      const auto [a, b] = layer->endpoints();
      qInfo("%s: ends (%.4f, %.4f, %.4f) and (%.4f, %.4f, %.4f) m, %.2e and %.2e m off the axis; pitch %.6f m/rad",
            name, a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), screw.distance(a), screw.distance(b),
            view->screwAxis()->pitch);
      QVERIFY(screw.distance(a) < 1e-9 && screw.distance(b) < 1e-9);
      // A stretch as long as the mesh's diagonal, along u.
      QVERIFY(std::abs((b - a).norm() - Vector3(0.3, 0.2, 0.4).norm()) < 1e-9);
      QVERIFY(std::abs(std::abs((b - a).normalized().dot(screw.u)) - 1.0) < 1e-12);
      QVERIFY(std::abs(view->screwAxis()->pitch - screw.h) < 1e-9);
      QCOMPARE(layer->text(), QStringLiteral("Mozzi axis, pitch %1 m/rad").arg(screw.h, 0, 'g', 3));
      const auto* infoLabel = view->findChild<QLabel*>(QStringLiteral("animationInfo"));
      QVERIFY(infoLabel->text().contains(QStringLiteral("Mozzi (screw) axis: pitch")));
      if (index == 0) {
        view->setPhase(1.2);
        QVERIFY(mozzi::views::test::saveShot(page, QStringLiteral("mode_screw_axis"), 200));
      }
    }
    // The check box hides and shows it.
    view->screwAxisCheck()->setChecked(false);
    QVERIFY(!layer->isVisible());
    view->screwAxisCheck()->setChecked(true);
    QVERIFY(layer->isVisible() && layer->hasAxis());
    // Measured along X only: no rigid motion is determined, and the page says so.
    QVERIFY(view->showShape(2));
    QVERIFY(!view->screwAxis());
    QVERIFY(!layer->hasAxis());
    QVERIFY2(view->screwAxisProblem().contains(QStringLiteral("unseen")), qPrintable(view->screwAxisProblem()));
    QVERIFY(
        view->findChild<QLabel*>(QStringLiteral("animationInfo"))->text().contains(QStringLiteral("No Mozzi axis")));
  }
};

int main(int argc, char** argv) {
  mozzi::views::SceneView::prepareSurfaceFormat();
  QApplication app(argc, argv);
  ModeScrewAxisTest test;
  return QTest::qExec(&test, argc, argv);
}
#include "mode_screw_axis_test.moc"
