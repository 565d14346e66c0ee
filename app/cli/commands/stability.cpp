// mozzi-cli stability: eigenvalues against speed with mode names and critical
// speeds for the benchmark bicycle (with the thesis's fork bending or torsion
// compliance, appendix 3) and the Sharp (1971) motorcycle with the lumped fork
// models of thesis §4.2.
#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <sstream>
#include <utility>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "core/io/project_store.h"
#include "core/stability/benchmark_bicycle.h"
#include "core/stability/compliant_fork_bicycle.h"
#include "core/stability/mode_tracking.h"
#include "core/stability/motorcycle.h"
#include "core/stability/stability_record.h"

namespace mozzi::cli {
namespace {

namespace st = core::stability;

constexpr const char* kUsage =
    "Usage: mozzi-cli stability bicycle [--params FILE] [--fork-bending k,c,hW | --fork-torsion k,c] "
    "--speeds A:B:STEP [--json] [--project P.mozzi [--store NAME] [--specimen NAME]]\n"
    "       mozzi-cli stability motorcycle --params FILE [--fork-model 1|2|3|rigid] --speeds A:B:STEP [--json]\n"
    "                                      [--project P.mozzi [--store NAME] [--specimen NAME]]\n";

// The option table (docs/cli/stability.md): road speeds; fork joint
// stiffness up to 1e12 N m/rad (rigid for practical purposes, balance.h),
// damping and bend arm of a real fork.
const OptionSpec kSpec{
    {"--params", "--fork-model", "--project", "--store", "--specimen"},
    {"--json"},
    {{"--speeds",
      "speed grid",
      {{"A", closed(0, 1000, "m/s")}, {"B", closed(0, 1000, "m/s")}, {"STEP", aboveTo(0, 1000, "m/s")}},
      ':'},
     {"--fork-bending",
      "fork bending joint",
      {{"k", aboveTo(0, 1e12, "N m/rad")}, {"c", closed(0, 1e6, "N m s/rad")}, {"hW", aboveTo(0, 5, "m")}},
      ','},
     {"--fork-torsion",
      "fork torsion joint",
      {{"k", aboveTo(0, 1e12, "N m/rad")}, {"c", closed(0, 1e6, "N m s/rad")}},
      ','}}};

void printText(std::ostream& out, const std::string& model, const st::StabilitySweep& sweep) {
  out << "stability of " << model << "\n";
  out << std::fixed;
  for (const auto& p : sweep.points) {
    out << "v = " << std::setprecision(3) << p.v << " m/s:";
    for (const auto& r : p.roots) {
      out << "  " << r.name << " " << std::setprecision(4) << r.lambda.real();
      if (r.lambda.imag() > 0.0) out << " +/- " << r.lambda.imag() << "i";
    }
    out << "\n";
  }
  out << "events:\n";
  if (sweep.events.empty()) out << "  none in this speed range\n";
  for (const auto& e : sweep.events) {
    out << "  " << e.mode << " " << e.kind << " at " << st::criticalSpeedText(e.v) << " m/s";
    if (e.kind == "stabilises" || e.kind == "destabilises")
      out << " (" << st::crossingFrequencyText(e.frequency) << " rad/s)";
    out << "\n";
  }
  out.unsetf(std::ios::floatfield);
}

// Keeps the sweep as an analysis of kind "stability" (stability_record.h)
// under the named specimen or the vehicle's default one; returns its id and name.
core::Result<std::pair<std::int64_t, std::string>> storeResult(const std::string& path, const std::string& name,
                                                               const std::optional<std::string>& specimen,
                                                               const st::StabilityRecord& record) {
  auto store = core::io::ProjectStore::open(path);
  if (!store) return store.error();
  auto id = specimen ? st::specimenNamed(*store, *specimen) : st::defaultStabilitySpecimen(*store, record.vehicle);
  if (!id) return id.error();
  auto row = st::stabilityAnalysis(*store, *id, name, record);
  if (!row) return row.error();
  auto added = store->addAnalysis(*row);
  if (!added) return added.error();
  return std::make_pair(*added, row->name);
}

// Keeps the record when --project is given, then prints the sweep (text or
// JSON) with where it was kept.
int keepAndPrint(const ParsedArgs& parsed, st::StabilityRecord record, std::ostream& out, std::ostream& err) {
  const auto project = parsed.value("--project");
  std::optional<std::pair<std::int64_t, std::string>> stored;
  if (project) {
    auto kept =
        storeResult(*project, parsed.value("--store").value_or(record.model), parsed.value("--specimen"), record);
    if (!kept) {
      err << "mozzi-cli stability: " << kept.error().describe() << "\n";
      return kExitFailure;
    }
    stored = *kept;
  }
  if (parsed.flag("--json")) {
    auto j = st::sweepJson(record.model, record.sweep);
    if (stored) j["stored_analysis"] = {{"id", stored->first}, {"name", stored->second}};
    out << j.dump(2) << "\n";
  } else {
    printText(out, record.model, record.sweep);
    if (stored) out << "stored in " << *project << " as analysis " << stored->first << " '" << stored->second << "'\n";
  }
  return kExitOk;
}

int stabilityCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto parsed = ParsedArgs::parse(args, kSpec);
  if (!parsed && exitCodeFor(parsed.error()) == kExitFailure) {
    err << "mozzi-cli stability: " << parsed.error().describe() << "\n";
    return kExitFailure;
  }
  if (!parsed || parsed->positional().size() != 1) {
    err << "mozzi-cli stability: " << (parsed ? "expected bicycle or motorcycle" : parsed.error().describe()) << "\n"
        << kUsage;
    return kExitUsage;
  }
  const std::string& kind = parsed->positional()[0];
  if (kind != "bicycle" && kind != "motorcycle") {
    err << "mozzi-cli stability: unknown model '" << kind << "'\n" << kUsage;
    return kExitUsage;
  }
  const auto speedsText = parsed->value("--speeds");
  if (!speedsText) {
    err << "mozzi-cli stability: --speeds A:B:STEP is required\n" << kUsage;
    return kExitUsage;
  }
  const auto range = parsed->numbers("--speeds");  // A, B, STEP, range-checked by parse()
  const auto speeds = st::speedGrid(range.at(0), range.at(1), range.at(2));
  if (!speeds) {
    err << "mozzi-cli stability: option --speeds: " << speeds.error().message << "\n";
    return kExitFailure;
  }

