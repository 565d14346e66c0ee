// The figures of a report drawn by whole pages and by the 3-D scene
// (report_figures.h): the Twist Axes page's plot, the Tyre Relaxation page's
// two charts, the measurement mesh (views/scene SceneView) and one still per
// mode (views/scene ModeAnimationView at its largest deflection). The pages
// are built offscreen on the project opened once per report; the 3-D scene
// needs an OpenGL context (Mesa's software renderer under Xvfb or a display,
// QT_QPA_PLATFORM=xcb; on Qt's offscreen platform the figure is left as a
// placeholder naming the view).
#include <QApplication>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QGuiApplication>
#include <QPainter>
#include <QTimer>
#include <cmath>

#include "core/geometry/mesh_placement.h"
#include "views/common/job_runner.h"
#include "views/common/page_registry.h"
#include "views/common/project_model.h"
#include "views/plots/interactive_plot.h"
#include "views/report/report_figures.h"
#include "views/report/report_writer.h"
#include "views/scene/mode_animation_view.h"
#include "views/scene/scene_view.h"
#include "views/scene/twist_axes_page.h"
#include "views/tyre/relaxation_page.h"

namespace mozzi {
namespace views {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("ReportFigures", text);
}

bool fail(QString* error, const QString& why) {
  if (error) *error = why;
  return false;
}

// The project as the pages see it, opened once per report (per path).
struct PageProject {
  QString path;
  std::unique_ptr<ProjectModel> model;
  std::unique_ptr<JobRunner> jobs;
};

PageProject* pageProject(const core::io::ProjectStore& store, QString* error) {
  static PageProject project;
  const QString path = QString::fromStdString(store.path());
  if (project.model && project.path == path) return &project;
  project.jobs = std::make_unique<JobRunner>();
  project.model = std::make_unique<ProjectModel>();
  if (auto opened = project.model->open(path); !opened) {
    fail(error, QString::fromStdString(opened.error().describe()));
    project.model.reset();
    return nullptr;
  }
  project.path = path;
  return &project;
}

PageContext contextOf(PageProject& p) {
  PageContext ctx;
  ctx.model = p.model.get();
  ctx.jobs = p.jobs.get();
  return ctx;
}

// VTK's OpenGL window needs a platform with OpenGL: Qt's offscreen platform
// has none here (VTK stops in GLEW), xcb has Mesa's (under Xvfb too).
bool sceneAvailable(QString* error) {
  const QString platform = QGuiApplication::platformName();
  if (platform != QLatin1String("offscreen") && platform != QLatin1String("minimal")) return true;
  return fail(error,
              tr("the 3-D scene needs a display with OpenGL (Xvfb is enough); the %1 platform has none").arg(platform));
}

// Shows `widget` (its OpenGL window needs exposing) and waits up to `ms` for `ready`.
template <typename Ready>
bool showAndWait(QWidget* widget, Ready ready, int ms) {
  widget->show();
  QElapsedTimer clock;
  clock.start();
  while (!ready() && clock.elapsed() < ms) QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
  return ready();
}

// The scene's picture, or a null image with *error when there is no OpenGL context.
QImage sceneImage(SceneView* scene, QString* error) {
  if (!showAndWait(
          scene->window(), [scene] { return scene->isReady(); }, 3000)) {
    fail(error, tr("the 3-D scene has no OpenGL context on this display"));
    return {};
  }
  QCoreApplication::processEvents();
  QImage image = scene->grabFrame();
  if (image.isNull()) fail(error, tr("the 3-D scene gave no picture"));
  return image;
}

}  // namespace

// The Twist Axes page on the test (its plot: silhouette, points, static axis,
// the dynamic axis and its path).
bool renderTwistAxes(const FigureRequest& r, FigureDrawing& out, QString* error) {
  PageProject* p = pageProject(r.store, error);
  if (!p) return false;
  auto page = std::make_unique<TwistAxesPage>(contextOf(*p));
  page->resize(1400, 900);
  page->showRigTest(r.figure.recordId);
  page->plot()->replot();
  out.plot = page->plot();
  out.keep.push_back(std::move(page));
  return true;
}

