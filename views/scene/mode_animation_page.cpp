#include "views/scene/mode_animation_page.h"

#include <QVBoxLayout>
#include <map>

#include "views/common/project_model.h"
#include "views/scene/mode_animation_view.h"

namespace mozzi {
namespace views {

ModeAnimationPage::ModeAnimationPage(ProjectModel* model, qint64 modalResultId, QWidget* parent)
    : QWidget(parent), model_(model), resultId_(modalResultId) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  view_ = new ModeAnimationView(this);
  view_->setObjectName(QStringLiteral("modeAnimation"));
  layout->addWidget(view_);
  connect(view_, &ModeAnimationView::message, this, &ModeAnimationPage::message);
  connect(model_, &ProjectModel::modalResultsChanged, this, [this] { reload(); });
  connect(model_, &ProjectModel::meshChanged, this, [this] { reload(); });
  connect(model_, &ProjectModel::projectChanged, this, [this] {
    resultId_ = 0;
    reload();
  });
  reload();
}

void ModeAnimationPage::reload() {
  core::io::ProjectStore* store = model_->store();
  view_->setShapes({});
  view_->setFrfSet(nullptr, {});
  if (!store) return;
  auto results = store->modalResults();
  if (!results || results->empty()) {
    emit message(tr("The project has no modal results to animate."));
    return;
  }
  const core::io::ModalResultInfo* chosen = &results->front();
  for (const auto& r : *results)
    if (r.id == resultId_) chosen = &r;
  auto mesh = store->mesh(chosen->specimenId);
  if (!mesh) {
    emit message(tr("Cannot read the mesh: %1").arg(QString::fromStdString(mesh.error().describe())));
    return;
  }
  core::io::MeshDocument doc;
  doc.mesh = std::move(mesh).value();
  view_->setMesh(doc);
  // Every mode of every result; those of other specimens carry their own mesh.
  std::map<std::int64_t, core::io::MeshDocument> meshes;
  std::vector<ModeAnimationView::Shape> shapes;
  int first = -1;
  for (const auto& info : *results) {
    auto table = store->modalResult(info.id);
    if (!table || table->dofs.empty()) continue;
    std::optional<core::io::MeshDocument> own;
    if (info.specimenId != chosen->specimenId) {
      if (!meshes.count(info.specimenId)) {
        auto other = store->mesh(info.specimenId);
        if (!other) continue;
        meshes[info.specimenId].mesh = std::move(other).value();
      }
      own = meshes[info.specimenId];
    }
    for (std::size_t m = 0; m < table->modes.size(); ++m) {
      const auto& mode = table->modes[m];
      if (mode.shape.size() != static_cast<Eigen::Index>(table->dofs.size())) continue;
      if (info.id == chosen->id && first < 0) first = static_cast<int>(shapes.size());
      ModeAnimationView::Shape s;
      s.name = tr("%1, mode %2").arg(QString::fromStdString(info.name)).arg(m + 1);
      s.frequencyHz = mode.frequencyHz;
      s.dampingRatio = mode.dampingRatio;
      s.dofs = table->dofs;
      s.values = mode.shape;
      s.mesh = own;
      shapes.push_back(std::move(s));
    }
  }
  view_->setShapes(std::move(shapes));
  // The chosen result's own FRF set, or none: never the set of a result shown
  // before (another specimen's, on this mesh).
  std::shared_ptr<const core::FrfMatrix> set;
  if (chosen->frfSetId) {
    if (auto frf = model_->frfSet(*chosen->frfSetId)) set = *frf;
  }
  view_->setFrfSet(set, set ? tr("FRF set %1").arg(*chosen->frfSetId) : QString());
  if (first >= 0) view_->showShape(first);
}

}  // namespace views
}  // namespace mozzi
