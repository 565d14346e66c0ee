#pragma once
// The structural gap benchmark (issues 10 and 16, GAP.md "Testing it
// honestly"): the case list with hidden truth under several noise models
// (relative and additive floor, with and without coherence, 0.3% to 3%), the
// diagnosis of each case from the nominal model and the noisy FRFs only (the
// noise model is estimated by the diagnosis, never told), and the summary
// figures per noise model. Shared by the
// CI-sized validation test and the larger Google Benchmark program
// (tests/bench/gap_benchmark_bench.cpp).

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "core/gap/diagnosis.h"
#include "core/gap/structural/structural_problem.h"
#include "validation/gap/structural_benchmark.h"

namespace mozzi::gap_bench {

enum class CaseKind { Control, Effect, Ambiguous, OutOfCatalogue, CalibratedGroup, TwoEffects };

// A noise model of the generator: relative sigma per component, an additive
// floor as a fraction of each FRF's median |H|, coherence records or not.
struct NoiseCase {
  std::string name;
  double relative = 0.01;
  double floor = 0.0;
  bool coherence = false;
};

inline std::string noiseName(double relative, double floor, bool coherence) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s%.1f%%%s", floor > 0 ? "rel+floor " : "rel ", 100 * relative,
                coherence ? " coh" : "");
  return buf;
}

inline NoiseCase noiseCase(double relative, double floor, bool coherence) {
  return {noiseName(relative, floor, coherence), relative, floor, coherence};
}

struct Case {
  std::string structure;
  CaseKind kind = CaseKind::Effect;
  std::string effect;                 // true effect (empty for controls and out-of-catalogue)
  std::vector<std::string> location;  // true location in the model's labels
  double trueSize = 0.0;              // true value of the effect's first parameter
  double absent = 0.0;                // that parameter's "no effect" value
  std::vector<std::string> pair;      // ambiguous cases: the two confusable effects
  Truth truth;
  Measurement spec;
  std::vector<std::string> restrictTo;  // catalogue restriction for the diagnosis (ambiguous cases)
  bool modesData = false;               // the test is identified modes (first mode only), not FRFs
  NoiseCase noise;                      // how the FRFs were made noisy
  // Two effects at once: the second effect.
  std::string effect2;
  std::vector<std::string> location2;
  double trueSize2 = 0.0, absent2 = 0.0;
};

struct CaseResult {
  Case c;
  core::gap::Verdict verdict = core::gap::Verdict::None;
  std::string bestEffect;
  std::vector<std::string> bestLocation;
  double fittedSize = std::nan("");
  double shrinkPct = std::nan("");
  bool ok = false;  // the diagnosis ran
  std::string error;
  // Two effects named by the verdict (the pair's joint fit), else empty.
  std::string secondEffect;
  std::vector<std::string> secondLocation;
  double fittedSize2 = std::nan("");
  std::string noiseSource;  // the noise model the diagnosis chose
  std::string explanation;  // the diagnosis's paragraph
  double seconds = 0.0;
};

struct BenchConfig {
  // The noise models; with `rotate`, structure s gets noises[s % size] only
  // (the CI variant), else every structure gets every noise model.
  std::vector<NoiseCase> noises = {noiseCase(0.01, 0.0, false), noiseCase(0.01, 0.01, false),
                                   noiseCase(0.003, 0.003, true), noiseCase(0.03, 0.03, false)};
  bool rotate = true;
  int controlsPerStructure = 3;  // per structure and noise model
  int seedsPerEffect = 1;        // noise/calibration draws per (effect, size, location)
  int lines = 160;
  int bootstrap = 20;
  int multistarts = 4;
  // Designed-ambiguous, out-of-catalogue and calibrated-group cases, made
  // with the first noise model of each structure only.
  bool extras = true;
  unsigned long long seed = 20261121;
};