  if (!parsed->value("--project") && (parsed->value("--store") || parsed->value("--specimen"))) {
    err << "mozzi-cli stability: --store and --specimen need --project P.mozzi\n" << kUsage;
    return kExitUsage;
  }
  st::StabilitySystem system;
  std::string model;
  st::StabilityRecord record;
  record.vehicle = kind;
  record.from = range.at(0);
  record.to = range.at(1);
  record.step = range.at(2);
  record.forkSource = "command line";
  record.fork = "rigid";
  record.parametersFile = parsed->value("--params").value_or("");
  if (kind == "bicycle") {
    if (parsed->value("--fork-model")) {
      err << "mozzi-cli stability bicycle: --fork-model is for the motorcycle\n" << kUsage;
      return kExitUsage;
    }
    const auto bending = parsed->value("--fork-bending");
    const auto torsion = parsed->value("--fork-torsion");
    if (bending && torsion) {
      err << "mozzi-cli stability bicycle: give --fork-bending or --fork-torsion, not both\n" << kUsage;
      return kExitUsage;
    }
    st::BenchmarkParameters params = st::meijaard2007Parameters();
    model = "benchmark bicycle (Meijaard et al. 2007)";
    if (const auto file = parsed->value("--params")) {
      auto p = st::loadBenchmarkParameters(*file);
      if (!p) {
        err << "mozzi-cli stability: " << p.error().describe() << "\n";
        return kExitFailure;
      }
      params = *p;
      model = "bicycle from " + *file;
    }
    core::Result<st::BicycleModel> m = core::makeError(core::ErrorCode::InvalidArgument, "no model");
    if (bending) {
      const auto v = parsed->numbers("--fork-bending");  // k, c, hW, range-checked by parse()
      m = st::forkBendingModel(params, {v.at(0), v.at(1), v.at(2)});
      model += " with fork bending";
      record.fork = "bending";
    } else if (torsion) {
      const auto v = parsed->numbers("--fork-torsion");  // k, c
      m = st::forkTorsionModel(params, {v.at(0), v.at(1), 0.0});
      model += " with fork torsion";
      record.fork = "torsion";
    } else {
      m = st::benchmarkModel(params);
    }
    if (!m) {
      err << "mozzi-cli stability: " << m.error().describe() << "\n";
      return kExitFailure;
    }
    system = st::bicycleSystem(*m);
  } else {
    if (parsed->value("--fork-bending") || parsed->value("--fork-torsion")) {
      err << "mozzi-cli stability motorcycle: use --fork-model 1|2|3|rigid\n" << kUsage;
      return kExitUsage;
    }
    const auto file = parsed->value("--params");
    if (!file) {
      err << "mozzi-cli stability motorcycle: --params FILE is required\n" << kUsage;
      return kExitUsage;
    }
    std::optional<st::LumpedForkModel> fork;
    const std::string forkName = parsed->value("--fork-model").value_or("rigid");
    if (forkName != "rigid") {
      if (forkName != "1" && forkName != "2" && forkName != "3") {
        err << "mozzi-cli stability: --fork-model must be 1, 2, 3 or rigid, not '" << forkName << "'\n" << kUsage;
        return kExitUsage;
      }
      auto f = st::thesisLumpedForkModel(std::stoi(forkName));
      if (!f) {
        err << "mozzi-cli stability: " << f.error().describe() << "\n";
        return kExitUsage;
      }
      fork = *f;
      record.fork = f->name;
    }
    if (!((*speeds)[0] > 0.0)) {
      err << "mozzi-cli stability motorcycle: option --speeds: speeds must be positive (tyre slip divides by "
             "speed)\n";
      return kExitFailure;
    }
    auto p = st::loadSharpParameters(*file);
    if (!p) {
      err << "mozzi-cli stability: " << p.error().describe() << "\n";
      return kExitFailure;
    }
    auto m = st::MotorcycleModel::build(*p, fork);
    if (!m) {
      err << "mozzi-cli stability: " << m.error().describe() << "\n";
      return kExitFailure;
    }
    system = m->system();
    model = "motorcycle (Sharp 1971 structure) from " + *file + ", fork " + (fork ? fork->name : "rigid");
  }
  const auto sweep = st::sweepSpeeds(system, *speeds);
  if (!sweep) {
    err << "mozzi-cli stability: " << sweep.error().describe() << "\n";
    return kExitFailure;
  }
  record.model = model;
  record.sweep = *sweep;
  return keepAndPrint(*parsed, std::move(record), out, err);
}

const CommandRegistrar kRegistrar(
    {"stability",
     "bicycle [--params FILE] [--fork-bending k,c,hW | --fork-torsion k,c] --speeds A:B:STEP "
     "[--json] | motorcycle --params FILE [--fork-model 1|2|3|rigid] --speeds A:B:STEP "
     "[--json]; either with [--project P.mozzi [--store NAME] [--specimen NAME]]",
     "Eigenvalues against speed with mode names and critical speeds (weave, capsize, wobble)", stabilityCommand,
     &kSpec});

}  // namespace
}  // namespace mozzi::cli
