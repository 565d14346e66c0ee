#include "core/stability/mode_tracking.h"

#include "core/common/parallel.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "core/stability/balance.h"
#include "core/stability/root_finding.h"

namespace mozzi::core::stability {

namespace {

// The state matrix must be finite before the (iterative) eigen-solve: inputs
// near the double range (a 1e308 stiffness) give inf/NaN entries, on which
// the QR iteration would spend its whole iteration budget for nothing.
Result<void> requireFinite(const Matrix& A, double v) {
  if (A.allFinite()) return {};
  return makeError(ErrorCode::NumericalFailure,
                   "the state matrix is not finite (a parameter far too large or too small for double precision)",
                   "v = " + std::to_string(v));
}

Result<ComplexVector> eigenvaluesOnly(const StabilitySystem& s, double v) {
  MOZZI_TRY_ASSIGN(auto A, s.stateMatrix(v));
  MOZZI_TRY(requireFinite(A, v));
  balanceInPlace(A);
  MOZZI_TRY(requireFinite(A, v));
  thread_local Eigen::EigenSolver<Matrix> es;  // its workspaces reused from speed to speed
  es.compute(A, false);
  if (es.info() != Eigen::Success || !es.eigenvalues().allFinite()) {
    return makeError(ErrorCode::NumericalFailure, "eigenvalue iteration failed", "v = " + std::to_string(v));
  }
  return ComplexVector(es.eigenvalues());
}

double share(const Root& r, const std::string& name, const std::vector<std::string>& names) {
  double s = 0.0;
  for (size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) s += std::norm(r.shape(static_cast<int>(k)));
  return s;
}

// MAC = |a^H b|^2 / (|a|^2 |b|^2), shapes are unit norm.
double mac(const ComplexVector& a, const ComplexVector& b) {
  return std::norm(a.dot(b));
}

// Names of the roots at one speed from their eigenvalues and shapes (before
// the track vote).
std::vector<std::string> namesAtSpeed(const std::vector<Root>& roots, const StabilitySystem& s) {
  std::vector<std::string> names(roots.size());
  int weaveCandidate = -1;
  for (size_t i = 0; i < roots.size(); ++i) {
    const Root& r = roots[i];
    const double bend = share(r, "bend", s.shapeNames), torsion = share(r, "torsion", s.shapeNames);
    const double roll = share(r, "roll", s.shapeNames), steer = share(r, "steer", s.shapeNames);
    const bool oscillating = r.lambda.imag() > 0.0;
    // The fork modes are steer/compliance oscillations (thesis §6.6: "dominated
    // by steer rotation and front fork bending"); weave carries < 5% compliance.
    if (bend >= 0.15 && oscillating) {
      names[i] = "fork bending";
    } else if (torsion >= 0.15 && oscillating) {
      names[i] = "fork torsion";
    } else if (s.kind == VehicleKind::Bicycle) {
      // Meijaard et al. (2007) §6: weave oscillates, capsize is the roll-dominated
      // real root, castering the steer-dominated one.
      names[i] = oscillating ? "weave" : (roll >= steer ? "capsize" : "castering");
    } else if (oscillating) {
      // Sharp (1971): wobble is the steer-dominated oscillation near 50-60 rad/s;
      // weave the lowest-frequency other oscillation; remaining oscillations
      // come from the tyre lag.
      if (steer > 0.5 && r.lambda.imag() > 30.0) {
        names[i] = "wobble";
      } else {
        names[i] = "tyre lag";
        if (weaveCandidate < 0 || r.lambda.imag() < roots[weaveCandidate].lambda.imag()) {
          weaveCandidate = static_cast<int>(i);
        }
      }
    } else {
      // capsize: the slow real root (roll and heading); other real roots are
      // steer or tyre-lag relaxations.
      names[i] = (std::fabs(r.lambda.real()) < 10.0 && steer < 0.5) ? "capsize" : "tyre lag";
    }
  }
  if (weaveCandidate >= 0) names[weaveCandidate] = "weave";
  return names;
}

}  // namespace

StabilitySystem bicycleSystem(const BicycleModel& model) {
  StabilitySystem s;
  s.stateMatrix = [model](double v) { return model.stateMatrix(v); };
  s.shapeNames = model.coordinates;
  for (int i = 0; i < model.size(); ++i) {
    s.shapeRows.push_back(i);
    s.shapeIsRate.push_back(false);
  }
  s.kind = VehicleKind::Bicycle;
  return s;
}

std::optional<double> StabilitySweep::criticalSpeed(const std::string& mode) const {
  for (const auto& e : events)
    if (e.mode == mode && (e.kind == "stabilises" || e.kind == "destabilises")) return e.v;
  return std::nullopt;
}

std::optional<ModeEvent> StabilitySweep::firstEvent(const std::string& mode, const std::string& kind) const {
  for (const auto& e : events)
    if (e.mode == mode && e.kind == kind) return e;
  return std::nullopt;
}

Result<std::vector<double>> speedGrid(double from, double to, double step) {
  if (!std::isfinite(from) || !std::isfinite(to) || !std::isfinite(step)) {
    return makeError(ErrorCode::InvalidArgument, "speed range must be finite", "speeds A:B:STEP");
  }
  if (!(step > 0.0)) return makeError(ErrorCode::InvalidArgument, "STEP must be positive", "speeds A:B:STEP");
  if (to < from) return makeError(ErrorCode::InvalidArgument, "B must not be below A", "speeds A:B:STEP");
  const double count = std::floor((to - from) / step * (1.0 + 1e-12) + 1e-6) + 1.0;
  if (count > 1e6) return makeError(ErrorCode::InvalidArgument, "more than a million speeds", "speeds A:B:STEP");
  std::vector<double> v;
  for (int k = 0; k < static_cast<int>(count); ++k) v.push_back(from + k * step);
  return v;
}

Result<SpeedPoint> solveAtSpeed(const StabilitySystem& s, double v) {
  MOZZI_TRY_ASSIGN(auto A, s.stateMatrix(v));
  if (s.shapeRows.size() != s.shapeNames.size() || s.shapeIsRate.size() != s.shapeNames.size() ||
      s.shapeNames.empty()) {
    return makeError(ErrorCode::InvalidArgument, "shape rows, names and rate flags differ in length",
                     "stability system");
  }
  for (int row : s.shapeRows)
    if (row < 0 || row >= A.rows())
      return makeError(ErrorCode::InvalidArgument, "shape row out of range", "stability system");
  MOZZI_TRY(requireFinite(A, v));
  const Vector scale = balanceInPlace(A);
  MOZZI_TRY(requireFinite(A, v));
  // One solver per thread, its workspaces reused from speed to speed (no
  // allocation once warm; issue 22: 10,000 speeds in 50 ms).
  thread_local Eigen::EigenSolver<Matrix> es;
  es.compute(A, true);
  const ComplexVector& values = es.eigenvalues();
  // Real Schur vectors: column i of a real root is its eigenvector; for a
  // pair (Im > 0 first, as Eigen orders it) columns i and i + 1 hold the real
  // and imaginary parts (EigenSolver::eigenvectors() builds the same, each
  // column normalised; only the shape rows are needed, normalised below).
  const Matrix& pseudo = es.pseudoEigenvectors();
  // Entries near the overflow limit pass the checks above, yet the iteration
  // can end with infinite or NaN eigenvalues: an error, never a wrong root.
  if (es.info() != Eigen::Success || !values.allFinite() || !pseudo.allFinite()) {
    return makeError(ErrorCode::NumericalFailure, "eigenvalue iteration failed", "v = " + std::to_string(v));
  }
  SpeedPoint p;
  p.v = v;
  p.roots.reserve(static_cast<std::size_t>(values.size()));
  for (int i = 0; i < values.size(); ++i) {
    if (values(i).imag() < 0.0) continue;  // one root per conjugate pair
    const bool pair = values(i).imag() != 0.0;
    Root r;
    r.lambda = values(i);
    r.shape.resize(static_cast<int>(s.shapeRows.size()));
    for (size_t k = 0; k < s.shapeRows.size(); ++k) {
      const int row = s.shapeRows[k];
      Complex a = scale(row) * Complex(pseudo(row, i), pair ? pseudo(row, i + 1) : 0.0);
      if (s.shapeIsRate[k] && std::abs(r.lambda) > 1e-9) a /= r.lambda;
      r.shape(static_cast<int>(k)) = a;
    }
    const double norm = r.shape.norm();
    if (norm > 0.0) r.shape /= norm;
    p.roots.push_back(r);
  }
  std::sort(p.roots.begin(), p.roots.end(), [](const Root& a, const Root& b) {
    return a.lambda.imag() != b.lambda.imag() ? a.lambda.imag() > b.lambda.imag() : a.lambda.real() > b.lambda.real();
  });
  return p;
}

namespace {

// A mode followed from speed to speed: its samples (point index, root index).
struct Track {
  std::vector<std::pair<int, int>> samples;
  std::string name;
};

// The tracks' events: critical speeds (a real part crossing zero) and pair
// births and splits, each refined by Brent's method on eigenvalues only.
std::vector<ModeEvent> refineEvents(const StabilitySystem& s, const std::vector<SpeedPoint>& points,
                                    const std::vector<Track>& tracks) {
  // Events, refined with Brent on eigenvalues only.
  auto nearestRoot = [&](double v, Complex target, bool allowConjugates) -> Result<Complex> {
    MOZZI_TRY_ASSIGN(auto ev, eigenvaluesOnly(s, v));
    Complex best = ev(0);
    double bestDist = -1.0;
    for (int i = 0; i < ev.size(); ++i) {
      const Complex l = ev(i);
      if (!allowConjugates && l.imag() < 0.0) continue;
      const double d = std::abs(l - target);
      if (bestDist < 0.0 || d < bestDist) {
        best = l;
        bestDist = d;
      }
    }
    return best;
  };
  const double tol = 1e-15;
  // The segments of a track where an event lies, in track and speed order;
  // each is refined on its own (on every core: the Brent iterations are
  // independent) into its own slots, then gathered in that order, so the
  // events do not depend on the threads.
  struct Segment {
    const Track* track;
    std::size_t m;
  };
  std::vector<Segment> segments;
  for (const Track& tr : tracks) {
    for (size_t m = 1; m < tr.samples.size(); ++m) {
      const Root& A = points[tr.samples[m - 1].first].roots[tr.samples[m - 1].second];
      const Root& B = points[tr.samples[m].first].roots[tr.samples[m].second];
      const bool crossing = (A.lambda.real() < 0.0) != (B.lambda.real() < 0.0);
      const bool pairEvent = (A.lambda.imag() == 0.0) != (B.lambda.imag() == 0.0);
      if (crossing || pairEvent) segments.push_back({&tr, m});
    }
  }
  std::vector<std::vector<ModeEvent>> found(segments.size());
  parallelFor(segments.size(), [&](std::size_t segment) {
    const Track& tr = *segments[segment].track;
    const std::size_t m = segments[segment].m;
    std::vector<ModeEvent>& events = found[segment];
    const auto [ka, ra] = tr.samples[m - 1];
    const auto [kb, rb] = tr.samples[m];
    const Root& A = points[ka].roots[ra];
    const Root& B = points[kb].roots[rb];
    const double va = points[ka].v, vb = points[kb].v;
    auto interp = [&](double v) { return A.lambda + (B.lambda - A.lambda) * ((v - va) / (vb - va)); };
    const bool crossing = (A.lambda.real() < 0.0) != (B.lambda.real() < 0.0);
    if (crossing) {
      bool failed = false;
      auto f = [&](double v) {
        if (v == va) return A.lambda.real();
        if (v == vb) return B.lambda.real();
        auto l = nearestRoot(v, interp(v), false);
        if (!l) failed = true;
        return l ? l->real() : 0.0;
      };
      auto root = brentRoot(f, va, vb, tol, "critical speed of " + tr.name);
      if (root && !failed) {
        auto l = nearestRoot(*root, interp(*root), false);
        events.push_back({tr.name, *root, A.lambda.real() > 0.0 ? "stabilises" : "destabilises", 0.0,
                          l ? std::fabs(l->imag()) : 0.0});
      }
    }
    const bool born = A.lambda.imag() == 0.0 && B.lambda.imag() > 0.0;
    const bool splits = A.lambda.imag() > 0.0 && B.lambda.imag() == 0.0;
    if (born || splits) {
      // Two real roots meet: (l1 - l2)^2 changes sign (positive while real,
      // -4 Im^2 when complex); the two eigenvalues nearest the merge point.
      auto centre = [&](double v) {
        const double ca = A.lambda.real(), cb = B.lambda.real();
        return Complex(ca + (cb - ca) * (v - va) / (vb - va), 0.0);
      };
      bool failed = false;
      auto gap = [&](double v) -> double {
        auto ev = eigenvaluesOnly(s, v);
        if (!ev) {
          failed = true;
          return 0.0;
        }
        std::vector<Complex> l(ev->data(), ev->data() + ev->size());
        const Complex c = centre(v);
        std::sort(l.begin(), l.end(), [&](Complex x, Complex y) { return std::abs(x - c) < std::abs(y - c); });
        return ((l[0] - l[1]) * (l[0] - l[1])).real();
      };
      auto root = brentRoot(gap, va, vb, tol, "pair event of " + tr.name);
      if (root && !failed) {
        auto l = nearestRoot(*root, centre(*root), true);
        events.push_back({tr.name, *root, born ? "pair born" : "pair splits", l ? l->real() : 0.0, 0.0});
      }
    }
  });
  std::vector<ModeEvent> all;
  for (auto& events : found)
    for (auto& e : events) all.push_back(std::move(e));
  return all;
}

Result<StabilitySweep> sweepOnGrid(const StabilitySystem& s, const std::vector<double>& speeds) {
  // The speeds are independent: solved on every core (issue 22: 10,000 speeds
  // in 50 ms), each into its own slot, so the points do not depend on the
  // threads; the first failing speed in speed order gives the error, as in
  // a serial loop.
  StabilitySweep out;
  out.points.resize(speeds.size());
  std::vector<std::optional<Error>> failed(speeds.size());
  parallelFor(speeds.size(), [&](std::size_t k) {
    auto p = solveAtSpeed(s, speeds[k]);
    if (p)
      out.points[k] = std::move(*p);
    else
      failed[k] = p.error();
  });
  for (const auto& e : failed)
    if (e) return *e;

  // Tracking: match each root to one at the previous speed by eigenvector
  // continuity (MAC) and distance to the eigenvalue extrapolated along the track.
  std::vector<Track> tracks;
  for (size_t i = 0; i < out.points[0].roots.size(); ++i) {
    tracks.push_back({{{0, static_cast<int>(i)}}, {}});
    out.points[0].roots[i].track = static_cast<int>(i);
  }
  struct Cand {
    double cost;
    int i, j;
  };
  std::vector<Cand> cands;     // reused from speed to speed
  std::vector<double> curAbs;  // |lambda| of the current roots
  for (size_t k = 1; k < out.points.size(); ++k) {
    auto& prev = out.points[k - 1].roots;
    auto& cur = out.points[k].roots;
    cands.clear();
    curAbs.resize(cur.size());
    for (size_t j = 0; j < cur.size(); ++j) curAbs[j] = std::abs(cur[j].lambda);
    for (size_t i = 0; i < prev.size(); ++i) {
      const double prevAbs = std::abs(prev[i].lambda);
      const Track& tr = tracks[prev[i].track];
      Complex predicted = prev[i].lambda;
      if (tr.samples.size() >= 2 && tr.samples[tr.samples.size() - 2].first == static_cast<int>(k) - 2) {
        const auto& [pk, pr] = tr.samples[tr.samples.size() - 2];
        const Complex older = out.points[pk].roots[pr].lambda;
        const double h0 = out.points[k - 1].v - out.points[pk].v, h1 = out.points[k].v - out.points[k - 1].v;
        predicted = prev[i].lambda + (prev[i].lambda - older) * (h1 / h0);
      }
      for (size_t j = 0; j < cur.size(); ++j) {
        const double scale = prevAbs + curAbs[j] + 1.0;
        // A real root turns complex only by meeting another real root: a type
        // change costs extra so it is chosen only when nothing fits better.
        const bool typeChange = (prev[i].lambda.imag() > 0.0) != (cur[j].lambda.imag() > 0.0);
        const double cost = (1.0 - mac(prev[i].shape, cur[j].shape)) +
                            2.0 * std::abs(cur[j].lambda - predicted) / scale + (typeChange ? 0.5 : 0.0);
        cands.push_back({cost, static_cast<int>(i), static_cast<int>(j)});
      }
    }
    std::sort(cands.begin(), cands.end(), [](const Cand& a, const Cand& b) { return a.cost < b.cost; });
    std::vector<bool> usedPrev(prev.size(), false), usedCur(cur.size(), false);
    for (const Cand& c : cands) {
      if (usedPrev[c.i] || usedCur[c.j]) continue;
      usedPrev[c.i] = usedCur[c.j] = true;
      cur[c.j].track = prev[c.i].track;
      tracks[cur[c.j].track].samples.push_back({static_cast<int>(k), c.j});
    }
    for (size_t j = 0; j < cur.size(); ++j) {
      if (usedCur[j]) continue;
      cur[j].track = static_cast<int>(tracks.size());
      tracks.push_back({{{static_cast<int>(k), static_cast<int>(j)}}, {}});
    }
  }

  // Naming: a track that is ever oscillatory takes the most frequent name of its
  // oscillating samples; otherwise the most frequent name of all its samples.
  std::vector<std::vector<std::string>> sampleNames;
  sampleNames.resize(out.points.size());
  parallelFor(out.points.size(), [&](std::size_t k) { sampleNames[k] = namesAtSpeed(out.points[k].roots, s); });
  for (Track& tr : tracks) {
    std::map<std::string, int> osc, all;
    for (const auto& [k, r] : tr.samples) {
      const Root& root = out.points[k].roots[r];
      const std::string& n = sampleNames[k][r];
      ++all[n];
      if (root.lambda.imag() > 0.0) ++osc[n];
    }
    const auto& votes = osc.empty() ? all : osc;
    tr.name = std::max_element(votes.begin(), votes.end(), [](const auto& a, const auto& b) {
                return a.second < b.second;
              })->first;
  }
  // A real track that ends where a pair is born, or starts where a pair splits,
  // belongs to that oscillatory mode (two real roots of one mode).
  auto nearestOscillating = [&](int k, Complex lambda) -> int {
    int best = -1;
    double bestDist = 0.0;
    for (const Root& r : out.points[k].roots) {
      if (!(r.lambda.imag() > 0.0)) continue;
      const double d = std::abs(r.lambda - lambda);
      if (best < 0 || d < bestDist) {
        best = r.track;
        bestDist = d;
      }
    }
    return best;
  };
  const int last = static_cast<int>(out.points.size()) - 1;
  for (Track& tr : tracks) {
    const auto [k0, r0] = tr.samples.front();
    const auto [k1, r1] = tr.samples.back();
    const bool everOscillating = std::any_of(tr.samples.begin(), tr.samples.end(), [&](const auto& kr) {
      return out.points[kr.first].roots[kr.second].lambda.imag() > 0.0;
    });
    if (everOscillating) continue;
    if (k1 < last) {
      const int t = nearestOscillating(k1 + 1, out.points[k1].roots[r1].lambda);
      if (t >= 0 && tracks[t].samples.front().first <= k1 + 1) tr.name = tracks[t].name;
    }
    if (k0 > 0) {
      const int t = nearestOscillating(k0 - 1, out.points[k0].roots[r0].lambda);
      if (t >= 0) tr.name = tracks[t].name;
    }
  }
  for (auto& p : out.points)
    for (auto& r : p.roots) r.name = tracks[r.track].name;

  out.events = refineEvents(s, out.points, tracks);
  std::sort(out.events.begin(), out.events.end(), [](const ModeEvent& a, const ModeEvent& b) { return a.v < b.v; });
  return out;
}

}  // namespace

Result<StabilitySweep> sweepSpeeds(const StabilitySystem& s, const std::vector<double>& speeds,
                                   double maxTrackingStep) {
  if (speeds.empty()) return makeError(ErrorCode::InvalidArgument, "no speeds", "speeds");
  for (size_t k = 0; k < speeds.size(); ++k) {
    if (!std::isfinite(speeds[k])) return makeError(ErrorCode::InvalidArgument, "speed is not finite", "speeds");
    if (k > 0 && !(speeds[k] > speeds[k - 1])) {
      return makeError(ErrorCode::InvalidArgument, "speeds must increase strictly",
                       "speeds[" + std::to_string(k) + "]");
    }
  }
  if (!(maxTrackingStep > 0.0)) {
    return makeError(ErrorCode::InvalidArgument, "tracking step must be positive", "maxTrackingStep");
  }
  // Track on a grid no coarser than maxTrackingStep so modes are followed (and
  // crossings found) however coarse the requested speeds are; report only the
  // requested speeds.
  std::vector<double> grid;
  std::vector<bool> requested;
  for (size_t k = 0; k < speeds.size(); ++k) {
    if (k > 0) {
      const int extra = static_cast<int>(std::ceil((speeds[k] - speeds[k - 1]) / maxTrackingStep)) - 1;
      for (int i = 1; i <= extra; ++i) {
        grid.push_back(speeds[k - 1] + (speeds[k] - speeds[k - 1]) * i / (extra + 1));
        requested.push_back(false);
      }
    }
    grid.push_back(speeds[k]);
    requested.push_back(true);
  }
  MOZZI_TRY_ASSIGN(auto sweep, sweepOnGrid(s, grid));
  StabilitySweep out;
  out.events = std::move(sweep.events);
  for (size_t k = 0; k < grid.size(); ++k)
    if (requested[k]) out.points.push_back(std::move(sweep.points[k]));
  return out;
}

}  // namespace mozzi::core::stability