// The full benchmark (MOZZI_GAP_BENCH_FULL=1): relative only, relative plus
// floor without coherence and with coherence, at 0.3%, 1% and 3%, on every
// structure.
inline BenchConfig fullConfig() {
  BenchConfig cfg;
  cfg.noises.clear();
  for (double level : {0.003, 0.01, 0.03}) {
    cfg.noises.push_back(noiseCase(level, 0.0, false));
    cfg.noises.push_back(noiseCase(level, level, false));
    cfg.noises.push_back(noiseCase(level, level, true));
  }
  cfg.rotate = false;
  cfg.controlsPerStructure = 4;
  return cfg;
}

inline Measurement defaultMeasurement(const Structure& s, const BenchConfig& cfg, const NoiseCase& noise = {}) {
  Measurement m;
  m.responses = s.model.labels;
  m.references = s.references;
  m.lowHz = s.bandLowHz;
  m.highHz = s.bandHighHz;
  m.lines = cfg.lines;
  m.relativeNoise = noise.relative;
  m.floorNoise = noise.floor;
  m.coherence = noise.coherence;
  return m;
}

inline std::vector<std::string> springLocation(const StructuralModel& m, const std::string& name) {
  for (const auto& s : m.springs)
    if (s.name == name) {
      std::vector<std::string> loc{m.labels[static_cast<std::size_t>(s.a)]};
      if (s.b >= 0) loc.push_back(m.labels[static_cast<std::size_t>(s.b)]);
      return loc;
    }
  return {};
}

// Per structure: the DOFs, springs and sizes the effects are applied at.
struct EffectPlan {
  std::vector<std::string> massDofs;
  std::vector<std::string> boundarySprings;
  std::vector<std::string> elementSprings;
  std::pair<std::string, std::string> misaligned;  // channel, the DOF it leans to
  std::string absorberDof;
  std::string calibratedSpring;  // a spring of the calibrated group (non-identifiable case)
};

inline EffectPlan planFor(const std::string& name) {
  if (name == "fork_wheel") return {{"2+X", "4+Z"}, {"head_x"}, {"leg_x34"}, {"3+X", "3+Z"}, "2+X", "leg_z23"};
  if (name == "frame") return {{"5+X", "3+Y"}, {"mount_3x"}, {"tube_x45"}, {"5+Y", "5+X"}, "2+Y", "tube_y34"};
  if (name == "subframe") return {{"3+Z", "1+X"}, {"strut"}, {"tail"}, {"2+X", "2+Z"}, "1+Z", "rail_z"};
  return {{"3+X", "2+Z"}, {"pivot_z"}, {"arm_z23"}, {"3+X", "3+Z"}, "2+X", "arm_x23"};
}

// Calibration offsets of the truth: the model's stiffness group within its
// 5% prior and the damping within 10% (the baseline calibration absorbs both).
inline void drawCalibration(Truth& t, std::mt19937_64& rng) {
  std::normal_distribution<double> nd(0.0, 1.0);
  t.groupScale = 1.0 + 0.05 * std::clamp(nd(rng), -2.0, 2.0);
  t.dampingScale = 1.0 + 0.1 * std::clamp(nd(rng), -2.0, 2.0);
}

