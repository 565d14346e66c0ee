#include "core/gap/stability/stability_problem.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/common/text.h"
#include "core/stability/mode_tracking.h"
#include "core/tire/tire_csv.h"

namespace mozzi::core::gap {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string pointLabel(const ModeFrequency& m) {
  return m.mode + " " + formatNumber(m.speed, 4) + " m/s";
}
}  // namespace

namespace {
// Equal-width speed ranges: each fold holds out one range of speeds.
std::vector<ConditionPoint> speedPoints(const std::vector<ModeFrequency>& modes, int bins) {
  double lo = modes.front().speed, hi = lo;
  for (const auto& m : modes) lo = std::min(lo, m.speed), hi = std::max(hi, m.speed);
  bins = std::max(1, bins);
  std::vector<ConditionPoint> points;
  for (const auto& m : modes) {
    const int fold = hi > lo ? std::min(static_cast<int>(bins * (m.speed - lo) / (hi - lo)), bins - 1) : 0;
    points.push_back({pointLabel(m), m.speed, m.frequencyHz, m.sigmaHz, fold});
  }
  return points;
}
}  // namespace

StabilityGapProblem::StabilityGapProblem(StabilityGapModel model, std::vector<ModeFrequency> modes)
    : ConditionSeriesProblem(speedPoints(modes, model.speedFolds), "frequency_residual"),
      model_(std::move(model)),
      modes_(std::move(modes)) {
  std::set<double> speeds;
  for (const auto& m : modes_) speeds.insert(m.speed);
  speeds_.assign(speeds.begin(), speeds.end());
}

Result<std::unique_ptr<StabilityGapProblem>> StabilityGapProblem::create(StabilityGapModel model,
                                                                         std::vector<ModeFrequency> measured) {
  const char* where = "stability gap problem";
  if (measured.empty()) return makeError(ErrorCode::InvalidArgument, "no measured mode frequencies", where);
  if (!(model.trailRelSigma > 0.0) || !std::isfinite(model.trailRelSigma))
    return makeError(ErrorCode::InvalidArgument, "the trail uncertainty must be positive", where);
  if (!(model.trackingStep > 0.0)) return makeError(ErrorCode::InvalidArgument, "tracking step must be > 0", where);
  for (const auto& m : measured) {
    if (!(m.speed > 0.0) || !(m.frequencyHz > 0.0) || !(m.sigmaHz > 0.0) || !std::isfinite(m.speed) ||
        !std::isfinite(m.frequencyHz) || !std::isfinite(m.sigmaHz))
      return makeError(ErrorCode::InvalidArgument, "speed, frequency and uncertainty must be positive", pointLabel(m));
    for (const auto& o : measured)
      if (&o != &m && o.mode == m.mode && o.speed == m.speed)
        return makeError(ErrorCode::InvalidArgument, "mode measured twice at one speed", pointLabel(m));
  }
  auto problem = std::unique_ptr<StabilityGapProblem>(new StabilityGapProblem(std::move(model), std::move(measured)));
  const double theta = 1.0;
  const auto pred = problem->predict({&theta, -1, nullptr});
  for (std::size_t j = 0; j < pred.size(); ++j)
    if (!std::isfinite(pred[j])) {
      auto sys = problem->system({&theta, -1, nullptr});
      return makeError(ErrorCode::InvalidArgument,
                       sys ? "the nominal model has no oscillating mode of that name at that speed"
                           : "the nominal model cannot be built: " + sys.error().describe(),
                       problem->points_[j].label);
    }
  return problem;
}

std::vector<std::string> StabilityGapProblem::effectNames() const {
  if (model_.vehicle == StabilityVehicle::Motorcycle) return {"fork_bending", "tyre_relaxation"};
  return {"fork_bending", "fork_torsion"};
}

std::vector<Parameter> StabilityGapProblem::calibrationParameters() const {
  return {{"trail_scale", "", 1.0, 0.7, 1.3, model_.trailRelSigma}};
}

std::vector<Candidate> StabilityGapProblem::candidates() const {
  std::vector<Candidate> out;
  for (const auto& name : effectNames()) {
    if (name == "tyre_relaxation")
      out.push_back({name, {"front and rear tyre"}, {{"sigma_scale", "", 1.0, 0.2, 5.0, 0.0}}});
    else
      out.push_back({name, {"front fork"}, {{"compliance_ratio", "", 0.0, 0.0, 5.0, 0.0}}});
  }
  return out;
}

