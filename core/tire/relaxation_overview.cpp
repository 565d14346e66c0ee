#include "core/tire/relaxation_overview.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/io/project_store.h"

namespace mozzi::core::tire {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string squashed(const std::string& s) {
  std::string out;
  for (char c : s)
    if (c != ' ' && c != '/' && c != '-') out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  return out;
}

const io::StoredTyreTest::Parameter* wholeTestParameter(const io::StoredTyreTest& t, const std::string& name) {
  for (const auto& p : t.parameters)
    if (p.name == name && !p.step) return &p;
  return nullptr;
}

bool samePressure(double a, double b) {
  return std::abs(a - b) <= 0.01 * std::max(std::abs(a), std::abs(b));
}

}  // namespace

const ThesisTyre* findThesisTyre(const std::string& text) {
  const std::string s = squashed(text);
  for (const auto& t : thesisTyres())
    if (s.find(squashed(t.size)) != std::string::npos) return &t;
  return nullptr;
}

Result<MeasuredRelaxation> measuredRelaxation(const io::StoredTyreTest& t) {
  const std::string where = "relaxation test '" + t.name + "'";
  if (t.kind != "relaxation")
    return makeError(ErrorCode::InvalidArgument, "a '" + t.kind + "' test holds no relaxation length", where);
  MeasuredRelaxation m;
  m.testId = t.id;
  m.name = t.name;
  m.pressurePa = t.inflationPressurePa;
  m.verticalLoadN = t.verticalLoadN;
  m.speedMps = t.speedMps;
  if (const auto* a = wholeTestParameter(t, "half_length")) m.halfLengthM = a->value;
  if (const auto* s = wholeTestParameter(t, "relaxation_length_m")) {
    m.bandMean = s->value;
    m.bandMeanStdError = s->uncertainty;
  }
  // Per step: the commanded frequency and the relaxation length (tyre_tests.cpp).
  std::map<int, MeasuredRelaxationPoint> steps;
  std::map<int, bool> hasSigma;
  for (const auto& p : t.parameters) {
    if (!p.step) continue;
    auto& point = steps[*p.step];
    point.step = *p.step;
    if (p.name == "frequency") point.frequencyHz = p.value;
    if (p.name == "relaxation_length_m") {
      point.sigma = p.value;
      point.sigmaStdError = p.uncertainty;
      hasSigma[*p.step] = true;
    }
  }
  for (const auto& [step, point] : steps)
    if (hasSigma[step] && point.frequencyHz > 0.0) m.points.push_back(point);
  if (m.points.empty() && !m.bandMean)
    return makeError(ErrorCode::NotFound, "no relaxation length stored (interrupted before the first frequency?)",
                     where);
  return m;
}