// Effect cases of one structure under one noise model (every catalogue effect
// at two sizes, masses at two DOFs).
inline void addEffectCases(std::vector<Case>& cases, const Structure& s,
                           const std::function<Case(CaseKind, const std::string&)>& base) {
  const StructuralModel& m = s.model;
  const EffectPlan plan = planFor(s.name);
  Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> eig(m.k, m.m);
  const double w1 = std::sqrt(eig.eigenvalues()[0]);
  for (const auto& dof : plan.massDofs) {
    const int d = m.findDof(*core::parseDof(dof));
    for (double frac : {0.15, 0.35}) {
      Case c = base(CaseKind::Effect, "mass_loading");
      c.location = {dof};
      c.trueSize = frac * m.m(d, d);
      c.truth.dm(d, d) = c.trueSize;
      cases.push_back(c);
    }
  }
  for (const auto& sp : plan.boundarySprings)
    for (double scale : {0.5, 0.25}) {
      Case c = base(CaseKind::Effect, "boundary_stiffness");
      c.location = springLocation(m, sp);
      c.trueSize = scale;
      c.absent = 1.0;
      c.truth.dk = (scale - 1.0) * springMatrix(m, sp);
      cases.push_back(c);
    }
  for (const auto& sp : plan.elementSprings)
    for (double scale : {0.5, 1.8}) {
      Case c = base(CaseKind::Effect, "element_stiffness");
      c.location = springLocation(m, sp);
      c.trueSize = scale;
      c.absent = 1.0;
      c.truth.dk = (scale - 1.0) * springMatrix(m, sp);
      cases.push_back(c);
    }
  for (double eta : {0.03, 0.05}) {
    // Structural instead of viscous damping: no viscous part at all.
    Case c = base(CaseKind::Effect, "hysteretic_damping");
    c.trueSize = eta;
    c.truth.dampingScale = 0.0;
    c.truth.eta = eta;
    cases.push_back(c);
  }
  for (double dz : {0.01, 0.03}) {
    // An uncorrected window adding dz to the first mode's damping ratio:
    // every pole's decay rises by a = dz omega_1 [1/s].
    Case c = base(CaseKind::Effect, "exponential_window");
    c.trueSize = dz * w1;
    c.truth.decay = c.trueSize;
    cases.push_back(c);
  }
  for (double degrees : {8.0, 17.0}) {
    Case c = base(CaseKind::Effect, "sensor_misalignment");
    c.location = {plan.misaligned.first, plan.misaligned.second};
    c.trueSize = degrees;
    c.truth.misDof = m.findDof(*core::parseDof(plan.misaligned.first));
    c.truth.misOther = m.findDof(*core::parseDof(plan.misaligned.second));
    c.truth.misAngle = degrees * M_PI / 180.0;
    cases.push_back(c);
  }
  for (double frac : {0.5, 1.5}) {
    // An out-of-band mode at 3.5x the band's top whose quasi-static
    // compliance along the deflection under the reference load is `frac`
    // times the model's own static compliance at the reference.
    Case c = base(CaseKind::Effect, "residual_mode");
    const int r = m.findDof(*core::parseDof(s.references[0]));
    const Matrix g = m.k.inverse();
    Vector u = g.col(r) / g(r, r);
    u /= u.cwiseAbs().maxCoeff();
    const double wx = 2 * M_PI * 3.5 * s.bandHighHz;
    c.location = {s.references[0]};
    c.truth.residualShape = u;
    c.truth.residualModeHz = wx / (2 * M_PI);
    c.truth.residualModalConstant = frac * g(r, r) / (u[r] * u[r]) * wx * wx;
    c.trueSize = c.truth.residualModalConstant / (wx * wx);  // the upper residual it implies
    cases.push_back(c);
  }
}

// Two effects at once: a mass with a softer boundary spring, and a stiffer
// element with an uncorrected window.
inline void addTwoEffectCases(std::vector<Case>& cases, const Structure& s,
                              const std::function<Case(CaseKind, const std::string&)>& base) {
  const StructuralModel& m = s.model;
  const EffectPlan plan = planFor(s.name);
  Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> eig(m.k, m.m);
  const double w1 = std::sqrt(eig.eigenvalues()[0]);
  {
    Case c = base(CaseKind::TwoEffects, "mass_loading");
    const int d = m.findDof(*core::parseDof(plan.massDofs[0]));
    c.location = {plan.massDofs[0]};
    c.trueSize = 0.3 * m.m(d, d);
    c.truth.dm(d, d) = c.trueSize;
    c.effect2 = "boundary_stiffness";
    c.location2 = springLocation(m, plan.boundarySprings[0]);
    c.trueSize2 = 0.5;
    c.absent2 = 1.0;
    c.truth.dk = -0.5 * springMatrix(m, plan.boundarySprings[0]);
    cases.push_back(c);
  }
  {
    Case c = base(CaseKind::TwoEffects, "element_stiffness");
    c.location = springLocation(m, plan.elementSprings[0]);
    c.trueSize = 1.8;
    c.absent = 1.0;
    c.truth.dk = 0.8 * springMatrix(m, plan.elementSprings[0]);
    c.effect2 = "exponential_window";
    c.trueSize2 = 0.02 * w1;
    c.truth.decay = c.trueSize2;
    cases.push_back(c);
  }
}

