#include "core/gap/engine/pairs.h"

#include <algorithm>
#include <atomic>
#include <set>
#include <thread>

#include "core/common/parallel.h"

namespace mozzi::core::gap::engine {

ComboProblem::ComboProblem(const GapProblem& base, std::vector<int> combo) : base_(base), combo_(std::move(combo)) {
  const auto all = base_.candidates();
  for (std::size_t i = 0; i < combo_.size(); ++i) {
    const Candidate& c = all[static_cast<std::size_t>(combo_[i])];
    combined_.effect += (i ? "+" : "") + c.effect;
    combined_.location.insert(combined_.location.end(), c.location.begin(), c.location.end());
    combined_.parameters.insert(combined_.parameters.end(), c.parameters.begin(), c.parameters.end());
  }
}

bool ComboProblem::residuals(const ModelPoint& at, double* r) const {
  if (at.candidate < 0) return base_.residuals({at.theta, -1, nullptr}, r);
  return base_.combinedResiduals(at.theta, combo_, at.phi, r);
}

std::unique_ptr<GapProblem> ComboProblem::simulated(const ModelPoint& at, std::mt19937_64& rng) const {
  return base_.simulated({at.theta, -1, nullptr}, rng);
}

GapMetrics ComboProblem::metrics(const ModelPoint& at) const {
  if (at.candidate < 0) return base_.metrics({at.theta, -1, nullptr});
  return base_.combinedMetrics(at.theta, combo_, at.phi);
}

std::vector<OverlayCurve> ComboProblem::overlay(const ModelPoint& at) const {
  if (at.candidate < 0) return base_.overlay({at.theta, -1, nullptr});
  return base_.combinedOverlay(at.theta, combo_, at.phi);
}

namespace {

// Grid minima tried per pair beside the two starts of its members' optima.
constexpr int kGridStarts = 2;

}  // namespace

Result<std::vector<PairFit>> fitPairs(const GapProblem& problem, const std::vector<Scaled>& theta,
                                      const std::vector<SingleFit>& singles, int leaders,
                                      const std::vector<PairStart>& known,
                                      const std::function<bool(double)>& keepGoing) {
  const std::string where = "pair fits";
  std::vector<PairFit> out;
  const auto p = static_cast<Eigen::Index>(theta.size());
  std::set<std::pair<int, int>> done;
  const int nLead = std::min<int>(leaders, static_cast<int>(singles.size()));
  FitOptions fo;
  fo.maxIterations = 60;
  fo.startIterations = 20;  // every start 20 iterations, the best polished
  // Each pair's fit is independent: collected first, fitted on every core.
  struct Job {
    const SingleFit *a, *b;
    const Eigen::VectorXd* from;
  };
  std::vector<Job> jobs;
  auto fitOne = [&](const SingleFit& a, const SingleFit& b, const Eigen::VectorXd* from) -> PairFit {
    ComboProblem combo(problem, {a.candidate, b.candidate});
    std::vector<Scaled> phi = a.phi;
    phi.insert(phi.end(), b.phi.begin(), b.phi.end());
    Model model(combo, theta, 0, phi);
    const auto qa = static_cast<Eigen::Index>(a.phi.size()), qb = static_cast<Eigen::Index>(b.phi.size());
    std::vector<Eigen::VectorXd> starts;
    if (from && from->size() == p + qa + qb) {
      starts.push_back(clipToBox(model, *from));
    } else {
      Eigen::VectorXd s1(p + qa + qb), s2(p + qa + qb);
      s1 << a.u.head(p), a.u.tail(qa), Eigen::VectorXd::Zero(qb);
      s2 << a.u.head(p), a.u.tail(qa), b.u.tail(qb);
      starts = {clipToBox(model, s1), clipToBox(model, s2)};
      for (auto& g : gridStarts(model, p + qa, qb, starts[0], kGridStarts)) starts.push_back(std::move(g));
    }
    const FitResult fit = fitModel(model, starts, fo);
    PairFit pf;
    if (!fit.ok) return pf;
    pf.a = a.candidate;
    pf.b = b.candidate;
    pf.phi = std::move(phi);
    pf.u = fit.u;
    pf.nll = fit.nll;
    pf.chiSquare = fit.chiSquare;
    pf.ok = true;
    return pf;
  };
  if (!known.empty()) {
    auto single = [&](int c) -> const SingleFit* {
      for (const auto& sf : singles)
        if (sf.candidate == c) return &sf;
      return nullptr;
    };
    for (const PairStart& k : known) {
      const SingleFit *a = single(k.a), *b = single(k.b);
      if (a && b && problem.combinable({k.a, k.b})) jobs.push_back({a, b, &k.u});
    }
  } else {
    for (int l = 0; l < nLead; ++l) {
      const SingleFit& a = singles[static_cast<std::size_t>(l)];
      for (const SingleFit& b : singles) {
        if (a.candidate == b.candidate) continue;
        const auto key = std::minmax(a.candidate, b.candidate);
        if (done.count(key) || !problem.combinable({a.candidate, b.candidate})) continue;
        done.insert(key);
        jobs.push_back({&a, &b, nullptr});
      }
    }
  }
  const auto mainThread = std::this_thread::get_id();
  std::atomic<bool> stopped{false};
  std::atomic<std::size_t> finished{0};
  std::vector<PairFit> fitted(jobs.size());
  parallelFor(jobs.size(), [&](std::size_t j) {
    if (stopped) return;
    if (keepGoing && std::this_thread::get_id() == mainThread &&
        !keepGoing(static_cast<double>(finished) / static_cast<double>(jobs.size()))) {
      stopped = true;
      return;
    }
    fitted[j] = fitOne(*jobs[j].a, *jobs[j].b, jobs[j].from);
    ++finished;
  });
  if (stopped) return makeError(ErrorCode::Cancelled, "cancelled", where);
  for (auto& pf : fitted)
    if (pf.ok) out.push_back(std::move(pf));
  std::stable_sort(out.begin(), out.end(), [](const PairFit& x, const PairFit& y) { return x.nll < y.nll; });
  return out;
}

}  // namespace mozzi::core::gap::engine
