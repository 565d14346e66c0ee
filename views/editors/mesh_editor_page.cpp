#include "views/editors/mesh_editor_page.h"

#include <QVBoxLayout>
#include <set>

#include "views/common/project_model.h"
#include "views/editors/mesh_editor.h"

namespace mozzi {
namespace views {

MeshEditorPage::MeshEditorPage(ProjectModel* model, qint64 specimenId, QWidget* parent)
    : QWidget(parent), model_(model), specimenId_(specimenId) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  editor_ = new MeshEditor(this);
  editor_->setObjectName(QStringLiteral("meshEditor"));
  layout->addWidget(editor_);
  connect(editor_, &MeshEditor::message, this, &MeshEditorPage::message);
  connect(editor_, &MeshEditor::documentChanged, this, &MeshEditorPage::save);
  connect(model_, &ProjectModel::meshChanged, this, [this](qint64 id) {
    if (!saving_ && (id == specimenId_ || id == 0)) reload();
  });
  connect(model_, &ProjectModel::projectChanged, this, [this] { reload(); });
  reload();
}

std::vector<core::geometry::MeasuredData> MeshEditorPage::measuredData(ProjectModel* model, qint64 specimenId) {
  std::vector<core::geometry::MeasuredData> out;
  core::io::ProjectStore* store = model ? model->store() : nullptr;
  if (!store) return out;
  if (auto campaigns = store->campaigns(specimenId)) {
    for (const auto& c : *campaigns) {
      auto hits = store->hits(c.id);
      if (!hits || hits->empty()) continue;
      core::geometry::MeasuredData d;
      d.name = tr("hits of campaign '%1'").arg(QString::fromStdString(c.name)).toStdString();
      for (const auto& h : *hits) d.dofs.push_back(h.point);
      out.push_back(std::move(d));
    }
  }
  if (auto sets = store->frfSets()) {
    for (const auto& info : *sets) {
      if (info.specimenId != specimenId) continue;
      auto frf = store->frfSet(info.id);
      if (!frf) continue;
      core::geometry::MeasuredData d;
      d.name = tr("FRF set %1 '%2'").arg(info.id).arg(QString::fromStdString(info.name)).toStdString();
      d.dofs = frf->responses;
      d.dofs.insert(d.dofs.end(), frf->references.begin(), frf->references.end());
      out.push_back(std::move(d));
    }
  }
  if (auto results = store->modalResults()) {
    for (const auto& info : *results) {
      if (info.specimenId != specimenId) continue;
      auto table = store->modalResult(info.id);
      if (!table || table->dofs.empty()) continue;
      out.push_back(
          {tr("modal result %1 '%2'").arg(info.id).arg(QString::fromStdString(info.name)).toStdString(), table->dofs});
    }
  }
  return out;
}

void MeshEditorPage::reload() {
  core::io::MeshDocument doc;
  core::io::ProjectStore* store = model_->store();
  if (store) {
    auto mesh = store->mesh(specimenId_);
    if (mesh) {
      doc.mesh = std::move(mesh).value();
    } else {
      emit message(tr("Cannot read the mesh: %1").arg(QString::fromStdString(mesh.error().describe())));
    }
  }
  const auto measured = measuredData(model_, specimenId_);
  // The measurement DOFs are not stored with the mesh: show those the data names.
  std::set<int> nodes;
  for (const auto& n : doc.mesh.nodes) nodes.insert(n.label);
  std::set<core::Dof> seen;
  for (const auto& d : measured)
    for (const auto& dof : d.dofs)
      if (nodes.count(dof.node) && seen.insert(dof).second) doc.measurementDofs.push_back(dof);
  editor_->setMeasuredData(measured);
  editor_->setDocument(doc);
  editor_->setEnabled(store && !model_->isReadOnly());
}

void MeshEditorPage::save() {
  saving_ = true;
  auto r = model_->setMesh(specimenId_, editor_->document().mesh);
  saving_ = false;
  if (!r) emit message(tr("Cannot save the mesh: %1").arg(QString::fromStdString(r.error().describe())));
}

}  // namespace views
}  // namespace mozzi