inline std::vector<Case> makeCases(const BenchConfig& cfg) {
  std::vector<Case> cases;
  std::mt19937_64 rng(cfg.seed);
  const auto all = structures();
  for (std::size_t si = 0; si < all.size(); ++si) {
    const Structure& s = all[si];
    const StructuralModel& m = s.model;
    const int n = m.dofCount();
    const EffectPlan plan = planFor(s.name);
    Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> eig(m.k, m.m);
    const double w1 = std::sqrt(eig.eigenvalues()[0]);
    std::vector<NoiseCase> noises = cfg.noises;
    if (cfg.rotate) noises = {cfg.noises[si % cfg.noises.size()]};
    for (std::size_t ni = 0; ni < noises.size(); ++ni) {
      const NoiseCase& noise = noises[ni];
      const Measurement spec = defaultMeasurement(s, cfg, noise);
      auto base = [&](CaseKind kind, const std::string& effect) {
        Case c;
        c.structure = s.name;
        c.kind = kind;
        c.effect = effect;
        c.truth = Truth(n);
        drawCalibration(c.truth, rng);
        c.spec = spec;
        c.noise = noise;
        return c;
      };
      for (int i = 0; i < cfg.controlsPerStructure; ++i) cases.push_back(base(CaseKind::Control, ""));
      for (int seed = 0; seed < cfg.seedsPerEffect; ++seed) addEffectCases(cases, s, base);
      addTwoEffectCases(cases, s, base);
      if (!cfg.extras || ni > 0) continue;
      // Designed-ambiguous pair: only the first mode (band 0.75-1.3 f1) at one
      // response: a mass at the driving point and the clamp stiffness both
      // just move that one peak.
      for (double frac : {0.1, 0.2}) {
        Case c = base(CaseKind::Ambiguous, "mass_loading");
        const std::string dof = s.references[0];
        const int d = m.findDof(*core::parseDof(dof));
        c.location = {dof};
        c.trueSize = frac * m.m(d, d);
        c.truth.dm(d, d) = c.trueSize;
        c.spec.responses = {dof};
        c.spec.references = {s.references[0]};
        c.spec.lowHz = 0.75 * w1 / (2 * M_PI);
        c.spec.highHz = 1.3 * w1 / (2 * M_PI);
        c.spec.lines = 60;
        c.pair = {"mass_loading", "boundary_stiffness"};
        c.restrictTo = c.pair;
        cases.push_back(c);
        // The same with identified modes: the first mode's frequency, damping
        // and its shape at the driving point only (GAP.md's fork A case: one
        // frequency cannot tell a mass from a stiffness).
        c.modesData = true;
        cases.push_back(c);
      }
      for (double frac : {0.1, 0.2}) {
        // Out of the catalogue: a tuned absorber (an extra in-band mode).
        Case c = base(CaseKind::OutOfCatalogue, "");
        const int d = m.findDof(*core::parseDof(plan.absorberDof));
        c.truth.absorberDof = d;
        c.truth.absorberMass = frac * m.m(d, d);
        c.truth.absorberHz = 0.5 * (s.bandLowHz + s.bandHighHz) * 0.6;
        c.truth.absorberZeta = 0.05;
        cases.push_back(c);
      }
      {
        // One spring of the calibrated stiffness group off by 8%: the group's
        // calibration parameter scales all its springs together and cannot
        // absorb a single member, so the spring should still be named.
        Case c = base(CaseKind::CalibratedGroup, "element_stiffness");
        c.location = springLocation(m, plan.calibratedSpring);
        c.trueSize = 1.08;
        c.absent = 1.0;
        c.truth.dk = 0.08 * springMatrix(m, plan.calibratedSpring);
        cases.push_back(c);
      }
    }
  }
  return cases;
}

