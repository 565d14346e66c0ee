// mozzi-cli project: create, inspect, demo and export projects
// (docs/cli/project.md).
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>

#include "app/build_info.h"
#include "app/cli/args.h"
#include "app/cli/command.h"
#include "app/cli/output.h"
#include "core/io/csv/csv_exchange.h"
#include "core/io/project_store.h"
#include "core/io/uff/uff.h"
#include "core/io/uff_import.h"
#include "devices/sim/virtual_specimens.h"

namespace mozzi::cli {
namespace {

constexpr const char* kUsage =
    "Usage: mozzi-cli project info FILE.mozzi [--json]\n"
    "       mozzi-cli project new|demo FILE.mozzi\n"
    "       mozzi-cli project import FILE.mozzi IN.uff [--specimen NAME]\n"
    "       mozzi-cli project check FILE.mozzi [--json]\n"
    "       mozzi-cli project export FILE.mozzi --uff OUT.uff [--binary] [--frf-set ID]\n"
    "       mozzi-cli project export FILE.mozzi --csv OUT.csv [--frf-set ID]\n";

// The option table (docs/cli.md, ranges): --frf-set is a row id.
const OptionSpec kSpec{{"--uff", "--csv", "--specimen"},
                       {"--json", "--binary"},
                       {{"--frf-set", wholeNumber(1, 9007199254740992.0), "FRF set id (see 'project info')"}},
                       {"--uff", "--csv"}};

int fail(std::ostream& err, const std::string& what, const core::Error& e) {
  err << "mozzi-cli project " << what << ": " << e.describe() << "\n";
  return kExitFailure;
}

int info(const std::string& file, bool json, std::ostream& out, std::ostream& err) {
  auto store = core::io::ProjectStore::open(file, core::io::ProjectStore::OpenMode::ReadOnly);
  if (!store) return fail(err, "info", store.error());
  auto summary = store->summary();
  if (!summary) return fail(err, "info", summary.error());
  auto frfSets = store->frfSets();
  if (!frfSets) return fail(err, "info", frfSets.error());
  auto modal = store->modalResults();
  if (!modal) return fail(err, "info", modal.error());
  auto rigTests = store->rigTests();
  if (!rigTests) return fail(err, "info", rigTests.error());
  auto tyreTests = store->tyreTests();
  if (!tyreTests) return fail(err, "info", tyreTests.error());
  auto testJson = [](const core::io::TestInfo& t) {
    return nlohmann::json{{"id", t.id},
                          {"specimen", t.specimenName},
                          {"name", t.name},
                          {"kind", t.kind},
                          {"status", core::io::testStatusName(t.status)},
                          {"status_note", t.statusNote},
                          {"recorded_utc", t.recordedUtc},
                          {"records", t.recordCount},
                          {"results", t.resultCount}};
  };
  auto testLine = [&out](const core::io::TestInfo& t) {
    out << "    " << t.id << " " << t.specimenName << " / " << t.name << " (" << t.kind << ", "
        << core::io::testStatusName(t.status) << "): " << t.recordCount << " records, " << t.resultCount << " results"
        << (t.statusNote.empty() ? "" : "; " + t.statusNote) << "\n";
  };

  // Per campaign: hits accepted / rejected and stored bytes.
  struct CampaignLine {
    std::string specimen, name, kind;
    std::int64_t id = 0, accepted = 0, rejected = 0, bytes = 0;
  };
  std::vector<CampaignLine> campaigns;
  for (const auto& sp : summary->specimens) {
    auto list = store->campaigns(sp.id);
    if (!list) return fail(err, "info", list.error());
    for (const auto& c : *list) {
      auto hits = store->hits(c.id);
      if (!hits) return fail(err, "info", hits.error());
      CampaignLine line{sp.name, c.name, c.kind, c.id};
      for (const auto& h : *hits) {
        (h.accepted ? line.accepted : line.rejected) += 1;
        line.bytes += h.storedBytes;
      }
      campaigns.push_back(line);
    }
  }

  if (json) {
    nlohmann::json j;
    j["file"] = file;
    j["schema"] = summary->schemaVersion;
    j["created_utc"] = summary->createdUtc;
    j["mozzi_version"] = summary->mozziVersion;
    j["read_only_reason"] = store->readOnlyReason();
    j["specimens"] = nlohmann::json::array();
    for (const auto& sp : summary->specimens) {
      j["specimens"].push_back({{"id", sp.id}, {"name", sp.name}, {"kind", sp.kind}});
    }
    j["tables"] = nlohmann::json::object();
    for (const auto& c : summary->counts) j["tables"][c.table] = c.rows;
    j["campaigns"] = nlohmann::json::array();
    for (const auto& c : campaigns) {
      j["campaigns"].push_back({{"id", c.id},
                                {"specimen", c.specimen},
                                {"name", c.name},
                                {"kind", c.kind},
                                {"hits_accepted", c.accepted},
                                {"hits_rejected", c.rejected},
                                {"stored_bytes", c.bytes}});
    }
    j["frf_sets"] = nlohmann::json::array();
    for (const auto& s : *frfSets) {
      j["frf_sets"].push_back({{"id", s.id},
                               {"name", s.name},
                               {"type", core::frfTypeName(s.type)},
                               {"lines", s.lineCount},
                               {"responses", s.responseCount},
                               {"references", s.referenceCount}});
    }
    j["modal_results"] = nlohmann::json::array();
    for (const auto& m : *modal) {
      j["modal_results"].push_back({{"id", m.id}, {"name", m.name}, {"method", m.method}, {"modes", m.modeCount}});
    }
    j["rig_tests"] = nlohmann::json::array();
    for (const auto& t : *rigTests) j["rig_tests"].push_back(testJson(t));
    j["tyre_tests"] = nlohmann::json::array();
    for (const auto& t : *tyreTests) j["tyre_tests"].push_back(testJson(t));
    out << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";

    return kExitOk;
  }
  out << "project " << file << "\n  schema " << summary->schemaVersion << ", created " << summary->createdUtc
      << " by Mozzi " << summary->mozziVersion << "\n  specimens: " << summary->specimens.size() << "\n";
  for (const auto& sp : summary->specimens) out << "    " << sp.name << " [" << sp.kind << "]\n";
  if (!campaigns.empty()) out << "  campaigns:\n";
  for (const auto& c : campaigns) {
    out << "    " << c.id << " " << c.specimen << " / " << c.name << " (" << c.kind << "): " << c.accepted
        << " accepted, " << c.rejected << " rejected hits, " << c.bytes << " bytes of samples\n";
  }
  if (!frfSets->empty()) out << "  FRF sets:\n";
  for (const auto& s : *frfSets) {
    out << "    " << s.id << " " << s.name << ": " << core::frfTypeName(s.type) << ", " << s.lineCount << " lines, "
        << s.responseCount << " responses x " << s.referenceCount << " references\n";
  }
  if (!modal->empty()) out << "  modal results:\n";
  for (const auto& m : *modal)
    out << "    " << m.id << " " << m.name << " (" << m.method << "): " << m.modeCount << " modes\n";
  if (!rigTests->empty()) out << "  rig tests:\n";
  for (const auto& t : *rigTests) testLine(t);
  if (!tyreTests->empty()) out << "  tyre tests:\n";
  for (const auto& t : *tyreTests) testLine(t);
  out << "  rows per table:\n";
  for (const auto& c : summary->counts) out << "    " << c.table << ": " << c.rows << "\n";
  return kExitOk;
}

// UFF export: header (151), units (164, SI), per specimen its coordinate
// systems (2420), nodes (2411) and trace lines (82), then every FRF set as 58
// records and every modal result whose DOFs 55 can hold as 55 records.
int exportUff(const core::io::ProjectStore& store, const std::string& file, const std::string& outPath, bool binary,
              std::optional<std::int64_t> onlySet, std::ostream& out, std::ostream& err) {
  namespace uff = core::io::uff;
  auto summary = store.summary();
  if (!summary) return fail(err, "export", summary.error());
  uff::UffFile uffFile;
  uff::Header151 header;
  header.modelName = summary->specimens.empty() ? file : summary->specimens.front().name;
  header.description = "exported from " + file;
  header.dbProgram = "Mozzi " + summary->mozziVersion;
  header.uffProgram = std::string("Mozzi ") + buildinfo::kMozziVersion;
  uffFile.datasets.push_back(uff::makeDataset(header));
  uff::Units164 units;
  units.description = "SI: meter (newton)";
  uffFile.datasets.push_back(uff::makeDataset(units));
  int warnings = 0;
  for (const auto& sp : summary->specimens) {
    auto mesh = store.mesh(sp.id);
    if (!mesh) return fail(err, "export", mesh.error());
    if (!mesh->coordinateSystems.empty()) {
      uff::CoordinateSystemSet set;
      set.partName = sp.name;
      for (const auto& c : mesh->coordinateSystems) {
        uff::CoordinateSystem cs;
        cs.label = c.label;
        cs.type = static_cast<int>(c.kind);
        cs.name = c.name;
        cs.origin = c.origin;
        cs.axes = c.rotation.transpose();  // UFF rows = axis directions; stored columns = axes
        set.systems.push_back(cs);
      }
      uffFile.datasets.push_back(uff::makeDataset(set));
    }
    if (!mesh->nodes.empty()) {
      uff::NodeSet nodes;
      for (const auto& n : mesh->nodes)
        nodes.nodes.push_back({n.label, n.definitionCs, n.displacementCs, 0, n.position});
      uffFile.datasets.push_back(uff::makeDataset(nodes));
    }
    if (!mesh->lines.empty()) {
      uff::TraceLine82 trace;
      trace.description = sp.name;
      for (const auto& l : mesh->lines) {
        if (!trace.nodes.empty()) trace.nodes.push_back(0);  // lift the pen between lines
        trace.nodes.push_back(l.nodeA);
        trace.nodes.push_back(l.nodeB);
      }
      uffFile.datasets.push_back(uff::makeDataset(trace));
    }
  }
  auto sets = store.frfSets();
  if (!sets) return fail(err, "export", sets.error());
  int exportedSets = 0;
  for (const auto& s : *sets) {
    if (onlySet && s.id != *onlySet) continue;
    auto frf = store.frfSet(s.id);
    if (!frf) return fail(err, "export", frf.error());
    auto records = uff::fromFrfMatrix(*frf);
    if (!records) return fail(err, "export", records.error());
    for (auto& r : *records) {
      r.binary = binary;
      uffFile.datasets.push_back(uff::makeDataset(r));
    }
    ++exportedSets;
  }
  if (onlySet && exportedSets == 0) {
    err << "mozzi-cli project export: no FRF set with id " << *onlySet << " in " << file << "\n";
    return kExitFailure;
  }
  auto modal = store.modalResults();
  if (!modal) return fail(err, "export", modal.error());
  int exportedModal = 0;
  if (!onlySet) {
    for (const auto& m : *modal) {
      auto table = store.modalResult(m.id);
      if (!table) return fail(err, "export", table.error());
      uff::ModalData data;
      data.dofs = table->dofs;
      const auto nm = static_cast<Eigen::Index>(table->modes.size());
      data.frequencyHz.resize(nm);
      data.dampingRatio.resize(nm);
      data.modalMass = core::Vector::Zero(nm);
      data.shapes = core::ComplexMatrix::Zero(static_cast<Eigen::Index>(table->dofs.size()), nm);
      for (Eigen::Index k = 0; k < nm; ++k) {
        const auto& mode = table->modes[static_cast<std::size_t>(k)];
        data.frequencyHz[k] = mode.frequencyHz;
        data.dampingRatio[k] = mode.dampingRatio;
        if (mode.shape.size() == data.shapes.rows()) data.shapes.col(k) = mode.shape;
        data.complexShapes = data.complexShapes || !mode.shape.imag().isZero(0.0);
      }
      auto records = uff::fromModalData(data);
      if (!records) {
        // 55 stores one vector per node in global axes; a result on other DOFs
        // stays in the project (export it as CSV) and the user is told.
        err << "mozzi-cli project export: warning: modal result " << m.id << " '" << m.name
            << "' not exported: " << records.error().describe() << "\n";
        ++warnings;
        continue;
      }
      for (auto& r : *records) uffFile.datasets.push_back(uff::makeDataset(r));
      ++exportedModal;
    }
  }
  uff::WriteOptions options;
  options.encoding = binary ? uff::Encoding58::Binary : uff::Encoding58::Ascii;
  if (auto r = uff::writeFile(outPath, uffFile, options); !r) return fail(err, "export", r.error());
  out << "wrote " << outPath << ": " << uffFile.datasets.size() << " datasets (" << exportedSets << " FRF sets, "
      << exportedModal << " modal results" << (warnings ? ", " + std::to_string(warnings) + " skipped" : "") << ")\n";
  return kExitOk;
}

int exportCsv(const core::io::ProjectStore& store, const std::string& file, const std::string& outPath,
              std::optional<std::int64_t> onlySet, std::ostream& out, std::ostream& err) {
  auto sets = store.frfSets();
  if (!sets) return fail(err, "export", sets.error());
  if (!onlySet) {
    if (sets->size() != 1) {
      err << "mozzi-cli project export: " << file << " holds " << sets->size()
          << " FRF sets; choose one with --frf-set ID (see 'project info')\n";
      return sets->empty() ? kExitFailure : kExitUsage;
    }
    onlySet = sets->front().id;
  }
  auto frf = store.frfSet(*onlySet);
  if (!frf) return fail(err, "export", frf.error());
  if (auto r = core::io::csv::exportFrfCsv(*frf, outPath); !r) return fail(err, "export", r.error());
  out << "wrote " << outPath << ": FRF set " << *onlySet << ", " << frf->lineCount() << " lines, "
      << frf->responseCount() << " x " << frf->referenceCount() << " FRFs\n";
  return kExitOk;
}

// Brings a Universal File into the project (core/io/uff_import.h): its mesh,
// FRF sets and modal results go to the specimen named by --specimen, created
// when the project has none of that name (default: the file's stem). The
// import converts everything before it writes, so a file that cannot be read
// leaves the project as it was.
int importFile(const std::string& file, const std::string& uffPath, std::optional<std::string> specimenName,
               std::ostream& out, std::ostream& err) {
  auto store = core::io::ProjectStore::open(file);
  if (!store) return fail(err, "import", store.error());
  auto summary = store->summary();
  if (!summary) return fail(err, "import", summary.error());
  const std::string name = specimenName.value_or(std::filesystem::path(uffPath).stem().string());
  std::int64_t specimenId = 0;
  for (const auto& sp : summary->specimens) {
    if (sp.name == name) specimenId = sp.id;
  }
  const bool created = specimenId == 0;
  if (created) {
    auto id = store->addSpecimen(name, "imported", "imported from " + uffPath);
    if (!id) return fail(err, "import", id.error());
    specimenId = *id;
  }
  auto report = core::io::importUff(*store, uffPath, specimenId);
  if (!report) return fail(err, "import", report.error());
  out << "imported " << uffPath << " into specimen '" << name << "'" << (created ? " (new)" : "") << ": "
      << report->nodes << " nodes, " << report->lines << " lines, " << report->frfPairs << " FRFs"
      << (report->frfSetId ? " (FRF set " + std::to_string(*report->frfSetId) + ")" : "") << ", " << report->modes
      << " modes" << (report->modalResultId ? " (modal result " + std::to_string(*report->modalResultId) + ")" : "")
      << "\n";
  for (const auto& note : report->notes) out << "  " << note << "\n";
  return kExitOk;
}

// Reads every record back and verifies its checksum (docs/cli/project.md).
// Exit 0 when nothing is damaged, 1 when something is (each damaged record
// named) or the file cannot be opened at all.
int check(const std::string& file, bool json, std::ostream& out, std::ostream& err) {
  auto store = core::io::ProjectStore::open(file, core::io::ProjectStore::OpenMode::ReadOnly);
  if (!store) return fail(err, "check", store.error());
  auto report = store->checkIntegrity();
  if (!report) return fail(err, "check", report.error());
  if (json) {
    nlohmann::json j;
    j["file"] = file;
    j["ok"] = report->ok();
    j["records_checked"] = report->recordsChecked;
    j["records_without_checksum"] = report->recordsWithoutChecksum;
    j["problems"] = nlohmann::json::array();
    for (const auto& p : report->problems) j["problems"].push_back({{"record", p.record}, {"message", p.message}});
    out << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  } else {
    out << "project " << file << ": " << report->recordsChecked << " records read back";
    if (report->recordsWithoutChecksum > 0) {
      out << " (" << report->recordsWithoutChecksum << " written before schema 4 carry no checksum)";
    }
    out << "\n";
    if (report->ok()) out << "no damaged record\n";
  }
  for (const auto& p : report->problems)
    err << "mozzi-cli project check: damaged: " << p.record << ": " << p.message << "\n";
  if (!report->ok()) {
    err << "mozzi-cli project check: " << report->problems.size() << " damaged record"
        << (report->problems.size() == 1 ? "" : "s") << " in " << file << "\n";
    return kExitFailure;
  }
  return kExitOk;
}

int projectCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto parsed = ParsedArgs::parse(args, kSpec);
  if (!parsed) {
    err << "mozzi-cli project: " << parsed.error().describe() << "\n";
    if (exitCodeFor(parsed.error()) == kExitUsage) err << kUsage;
    return exitCodeFor(parsed.error());
  }
  const auto& pos = parsed->positional();
  const bool isImport = !pos.empty() && pos[0] == "import";
  if (pos.size() != (isImport ? 3u : 2u)) {
    err << "mozzi-cli project: expected " << (isImport ? "a project and a UFF file" : "a subcommand and a file") << "\n"
        << kUsage;
    return kExitUsage;
  }
  const std::string& sub = pos[0];
  const std::string& file = pos[1];
  if (isImport) return importFile(file, pos[2], parsed->value("--specimen"), out, err);
  if (sub == "new") {
    auto store = core::io::ProjectStore::create(file, buildinfo::kMozziVersion);
    if (!store) return fail(err, "new", store.error());
    out << "created " << file << " (schema " << store->schemaVersion() << ")\n";
    return kExitOk;
  }
  if (sub == "demo") {
    // Built under a temporary name and renamed into place: a killed run leaves
    // no project or a whole one (core/io/project_store.h).
    auto made = core::io::createProjectAtomically(
        file, [](const std::string& temp) { return devices::sim::createDemoProject(temp, buildinfo::kMozziVersion); });
    if (!made) return fail(err, "demo", made.error());
    out << "created demo project " << file << " with " << devices::sim::virtualSpecimens().size()
        << " virtual specimens\n";
    return kExitOk;
  }
  if (sub == "info") return info(file, parsed->flag("--json"), out, err);
  if (sub == "check") return check(file, parsed->flag("--json"), out, err);
  if (sub == "export") {
    const auto uffPath = parsed->value("--uff");
    const auto csvPath = parsed->value("--csv");
    if (uffPath.has_value() == csvPath.has_value()) {
      err << "mozzi-cli project export: give exactly one of --uff OUT.uff or --csv OUT.csv\n" << kUsage;
      return kExitUsage;
    }
    std::optional<std::int64_t> onlySet;
    if (const auto number = parsed->number("--frf-set"); number && number->has_value()) {
      onlySet = static_cast<std::int64_t>(**number);
    }
    if (csvPath && parsed->flag("--binary")) {
      err << "mozzi-cli project export: --binary applies to --uff only\n";
      return kExitUsage;
    }
    if (int rc = refuseOutputsOntoInputs(*parsed, kSpec, {file, file + "-wal", file + "-shm"}, "project export", err);
        rc != kExitOk) {
      return rc;
    }
    auto store = core::io::ProjectStore::open(file, core::io::ProjectStore::OpenMode::ReadOnly);
    if (!store) return fail(err, "export", store.error());
    if (uffPath) return exportUff(*store, file, *uffPath, parsed->flag("--binary"), onlySet, out, err);
    return exportCsv(*store, file, *csvPath, onlySet, out, err);
  }
  err << "mozzi-cli project: unknown subcommand '" << sub << "'\n" << kUsage;
  return kExitUsage;
}

const CommandRegistrar kRegistrar(
    {"project",
     "info|new|demo|check|export FILE.mozzi [--json] [--uff OUT.uff | --csv OUT.csv] | import FILE.mozzi IN.uff "
     "[--specimen NAME]",
     "Create a project (empty or the demo), summarise or check it, import a UFF into it, "
     "or export its FRFs and modes",
     projectCommand, &kSpec});

}  // namespace
}  // namespace mozzi::cli
