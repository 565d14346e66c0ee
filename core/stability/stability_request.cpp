// The Stability page's and the demo project's sweeps (stability_record.h):
// the vehicle's system from the request, swept by mode_tracking.h.
#include "core/stability/benchmark_bicycle.h"
#include "core/stability/compliant_fork_bicycle.h"
#include "core/stability/motorcycle.h"
#include "core/stability/stability_record.h"

namespace mozzi::core::stability {

namespace {

Result<StabilitySystem> motorcycleSystem(const StabilityRequest& r, bool rigid, std::string* model) {
  SharpParameters p = sharp1971Parameters();
  if (!r.parametersFile.empty()) {
    MOZZI_TRY_ASSIGN(p, loadSharpParameters(r.parametersFile));
  }
  std::optional<LumpedForkModel> fork;
  if (!rigid && r.fork != "rigid") {
    int index = 0;
    for (int i = 1; i <= 3; ++i)
      if (r.fork == "model " + std::to_string(i)) index = i;
    if (index == 0)
      return makeError(ErrorCode::InvalidArgument, "'" + r.fork + "' is not rigid, model 1, model 2 or model 3",
                       "motorcycle fork");
    if (r.kept) {
      const auto& m = r.kept->lumped.at(static_cast<std::size_t>(index - 1));
      if (!m)
        return makeError(ErrorCode::InvalidArgument,
                         "the kept fork '" + r.kept->name + "' has no model " + std::to_string(index), "fork");
      fork = *m;
    } else {
      MOZZI_TRY_ASSIGN(fork, thesisLumpedForkModel(index));
    }
  }
  MOZZI_TRY_ASSIGN(const MotorcycleModel m, MotorcycleModel::build(p, fork));
  if (model) {
    *model = r.parametersFile.empty() ? "motorcycle (Sharp 1971 standard machine, built in)"
                                      : "motorcycle (Sharp 1971 structure) from " + r.parametersFile;
    *model += ", fork " + (fork ? fork->name : std::string("rigid"));
    if (fork && r.kept) *model += " of " + r.kept->name;
  }
  return m.system();
}

Result<StabilitySystem> bicycleSystemOf(const StabilityRequest& r, bool rigid, std::string* model) {
  BenchmarkParameters p = meijaard2007Parameters();
  if (!r.parametersFile.empty()) {
    MOZZI_TRY_ASSIGN(p, loadBenchmarkParameters(r.parametersFile));
  }
  if (model)
    *model = r.parametersFile.empty() ? "benchmark bicycle (Meijaard et al. 2007)" : "bicycle from " + r.parametersFile;
  if (rigid || r.fork == "rigid") {
    MOZZI_TRY_ASSIGN(auto m, benchmarkModel(p));
    return bicycleSystem(m);
  }
  if (r.fork != "bending" && r.fork != "torsion")
    return makeError(ErrorCode::InvalidArgument, "'" + r.fork + "' is not rigid, bending or torsion", "bicycle fork");
  const bool bending = r.fork == "bending";
  if (r.kept && ((bending && !r.kept->bending) || (!bending && !r.kept->torsion)))
    return makeError(ErrorCode::InvalidArgument, "the kept fork '" + r.kept->name + "' has no " + r.fork + " stiffness",
                     "fork");
  MOZZI_TRY_ASSIGN(auto m, bending ? forkBendingModel(p, r.kept ? *r.kept->bending : thesisSteelForkBending())
                                   : forkTorsionModel(p, r.kept ? *r.kept->torsion : thesisSteelForkTorsion()));
  if (model) *model += " with fork " + r.fork + (r.kept ? " of " + r.kept->name : std::string());
  return bicycleSystem(m);
}

}  // namespace

Result<StabilitySystem> stabilitySystem(const StabilityRequest& r, bool rigid, std::string* model) {
  if (r.vehicle == "motorcycle") return motorcycleSystem(r, rigid, model);
  if (r.vehicle == "bicycle") return bicycleSystemOf(r, rigid, model);
  return makeError(ErrorCode::InvalidArgument, "'" + r.vehicle + "' is neither bicycle nor motorcycle", "vehicle");
}

Result<StabilityRecord> computeStabilityRecord(const StabilityRequest& r) {
  MOZZI_TRY_ASSIGN(auto speeds, speedGrid(r.from, r.to, r.step));
  if (r.vehicle == "motorcycle" && !(speeds.front() > 0.0))
    return makeError(ErrorCode::InvalidArgument, "speeds must be positive (tyre slip divides by speed)",
                     "motorcycle speeds");
  StabilityRecord out;
  out.vehicle = r.vehicle;
  out.fork = r.fork;
  out.forkSource = r.fork == "rigid" ? "" : r.kept ? "kept analysis " + std::to_string(r.kept->analysisId) : "thesis";
  out.parametersFile = r.parametersFile;
  out.from = r.from;
  out.to = r.to;
  out.step = r.step;
  MOZZI_TRY_ASSIGN(auto system, stabilitySystem(r, false, &out.model));
  MOZZI_TRY_ASSIGN(out.sweep, sweepSpeeds(system, speeds));
  if (r.compareRigid && r.fork != "rigid") {
    MOZZI_TRY_ASSIGN(auto rigid, stabilitySystem(r, true));
    MOZZI_TRY_ASSIGN(out.rigidSweep, sweepSpeeds(rigid, speeds));
  }
  return out;
}

}  // namespace mozzi::core::stability