inline CaseResult runCase(const Case& c, const BenchConfig& cfg, unsigned long long seed) {
  CaseResult res;
  res.c = c;
  Structure s;
  for (const auto& st : structures())
    if (st.name == c.structure) s = st;
  std::mt19937_64 rng(seed);
  // Default options: the diagnosis is not told the noise (it estimates it, or
  // reads the coherence when the file has it).
  core::gap::structural::StructuralOptions so;
  core::Result<std::unique_ptr<core::gap::GapProblem>> problem =
      core::makeError(core::ErrorCode::InvalidArgument, "no problem");
  if (c.modesData) {
    so.bandLowHz = c.spec.lowHz;
    so.bandHighHz = c.spec.highHz;
    problem = core::gap::structural::makeModesProblem(s.model, measureModes(s.model, c.truth, c.spec, rng), so);
  } else {
    problem = core::gap::structural::makeFrfProblem(s.model, measure(s.model, c.truth, c.spec, rng), so);
  }
  if (!problem) {
    res.error = problem.error().describe();
    return res;
  }
  core::gap::DiagnosisOptions opt;
  opt.bootstrapSamples = cfg.bootstrap;
  opt.multistarts = cfg.multistarts;
  opt.seed = seed;
  opt.effects = c.restrictTo;
  const auto t0 = std::chrono::steady_clock::now();
  auto d = core::gap::diagnose(**problem, opt);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!d) {
    res.error = d.error().describe();
    return res;
  }
  res.ok = true;
  res.verdict = d->verdict;
  res.explanation = d->explanation;
  res.noiseSource = d->noise.source;
  const bool two = d->verdictSet.size() == 2 && d->verdict != core::gap::Verdict::Ambiguous && d->pairFitted &&
                   d->pair.effects.size() == 2;
  if (two) {
    const auto& a = d->pair.effects[0];
    const auto& b = d->pair.effects[1];
    res.bestEffect = a.candidate.effect;
    res.bestLocation = a.candidate.location;
    if (!a.parameters.empty()) res.fittedSize = a.parameters[0];
    res.secondEffect = b.candidate.effect;
    res.secondLocation = b.candidate.location;
    if (!b.parameters.empty()) res.fittedSize2 = b.parameters[0];
    res.shrinkPct = d->pair.shrinkBothPct;
  } else if (!d->verdictSet.empty()) {
    const auto& best = d->ranking[static_cast<std::size_t>(d->verdictSet.front())];
    res.bestEffect = best.candidate.effect;
    res.bestLocation = best.candidate.location;
    if (!best.parameters.empty()) res.fittedSize = best.parameters[0];
    res.shrinkPct = best.shrinkPct;
  }
  return res;
}

struct Summary {
  int effectCases = 0, top1 = 0, locatedCases = 0, locationRight = 0;
  double medianSizeError = std::nan(""), medianShrink = std::nan("");
  int controls = 0, controlNone = 0, controlAttributions = 0;
  int twoEffects = 0, twoBothNamed = 0, twoOneNamed = 0;
  int ambiguous = 0, ambiguousWrong = 0;
  int outOfCatalogue = 0, outOfCatalogueClean = 0;
  int calibratedGroup = 0, calibratedGroupNamed = 0;
  int failures = 0;
  double seconds = 0.0;
  int diagnoses = 0;
};

inline bool attributes(core::gap::Verdict v) {
  using core::gap::Verdict;
  return v == Verdict::Effect || v == Verdict::Partial || v == Verdict::Ambiguous;
}

inline double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// An effect named right: same effect and, when the truth has a location, the
// same location.
inline bool namedRight(const std::string& effect, const std::vector<std::string>& location,
                       const std::string& trueEffect, const std::vector<std::string>& trueLocation) {
  return effect == trueEffect && (trueLocation.empty() || location == trueLocation);
}

