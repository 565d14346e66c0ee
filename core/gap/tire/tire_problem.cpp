#include "core/gap/tire/tire_problem.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/common/text.h"
#include "core/tire/relaxation_prediction.h"
#include "core/tire/thesis_tyres.h"
#include "core/tire/tire_csv.h"

namespace mozzi::core::gap {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

enum TireEffect { kBeltModes = 0, kCarcassDamping, kTrailFeedback, kContactPatchFraction, kRingPressureStiffening };

std::string pressureLabel(double bar) {
  return formatNumber(bar, 3) + " bar";
}

// A copy of the ring with every mode's viscous ratio set to zeta
// (c_k = 2 zeta C_k / w_k, ring_model.h).
tire::RingModel withDamping(const tire::RingModel& ring, double zeta) {
  tire::RingModel out = ring;
  for (auto& m : out.modes) {
    const double w = 2.0 * kPi * m.naturalFrequencyHz;
    m.dampingRatio = zeta;
    m.dampingCoefficient = w > 0.0 ? 2.0 * zeta * m.modalStiffness / w : 0.0;
  }
  return out;
}
}  // namespace

TireGapProblem::TireGapProblem(TireGapModel model, std::vector<ConditionPoint> points)
    : ConditionSeriesProblem(std::move(points), "relaxation_residual"), model_(std::move(model)) {}

Result<std::unique_ptr<TireGapProblem>> TireGapProblem::create(TireGapModel model,
                                                               std::vector<ConditionPoint> measured) {
  const char* where = "tyre gap problem";
  if (!model.ring.mode(0) || !model.ring.mode(1))
    return makeError(ErrorCode::InvalidArgument, "the ring model needs the lateral (k=0) and camber (k=1) modes",
                     where);
  if (model.contactPatch.empty())
    return makeError(ErrorCode::InvalidArgument, "no contact-patch half-length given", where);
  std::sort(model.contactPatch.begin(), model.contactPatch.end());
  for (std::size_t i = 0; i < model.contactPatch.size(); ++i) {
    const auto& [p, a] = model.contactPatch[i];
    if (!(p >= 0.0) || !(a > 0.0) || !std::isfinite(p) || !std::isfinite(a))
      return makeError(ErrorCode::InvalidArgument, "contact patch entries need pressure >= 0 and half-length > 0",
                       where);
    if (i > 0 && p == model.contactPatch[i - 1].first)
      return makeError(ErrorCode::InvalidArgument, "contact patch pressure " + pressureLabel(p / 1e5) + " repeated",
                       where);
  }
  if (!(model.corneringStiffness > 0.0) || !(model.verticalLoad > 0.0) || !(model.friction > 0.0) ||
      !(model.speed > 0.0) || !(model.nominalPressure > 0.0))
    return makeError(ErrorCode::InvalidArgument,
                     "cornering stiffness, vertical load, friction, speed and nominal pressure must be positive",
                     where);
  if (!(model.corneringStiffnessRelSigma > 0.0))
    return makeError(ErrorCode::InvalidArgument, "the cornering stiffness uncertainty must be positive", where);
  if (model.excitationHz.empty())
    return makeError(ErrorCode::InvalidArgument, "at least one excitation frequency is needed", where);
  if (model.excitationHz.size() > kMaxExcitationFrequencies)
    return makeError(ErrorCode::InvalidArgument,
                     "at most " + std::to_string(kMaxExcitationFrequencies) + " excitation frequencies (got " +
                         std::to_string(model.excitationHz.size()) + ")",
                     "excitation_hz");
  for (std::size_t i = 0; i < model.excitationHz.size(); ++i) {
    const double f = model.excitationHz[i];
    if (!(f > 0.0) || !(f <= kMaxExcitationHz))
      return makeError(ErrorCode::InvalidArgument,
                       "excitation frequencies must lie in (0, " + formatNumber(kMaxExcitationHz) + "] Hz (got " +
                           formatNumber(f) + ")",
                       "excitation_hz[" + std::to_string(i) + "]");
  }
  if (measured.empty()) return makeError(ErrorCode::InvalidArgument, "no measured relaxation lengths", where);
  const double pLo = model.contactPatch.front().first / 1e5, pHi = model.contactPatch.back().first / 1e5;
  for (std::size_t j = 0; j < measured.size(); ++j) {
    auto& pt = measured[j];
    if (!(pt.sigma > 0.0) || !std::isfinite(pt.sigma) || !std::isfinite(pt.measured) || !(pt.measured > 0.0) ||
        !(pt.x > 0.0) || !std::isfinite(pt.x))
      return makeError(ErrorCode::InvalidArgument, "pressure, relaxation length and its uncertainty must be positive",
                       pressureLabel(pt.x));
    if (model.contactPatch.size() > 1 && (pt.x < pLo - 1e-9 || pt.x > pHi + 1e-9))
      return makeError(ErrorCode::InvalidArgument,
                       "pressure outside the contact-patch table (" + pressureLabel(pLo) + " to " + pressureLabel(pHi) +
                           "): a(p) would be extrapolated",
                       pressureLabel(pt.x));
    if (pt.label.empty()) pt.label = pressureLabel(pt.x);
    pt.fold = static_cast<int>(j);  // every pressure is its own held-out group
  }
  auto problem = std::unique_ptr<TireGapProblem>(new TireGapProblem(std::move(model), std::move(measured)));
  // The model must evaluate at the nominal parameters (e.g. eq. 49's m > 0).
  const double theta = 1.0;
  TireGapProblem::Terms t;
  for (const auto& pt : problem->points_)
    if (!problem->predictOne(pt.x * 1e5, {&theta, -1, nullptr}, t)) {
      auto m =
          tire::adhesionFraction({problem->halfLength(pt.x * 1e5), problem->model_.corneringStiffness,
                                  problem->model_.verticalLoad, problem->model_.friction, problem->model_.slipAngle});
      return makeError(
          ErrorCode::InvalidArgument,
          "the first-order prediction cannot be evaluated" + (m ? std::string() : ": " + m.error().message),
          pressureLabel(pt.x));
    }
  return problem;
}

