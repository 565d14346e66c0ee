#include "core/io/uff_import.h"

#include <cmath>
#include <filesystem>

#include "core/io/project_store.h"

namespace mozzi::core::io {

Result<StoredMesh> meshFromUff(const uff::UffFile& file) {
  double lengthFactor = 1.0;
  if (const auto units = file.all<uff::Units164>(); !units.empty()) lengthFactor = units.front()->lengthFactor;
  if (!(lengthFactor > 0.0) || !std::isfinite(lengthFactor)) {
    return makeError(ErrorCode::ParseError, "length unit factor must be positive", "dataset 164");
  }
  StoredMesh mesh;
  for (const auto* set : file.all<uff::CoordinateSystemSet>()) {
    for (const auto& cs : set->systems) {
      StoredCoordinateSystem stored;
      stored.label = cs.label;
      stored.name = cs.name;
      stored.kind = static_cast<StoredCoordinateSystem::Kind>(cs.type >= 0 && cs.type <= 2 ? cs.type : 0);
      stored.origin = cs.origin / lengthFactor;
      stored.rotation = cs.axes.transpose();  // UFF rows are the axes; stored columns are
      mesh.coordinateSystems.push_back(std::move(stored));
    }
  }
  for (const auto* set : file.all<uff::NodeSet>()) {
    for (const auto& node : set->nodes) {
      StoredNode stored;
      stored.label = node.label;
      stored.definitionCs = node.definitionCs;
      stored.displacementCs = node.displacementCs;
      stored.position = node.xyz / lengthFactor;
      mesh.nodes.push_back(stored);
    }
  }
  for (const auto* trace : file.all<uff::TraceLine82>()) {
    for (std::size_t i = 1; i < trace->nodes.size(); ++i) {
      const int a = trace->nodes[i - 1], b = trace->nodes[i];
      if (a != 0 && b != 0 && a != b) mesh.lines.push_back({a, b});
    }
  }
  return mesh;
}

Result<UffImportReport> importUff(ProjectStore& store, const std::string& uffPath, std::int64_t specimenId) {
  auto file = uff::readFile(uffPath);
  if (!file) return file.error();
  const std::string name = std::filesystem::path(uffPath).filename().string();
  UffImportReport report;
  report.specimenId = specimenId;
  for (const auto& w : file->warnings) report.notes.push_back(w.describe());

  // Convert everything first: no write happens unless the whole file is usable.
  auto mesh = meshFromUff(*file);
  if (!mesh) return mesh.error();
  bool hasFrf = false;
  for (const auto* f : file->all<uff::Function58>()) hasFrf = hasFrf || f->functionType == uff::FunctionType::Frf;
  std::optional<FrfMatrix> frf;
  if (hasFrf) {
    auto converted = uff::toFrfMatrix(*file);
    if (!converted) return converted.error();
    frf = std::move(converted).value();
  }
  std::optional<uff::ModalData> modal;
  if (!file->all<uff::ModalData55>().empty()) {
    auto converted = uff::toModalData(*file);
    if (!converted) return converted.error();
    modal = std::move(converted).value();
  }
  if (mesh->nodes.empty() && !frf && !modal) {
    return makeError(ErrorCode::NotFound, "the file holds no nodes, FRFs (58, type 4) or modal data (55) to import",
                     uffPath);
  }

  if (!mesh->nodes.empty()) {
    auto existing = store.mesh(specimenId);
    if (!existing) return existing.error();
    if (!existing->nodes.empty()) {
      report.notes.push_back("geometry not imported: the specimen already has a mesh of " +
                             std::to_string(existing->nodes.size()) + " nodes");
    } else {
      if (auto r = store.setMesh(specimenId, *mesh); !r) return r.error();
      report.nodes = static_cast<int>(mesh->nodes.size());
      report.lines = static_cast<int>(mesh->lines.size());
      report.coordinateSystems = static_cast<int>(mesh->coordinateSystems.size());
    }
  }
  if (frf) {
    FrfSetInfo info;
    info.specimenId = specimenId;
    info.name = name;
    info.source = "imported from " + name;
    info.type = frf->type;
    auto id = store.addFrfSet(info, *frf);
    if (!id) return id.error();
    report.frfSetId = *id;
    report.frfPairs = static_cast<int>(frf->responseCount() * frf->referenceCount());
  }
  if (modal) {
    ModalTable table;
    table.dofs = modal->dofs;
    for (Eigen::Index m = 0; m < modal->frequencyHz.size(); ++m) {
      table.modes.push_back({modal->frequencyHz[m], modal->dampingRatio[m], modal->shapes.col(m)});
    }
    ModalResultInfo info;
    info.specimenId = specimenId;
    info.name = name;
    info.method = "imported (UFF 55)";
    if (modal->frequencyHz.size() > 0) {
      info.bandLowHz = modal->frequencyHz.minCoeff();
      info.bandHighHz = modal->frequencyHz.maxCoeff();
    }
    auto id = store.addModalResult(info, table);
    if (!id) return id.error();
    report.modalResultId = *id;
    report.modes = static_cast<int>(table.modes.size());
  }
  return report;
}

}  // namespace mozzi::core::io