inline Summary summarise(const std::vector<CaseResult>& results) {
  Summary s;
  std::vector<double> sizeErr, shrink;
  using core::gap::Verdict;
  for (const auto& r : results) {
    ++s.diagnoses;
    s.seconds += r.seconds;
    if (!r.ok) {
      ++s.failures;
      continue;
    }
    switch (r.c.kind) {
      case CaseKind::Control:
        ++s.controls;
        if (r.verdict == Verdict::None) ++s.controlNone;
        if (attributes(r.verdict)) ++s.controlAttributions;
        break;
      case CaseKind::Effect: {
        ++s.effectCases;
        const bool named = r.verdict == Verdict::Effect || r.verdict == Verdict::Partial;
        if (named && r.bestEffect == r.c.effect) {
          ++s.top1;
          if (!r.c.location.empty()) {
            ++s.locatedCases;
            if (r.bestLocation == r.c.location) ++s.locationRight;
          }
          if (std::isfinite(r.fittedSize))
            sizeErr.push_back(std::abs(r.fittedSize - r.c.trueSize) / std::abs(r.c.trueSize - r.c.absent));
          if (std::isfinite(r.shrinkPct)) shrink.push_back(r.shrinkPct);
        }
        break;
      }
      case CaseKind::TwoEffects: {
        ++s.twoEffects;
        const bool named = r.verdict == Verdict::Effect || r.verdict == Verdict::Partial;
        if (!named) break;
        const bool first = namedRight(r.bestEffect, r.bestLocation, r.c.effect, r.c.location) ||
                           namedRight(r.secondEffect, r.secondLocation, r.c.effect, r.c.location);
        const bool second = namedRight(r.bestEffect, r.bestLocation, r.c.effect2, r.c.location2) ||
                            namedRight(r.secondEffect, r.secondLocation, r.c.effect2, r.c.location2);
        if (first && second) ++s.twoBothNamed;
        if (first || second) ++s.twoOneNamed;
        break;
      }
      case CaseKind::Ambiguous:
        ++s.ambiguous;
        if (r.verdict == Verdict::Effect && (r.bestEffect != r.c.effect || r.bestLocation != r.c.location))
          ++s.ambiguousWrong;
        break;
      case CaseKind::OutOfCatalogue:
        ++s.outOfCatalogue;
        if (r.verdict == Verdict::Effect) ++s.outOfCatalogueClean;
        break;
      case CaseKind::CalibratedGroup:
        ++s.calibratedGroup;
        if (r.verdict == Verdict::Effect && r.bestEffect == r.c.effect && r.bestLocation == r.c.location)
          ++s.calibratedGroupNamed;
        break;
    }
  }
  s.medianSizeError = median(sizeErr);
  s.medianShrink = median(shrink);
  return s;
}

inline const char* kindName(CaseKind k) {
  switch (k) {
    case CaseKind::Control: return "control";
    case CaseKind::Effect: return "effect";
    case CaseKind::Ambiguous: return "ambiguous";
    case CaseKind::OutOfCatalogue: return "out_of_catalogue";
    case CaseKind::CalibratedGroup: return "calibrated_group";
    case CaseKind::TwoEffects: return "two_effects";
  }
  return "";
}

inline std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& l : v) s += (s.empty() ? "" : "-") + l;
  return s;
}

inline void printHeader() {
  std::printf("%-9s %-17s %-16s %-20s %-10s %-10s | %-12s %-20s %-10s %-10s %-7s %-6s\n", "structure", "noise", "kind",
              "true effect", "location", "true size", "verdict", "named", "location", "fitted", "shrink%", "s");
}

