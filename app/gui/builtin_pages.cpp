// The page table. One entry per page: add yours at the end of
// registerBuiltinPages() (docs/workbench-pages.md); keep the page's code in
// views/<area>/ and only the wiring here.
#include "app/gui/builtin_pages.h"

#include <QCoreApplication>
#include <QTabWidget>
#include <QVariant>
#include <algorithm>
#include <functional>
#include <initializer_list>
#include <memory>
#include <vector>

#include "core/io/project_store.h"
#include "core/stability/stability_record.h"
#include "core/stability/wheelchair_record.h"
#include "views/campaign/campaign_session.h"
#include "views/campaign/hammer_station_page.h"
#include "views/common/page_registry.h"
#include "views/editors/mesh_editor_page.h"
#include "views/gap/model_test_view.h"
#include "views/modal/identification_page.h"
#include "views/panels/project_overview.h"
#include "views/plots/frf_plot.h"
#include "views/plots/hit_time_view.h"
#include "views/rigs/rig_test_page.h"
#include "views/scene/mode_animation_page.h"
#include "views/scene/scene_view.h"
#include "views/scene/twist_axes_page.h"
#include "views/stability/stability_page.h"
// Stiffness tables and lumped forks (issue 22, branch stiffpages).
#include "views/stiffness/lumped_fork_page.h"
#include "views/stiffness/stiffness_table_page.h"
#include "views/tyre/relaxation_page.h"
#include "views/wheelchair/wheelchair_page.h"

