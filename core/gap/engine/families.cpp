#include "core/gap/engine/families.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace mozzi::core::gap::engine {

namespace {

double largest(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

bool sameParameters(const Candidate& a, const Candidate& b) {
  if (a.effect != b.effect || a.parameters.size() != b.parameters.size()) return false;
  for (std::size_t i = 0; i < a.parameters.size(); ++i) {
    const Parameter& p = a.parameters[i];
    const Parameter& q = b.parameters[i];
    if (p.name != q.name || p.unit != q.unit || p.nominal != q.nominal || p.priorSigma != q.priorSigma) return false;
  }
  return true;
}

}  // namespace

bool equalShapes(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.empty() || a.size() != b.size()) return false;
  const double scale = std::max(largest(a), largest(b));
  if (!(scale > 0.0) || !std::isfinite(scale)) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!(std::abs(a[i] - b[i]) <= kEqualShapeTolerance * scale)) return false;
  }
  return true;
}

std::vector<std::vector<int>> equalEffectFamilies(const GapProblem& problem, const std::vector<Candidate>& candidates,
                                                  const std::vector<int>& indices) {
  std::vector<std::vector<int>> families;
  std::vector<std::vector<double>> shapes;  // of each family's representative
  for (int c : indices) {
    std::vector<double> shape = problem.effectShape(c);
    bool joined = false;
    if (!shape.empty()) {
      // Against the representative, not every member: a family is the
      // candidates within the tolerance of its first, never a chain that
      // drifts further.
      for (std::size_t f = 0; f < families.size() && !joined; ++f) {
        const Candidate& rep = candidates[static_cast<std::size_t>(families[f][0])];
        if (sameParameters(rep, candidates[static_cast<std::size_t>(c)]) && equalShapes(shapes[f], shape)) {
          families[f].push_back(c);
          joined = true;
        }
      }
    }
    if (!joined) {
      families.push_back({c});
      shapes.push_back(std::move(shape));
    }
  }
  return families;
}

Candidate familyCandidate(const std::vector<Candidate>& candidates, const std::vector<int>& family) {
  Candidate rep = candidates[static_cast<std::size_t>(family[0])];
  for (std::size_t m = 1; m < family.size(); ++m) {
    const Candidate& other = candidates[static_cast<std::size_t>(family[m])];
    rep.equivalent.push_back(other.location);
    for (std::size_t i = 0; i < rep.parameters.size() && i < other.parameters.size(); ++i) {
      rep.parameters[i].lower = std::min(rep.parameters[i].lower, other.parameters[i].lower);
      rep.parameters[i].upper = std::max(rep.parameters[i].upper, other.parameters[i].upper);
    }
  }
  return rep;
}

}  // namespace mozzi::core::gap::engine