double TireGapProblem::halfLength(double pressurePa) const {
  const auto& t = model_.contactPatch;
  if (t.size() == 1 || pressurePa <= t.front().first) return t.front().second;
  if (pressurePa >= t.back().first) return t.back().second;
  // front < p < back here, so hi is past the first entry.
  auto hi = std::upper_bound(t.begin(), t.end(), pressurePa,
                             [](double p, const std::pair<double, double>& e) { return p < e.first; });
  auto lo = hi - 1;
  const double u = (pressurePa - lo->first) / (hi->first - lo->first);
  return lo->second + u * (hi->second - lo->second);
}

std::vector<Parameter> TireGapProblem::calibrationParameters() const {
  // The cornering stiffness multiplies the whole carcass term of eq. 48; it is
  // measured (appendix 2), so it is calibrated within its uncertainty only.
  return {{"cornering_stiffness_scale", "", 1.0, 0.5, 2.0, model_.corneringStiffnessRelSigma}};
}

std::vector<Candidate> TireGapProblem::candidates() const {
  return {
      {"belt_modes", {}, {{"compliance_ratio", "", 0.0, 0.0, 5.0, 0.0}}},
      {"carcass_damping", {}, {{"zeta", "", 0.0, 0.0, 0.5, 0.0}}},
      {"trail_feedback", {}, {{"trail", "m", 0.0, 0.0, 0.06, 0.0}}},
      {"contact_patch_fraction", {}, {{"patch_scale", "", 1.0, 0.2, 4.0, 0.0}}},
      {"ring_pressure_stiffening", {}, {{"beta", "", 0.0, -1.0, 3.0, 0.0}}},
  };
}