inline void printCase(const CaseResult& r) {
  std::printf("%-9s %-17s %-16s %-20s %-10s %-10.4g | %-12s %-20s %-10s %-10.4g %-7.3g %-6.1f %s\n",
              r.c.structure.c_str(), r.c.noise.name.c_str(), r.c.modesData ? "ambiguous_modes" : kindName(r.c.kind),
              r.c.effect.c_str(), joined(r.c.location).c_str(), r.c.trueSize,
              r.ok ? core::gap::verdictName(r.verdict) : "ERROR", r.bestEffect.c_str(), joined(r.bestLocation).c_str(),
              r.fittedSize, r.shrinkPct, r.seconds, r.error.c_str());
  if (r.c.kind == CaseKind::TwoEffects || !r.secondEffect.empty()) {
    std::printf("%-9s %-17s %-16s %-20s %-10s %-10.4g | %-12s %-20s %-10s %-10.4g\n", "", "", "  (second)",
                r.c.effect2.c_str(), joined(r.c.location2).c_str(), r.c.trueSize2, "", r.secondEffect.c_str(),
                joined(r.secondLocation).c_str(), r.fittedSize2);
  }
}

inline double pct(int a, int b) {
  return b > 0 ? 100.0 * a / b : std::nan("");
}

// One line per noise model: the issue 16 targets.
inline void printNoiseRow(const std::string& name, const Summary& s) {
  std::printf("  %-18s %5.1f%% (%2d/%2d)  %5.1f%% (%2d/%2d)  %5.1f%% (%2d/%2d)  %5.1f%% (%2d/%2d)  %6.2f%%   %5.1f\n",
              name.c_str(), pct(s.top1, s.effectCases), s.top1, s.effectCases, pct(s.controlNone, s.controls),
              s.controlNone, s.controls, pct(s.controlAttributions, s.controls), s.controlAttributions, s.controls,
              pct(s.twoBothNamed, s.twoEffects), s.twoBothNamed, s.twoEffects, 100 * s.medianSizeError,
              s.diagnoses > 0 ? s.seconds / s.diagnoses : 0.0);
}

// The case's own right answer (issues 10 and 16): a control `none`; an
// effect case names the true effect (`effect` or `partial`); a two-effect case
// names both at their locations; an ambiguous pair does not commit to the
// wrong member; an out-of-catalogue case is not a clean `effect`; a
// calibrated-group member is named with `effect`.
inline bool answeredRight(const CaseResult& r) {
  using core::gap::Verdict;
  if (!r.ok) return false;
  const bool named = r.verdict == Verdict::Effect || r.verdict == Verdict::Partial;
  switch (r.c.kind) {
    case CaseKind::Control: return r.verdict == Verdict::None;
    case CaseKind::Effect: return named && r.bestEffect == r.c.effect;
    case CaseKind::TwoEffects:
      return named &&
             (namedRight(r.bestEffect, r.bestLocation, r.c.effect, r.c.location) ||
              namedRight(r.secondEffect, r.secondLocation, r.c.effect, r.c.location)) &&
             (namedRight(r.bestEffect, r.bestLocation, r.c.effect2, r.c.location2) ||
              namedRight(r.secondEffect, r.secondLocation, r.c.effect2, r.c.location2));
    case CaseKind::Ambiguous:
      return !(r.verdict == Verdict::Effect && (r.bestEffect != r.c.effect || r.bestLocation != r.c.location));
    case CaseKind::OutOfCatalogue: return r.verdict != Verdict::Effect;
    case CaseKind::CalibratedGroup:
      return r.verdict == Verdict::Effect && r.bestEffect == r.c.effect && r.bestLocation == r.c.location;
  }
  return false;
}

// Row label of the verdict table: the case kind, and the true effect(s).
inline std::string tableRow(const Case& c) {
  if (c.kind == CaseKind::Control) return "control (no effect)";
  if (c.kind == CaseKind::TwoEffects) return c.effect + " + " + c.effect2;
  if (c.kind == CaseKind::Ambiguous) return c.modesData ? "ambiguous pair (modes)" : "ambiguous pair (FRF)";
  if (c.kind == CaseKind::OutOfCatalogue) return "out of catalogue (absorber)";
  if (c.kind == CaseKind::CalibratedGroup) return "calibrated-group member";
  return c.effect;
}

