// mozzi-cli tire: relaxation length from harmonic yaw tests (thesis §1.9),
// ring modal model (§5.3), relaxation-length prediction (§5.4) and
// steady-state characteristics with a Magic Formula fit (appendix 2, ch. 7).
// File formats and examples: docs/cli/tire.md.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "core/tire/magic_formula.h"
#include "core/tire/relaxation_length.h"
#include "core/tire/relaxation_overview.h"
#include "core/tire/relaxation_prediction.h"
#include "core/tire/ring_model.h"
#include "core/tire/steady_state.h"
#include "core/tire/thesis_tyres.h"
#include "core/tire/tire_csv.h"

namespace mozzi::cli {
namespace {

namespace tr = core::tire;
using core::ErrorCode;
using core::makeError;
using core::Result;
using Json = nlohmann::json;
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

const char* kUsage =
    "Usage: mozzi-cli tire relaxation TEST.csv --half-length A [--speed V] [--force-sign -1] [--band LO:HI] [--json]\n"
    "       mozzi-cli tire ring --modes k:fHz:zeta,... --mass KG --radius M [--belt-share S] [--json]\n"
    "       mozzi-cli tire predict (--thesis-tyre SIZE | --stiffness k:N/m,... --cornering-stiffness C --load FZ\n"
    "                               --half-length A | --contact PRESSURES.csv) [--friction L] [--trail T]\n"
    "                               [--frequencies f1,f2,...] [--json]\n"
    "       mozzi-cli tire steady SWEEP.csv [--window DEG] [--magic-formula] [--nominal-load N]\n"
    "                               [--nominal-pressure BAR] [--radius M] [--hold NAME,...] [--json]\n";

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  const auto b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

int fail(std::ostream& err, const std::string& sub, const core::Error& e) {
  err << "mozzi-cli tire " << sub << ": " << e.describe() << "\n";
  return kExitFailure;
}
int usage(std::ostream& err, const std::string& msg) {
  err << "mozzi-cli tire: " << msg << "\n" << kUsage;
  return kExitUsage;
}

// The option table (docs/cli/tire.md): ranges of motorcycle, scooter,
// bicycle and wheelchair tyres with room to spare (thesis ch. 5-7 values
// are well inside).
const OptionSpec kSpec{
    {"--thesis-tyre", "--contact", "--hold"},
    {"--json", "--magic-formula"},
    {{"--half-length", aboveTo(0, 1, "m"), "contact patch half-length a"},
     {"--speed", aboveTo(0, 100, "m/s"), "rolling speed"},
     {"--force-sign", wholeNumber(-1, 1), "sign of the measured lateral force (-1 or 1)"},
     {"--band", "band in Hz, LO < HI", {{"LO", closed(0, 1e4, "Hz")}, {"HI", aboveTo(0, 1e4, "Hz")}}, ':'},
     {"--modes",
      "ring modes",
      {{"k", wholeNumber(0, 50)}, {"f", aboveTo(0, 1e4, "Hz")}, {"zeta", closed(0, 1)}},
      ':',
      true,
      64},
     {"--mass", aboveTo(0, 1000, "kg"), "ring (tyre) mass"},
     {"--radius", aboveTo(0, 5, "m"), "ring or unloaded radius"},
     {"--belt-share", aboveTo(0, 1), "share of the mass in the belt"},
     {"--stiffness",
      "ring stiffness per mode",
      {{"k", wholeNumber(0, 50)}, {"C", aboveTo(0, 1e9, "N/m")}},
      ':',
      true,
      64},
     {"--cornering-stiffness", aboveTo(0, 1e7, "N/rad"), "cornering stiffness C_alpha"},
     {"--load", aboveTo(0, 1e6, "N"), "vertical load F_z"},
     {"--friction", aboveTo(0, 10), "friction coefficient"},
     {"--trail", closed(-1, 1, "m"), "pneumatic trail"},
     {"--frequencies", "frequencies", {{"f", aboveTo(0, 1e4, "Hz")}}, ',', true, 1000},
     {"--damping-ratio", NumberRange(0, 1, false, true), "ring damping ratio"},
     {"--window", aboveTo(0, 90, "deg"), "regression half-window"},
     {"--nominal-load", aboveTo(0, 1e6, "N"), "Magic Formula nominal load F_z0"},
     {"--nominal-pressure", aboveTo(0, 100, "bar"), "Magic Formula nominal pressure"}}};

// Reads an optional number option, range-checked by parse().
bool number(const ParsedArgs& a, const std::string& name, std::optional<double>& out, std::ostream& err) {
  auto v = a.number(name);
  if (!v) {
    usage(err, v.error().describe());
    return false;
  }
  out = *v;
  return true;
}

// ---- relaxation ---------------------------------------------------------------
int relaxation(const ParsedArgs& a, std::ostream& out, std::ostream& err) {
  if (a.positional().size() != 2) return usage(err, "relaxation needs one TEST.csv");
  std::optional<double> half, speed, sign;
  if (!number(a, "--half-length", half, err) || !number(a, "--speed", speed, err) ||
      !number(a, "--force-sign", sign, err))
    return kExitUsage;
  if (!half) return usage(err, "relaxation needs --half-length (contact patch half-length a, m)");
  tr::HarmonicYawSettings s;
  s.halfLength = *half;
  if (speed) s.speed = *speed;
  if (sign) {
    if (*sign == 0.0) {
      err << "mozzi-cli tire: option --force-sign = 0 is out of range; valid: -1 or 1\n";
      return kExitFailure;
    }
    s.forceSign = *sign;
  }
  if (a.value("--band")) {
    const auto b = a.numbers("--band");
    if (!(b.at(1) > b.at(0))) {
      err << "mozzi-cli tire: option --band needs LO < HI (got '" << *a.value("--band") << "')\n";
      return kExitFailure;
    }
    s.bandLowHz = b[0], s.bandHighHz = b[1];
  }
  const std::string& file = a.positional()[1];
  auto t = tr::readNumericTable(file, tr::harmonicYawColumns());
  if (!t) return fail(err, "relaxation", t.error());
  auto recs = tr::harmonicYawRecords(*t, file);
  if (!recs) return fail(err, "relaxation", recs.error());
  auto res = tr::relaxationFromHarmonicYaw(*recs, s);
  if (!res) return fail(err, "relaxation", res.error());
  if (a.flag("--json")) {
    Json pts = Json::array();
    for (const auto& p : res->points) {
      Json j = {{"frequency_hz", p.frequencyHz},
                {"phase_lag_rad", p.phaseLagRad},
                {"phase_lag_std_error_rad", p.phaseLagStdError},
                {"valid", p.valid}};
      if (p.valid)
        j["sigma_m"] = p.sigma, j["sigma_std_error_m"] = p.sigmaStdError;
      else
        j["note"] = p.note;
      pts.push_back(j);
    }
    out << Json{{"points", pts},
                {"mean_sigma_m", res->meanSigma},
                {"mean_sigma_std_error_m", res->meanSigmaStdError},
                {"band_scatter_m", res->bandScatter},
                {"points_in_band", res->pointsInBand},
                {"band_hz", {s.bandLowHz, s.bandHighHz}}}
               .dump(2)
        << "\n";
    return kExitOk;
  }
  out << "relaxation length (thesis eq. 28), V = " << s.speed << " m/s, a = " << s.halfLength << " m\n";
  out << "  f [Hz]   lag [deg]        sigma [m]\n";
  for (const auto& p : res->points) {
    char line[160];
    if (p.valid)
      std::snprintf(line, sizeof line, "  %6.3f  %7.2f +- %5.2f   %.4f +- %.4f\n", p.frequencyHz, p.phaseLagRad / kDeg,
                    p.phaseLagStdError / kDeg, p.sigma, p.sigmaStdError);
    else
      std::snprintf(line, sizeof line, "  %6.3f  %7.2f +- %5.2f   flagged: ", p.frequencyHz, p.phaseLagRad / kDeg,
                    p.phaseLagStdError / kDeg);
    out << line << (p.valid ? "" : p.note + "\n");
  }
  char line[160];
  std::snprintf(line, sizeof line, "mean over %.2f-%.2f Hz (%d points): %.4f +- %.4f m (scatter %.4f m)\n", s.bandLowHz,
                s.bandHighHz, res->pointsInBand, res->meanSigma, res->meanSigmaStdError, res->bandScatter);
  out << line;
  return kExitOk;
}

// ---- ring ---------------------------------------------------------------------
void printRing(const tr::RingModel& r, std::ostream& out) {
  out << "ring mass " << r.ringMass << " kg (eq. 45-47, c = 2 zeta sqrt(C m))\n";
  out << "  k  mode        f [Hz]   zeta    m_k [kg]   C_k [kN/m]   c_k [Ns/m]\n";
  for (const auto& m : r.modes) {
    char line[160];
    std::snprintf(line, sizeof line, "  %d  %-10s %7.1f  %6.4f  %8.3f  %10.1f  %10.2f\n", m.k, m.name.c_str(),
                  m.naturalFrequencyHz, m.dampingRatio, m.modalMass, m.modalStiffness / 1e3, m.dampingCoefficient);
    out << line;
  }
}

int ring(const ParsedArgs& a, std::ostream& out, std::ostream& err) {
  std::optional<double> mass, radius, share;
  if (!number(a, "--mass", mass, err) || !number(a, "--radius", radius, err) || !number(a, "--belt-share", share, err))
    return kExitUsage;
  const auto modesText = a.value("--modes");
  if (!modesText || !mass || !radius) return usage(err, "ring needs --modes, --mass and --radius");
  const auto values = a.numbers("--modes");  // k, f, zeta per mode, range-checked by parse()
  std::vector<tr::RingModeInput> in;
  for (std::size_t k = 0; k + 2 < values.size(); k += 3)
    in.push_back({static_cast<int>(values[k]), values[k + 1], values[k + 2]});
  tr::RingModelSettings s{*mass, share.value_or(0.8), *radius};
  auto r = tr::identifyRingModel(in, s);
  if (!r) return fail(err, "ring", r.error());
  if (a.flag("--json"))
    out << tr::ringModelJson(*r).dump(2) << "\n";
  else
    printRing(*r, out);
  return kExitOk;
}

// ---- predict ------------------------------------------------------------------
int predict(const ParsedArgs& a, std::ostream& out, std::ostream& err) {
  std::optional<double> C, load, half, friction, trail, mass, radius, zeta;
  for (auto [n, v] : std::vector<std::pair<const char*, std::optional<double>*>>{{"--cornering-stiffness", &C},
                                                                                 {"--load", &load},
                                                                                 {"--half-length", &half},
                                                                                 {"--friction", &friction},
                                                                                 {"--trail", &trail},
                                                                                 {"--mass", &mass},
                                                                                 {"--radius", &radius},
                                                                                 {"--damping-ratio", &zeta}})
    if (!number(a, n, *v, err)) return kExitUsage;
  std::vector<tr::RingStiffnessInput> stiff;
  std::vector<std::pair<double, double>> contact;  // pressure [Pa], a [m]
  double fz = 0, cAlpha = 0, lambda = friction.value_or(tr::kAssumedFriction);
  double ringMass = mass.value_or(4.0), ringRadius = radius.value_or(0.3);
  const double z = zeta.value_or(tr::kAssumedDampingRatio);
  std::string label;
  if (auto size = a.value("--thesis-tyre")) {
    const tr::ThesisTyre* found = nullptr;
    auto squash = [](std::string s) {
      s.erase(std::remove_if(s.begin(), s.end(), [](char c) { return c == ' ' || c == '/' || c == '-'; }), s.end());
      return s;
    };
    for (const auto& t : tr::thesisTyres())
      if (squash(t.size) == squash(*size)) found = &t;
    if (!found)
      return usage(err, "unknown thesis tyre '" + *size +
                            "' (120/70R17, 180/55R17, 110/70-16, 140/70-14, 120/70-12, 130/70-12)");
    label = found->size + " (thesis Tables 16, 17; assumed inputs in docs/validation/tire.md)";
    stiff = {{0, found->lateralStiffness, z},
             {1, found->camberStiffness, z},
             {2, found->cShapedStiffness, z},
             {3, found->sShapedStiffness, z}};
    fz = load.value_or(found->testLoad);
    cAlpha = C.value_or(tr::kAssumedNormalisedCorneringStiffness * fz);
    ringMass = mass.value_or(found->tyreMass);
    ringRadius = radius.value_or(found->outerRadius);
    for (std::size_t i = 0; i < tr::kThesisPressures.size(); ++i)
      contact.push_back({tr::kThesisPressures[i], found->halfLength[i]});
    if (half) contact = {{0.0, *half}};
  } else {
    const auto st = a.value("--stiffness");
    if (!st || !C || !load)
      return usage(err, "predict needs --thesis-tyre, or --stiffness, --cornering-stiffness and --load");
    const auto values = a.numbers("--stiffness");  // k, C per mode, range-checked by parse()
    for (std::size_t k = 0; k + 1 < values.size(); k += 2)
      stiff.push_back({static_cast<int>(values[k]), values[k + 1], z});
    fz = *load;
    cAlpha = *C;
    label = "user input";
    if (half) {
      contact = {{0.0, *half}};
    } else if (auto file = a.value("--contact")) {
      auto t = tr::readNumericTable(*file, {"pressure_bar", "half_length_m"});
      if (!t) return fail(err, "predict", t.error());
      for (const auto& r : t->rows)
        contact.push_back({r[t->column("pressure_bar")] * 1e5, r[t->column("half_length_m")]});
    } else {
      return usage(err, "predict needs --half-length or --contact PRESSURES.csv");
    }
  }
  auto ringModel = tr::ringModelFromStiffness(stiff, {ringMass, 0.8, ringRadius});
  if (!ringModel) return fail(err, "predict", ringModel.error());
  std::vector<tr::PressureCase> cases;
  for (const auto& [p, aa] : contact) cases.push_back({p, {aa, cAlpha, fz, lambda, 1.5 * kDeg}, *ringModel});
  auto pred = tr::predictOverPressures(cases);
  if (!pred) return fail(err, "predict", pred.error());

  // Optional: sigma implied by the appendix-1 FRF phase at given frequencies (first pressure... each pressure).
  std::vector<double> freqs;
  if (a.value("--frequencies")) freqs = a.numbers("--frequencies");  // range-checked by parse()
  Json rows = Json::array();
  if (!a.flag("--json")) {
    out << "relaxation length prediction (thesis eq. 48-50), " << label << "\n  C_alpha " << cAlpha << " N/rad, F_z "
        << fz << " N, lambda " << lambda << "\n";
    out << "  p [bar]   a [m]      m   a m [m]  camber  lateral  C-shape  S-shape   sigma [m]\n";
  }
  for (std::size_t i = 0; i < pred->size(); ++i) {
    const auto& pp = (*pred)[i];
    const auto& r = pp.prediction;
    Json j = {{"pressure_bar", pp.pressure / 1e5},
              {"half_length_m", cases[i].contact.halfLength},
              {"adhesion_fraction", r.adhesionFraction},
              {"contact_patch_m", r.contactPatch},
              {"camber_m", r.camber},
              {"lateral_m", r.lateral},
              {"c_shaped_m", r.cShaped},
              {"s_shaped_m", r.sShaped},
              {"higher_modes_m", r.higherModes},
              {"sigma_m", r.total()}};
    char line[200];
    std::snprintf(line, sizeof line, "  %7.2f  %6.3f  %5.3f  %7.4f  %6.4f  %7.4f  %7.4f  %7.4f   %8.4f\n",
                  pp.pressure / 1e5, cases[i].contact.halfLength, r.adhesionFraction, r.contactPatch, r.camber,
                  r.lateral, r.cShaped, r.sShaped, r.total());
    if (!a.flag("--json")) out << line;
    if (!freqs.empty()) {
      core::Vector w(static_cast<Eigen::Index>(freqs.size()));
      for (std::size_t k = 0; k < freqs.size(); ++k) w[static_cast<Eigen::Index>(k)] = 2 * kPi * freqs[k];
      tr::RingFrfInputs in{5.0 / 3.6, cases[i].contact.halfLength, r.contactPatch, cAlpha, trail.value_or(0.0)};
      Json frf = Json::array();
      for (auto variant : {tr::RingFrfVariant::FirstOrder, tr::RingFrfVariant::NoTrail, tr::RingFrfVariant::Full}) {
        auto s = tr::impliedRelaxationLength(*ringModel, in, w, variant);
        if (!s) return fail(err, "predict", s.error());
        const char* name = variant == tr::RingFrfVariant::FirstOrder ? "first-order"
                           : variant == tr::RingFrfVariant::NoTrail  ? "no-trail"
                                                                     : "full";
        Json sig = Json::array();
        if (!a.flag("--json")) out << "      appendix-1 " << name << ":";
        for (Eigen::Index k = 0; k < w.size(); ++k) {
          const bool ok = s->valid[static_cast<std::size_t>(k)];
          sig.push_back(ok ? Json(s->sigma[k]) : Json(nullptr));
          if (!a.flag("--json")) {
            char c[64];
            if (ok)
              std::snprintf(c, sizeof c, " %.2f Hz %.4f m", freqs[static_cast<std::size_t>(k)], s->sigma[k]);
            else
              std::snprintf(c, sizeof c, " %.2f Hz out of range", freqs[static_cast<std::size_t>(k)]);
            out << c;
          }
        }
        if (!a.flag("--json")) out << "\n";
        frf.push_back({{"variant", name}, {"frequencies_hz", freqs}, {"sigma_m", sig}});
      }
      j["frf_implied_sigma"] = frf;
    }
    rows.push_back(j);
  }
  if (a.flag("--json"))
    out << Json{{"tyre", label},      {"cornering_stiffness_n_per_rad", cAlpha}, {"load_n", fz},
                {"friction", lambda}, {"ring", tr::ringModelJson(*ringModel)},   {"pressures", rows}}
               .dump(2)
        << "\n";
  return kExitOk;
}

// ---- steady -------------------------------------------------------------------
int steady(const ParsedArgs& a, std::ostream& out, std::ostream& err) {
  if (a.positional().size() != 2) return usage(err, "steady needs one SWEEP.csv");
  std::optional<double> window, nomLoad, nomP, radius;
  if (!number(a, "--window", window, err) || !number(a, "--nominal-load", nomLoad, err) ||
      !number(a, "--nominal-pressure", nomP, err) || !number(a, "--radius", radius, err))
    return kExitUsage;
  const std::string& file = a.positional()[1];
  auto t = tr::readNumericTable(file, tr::steadyStateColumns());
  if (!t) return fail(err, "steady", t.error());
  auto sweeps = tr::steadyStateSweeps(*t, file);
  if (!sweeps) return fail(err, "steady", sweeps.error());
  const double win = window.value_or(3.0) * kDeg;
  Json js = Json::array();
  if (!a.flag("--json"))
    out << "steady-state slopes at the origin (local quadratic regression over +-" << win / kDeg << " deg)\n";
  for (const auto& sw : *sweeps) {
    const bool camber = sw.camberSweep;
    const double load = sw.sweep.verticalLoad, bar = sw.sweep.pressure / 1e5;
    auto c = tr::characteriseSweep(sw.sweep, win, 2);
    if (!c) {
      auto e = c.error();
      e.where = file + ", " + (camber ? "camber" : "slip") + " sweep at " + std::to_string(load) + " N, " +
                std::to_string(bar) + " bar (line " + std::to_string(sw.firstLine) + "): " + e.where;
      return fail(err, "steady", e);
    }
    const char* fName = camber ? "camber_stiffness_n_per_rad" : "cornering_stiffness_n_per_rad";
    const char* mName = camber ? "twisting_torque_stiffness_nm_per_rad" : "aligning_torque_stiffness_nm_per_rad";
    js.push_back(
        {{"sweep", camber ? "camber" : "slip"},
         {"load_n", load},
         {"pressure_bar", bar},
         {fName, c->forceSlope.slope},
         {std::string(fName) + "_std_error", c->forceSlope.slopeStdError},
         {mName, c->torqueSlope.slope},
         {std::string(mName) + "_std_error", c->torqueSlope.slopeStdError},
         {"normalised_force_slope_per_rad", c->normalisedForceSlope},
         {"normalised_force",
          std::vector<double>(c->normalisedForce.data(), c->normalisedForce.data() + c->normalisedForce.size())},
         {"normalised_torque_m",
          std::vector<double>(c->normalisedTorque.data(), c->normalisedTorque.data() + c->normalisedTorque.size())}});
    if (!a.flag("--json")) {
      char line[240];
      std::snprintf(line, sizeof line,
                    "  %-6s sweep  F_z %6.0f N  p %4.2f bar: %s %9.1f +- %6.1f N/rad (%.2f /rad of F_z), %s %8.2f +- "
                    "%5.2f Nm/rad\n",
                    camber ? "camber" : "slip", load, bar, camber ? "C_gamma" : "C_alpha", c->forceSlope.slope,
                    c->forceSlope.slopeStdError, c->normalisedForceSlope, camber ? "C_twist" : "C_Mz",
                    c->torqueSlope.slope, c->torqueSlope.slopeStdError);
      out << line;
    }
  }
  Json result = {{"sweeps", js}};
  if (a.flag("--magic-formula")) {
    const std::vector<tr::SteadyStatePoint> pts = tr::steadyStatePoints(*t);
    double meanLoad = 0, meanP = 0;
    for (const auto& q : pts) meanLoad += q.load / pts.size(), meanP += q.pressure / pts.size();
    tr::MfConstants c{nomLoad.value_or(meanLoad), nomP ? *nomP * 1e5 : meanP, radius.value_or(0.3)};
    tr::MfFitOptions latOpt, alOpt;  // --hold a,b,...: names of either set
    if (auto hold = a.value("--hold")) {
      std::stringstream ss(*hold);
      std::string name;
      while (std::getline(ss, name, ',')) {
        name = trim(name);
        const auto& ln = tr::mfLateralNames();
        const auto& an = tr::mfAligningNames();
        if (std::find(ln.begin(), ln.end(), name) != ln.end())
          latOpt.fixed.insert(name);
        else if (std::find(an.begin(), an.end(), name) != an.end())
          alOpt.fixed.insert(name);
        else
          return usage(err, "--hold: unknown Magic Formula coefficient '" + name + "'");
      }
    }
    auto lat = tr::fitMfLateral(pts, c, latOpt);
    if (!lat) return fail(err, "steady --magic-formula", lat.error());
    auto al = tr::fitMfAligning(pts, c, lat->value, alOpt);
    if (!al) return fail(err, "steady --magic-formula", al.error());
    Json lj, aj;
    for (int i = 0; i < tr::kMfLateralCount; ++i)
      lj[tr::mfLateralNames()[i]] = {
          {"value", lat->value[i]}, {"std_error", lat->stdError[i]}, {"free", bool(lat->free[i])}};
    for (int i = 0; i < tr::kMfAligningCount; ++i)
      aj[tr::mfAligningNames()[i]] = {
          {"value", al->value[i]}, {"std_error", al->stdError[i]}, {"free", bool(al->free[i])}};
    result["magic_formula"] = {{"nominal_load_n", c.nominalLoad},
                               {"nominal_pressure_bar", c.nominalPressure / 1e5},
                               {"unloaded_radius_m", c.unloadedRadius},
                               {"lateral", lj},
                               {"lateral_rms_residual_n", lat->rmsResidual},
                               {"lateral_held_by_data", lat->heldByData},
                               {"aligning", aj},
                               {"aligning_rms_residual_nm", al->rmsResidual},
                               {"aligning_held_by_data", al->heldByData}};
    if (!a.flag("--json")) {
      out << "Magic Formula (Pacejka 2002 style), F_z0 " << c.nominalLoad << " N, p0 " << c.nominalPressure / 1e5
          << " bar; F_y rms " << lat->rmsResidual << " N, M_z rms " << al->rmsResidual << " Nm\n";
      for (int i = 0; i < tr::kMfLateralCount; ++i)
        if (lat->free[i])
          out << "  " << tr::mfLateralNames()[i] << " = " << lat->value[i] << " +- " << lat->stdError[i] << "\n";
      for (int i = 0; i < tr::kMfAligningCount; ++i)
        if (al->free[i])
          out << "  " << tr::mfAligningNames()[i] << " = " << al->value[i] << " +- " << al->stdError[i] << "\n";
      out << "  held (data cannot determine them):";
      for (const auto& n : lat->heldByData) out << " " << n;
      for (const auto& n : al->heldByData) out << " " << n;
      out << "\n";
    }
  }
  if (a.flag("--json")) out << result.dump(2) << "\n";
  return kExitOk;
}

int tireCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto parsed = ParsedArgs::parse(args, kSpec);
  if (!parsed && exitCodeFor(parsed.error()) == kExitFailure) {
    err << "mozzi-cli tire: " << parsed.error().describe() << "\n";
    return kExitFailure;
  }
  if (!parsed) return usage(err, parsed.error().describe());
  if (parsed->positional().empty()) return usage(err, "expected a subcommand");
  const std::string& sub = parsed->positional()[0];
  if (sub == "relaxation") return relaxation(*parsed, out, err);
  if (sub == "ring") return ring(*parsed, out, err);
  if (sub == "predict") return predict(*parsed, out, err);
  if (sub == "steady") return steady(*parsed, out, err);
  return usage(err, "unknown subcommand '" + sub + "'");
}

const CommandRegistrar kRegistrar(
    {"tire", "relaxation|ring|predict|steady ... [--json]",
     "Tyre relaxation length, ring modal model, prediction, steady-state and Magic Formula", tireCommand, &kSpec});

}  // namespace
}  // namespace mozzi::cli
