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
      stored.name = cs.name == "NONE" ? std::string() : cs.name;
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

Result<MeshUffExport> meshToUff(const StoredMesh& mesh, const MeshUffOptions& options) {
  MeshUffExport out;
  auto& datasets = out.file.datasets;
  if (!options.description.empty()) {
    uff::Header151 header;
    header.modelName = options.description;
    header.description = "measurement mesh";
    header.uffProgram = "Mozzi";
    datasets.push_back(uff::makeDataset(header));
  }
  uff::Units164 units;  // SI: metre, newton; factors 1 so values are written as they are
  units.unitsCode = 1;
  units.description = "SI: Meter (newton)";
  datasets.push_back(uff::makeDataset(units));

  if (!mesh.coordinateSystems.empty()) {
    uff::CoordinateSystemSet set;
    set.datasetType = options.doublePrecision ? 2420 : 18;
    set.partName = options.description.empty() ? std::string("NONE") : options.description.substr(0, 80);
    const std::size_t width = options.doublePrecision ? 80 : 40;
    for (const auto& stored : mesh.coordinateSystems) {
      const std::string where = "coordinate system " + std::to_string(stored.label);
      const std::string& name = stored.name;
      if (name.size() > width || name.find_first_of("\r\n") != std::string::npos ||
          (!name.empty() && (name.back() == ' ' || name.back() == '\t'))) {
        return makeError(ErrorCode::InvalidArgument,
                         "its name cannot be written in dataset " + std::to_string(set.datasetType) + " (at most " +
                             std::to_string(width) + " characters, no line breaks or trailing blanks)",
                         where);
      }
      uff::CoordinateSystem cs;
      cs.label = stored.label;
      cs.type = static_cast<int>(stored.kind);
      cs.name = name;
      cs.origin = stored.origin;
      cs.axes = stored.rotation.transpose();  // rows are the axes in UFF
      cs.xPoint = stored.origin + stored.rotation.col(0);
      cs.xzPoint = stored.origin + stored.rotation.col(2);
      set.systems.push_back(std::move(cs));
    }
    datasets.push_back(uff::makeDataset(std::move(set)));
  }
  if (!mesh.nodes.empty()) {
    uff::NodeSet set;
    set.datasetType = options.doublePrecision ? 2411 : 15;
    for (const auto& stored : mesh.nodes) {
      uff::Node node;
      node.label = stored.label;
      node.definitionCs = stored.definitionCs;
      node.displacementCs = stored.displacementCs;
      node.color = 8;
      node.xyz = stored.position;
      set.nodes.push_back(node);
    }
    datasets.push_back(uff::makeDataset(std::move(set)));
  }
  // Trace lines: chains of consecutive segments, pen lifted (0) between chains.
  constexpr std::size_t kMaxTraceNodes = 250;
  std::vector<int> trace;
  int traceNumber = 1;
  auto flush = [&]() {
    if (trace.empty()) return;
    uff::TraceLine82 line;
    line.traceNumber = traceNumber++;
    line.color = 8;
    line.description = "trace line " + std::to_string(line.traceNumber);
    line.nodes = std::move(trace);
    trace.clear();
    datasets.push_back(uff::makeDataset(std::move(line)));
  };
  for (const auto& segment : mesh.lines) {
    const bool continues = !trace.empty() && trace.back() == segment.nodeA;
    const std::size_t needed = continues ? 1 : (trace.empty() ? 2 : 3);
    if (trace.size() + needed > kMaxTraceNodes) flush();
    if (!trace.empty() && trace.back() == segment.nodeA) {
      trace.push_back(segment.nodeB);
    } else {
      if (!trace.empty()) trace.push_back(0);
      trace.push_back(segment.nodeA);
      trace.push_back(segment.nodeB);
    }
  }
  flush();
  out.facesLeftOut = static_cast<int>(mesh.faces.size());
  return out;
}

Result<MeshUffExport> exportMeshUff(const StoredMesh& mesh, const std::string& path, const MeshUffOptions& options) {
  auto out = meshToUff(mesh, options);
  if (!out) return out.error();
  if (auto written = uff::writeFile(path, out->file); !written) return written.error();
  return out;
}

Result<StoredMesh> importMeshUff(const std::string& path) {
  auto file = uff::readFile(path);
  if (!file) return file.error();
  return meshFromUff(*file);
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