// The Tyre Relaxation page on the specimen: relaxation length against
// frequency above, the stacked eq. 48 contributions against pressure below.
bool renderTyreRelaxation(const FigureRequest& r, FigureDrawing& out, QString* error) {
  PageProject* p = pageProject(r.store, error);
  if (!p) return false;
  auto page = std::make_unique<RelaxationPage>(contextOf(*p));
  page->resize(1200, 900);
  bool done = false, ok = false;
  QObject::connect(page.get(), &RelaxationPage::finished, [&](bool result) { done = true, ok = result; });
  page->showSpecimen(r.figure.recordId);
  QElapsedTimer clock;
  clock.start();
  while (!done && clock.elapsed() < 20000) QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
  if (!done || !ok) return fail(error, page->statusText());
  // Both charts, one above the other, as one picture at print resolution.
  const int w = 2400, h = 1600;
  QImage image(w, 2 * h, QImage::Format_ARGB32);
  image.fill(Qt::white);
  const int dotsPerMetre = qRound(r.options.dpi * 1000.0 / 25.4);
  image.setDotsPerMeterX(dotsPerMetre);
  image.setDotsPerMeterY(dotsPerMetre);
  QPainter painter(&image);
  renderPlot(page->frequencyPlot(), painter, QRectF(0, 0, w, h));
  renderPlot(page->pressurePlot(), painter, QRectF(0, h, w, h));
  painter.end();
  out.image = image;
  out.keep.push_back(std::move(page));
  return true;
}

bool renderMesh(const FigureRequest& r, FigureDrawing& out, QString* error) {
  auto mesh = r.store.mesh(r.figure.recordId);
  if (!mesh) return fail(error, QString::fromStdString(mesh.error().describe()));
  if (!sceneAvailable(error)) return false;
  auto positions = core::geometry::globalNodePositions(*mesh);
  if (!positions) return fail(error, QString::fromStdString(positions.error().describe()));
  auto scene = std::make_unique<SceneView>();
  scene->resize(1200, 800);
  scene->setLabelsVisible(true);
  scene->showMesh(*mesh, *positions);
  out.image = sceneImage(scene.get(), error);
  out.keep.push_back(std::move(scene));
  return !out.image.isNull();
}

bool renderModeShape(const FigureRequest& r, FigureDrawing& out, QString* error) {
  auto results = r.store.modalResults();
  if (!results) return fail(error, QString::fromStdString(results.error().describe()));
  std::int64_t specimen = 0;
  for (const auto& m : *results)
    if (m.id == r.figure.recordId) specimen = m.specimenId;
  auto table = r.store.modalResult(r.figure.recordId);
  if (!table) return fail(error, QString::fromStdString(table.error().describe()));
  auto mesh = r.store.mesh(specimen);
  if (!mesh) return fail(error, QString::fromStdString(mesh.error().describe()));
  if (!sceneAvailable(error)) return false;
  const auto index = static_cast<std::size_t>(r.figure.index);
  if (index >= table->modes.size()) return fail(error, tr("no such mode"));
  auto view = std::make_unique<ModeAnimationView>();
  view->resize(1200, 800);
  core::io::MeshDocument doc;
  doc.mesh = std::move(*mesh);
  view->setMesh(doc);
  ModeAnimationView::Shape shape;
  shape.name = tr("Mode %1").arg(index + 1);
  shape.frequencyHz = table->modes[index].frequencyHz;
  shape.dampingRatio = table->modes[index].dampingRatio;
  shape.dofs = table->dofs;
  shape.values = table->modes[index].shape;
  view->setShapes({shape});
  if (!showAndWait(
          view.get(), [&] { return view->scene()->isReady(); }, 3000))
    return fail(error, tr("the 3-D scene has no OpenGL context on this display"));
  if (!view->showShape(0)) return fail(error, tr("the mode shape does not fit the mesh"));
  view->setPhase(M_PI / 2);  // the largest deflection: A sin(theta) = A
  out.image = sceneImage(view->scene(), error);
  out.keep.push_back(std::move(view));
  return !out.image.isNull();
}

}  // namespace views
}  // namespace mozzi