Result<stability::StabilitySystem> StabilityGapProblem::system(const ModelPoint& at) const {
  const auto names = effectNames();
  const std::string effect = at.candidate >= 0 && at.candidate < static_cast<int>(names.size())
                                 ? names[static_cast<std::size_t>(at.candidate)]
                                 : "";
  if (at.candidate >= static_cast<int>(names.size()))
    return makeError(ErrorCode::InvalidArgument, "no such candidate", "stability gap problem");
  const double ratio = effect.empty() ? 0.0 : at.phi[0];
  if (model_.vehicle == StabilityVehicle::Motorcycle) {
    auto p = model_.motorcycle;
    p.t *= at.theta[0];
    std::optional<stability::LumpedForkModel> fork;
    if (effect == "fork_bending" && ratio > 0.0) {
      fork = model_.motorcycleFork;
      fork->stiffness /= ratio;           // k = k_ref / phi
      fork->damping /= std::sqrt(ratio);  // c = 2 zeta sqrt(k J): same zeta
    }
    if (effect == "tyre_relaxation") p.sigma *= ratio;
    MOZZI_TRY_ASSIGN(const stability::MotorcycleModel m, stability::MotorcycleModel::build(p, fork));
    return m.system();
  }
  auto p = model_.bicycle;
  p.c *= at.theta[0];
  Result<stability::BicycleModel> m = makeError(ErrorCode::InvalidArgument, "unset");
  if (effect == "fork_bending" && ratio > 0.0) {
    auto f = model_.bicycleBending;
    f.stiffness /= ratio;
    f.damping /= std::sqrt(ratio);
    m = stability::forkBendingModel(p, f);
  } else if (effect == "fork_torsion" && ratio > 0.0) {
    auto f = model_.bicycleTorsion;
    f.stiffness /= ratio;
    f.damping /= std::sqrt(ratio);
    m = stability::forkTorsionModel(p, f);
  } else {
    m = stability::benchmarkModel(p);
  }
  if (!m) return m.error();
  return stability::bicycleSystem(*m);
}

std::vector<double> StabilityGapProblem::predict(const ModelPoint& at) const {
  std::vector<double> out(modes_.size(), kNaN);
  auto sys = system(at);
  if (!sys) return out;
  auto sweep = stability::sweepSpeeds(*sys, speeds_, model_.trackingStep);
  if (!sweep) return out;
  for (std::size_t j = 0; j < modes_.size(); ++j) {
    const auto it = std::lower_bound(speeds_.begin(), speeds_.end(), modes_[j].speed);
    const auto& pt = sweep->points[static_cast<std::size_t>(it - speeds_.begin())];
    for (const auto& r : pt.roots)
      if (r.name == modes_[j].mode && r.lambda.imag() > 0.0) {
        out[j] = r.lambda.imag() / kTwoPi;
        break;
      }
  }
  return out;
}

std::unique_ptr<GapProblem> StabilityGapProblem::withPoints(std::vector<ConditionPoint> points) const {
  auto modes = modes_;
  for (std::size_t j = 0; j < modes.size(); ++j) modes[j].frequencyHz = points[j].measured;
  return std::unique_ptr<GapProblem>(new StabilityGapProblem(model_, std::move(modes)));
}

std::vector<std::vector<std::pair<std::string, double>>> StabilityGapProblem::details(const ModelPoint&) const {
  std::vector<std::vector<std::pair<std::string, double>>> extra;
  for (const auto& m : modes_) extra.push_back({{"speed_m_s", m.speed}});
  return extra;
}

GapMetrics StabilityGapProblem::metrics(const ModelPoint& at) const {
  GapMetrics m = ConditionSeriesProblem::metrics(at);
  auto sys = system(at);
  if (!sys) return m;
  auto grid = stability::speedGrid(0.5 * speeds_.front(), 1.5 * speeds_.back(), model_.trackingStep);
  if (!grid) return m;
  auto sweep = stability::sweepSpeeds(*sys, *grid, model_.trackingStep);
  if (!sweep) return m;
  std::vector<std::string> names;
  for (const auto& md : modes_)
    if (std::find(names.begin(), names.end(), md.mode) == names.end()) names.push_back(md.mode);
  for (const auto& name : names) {
    const auto v = sweep->criticalSpeed(name);
    GapEntry e;
    e.kind = "prediction";
    e.label = name + " critical speed [m/s]";
    e.value = v ? *v : 0.0;
    e.details = {{"found", v ? 1.0 : 0.0}, {"from_m_s", grid->front()}, {"to_m_s", grid->back()}};
    m.entries.push_back(std::move(e));
  }
  return m;
}