bool TireGapProblem::predictOne(double pressurePa, const ModelPoint& at, Terms& out) const {
  const double a = halfLength(pressurePa);
  const double C = at.theta[0] * model_.corneringStiffness;
  const tire::ContactPatchInputs in{a, C, model_.verticalLoad, model_.friction, model_.slipAngle};
  auto p = tire::predictRelaxationLength(model_.ring, in);  // eq. 48-50
  if (!p) return false;
  double contact = p->contactPatch;
  double carcass = p->carcass();
  auto implied = [&](const tire::RingModel& ring, double trail, tire::RingFrfVariant variant, double& sigma) {
    Vector w(static_cast<Eigen::Index>(model_.excitationHz.size()));
    for (Eigen::Index i = 0; i < w.size(); ++i) w[i] = 2.0 * kPi * model_.excitationHz[static_cast<std::size_t>(i)];
    auto s = tire::impliedRelaxationLength(ring, {model_.speed, a, contact, C, trail}, w, variant);
    if (!s) return false;
    double sum = 0.0;
    for (Eigen::Index i = 0; i < w.size(); ++i) {
      if (!s->valid[static_cast<std::size_t>(i)]) return false;
      sum += s->sigma[i];
    }
    sigma = sum / static_cast<double>(w.size());  // §5.4: the measured line averages the frequencies
    return true;
  };
  double sigma = contact + carcass;
  switch (at.candidate) {
    case -1: break;
    case kBeltModes:
      // One more ring mode in series: C_bFalpha / C_4 with 1/C_4 = rho / C_yg.
      carcass += C * at.phi[0] * model_.ring.staticLateralCompliance();
      sigma = contact + carcass;
      break;
    case kCarcassDamping:
      if (!implied(withDamping(model_.ring, at.phi[0]), 0.0, tire::RingFrfVariant::NoTrail, sigma)) return false;
      break;
    case kTrailFeedback:
      if (!implied(withDamping(model_.ring, 0.0), at.phi[0], tire::RingFrfVariant::Full, sigma)) return false;
      break;
    case kContactPatchFraction:
      contact *= at.phi[0];
      sigma = contact + carcass;
      break;
    case kRingPressureStiffening:
      carcass *= std::pow(pressurePa / model_.nominalPressure, -at.phi[0]);
      sigma = contact + carcass;
      break;
    default: return false;
  }
  // For the FRF-based effects the carcass part is what the phase adds beyond a m.
  if (at.candidate == kCarcassDamping || at.candidate == kTrailFeedback) carcass = sigma - contact;
  out = {sigma, contact, carcass};
  return std::isfinite(sigma);
}

std::vector<double> TireGapProblem::predict(const ModelPoint& at) const {
  std::vector<double> out(points_.size(), kNaN);
  Terms t;
  for (std::size_t j = 0; j < points_.size(); ++j)
    if (predictOne(points_[j].x * 1e5, at, t)) out[j] = t.sigma;
  return out;
}

std::unique_ptr<GapProblem> TireGapProblem::withPoints(std::vector<ConditionPoint> points) const {
  return std::unique_ptr<GapProblem>(new TireGapProblem(model_, std::move(points)));
}

std::vector<std::vector<std::pair<std::string, double>>> TireGapProblem::details(const ModelPoint& at) const {
  std::vector<std::vector<std::pair<std::string, double>>> extra(points_.size());
  Terms t;
  for (std::size_t j = 0; j < points_.size(); ++j) {
    const double pa = points_[j].x * 1e5;
    if (!predictOne(pa, at, t)) continue;
    extra[j] = {{"pressure_bar", points_[j].x},
                {"half_length", halfLength(pa)},
                {"contact_patch_term", t.contactPatch},
                {"carcass_term", t.carcass}};
  }
  return extra;
}

std::vector<OverlayCurve> TireGapProblem::overlay(const ModelPoint& at) const {
  OverlayCurve c;
  c.label = "relaxation length";
  c.xLabel = "Pressure [bar]";
  c.yLabel = "sigma [m]";
  c.predicted = predict(at);
  for (const auto& pt : points_) {
    c.x.push_back(pt.x);
    c.measured.push_back(pt.measured);
  }
  return {c};
}

// ---- files ---------------------------------------------------------------------

namespace {
using Json = nlohmann::json;

Result<double> number(const Json& j, const char* key, const std::string& where, double fallback, bool required) {
  if (!j.contains(key)) {
    if (required) return makeError(ErrorCode::ParseError, std::string("missing \"") + key + "\"", where);
    return fallback;
  }
  const Json& v = j.at(key);
  if (!v.is_number() || !std::isfinite(v.get<double>()))
    return makeError(ErrorCode::ParseError, std::string("\"") + key + "\" must be a finite number", where);
  return v.get<double>();
}

std::string squash(std::string s) {
  s.erase(std::remove_if(s.begin(), s.end(), [](char c) { return c == ' ' || c == '/' || c == '-'; }), s.end());
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}
}  // namespace

