#include "core/modal/mode_merging.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/common/text.h"
#include "core/modal/shape_tools.h"

namespace mozzi::core::modal {

double frequencyResolutionHz(const VectorRef& f, double lowHz, double highHz) {
  std::vector<double> steps;
  for (Eigen::Index k = 1; k < f.size(); ++k) {
    if (f[k - 1] >= lowHz && f[k] <= highHz) steps.push_back(f[k] - f[k - 1]);
  }
  if (steps.empty()) return 0.0;
  const std::size_t h = steps.size() / 2;
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(h), steps.end());
  return steps[h];
}

SameModeCriteria sameModeCriteria(const PlscfOptions& options, double resolutionHz) {
  SameModeCriteria c;
  c.resolutionHz = resolutionHz;
  c.macThreshold = options.criteria.macThreshold;
  c.frequencyTolerance = options.criteria.frequencyTolerance;
  return c;
}

SameModePair compareModes(const ModeCandidate& a, const ModeCandidate& b, const SameModeCriteria& c) {
  SameModePair p;
  p.separationHz = std::abs(a.frequencyHz - b.frequencyHz);
  const bool shapes = a.shape.size() > 0 && a.shape.size() == b.shape.size();
  p.mac = shapes ? mac(a.shape, b.shape) : 0.0;
  if (p.separationHz < c.resolutionHz) {
    p.reason = SameModeReason::WithinResolution;
  } else if (shapes && p.mac >= c.macThreshold &&
             p.separationHz <= c.frequencyTolerance * std::min(a.frequencyHz, b.frequencyHz)) {
    p.reason = SameModeReason::SameShape;
  }
  return p;
}

std::vector<SameModePair> findSameModes(const std::vector<ModeCandidate>& cand, const SameModeCriteria& c) {
  std::vector<SameModePair> out;
  for (std::size_t i = 0; i < cand.size(); ++i) {
    for (std::size_t j = i + 1; j < cand.size(); ++j) {
      SameModePair p = compareModes(cand[i], cand[j], c);
      if (p.reason == SameModeReason::Distinct) continue;
      p.first = i;
      p.second = j;
      out.push_back(p);
    }
  }
  return out;
}

std::vector<std::size_t> keepOnePerMode(const std::vector<ModeCandidate>& cand, const std::vector<int>& support,
                                        const SameModeCriteria& c) {
  // Union-find over the same-mode pairs.
  std::vector<std::size_t> parent(cand.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& p : findSameModes(cand, c)) parent[root(p.second)] = root(p.first);
  auto supportOf = [&](std::size_t i) { return i < support.size() ? support[i] : 0; };
  std::vector<std::size_t> best(cand.size(), cand.size());
  for (std::size_t i = 0; i < cand.size(); ++i) {
    std::size_t& b = best[root(i)];
    if (b == cand.size() || supportOf(i) > supportOf(b)) b = i;
  }
  std::vector<std::size_t> kept;
  for (std::size_t b : best) {
    if (b < cand.size()) kept.push_back(b);
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

void mergeSameModes(std::vector<SelectedPole>& selected, const PlscfOptions& options, double resolutionHz) {
  if (selected.size() < 2) return;
  std::vector<ModeCandidate> cand;
  std::vector<int> support;
  for (const auto& s : selected) {
    cand.push_back({poleFrequencyHz(s.pole), s.shape});
    support.push_back(s.clusterSize);
  }
  const auto kept = keepOnePerMode(cand, support, sameModeCriteria(options, resolutionHz));
  if (kept.size() == selected.size()) return;
  std::vector<SelectedPole> out;
  for (std::size_t k : kept) out.push_back(std::move(selected[k]));
  selected = std::move(out);
}

std::string describeSameMode(const SameModePair& p, const std::vector<ModeCandidate>& cand, const SameModeCriteria& c) {
  // Six significant digits, more when two poles would read the same.
  int digits = 6;
  while (digits < 12 &&
         formatNumber(cand[p.first].frequencyHz, digits) == formatNumber(cand[p.second].frequencyHz, digits))
    ++digits;
  const std::string a = formatNumber(cand[p.first].frequencyHz, digits) + " Hz";
  const std::string b = formatNumber(cand[p.second].frequencyHz, digits) + " Hz";
  const std::string apart = a + " and " + b + " are " + formatNumber(p.separationHz, 3) + " Hz apart";
  if (p.reason == SameModeReason::WithinResolution) {
    return apart + ", closer than the frequency resolution (" + formatNumber(c.resolutionHz, 4) +
           " Hz): one mode, fitted twice";
  }
  if (p.reason == SameModeReason::SameShape) {
    return apart + " with the same shape (MAC " + formatNumber(p.mac, 4) + "): one mode, fitted twice";
  }
  return apart + ": distinct modes";
}

}  // namespace mozzi::core::modal