Result<RelaxationOverview> relaxationOverview(const io::ProjectStore& store, std::int64_t specimenId) {
  MOZZI_TRY_ASSIGN(auto summary, store.summary());
  RelaxationOverview o;
  o.specimenId = specimenId;
  bool found = false;
  for (const auto& s : summary.specimens)
    if (s.id == specimenId) o.specimenName = s.name, found = true;
  const std::string where = "relaxation overview of specimen " + std::to_string(specimenId);
  if (!found) return makeError(ErrorCode::NotFound, "no such specimen in the project", where);
  const ThesisTyre* tyre = findThesisTyre(o.specimenName);
  if (!tyre)
    return makeError(ErrorCode::NotFound,
                     "'" + o.specimenName +
                         "' names none of the thesis tyres (Table 16 gives the ring stiffness of 120/70 R17, "
                         "180/55 R17, 110/70-16, 140/70-14, 120/70-12, 130/70-12)",
                     where);
  o.tyre = *tyre;
  // Table 16 ring at nominal pressure, eq. 45 to 47 with the assumed mass and damping.
  MOZZI_TRY_ASSIGN(o.ring, ringModelFromStiffness({{0, tyre->lateralStiffness, kAssumedDampingRatio},
                                                   {1, tyre->camberStiffness, kAssumedDampingRatio},
                                                   {2, tyre->cShapedStiffness, kAssumedDampingRatio},
                                                   {3, tyre->sShapedStiffness, kAssumedDampingRatio}},
                                                  RingModelSettings{tyre->tyreMass, 0.8, tyre->outerRadius}));

  MOZZI_TRY_ASSIGN(auto infos, store.tyreTests());
  struct Cornering {
    std::int64_t id;
    double pressurePa, loadN, value;
  };
  std::vector<Cornering> cornering;  // the specimen's steady-state results
  for (const auto& info : infos) {
    if (info.specimenId != specimenId) continue;
    MOZZI_TRY_ASSIGN(auto t, store.tyreTest(info.id));
    if (t.kind == "relaxation") {
      auto m = measuredRelaxation(t);
      if (m)
        o.tests.push_back(std::move(*m));
      else
        o.unreadableTests.push_back(info.id);
    } else if (const auto* c = wholeTestParameter(t, "cornering_stiffness"); c && c->value > 0.0) {
      cornering.push_back({t.id, t.inflationPressurePa, t.verticalLoadN, c->value});
    }
  }
  std::stable_sort(o.tests.begin(), o.tests.end(), [](const MeasuredRelaxation& a, const MeasuredRelaxation& b) {
    return a.pressurePa < b.pressurePa;
  });

  // One eq. 48 case: C_bFalpha measured at this pressure (scaled to F_z by
  // C/F_z when the loads differ) or assumed.
  auto predict = [&](double pressurePa, double halfLength, double load) -> Result<PredictionCase> {
    PredictionCase c;
    c.pressurePa = pressurePa;
    c.contact.halfLength = halfLength;
    c.contact.verticalLoad = load;
    c.contact.friction = kAssumedFriction;
    c.contact.slipAngle = 1.5 * kPi / 180.0;  // §5.4
    c.contact.corneringStiffness = kAssumedNormalisedCorneringStiffness * load;
    for (const auto& m : cornering)
      if (samePressure(m.pressurePa, pressurePa) && m.loadN > 0.0) {
        c.contact.corneringStiffness = m.value / m.loadN * load;
        c.corneringSource = CorneringSource::SteadyStateTest;
        c.corneringTestId = m.id;
        break;
      }
    auto p = predictRelaxationLength(o.ring, c.contact);
    if (!p) {
      std::ostringstream w;
      w << p.error().where << ", " << pressurePa / 1e5 << " bar";
      return makeError(p.error().code, p.error().message, w.str());
    }
    c.prediction = *p;
    return c;
  };
  for (std::size_t i = 0; i < kThesisPressures.size(); ++i) {
    MOZZI_TRY_ASSIGN(auto c, predict(kThesisPressures[i], tyre->halfLength[i], tyre->testLoad));
    o.table17.push_back(c);
  }
  for (const auto& t : o.tests) {
    const double load = t.verticalLoadN > 0.0 ? t.verticalLoadN : tyre->testLoad;
    // A test that stored no half-length: Table 17 at its pressure.
    MOZZI_TRY_ASSIGN(
        auto c,
        predict(t.pressurePa, t.halfLengthM > 0.0 ? t.halfLengthM : table17HalfLength(*tyre, t.pressurePa), load));
    o.atTests.push_back(c);
  }
  return o;
}

nlohmann::json ringModelJson(const RingModel& r) {
  nlohmann::json modes = nlohmann::json::array();
  for (const auto& m : r.modes)
    modes.push_back({{"k", m.k},
                     {"name", m.name},
                     {"natural_frequency_hz", m.naturalFrequencyHz},
                     {"damping_ratio", m.dampingRatio},
                     {"modal_mass_kg", m.modalMass},
                     {"modal_stiffness_n_per_m", m.modalStiffness},
                     {"damping_n_s_per_m", m.dampingCoefficient}});
  return {{"ring_mass_kg", r.ringMass}, {"ring_radius_m", r.ringRadius}, {"modes", modes}};
}

std::string relaxationOverviewJson(const RelaxationOverview& o) {
  using Json = nlohmann::json;
  auto cases = [](const std::vector<PredictionCase>& list) {
    Json out = Json::array();
    for (const auto& c : list) {
      const auto& p = c.prediction;
      Json j = {{"pressure_bar", c.pressurePa / 1e5},
                {"half_length_m", c.contact.halfLength},
                {"load_n", c.contact.verticalLoad},
                {"cornering_stiffness_n_per_rad", c.contact.corneringStiffness},
                {"cornering_stiffness_source",
                 c.corneringSource == CorneringSource::SteadyStateTest ? "steady-state test" : "assumed"},
                {"adhesion_fraction", p.adhesionFraction},
                {"contact_patch_m", p.contactPatch},
                {"camber_m", p.camber},
                {"lateral_m", p.lateral},
                {"c_shaped_m", p.cShaped},
                {"s_shaped_m", p.sShaped},
                {"higher_modes_m", p.higherModes},
                {"sigma_m", p.total()}};
      if (c.corneringSource == CorneringSource::SteadyStateTest) j["cornering_test_id"] = c.corneringTestId;
      out.push_back(j);
    }
    return out;
  };
  Json measured = Json::array();
  for (const auto& t : o.tests) {
    Json j = {{"tyre_test_id", t.testId}, {"pressure_bar", t.pressurePa / 1e5}, {"points", t.points.size()}};
    if (t.bandMean) j["band_mean_sigma_m"] = *t.bandMean, j["band_mean_std_error_m"] = t.bandMeanStdError;
    measured.push_back(j);
  }
  return Json{{"method", "thesis eq. 48-50, Table 16 ring, Table 17 contact half-length"},
              {"tyre", o.tyre.size},
              {"ring", ringModelJson(o.ring)},
              {"table17", cases(o.table17)},
              {"at_tests", cases(o.atTests)},
              {"measured", measured}}
      .dump();
}

}  // namespace mozzi::core::tire