Result<TireGapModel> parseTireGapModel(const std::string& jsonText, const std::string& source) {
  Json j = Json::parse(jsonText, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return makeError(ErrorCode::ParseError, "not a JSON object", source);
  if (!j.contains("schema") || !j["schema"].is_string() || j["schema"].get<std::string>() != "mozzi-tire-gap/1")
    return makeError(ErrorCode::ParseError, "\"schema\" must be \"mozzi-tire-gap/1\"", source);
  TireGapModel m;
  const tire::ThesisTyre* thesis = nullptr;
  if (j.contains("thesis_tyre")) {
    if (!j["thesis_tyre"].is_string())
      return makeError(ErrorCode::ParseError, "\"thesis_tyre\" must be a string", source);
    const std::string id = j["thesis_tyre"].get<std::string>();
    for (const auto& t : tire::thesisTyres())
      if (squash(t.size) == squash(id)) thesis = &t;
    if (!thesis)
      return makeError(
          ErrorCode::NotFound,
          "unknown thesis tyre '" + id + "' (120/70 R17, 180/55 R17, 110/70-16, 140/70-14, 120/70-12, 130/70-12)",
          source + ": thesis_tyre");
  }
  auto num = [&](const Json& obj, const char* key, const std::string& where, double fallback, bool required) {
    return number(obj, key, where, fallback, required);
  };
  // Ring model: explicit "ring" wins; otherwise the thesis tyre's Table 16.
  tire::RingModelSettings settings;
  if (thesis) settings = {thesis->tyreMass, 0.8, thesis->outerRadius};
  const bool hasRing = j.contains("ring");
  if (!hasRing && !thesis) return makeError(ErrorCode::ParseError, "needs \"thesis_tyre\" or \"ring\"", source);
  if (hasRing) {
    const Json& r = j["ring"];
    const std::string where = source + ": ring";
    if (!r.is_object()) return makeError(ErrorCode::ParseError, "\"ring\" must be an object", where);
    MOZZI_TRY_ASSIGN(const double mass, num(r, "tyre_mass_kg", where, settings.tyreMass, !thesis));
    MOZZI_TRY_ASSIGN(const double share, num(r, "belt_share", where, settings.beltShare, false));
    MOZZI_TRY_ASSIGN(const double radius, num(r, "ring_radius_m", where, settings.ringRadius, !thesis));
    settings = {mass, share, radius};
    if (!r.contains("modes") || !r["modes"].is_array() || r["modes"].empty())
      return makeError(ErrorCode::ParseError, "\"modes\" must be a non-empty array", where);
    std::vector<tire::RingStiffnessInput> stiff;
    std::vector<tire::RingModeInput> freq;
    for (std::size_t i = 0; i < r["modes"].size(); ++i) {
      const Json& e = r["modes"][i];
      const std::string w = where + ".modes[" + std::to_string(i) + "]";
      if (!e.is_object()) return makeError(ErrorCode::ParseError, "mode must be an object", w);
      if (!e.contains("k") || !e["k"].is_number_integer())
        return makeError(ErrorCode::ParseError, "\"k\" must be an integer", w);
      const int k = e["k"].get<int>();
      MOZZI_TRY_ASSIGN(const double zeta, num(e, "damping_ratio", w, 0.0, false));
      const bool byStiffness = e.contains("stiffness_n_per_m"), byFrequency = e.contains("frequency_hz");
      if (byStiffness == byFrequency)
        return makeError(ErrorCode::ParseError, "give exactly one of \"stiffness_n_per_m\" and \"frequency_hz\"", w);
      if (byStiffness) {
        MOZZI_TRY_ASSIGN(const double c, num(e, "stiffness_n_per_m", w, 0.0, true));
        stiff.push_back({k, c, zeta});
      } else {
        MOZZI_TRY_ASSIGN(const double f, num(e, "frequency_hz", w, 0.0, true));
        freq.push_back({k, f, zeta});
      }
    }
    if (!stiff.empty() && !freq.empty())
      return makeError(ErrorCode::ParseError, "modes must all be given by stiffness or all by frequency", where);
    auto ring = stiff.empty() ? tire::identifyRingModel(freq, settings) : tire::ringModelFromStiffness(stiff, settings);
    if (!ring) return makeError(ring.error().code, ring.error().message, where + " (" + ring.error().where + ")");
    m.ring = *ring;
  } else {
    MOZZI_TRY_ASSIGN(m.ring, tire::ringModelFromStiffness({{0, thesis->lateralStiffness, 0.0},
                                                           {1, thesis->camberStiffness, 0.0},
                                                           {2, thesis->cShapedStiffness, 0.0},
                                                           {3, thesis->sShapedStiffness, 0.0}},
                                                          settings));
  }
  // Contact patch: explicit table wins; otherwise Table 17.
  if (j.contains("contact_patch")) {
    const Json& c = j["contact_patch"];
    const std::string where = source + ": contact_patch";
    if (!c.is_array() || c.empty()) return makeError(ErrorCode::ParseError, "must be a non-empty array", where);
    for (std::size_t i = 0; i < c.size(); ++i) {
      const std::string w = where + "[" + std::to_string(i) + "]";
      if (!c[i].is_object()) return makeError(ErrorCode::ParseError, "entry must be an object", w);
      MOZZI_TRY_ASSIGN(const double p, num(c[i], "pressure_bar", w, 0.0, true));
      MOZZI_TRY_ASSIGN(const double a, num(c[i], "half_length_m", w, 0.0, true));
      m.contactPatch.push_back({p * 1e5, a});
    }
  } else if (thesis) {
    for (std::size_t i = 0; i < tire::kThesisPressures.size(); ++i)
      m.contactPatch.push_back({tire::kThesisPressures[i], thesis->halfLength[i]});
  } else {
    return makeError(ErrorCode::ParseError, "missing \"contact_patch\"", source);
  }
  MOZZI_TRY_ASSIGN(m.verticalLoad, num(j, "vertical_load_n", source, thesis ? thesis->testLoad : 0.0, !thesis));
  MOZZI_TRY_ASSIGN(m.corneringStiffness,
                   num(j, "cornering_stiffness_n_per_rad", source,
                       thesis ? tire::kAssumedNormalisedCorneringStiffness * m.verticalLoad : 0.0, !thesis));
  MOZZI_TRY_ASSIGN(m.corneringStiffnessRelSigma, num(j, "cornering_stiffness_rel_sigma", source, 0.1, false));
  MOZZI_TRY_ASSIGN(m.friction, num(j, "friction", source, tire::kAssumedFriction, false));
  MOZZI_TRY_ASSIGN(const double slipDeg, num(j, "slip_angle_deg", source, 1.5, false));
  MOZZI_TRY_ASSIGN(m.speed, num(j, "speed_m_s", source, 5.0 / 3.6, false));
  MOZZI_TRY_ASSIGN(const double nominalBar, num(j, "nominal_pressure_bar", source, 2.0, false));
  m.slipAngle = slipDeg * kPi / 180.0;
  m.nominalPressure = nominalBar * 1e5;
  if (j.contains("excitation_hz")) {
    const Json& e = j["excitation_hz"];
    if (!e.is_array() || e.empty())
      return makeError(ErrorCode::ParseError, "\"excitation_hz\" must be a non-empty array", source);
    m.excitationHz.clear();
    for (const auto& f : e) {
      if (!f.is_number()) return makeError(ErrorCode::ParseError, "\"excitation_hz\" entries must be numbers", source);
      m.excitationHz.push_back(f.get<double>());
    }
  }
  m.label = thesis ? thesis->size + " (thesis Tables 16, 17)" : std::string("ring model");
  if (j.contains("label") && j["label"].is_string()) m.label = j["label"].get<std::string>();
  return m;
}

Result<std::vector<ConditionPoint>> parseRelaxationCsv(const std::string& csvText, const std::string& source) {
  MOZZI_TRY_ASSIGN(const tire::NumericTable t,
                   tire::parseNumericTable(csvText, source, {"pressure_bar", "sigma_m", "uncertainty_m"}));
  const int cp = t.column("pressure_bar"), cs = t.column("sigma_m"), cu = t.column("uncertainty_m");
  std::vector<ConditionPoint> out;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const auto& r = t.rows[i];
    const std::string where = source + ":" + std::to_string(t.lines[i]);
    if (!(r[cp] > 0.0)) return makeError(ErrorCode::ParseError, "pressure_bar must be positive", where);
    if (!(r[cs] > 0.0)) return makeError(ErrorCode::ParseError, "sigma_m must be positive", where);
    if (!(r[cu] > 0.0)) return makeError(ErrorCode::ParseError, "uncertainty_m must be positive", where);
    for (const auto& o : out)
      if (o.x == r[cp])
        return makeError(ErrorCode::ParseError, "pressure " + pressureLabel(r[cp]) + " repeated", where);
    out.push_back({pressureLabel(r[cp]), r[cp], r[cs], r[cu], 0});
  }
  return out;
}

Result<std::unique_ptr<GapProblem>> loadTireGapProblem(const std::string& modelPath, const std::string& measuredPath,
                                                       const TireLoadOptions& options) {
  return loadConditionSeriesProblem<TireGapProblem, ConditionPoint>(
      modelPath, [&](const std::string& text) { return parseTireGapModel(text, modelPath); }, measuredPath,
      parseRelaxationCsv, [](const ConditionPoint& p) { return p.x; }, options.minPressureBar, options.maxPressureBar,
      "pressure");
}

}  // namespace mozzi::core::gap