std::vector<OverlayCurve> StabilityGapProblem::overlay(const ModelPoint& at) const {
  const auto pred = predict(at);
  std::vector<OverlayCurve> curves;
  for (std::size_t j = 0; j < modes_.size(); ++j) {
    auto it =
        std::find_if(curves.begin(), curves.end(), [&](const OverlayCurve& c) { return c.label == modes_[j].mode; });
    if (it == curves.end()) {
      curves.push_back({modes_[j].mode, "Speed [m/s]", "Frequency [Hz]", false, {}, {}, {}});
      it = curves.end() - 1;
    }
    it->x.push_back(modes_[j].speed);
    it->measured.push_back(modes_[j].frequencyHz);
    it->predicted.push_back(pred[j]);
  }
  return curves;
}

// ---- files ---------------------------------------------------------------------

namespace {
using Json = nlohmann::json;

Result<double> optionalNumber(const Json& j, const char* key, double fallback, const std::string& where) {
  if (!j.contains(key)) return fallback;
  if (!j[key].is_number() || !std::isfinite(j[key].get<double>()))
    return makeError(ErrorCode::ParseError, std::string("\"") + key + "\" must be a finite number", where);
  return j[key].get<double>();
}

// The numbers of an optional object j[key] into the given fields (absent
// numbers keep their value).
Result<void> readOptionalObject(const Json& j, const char* key, const std::string& source,
                                const std::vector<std::pair<const char*, double*>>& fields) {
  if (!j.contains(key)) return {};
  const Json& o = j[key];
  const std::string where = source + ": " + key;
  if (!o.is_object()) return makeError(ErrorCode::ParseError, "must be an object", where);
  for (const auto& [name, value] : fields) {
    MOZZI_TRY_ASSIGN(*value, optionalNumber(o, name, *value, where));
  }
  return {};
}
}  // namespace