// The verdicts over noise models and cases, one Markdown table: per row (case
// kind or true effect) and noise model, right answers / cases and the
// verdicts given (E effect, P partial, N none, A ambiguous, U unexplained,
// I not identifiable, X failed).
inline void printVerdictTable(const std::vector<CaseResult>& results, const std::vector<NoiseCase>& noises) {
  std::vector<std::string> rows;
  for (const auto& r : results)
    if (std::find(rows.begin(), rows.end(), tableRow(r.c)) == rows.end()) rows.push_back(tableRow(r.c));
  std::printf("\n| case |");
  for (const auto& n : noises) std::printf(" %s |", n.name.c_str());
  std::printf("\n|---|");
  for (std::size_t i = 0; i < noises.size(); ++i) std::printf("---|");
  std::printf("\n");
  for (const auto& row : rows) {
    std::printf("| %s |", row.c_str());
    for (const auto& n : noises) {
      int total = 0, right = 0;
      std::map<char, int> letters;
      for (const auto& r : results) {
        if (tableRow(r.c) != row || r.c.noise.name != n.name) continue;
        ++total;
        if (answeredRight(r)) ++right;
        const char* v = r.ok ? core::gap::verdictName(r.verdict) : "x";
        ++letters[static_cast<char>(v[0] == 'n' && v[1] == 'o' && v[2] == 't' ? 'I' : std::toupper(v[0]))];
      }
      if (total == 0) {
        std::printf(" |");
        continue;
      }
      std::printf(" %d/%d", right, total);
      for (const char l : std::string("EPNAUIX"))
        if (letters.count(l)) std::printf(" %c%d", l, letters[l]);
      std::printf(" |");
    }
    std::printf("\n");
  }
}

inline void printSummary(const Summary& s) {
  std::printf("\nStructural gap benchmark, all noise models (issues 10 and 16)\n");
  std::printf("  top-1 attribution accuracy      %5.1f%%  (%d/%d effect cases)   target >= 90%%\n",
              pct(s.top1, s.effectCases), s.top1, s.effectCases);
  std::printf("  location accuracy               %5.1f%%  (%d/%d located, top-1 right)\n",
              pct(s.locationRight, s.locatedCases), s.locationRight, s.locatedCases);
  std::printf("  median fitted-size error        %5.2f%%  (of the true change)      target < 5%%\n",
              100 * s.medianSizeError);
  std::printf("  median shrink when right        %5.1f%%\n", s.medianShrink);
  std::printf("  controls 'none'                 %5.1f%%  (%d/%d)                 target >= 90%%\n",
              pct(s.controlNone, s.controls), s.controlNone, s.controls);
  std::printf("  false attributions on controls  %5.1f%%  (%d/%d)                 target <= 5%%\n",
              pct(s.controlAttributions, s.controls), s.controlAttributions, s.controls);
  std::printf("  two effects: both named         %5.1f%%  (%d/%d; one of two %d)   target >= 70%%\n",
              pct(s.twoBothNamed, s.twoEffects), s.twoBothNamed, s.twoEffects, s.twoOneNamed);
  std::printf("  ambiguous pairs wrong commit    %5.1f%%  (%d/%d)                 target <= 10%%\n",
              pct(s.ambiguousWrong, s.ambiguous), s.ambiguousWrong, s.ambiguous);
  std::printf("  out-of-catalogue clean attrib.  %5.1f%%  (%d/%d)                 target <= 20%%\n",
              pct(s.outOfCatalogueClean, s.outOfCatalogue), s.outOfCatalogueClean, s.outOfCatalogue);
  std::printf("  calibrated-group member named   %5.1f%%  (%d/%d)\n", pct(s.calibratedGroupNamed, s.calibratedGroup),
              s.calibratedGroupNamed, s.calibratedGroup);
  std::printf("  failed diagnoses                %d\n", s.failures);
  std::printf("  diagnoses                       %d, %.1f s in all (%.2f s each)\n", s.diagnoses, s.seconds,
              s.diagnoses > 0 ? s.seconds / s.diagnoses : 0.0);
}

}  // namespace mozzi::gap_bench