namespace mozzi {
namespace app {

namespace {

using views::PageContext;
using views::PageMenu;
using views::PageSpec;
using views::ProjectItem;
using views::RecordKind;

bool isKind(const ProjectItem& item, std::initializer_list<RecordKind> kinds) {
  for (RecordKind kind : kinds) {
    if (item.kind == kind) return true;
  }
  return false;
}

// The kind of a stored gap diagnosis (core/io/project_records.h, StoredAnalysis).
constexpr const char* kGapDiagnosisKind = "gap-diagnosis";

// A stored analysis of one kind (the pages that keep their results as analyses).
std::function<bool(const ProjectItem&)> isAnalysisOf(const char* kind) {
  const QString wanted = QString::fromLatin1(kind);
  return [wanted](const ProjectItem& item) { return item.kind == RecordKind::Analysis && item.analysisKind == wanted; };
}

// --- 3-D view: the selected specimen's mesh ---------------------------------------
// (views/scene owns the view; this is only its wiring to the project.)

void showSpecimenMesh(views::SceneView* scene, views::ProjectModel* model, qint64 specimenId,
                      const std::function<void(const QString&)>& log) {
  scene->setProperty("mozziSpecimen", QVariant::fromValue<qlonglong>(specimenId));
  const views::ShownMesh shown = views::showStoredMesh(*scene, model->store(), specimenId);
  if (!shown.problem.isEmpty() && log) log(shown.problem);
  if (shown.mesh && scene->skippedLineCount() > 0 && log) {
    log(QCoreApplication::translate("Pages",
                                    "%n trace line segment(s) name nodes the mesh does not have and are not drawn",
                                    nullptr, scene->skippedLineCount()));
  }
}

QWidget* createScene(const PageContext& ctx) {
  auto* scene = new views::SceneView(ctx.parent);
  scene->setObjectName(QStringLiteral("sceneTab"));
  views::ProjectModel* model = ctx.model;
  const auto log = ctx.log;
  const auto shown = [scene] { return scene->property("mozziSpecimen").toLongLong(); };
  QObject::connect(model, &views::ProjectModel::meshChanged, scene, [=](qint64 specimenId) {
    if (specimenId == shown() || specimenId == 0) showSpecimenMesh(scene, model, shown(), log);
  });
  QObject::connect(model, &views::ProjectModel::projectChanged, scene, [=] { showSpecimenMesh(scene, model, 0, log); });
  return scene;
}

// --- FRF page: a stored set, the modes identified from it for the cursor ---------

// Natural frequencies of the latest modal result identified from FRF set `id`.
std::vector<double> modeFrequenciesOf(core::io::ProjectStore* store, qint64 frfSetId) {
  std::vector<double> out;
  auto results = store->modalResults();
  if (!results) return out;
  qint64 latest = 0;
  for (const auto& r : *results) {
    if (r.frfSetId && *r.frfSetId == frfSetId) latest = std::max<qint64>(latest, r.id);
  }
  if (latest == 0) return out;
  auto table = store->modalResult(latest);
  if (!table) return out;
  for (const auto& m : table->modes) out.push_back(m.frequencyHz);
  return out;
}

QWidget* createFrfPage(const PageContext& ctx) {
  core::io::ProjectStore* store = ctx.model->store();
  if (!store) return nullptr;
  auto frf = ctx.model->frfSet(ctx.item.id);
  if (!frf) {
    if (ctx.log)
      ctx.log(QCoreApplication::translate("Pages", "Could not read the FRF set: %1")
                  .arg(QString::fromStdString(frf.error().describe())));
    return nullptr;
  }
  auto* plot = new views::FrfPlot(ctx.parent);
  plot->setFrfs(std::move(frf).value());
  plot->setModeFrequencies(modeFrequenciesOf(store, ctx.item.id));
  views::ProjectModel* model = ctx.model;
  const qint64 id = ctx.item.id;
  QObject::connect(model, &views::ProjectModel::modalResultsChanged, plot, [plot, model, id] {
    if (model->store()) plot->setModeFrequencies(modeFrequenciesOf(model->store(), id));
  });
  // A campaign's set: its stored hits in the time domain beside the FRFs.
  auto* hits = new views::HitTimeView;
  if (!hits->setFrfSet(*store, ctx.item.id)) {
    delete hits;
    return plot;
  }
  auto* tabs = new QTabWidget(ctx.parent);
  tabs->setObjectName(QStringLiteral("frfPageTabs"));
  tabs->setDocumentMode(true);
  tabs->addTab(plot, QCoreApplication::translate("Pages", "FRFs"));
  tabs->addTab(hits, QCoreApplication::translate("Pages", "Hits (time)"));
  return tabs;
}

}  // namespace

void registerBuiltinPages(views::PageRegistry& registry) {
  registry.add(
      PageSpec{QStringLiteral("overview"), QT_TRANSLATE_NOOP("Pages", "Overview"),
               QT_TRANSLATE_NOOP("Pages", "The open project: where to start, its specimens and what each holds"),
               QString(), PageMenu::Pages, [](const ProjectItem& item) { return item.kind == RecordKind::Project; },
               [](const PageContext& ctx) -> QWidget* {
                 auto* page = new views::ProjectOverview(ctx.parent);
                 page->setObjectName(QStringLiteral("overviewTab"));
                 page->setPages(ctx.registry, ctx.openPage);
                 page->setModel(ctx.model);
                 return page;
               },
               /*singleton=*/true, /*openAtStart=*/true, nullptr});

  registry.add(PageSpec{QStringLiteral("scene"), QT_TRANSLATE_NOOP("Pages", "3-D View"),
                        QT_TRANSLATE_NOOP("Pages", "The selected specimen's measurement mesh in 3-D"), QString(),
                        PageMenu::Pages,
                        [](const ProjectItem& item) {
                          return isKind(item, {RecordKind::Specimen, RecordKind::Mesh});
                        },
                        createScene, /*singleton=*/true, /*openAtStart=*/true,
                        [](QWidget* page, const PageContext& ctx) {
                          const qint64 specimen = ctx.item.specimenId ? ctx.item.specimenId : ctx.item.id;
                          showSpecimenMesh(static_cast<views::SceneView*>(page), ctx.model, specimen, ctx.log);
                        }});

  registry.add(PageSpec{QStringLiteral("frf-plot"), QT_TRANSLATE_NOOP("Pages", "FRF"),
                        QT_TRANSLATE_NOOP("Pages",
                                          "The FRFs of a stored set: Bode, real and imaginary, Nyquist, "
                                          "coherence, sum and CMIF, with a cursor"),
                        QString(), PageMenu::None,
                        [](const ProjectItem& item) { return item.kind == RecordKind::FrfSet; }, createFrfPage,
                        /*singleton=*/false, /*openAtStart=*/false, nullptr});

  registry.add(PageSpec{
      QStringLiteral("model-vs-test"), QT_TRANSLATE_NOOP("Pages", "Model vs Test"),
      QT_TRANSLATE_NOOP("Pages", "Diagnose where a model and a test disagree and which unmodelled effect explains it"),
      QString(), PageMenu::Tools, isAnalysisOf(kGapDiagnosisKind),
      [](const PageContext& ctx) -> QWidget* {
        auto* view = new views::ModelTestView(ctx.parent, ctx.jobs);
        view->setObjectName(QStringLiteral("modelTestTab"));
        view->setProjectModel(ctx.model);  // the gap diagnoses the project keeps
        // The kept diagnosis it was opened on, else the newest; a run on files stays possible.
        if (ctx.item.kind != RecordKind::Analysis || !view->showStored(ctx.item.id)) view->showNewestStored();
        const auto log = ctx.log;
        QObject::connect(view, &views::ModelTestView::finished, view, [view, log](bool ok) {
          if (log)
            log(QCoreApplication::translate("Pages", "Model vs test: %1")
                    .arg(ok ? view->verdictText() : view->statusText()));
        });
        return view;
      },
      /*singleton=*/true, /*openAtStart=*/false,
      [](QWidget* page, const PageContext& ctx) {
        if (ctx.item.kind == RecordKind::Analysis) static_cast<views::ModelTestView*>(page)->showStored(ctx.item.id);
      }});

  registry.add(PageSpec{QStringLiteral("stability"), QT_TRANSLATE_NOOP("Pages", "Stability"),
                        QT_TRANSLATE_NOOP("Pages",
                                          "Eigenvalues of a bicycle model against speed, its modes named and "
                                          "its critical speeds marked"),
                        QString(), PageMenu::Tools, isAnalysisOf(core::stability::kStabilityAnalysisKind),
                        [](const PageContext& ctx) -> QWidget* {
                          auto* page = new views::StabilityPage(ctx.parent, ctx.jobs);
                          page->setObjectName(QStringLiteral("stabilityTab"));
                          page->setProjectModel(ctx.model);  // the forks and sweeps the project keeps
                          // The kept sweep it was opened on; else the last kept
                          // one, or the benchmark bicycle 0 to 10 m/s.
                          if (ctx.item.kind != RecordKind::Analysis || !page->showStored(ctx.item.id))
                            page->openShowing();
                          return page;
                        },
                        /*singleton=*/true, /*openAtStart=*/false,
                        [](QWidget* page, const PageContext& ctx) {
                          if (ctx.item.kind == RecordKind::Analysis)
                            static_cast<views::StabilityPage*>(page)->showStored(ctx.item.id);
                        }});

  // Mesh editor (views/editors): one tab per specimen.
  registry.add(PageSpec{QStringLiteral("mesh-editor"), QT_TRANSLATE_NOOP("Pages", "Mesh Editor"),
                        QT_TRANSLATE_NOOP("Pages", "Edit a specimen's measurement mesh: nodes, lines, faces, DOFs"),
                        QString(), PageMenu::None,
                        [](const ProjectItem& item) {
                          return isKind(item, {RecordKind::Specimen, RecordKind::Mesh});
                        },
                        [](const PageContext& ctx) -> QWidget* {
                          const qint64 specimen = ctx.item.specimenId ? ctx.item.specimenId : ctx.item.id;
                          if (!ctx.model->store() || specimen == 0) return nullptr;
                          auto* page = new views::MeshEditorPage(ctx.model, specimen, ctx.parent);
                          const auto log = ctx.log;
                          if (log) QObject::connect(page, &views::MeshEditorPage::message, page, log);
                          return page;
                        },
                        /*singleton=*/false, /*openAtStart=*/false, nullptr});

  // Mode animation (views/scene): one tab per modal result.
  registry.add(PageSpec{QStringLiteral("mode-animation"), QT_TRANSLATE_NOOP("Pages", "Mode Animation"),
                        QT_TRANSLATE_NOOP("Pages", "Animate identified or imported modes on their mesh"), QString(),
                        PageMenu::Pages, [](const ProjectItem& item) { return item.kind == RecordKind::ModalResult; },
                        [](const PageContext& ctx) -> QWidget* {
                          const qint64 result = ctx.item.kind == RecordKind::ModalResult ? ctx.item.id : 0;
                          auto* page = new views::ModeAnimationPage(ctx.model, result, ctx.parent);
                          const auto log = ctx.log;
                          if (log) QObject::connect(page, &views::ModeAnimationPage::message, page, log);
                          return page;
                        },
                        /*singleton=*/false, /*openAtStart=*/false, nullptr});

  registry.add(PageSpec{QStringLiteral("hammer-station"), QT_TRANSLATE_NOOP("Pages", "Hammer Station"),
                        QT_TRANSLATE_NOOP("Pages", "Run an impact campaign point by point: arm, hit, accept or reject"),
                        QString(), PageMenu::Tools,
                        [](const ProjectItem& item) { return item.kind == RecordKind::Campaign; },
                        [](const PageContext& ctx) -> QWidget* {
                          auto* page = new views::HammerStationPage(ctx);
                          page->setObjectName(QStringLiteral("hammerStationTab"));
                          return page;
                        },
                        /*singleton=*/true, /*openAtStart=*/false,
                        [](QWidget* page, const PageContext& ctx) {
                          auto* station = static_cast<views::HammerStationPage*>(page);
                          // A running campaign keeps the page: the selection cannot switch it.
                          if (ctx.item.kind == RecordKind::Campaign && !station->session()->isRunning())
                            station->showCampaign(ctx.item.id);
                        }});
  // Stiffness rig and tyre tester (issue 20): run a test sequence on the
  // simulated rig, or show a stored test opened from the project tree.
  const auto rigPage = [](views::RigTestPage::Rig rig, const char* objectName) {
    return [rig, objectName](const PageContext& ctx) -> QWidget* {
      auto* page = new views::RigTestPage(rig, ctx);
      page->setObjectName(QLatin1String(objectName));
      return page;
    };
  };
  const auto showStoredTest = [](QWidget* page, const PageContext& ctx) {
    static_cast<views::RigTestPage*>(page)->showStoredTest(ctx.item.id);
  };
  registry.add(PageSpec{QStringLiteral("stiffness-rig"), QT_TRANSLATE_NOOP("Pages", "Stiffness Rig"),
                        QT_TRANSLATE_NOOP("Pages", "Static and dynamic stiffness tests on the Motostiffmeter"),
                        QString(), PageMenu::Pages,
                        [](const ProjectItem& item) { return item.kind == RecordKind::RigTest; },
                        rigPage(views::RigTestPage::Rig::Stiffness, "stiffnessRigTab"),
                        /*singleton=*/true, /*openAtStart=*/false, showStoredTest});
  registry.add(PageSpec{QStringLiteral("tyre-tester"), QT_TRANSLATE_NOOP("Pages", "Tyre Tester"),
                        QT_TRANSLATE_NOOP("Pages", "Relaxation and steady-state tests on the Mototiremeter"), QString(),
                        PageMenu::Pages, [](const ProjectItem& item) { return item.kind == RecordKind::TyreTest; },
                        rigPage(views::RigTestPage::Rig::Tyre, "tyreTesterTab"),
                        /*singleton=*/true, /*openAtStart=*/false, showStoredTest});
  registry.add(PageSpec{QStringLiteral("identification"), QT_TRANSLATE_NOOP("Pages", "Identification"),
                        QT_TRANSLATE_NOOP("Pages", "Identify modes on a stabilization diagram"), QString(),
                        PageMenu::Pages, [](const ProjectItem& item) { return item.kind == RecordKind::FrfSet; },
                        [](const PageContext& ctx) -> QWidget* {
                          if (!ctx.model->store()) return nullptr;
                          auto* page = new views::IdentificationPage(ctx);
                          page->setObjectName(QStringLiteral("identificationTab"));
                          return page;
                        },
                        /*singleton=*/false, /*openAtStart=*/false, nullptr});
  // Twist axes over the component (issue 22, views/scene): the stored static
  // and dynamic stiffness tests of a specimen drawn over its silhouette. A
  // rig test's second page (the Stiffness Rig page is its default).
  registry.add(PageSpec{QStringLiteral("twist-axes"), QT_TRANSLATE_NOOP("Pages", "Twist Axes"),
                        QT_TRANSLATE_NOOP("Pages",
                                          "The static and dynamic twist axes of stored stiffness-rig tests over "
                                          "the component's silhouette"),
                        QString(), PageMenu::Pages,
                        [](const ProjectItem& item) { return item.kind == RecordKind::RigTest; },
                        [](const PageContext& ctx) -> QWidget* {
                          auto* page = new views::TwistAxesPage(ctx);
                          page->setObjectName(QStringLiteral("twistAxesTab"));
                          const auto log = ctx.log;
                          if (log) QObject::connect(page, &views::TwistAxesPage::message, page, log);
                          return page;
                        },
                        /*singleton=*/true, /*openAtStart=*/false,
                        [](QWidget* page, const PageContext& ctx) {
                          if (ctx.item.kind == RecordKind::RigTest)
                            static_cast<views::TwistAxesPage*>(page)->showRigTest(ctx.item.id);
                        }});

  // --- Stiffness and forks (issue 22; views/stiffness) -----------------------------
  // The stiffness tables of every static rig test side by side with the
  // thesis's, a rig test's third page; the lumped fork models from the Tools menu.
  registry.add(PageSpec{QStringLiteral("stiffness-tables"), QT_TRANSLATE_NOOP("Pages", "Stiffness"),
                        QT_TRANSLATE_NOOP("Pages",
                                          "Stiffness tables of the stored static rig tests, side by side across "
                                          "specimens, with the thesis's values"),
                        QString(), PageMenu::Pages,
                        [](const ProjectItem& item) { return item.kind == RecordKind::RigTest; },
                        [](const PageContext& ctx) -> QWidget* {
                          auto* page = new views::StiffnessTablePage(ctx);
                          page->setObjectName(QStringLiteral("stiffnessTablesTab"));
                          const auto log = ctx.log;
                          if (log) QObject::connect(page, &views::StiffnessTablePage::message, page, log);
                          if (ctx.item.kind == RecordKind::RigTest) page->showRigTest(ctx.item.id);
                          return page;
                        },
                        /*singleton=*/true, /*openAtStart=*/false,
                        [](QWidget* page, const PageContext& ctx) {
                          if (ctx.item.kind == RecordKind::RigTest)
                            static_cast<views::StiffnessTablePage*>(page)->showRigTest(ctx.item.id);
                        }});
  registry.add(PageSpec{QStringLiteral("lumped-fork"), QT_TRANSLATE_NOOP("Pages", "Lumped Fork"),
                        QT_TRANSLATE_NOOP("Pages",
                                          "Lumped fork models 1 to 3 against the measured modes, and the "
                                          "bicycle-fork stiffness and damping"),
                        QString(), PageMenu::Tools, nullptr,
                        [](const PageContext& ctx) -> QWidget* {
                          auto* page = new views::LumpedForkPage(ctx);
                          page->setObjectName(QStringLiteral("lumpedForkTab"));
                          const auto log = ctx.log;
                          if (log) QObject::connect(page, &views::LumpedForkPage::message, page, log);
                          return page;
                        },
                        /*singleton=*/true, /*openAtStart=*/false, nullptr});

  // --- Tyres and wheelchairs (issue 22, views/tyre) ---------------------------
  // Tyre relaxation (thesis §5.4, Figure 43): a tyre test's second page (the
  // Tyre Tester is its default), or from the Pages menu on the project's tyres.
  registry.add(PageSpec{QStringLiteral("tyre-relaxation"), QT_TRANSLATE_NOOP("Pages", "Tyre Relaxation"),
                        QT_TRANSLATE_NOOP("Pages",
                                          "Relaxation length against frequency and pressure, the ring model's "
                                          "prediction and its contributions, the rigid-ring modes"),
                        QString(), PageMenu::Pages,
                        [](const ProjectItem& item) { return item.kind == RecordKind::TyreTest; },
                        [](const PageContext& ctx) -> QWidget* {
                          auto* page = new views::RelaxationPage(ctx);
                          page->setObjectName(QStringLiteral("tyreRelaxationTab"));
                          const auto log = ctx.log;
                          if (log) QObject::connect(page, &views::RelaxationPage::message, page, log);
                          return page;
                        },
                        /*singleton=*/true, /*openAtStart=*/false,
                        [](QWidget* page, const PageContext& ctx) {
                          if (ctx.item.kind == RecordKind::TyreTest)
                            static_cast<views::RelaxationPage*>(page)->showTyreTest(ctx.item.id);
                        }});
  // Wheelchair manoeuvres (thesis §7.2 to §7.4, Figures 57 to 60).
  registry.add(PageSpec{QStringLiteral("wheelchair"), QT_TRANSLATE_NOOP("Pages", "Wheelchair"),
                        QT_TRANSLATE_NOOP("Pages",
                                          "Slalom and steady-turning trajectories and rear slip angles of the "
                                          "wheelchair model, with the tyre stiffness studies"),
                        QString(), PageMenu::Tools, isAnalysisOf(core::stability::kWheelchairAnalysisKind),
                        [](const PageContext& ctx) -> QWidget* {
                          auto* page = new views::WheelchairPage(ctx.parent, ctx.jobs);
                          page->setObjectName(QStringLiteral("wheelchairTab"));
                          page->setProjectModel(ctx.model);  // the manoeuvres the project keeps
                          // The kept manoeuvre it was opened on; else the last kept
                          // one, or the cornering-stiffness slalom of Figure 58.
                          if (ctx.item.kind != RecordKind::Analysis || !page->showStored(ctx.item.id))
                            page->openShowing();
                          return page;
                        },
                        /*singleton=*/true, /*openAtStart=*/false,
                        [](QWidget* page, const PageContext& ctx) {
                          if (ctx.item.kind == RecordKind::Analysis)
                            static_cast<views::WheelchairPage*>(page)->showStored(ctx.item.id);
                        }});
}

}  // namespace app
}  // namespace mozzi