Result<StabilityGapModel> parseStabilityGapModel(const std::string& jsonText, const std::string& source,
                                                 const std::string& baseDir) {
  Json j = Json::parse(jsonText, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return makeError(ErrorCode::ParseError, "not a JSON object", source);
  if (!j.contains("schema") || !j["schema"].is_string() || j["schema"].get<std::string>() != "mozzi-stability-gap/1")
    return makeError(ErrorCode::ParseError, "\"schema\" must be \"mozzi-stability-gap/1\"", source);
  if (!j.contains("vehicle") || !j["vehicle"].is_string())
    return makeError(ErrorCode::ParseError, "\"vehicle\" must be \"motorcycle\" or \"bicycle\"", source);
  const std::string vehicle = j["vehicle"].get<std::string>();
  StabilityGapModel m;
  std::string paramPath;
  if (j.contains("parameters")) {
    if (!j["parameters"].is_string())
      return makeError(ErrorCode::ParseError, "\"parameters\" must be a file path", source);
    paramPath = j["parameters"].get<std::string>();
    if (!paramPath.empty() && paramPath[0] != '/' && !baseDir.empty()) paramPath = baseDir + "/" + paramPath;
  }
  if (vehicle == "motorcycle") {
    m.vehicle = StabilityVehicle::Motorcycle;
    if (paramPath.empty())
      return makeError(ErrorCode::ParseError, "a motorcycle needs \"parameters\" (Sharp 1971 CSV)", source);
    MOZZI_TRY_ASSIGN(m.motorcycle, stability::loadSharpParameters(paramPath));
    int forkModel = 1;
    if (j.contains("fork_model")) {
      if (!j["fork_model"].is_number_integer())
        return makeError(ErrorCode::ParseError, "\"fork_model\" must be 1, 2 or 3 (thesis Table 12)", source);
      forkModel = j["fork_model"].get<int>();
    }
    auto fork = stability::thesisLumpedForkModel(forkModel);
    if (!fork) return makeError(fork.error().code, fork.error().message, source + ": fork_model");
    m.motorcycleFork = *fork;
    m.label = "motorcycle (Sharp 1971), fork bending as thesis Table 12 model " + std::to_string(forkModel);
  } else if (vehicle == "bicycle") {
    m.vehicle = StabilityVehicle::Bicycle;
    if (paramPath.empty()) {
      m.bicycle = stability::meijaard2007Parameters();
    } else {
      MOZZI_TRY_ASSIGN(m.bicycle, stability::loadBenchmarkParameters(paramPath));
    }
    m.bicycleBending = stability::thesisSteelForkBending();
    m.bicycleTorsion = stability::thesisSteelForkTorsion();
    MOZZI_TRY(readOptionalObject(j, "fork_bending", source,
                                 {{"stiffness_n_m_per_rad", &m.bicycleBending.stiffness},
                                  {"damping_n_m_s_per_rad", &m.bicycleBending.damping},
                                  {"h_w_m", &m.bicycleBending.hW}}));
    MOZZI_TRY(readOptionalObject(j, "fork_torsion", source,
                                 {{"stiffness_n_m_per_rad", &m.bicycleTorsion.stiffness},
                                  {"damping_n_m_s_per_rad", &m.bicycleTorsion.damping}}));
    if (!(m.bicycleBending.stiffness > 0.0) || !(m.bicycleTorsion.stiffness > 0.0))
      return makeError(ErrorCode::ParseError, "reference fork stiffnesses must be positive", source);
    m.label = "benchmark bicycle (Meijaard et al. 2007), fork joints of thesis appendix 3";
  } else {
    return makeError(ErrorCode::ParseError, "\"vehicle\" must be \"motorcycle\" or \"bicycle\", not '" + vehicle + "'",
                     source);
  }
  MOZZI_TRY_ASSIGN(m.trailRelSigma, optionalNumber(j, "trail_rel_sigma", m.trailRelSigma, source));
  if (j.contains("speed_folds")) {
    if (!j["speed_folds"].is_number_integer() || j["speed_folds"].get<int>() < 1 || j["speed_folds"].get<int>() > 50)
      return makeError(ErrorCode::ParseError, "\"speed_folds\" must be an integer from 1 to 50", source);
    m.speedFolds = j["speed_folds"].get<int>();
  }
  if (j.contains("label") && j["label"].is_string()) m.label = j["label"].get<std::string>();
  return m;
}

Result<std::vector<ModeFrequency>> parseModeFrequencyCsv(const std::string& csvText, const std::string& source) {
  // The "mode" column holds names: each is swapped for its row number so the
  // numeric table reader (core/tire/tire_csv.h) checks every other cell with
  // the file's own line numbers, then mapped back.
  std::istringstream in(csvText);
  std::ostringstream numeric;
  std::vector<std::string> names;
  std::string line;
  int modeColumn = -2, n = 0;  // -2: header not seen yet
  auto trim = [](const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r");
    return a == std::string::npos ? std::string() : s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
  };
  while (std::getline(in, line)) {
    ++n;
    const std::string t = trim(line);
    if (!t.empty() && t[0] != '#') {
      std::vector<std::string> cells;
      std::stringstream ss(t);
      std::string cell;
      while (std::getline(ss, cell, ',')) cells.push_back(trim(cell));
      if (modeColumn == -2) {
        const auto it = std::find(cells.begin(), cells.end(), "mode");
        modeColumn = it == cells.end() ? -1 : static_cast<int>(it - cells.begin());
      } else if (modeColumn >= 0 && modeColumn < static_cast<int>(cells.size())) {
        std::string& name = cells[static_cast<std::size_t>(modeColumn)];
        if (name.empty()) return makeError(ErrorCode::ParseError, "empty mode name", source + ":" + std::to_string(n));
        names.push_back(name);
        name = std::to_string(names.size() - 1);
        std::string joined;
        for (std::size_t i = 0; i < cells.size(); ++i) joined += (i ? "," : "") + cells[i];
        if (!t.empty() && t.back() == ',') joined += ",";
        numeric << joined << "\n";
        continue;
      }
    }
    numeric << line << "\n";
  }
  MOZZI_TRY_ASSIGN(
      const tire::NumericTable table,
      tire::parseNumericTable(numeric.str(), source, {"speed_m_s", "mode", "frequency_hz", "uncertainty_hz"}));
  const int cs = table.column("speed_m_s"), cm = table.column("mode"), cf = table.column("frequency_hz"),
            cu = table.column("uncertainty_hz");
  std::vector<ModeFrequency> out;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const auto& r = table.rows[i];
    const std::string where = source + ":" + std::to_string(table.lines[i]);
    ModeFrequency m{names[static_cast<std::size_t>(r[cm])], r[cs], r[cf], r[cu]};
    for (const auto& [v, name] :
         {std::pair{m.speed, "speed_m_s"}, {m.frequencyHz, "frequency_hz"}, {m.sigmaHz, "uncertainty_hz"}})
      if (!(v > 0.0)) return makeError(ErrorCode::ParseError, std::string(name) + " must be positive", where);
    for (const auto& o : out)
      if (o.mode == m.mode && o.speed == m.speed)
        return makeError(ErrorCode::ParseError, "mode measured twice at one speed", where);
    out.push_back(m);
  }
  return out;
}

Result<std::unique_ptr<GapProblem>> loadStabilityGapProblem(const std::string& modelPath,
                                                            const std::string& measuredPath,
                                                            const StabilityLoadOptions& options) {
  const auto slash = modelPath.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string(".") : modelPath.substr(0, slash);
  return loadConditionSeriesProblem<StabilityGapProblem, ModeFrequency>(
      modelPath, [&](const std::string& text) { return parseStabilityGapModel(text, modelPath, dir); }, measuredPath,
      parseModeFrequencyCsv, [](const ModeFrequency& m) { return m.speed; }, options.minSpeed, options.maxSpeed,
      "speed");
}

}  // namespace mozzi::core::gap
