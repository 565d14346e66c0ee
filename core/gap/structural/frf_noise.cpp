#include "core/gap/structural/frf_noise.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/gap/engine/statistics.h"

namespace mozzi::core::gap::structural {
namespace {

// One term per difference (or per line for replicates): t ~ V chi2_nu / nu with
// V = a2 gw + b2 gf; `line` places it in a band.
struct Terms {
  std::vector<double> t, gw, gf;
  std::vector<Eigen::Index> line;
};

double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto mid = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  if (v.size() % 2) return *mid;
  const double hi = *mid;
  return 0.5 * (hi + *std::max_element(v.begin(), mid));
}

// The least-trimmed fits need at least this many usable terms; a band needs
// 32 inliers before it may get its own scale (its log-scale then has a
// standard error of about 0.25 for differences, so only a clear difference counts).
constexpr int kMinTerms = 16;
constexpr int kMinBandTerms = 32;
// A band's scale is kept when it differs from the FRF's by more than three
// of its standard errors.
constexpr double kBandSignificance = 3.0;
// Inliers: t / V below the 99% point of chi2_nu / nu.
constexpr double kInlierQuantile = 0.99;

// Scale per band against V, kept when significant: robust within the band
// (median of t / V, then the trimmed mean about it), so a band much noisier
// than the rest, whose terms are outliers against the FRF's level, still gets
// its own level.
template <typename VFn>
void bandScales(const Terms& in, const std::vector<std::size_t>& use, VFn v, double nu, double perTerm,
                const std::vector<Eigen::Index>& edges, FrfNoiseFit& fit) {
  const double medianConst = chiSquareQuantile(0.5, nu) / nu;
  const double q = chiSquareQuantile(kInlierQuantile, nu) / nu;
  const double truncatedMean = (1.0 - chiSquareSurvival(nu * q, nu + 2.0)) / kInlierQuantile;
  fit.bands.clear();
  for (std::size_t b = 0; b + 1 < edges.size(); ++b) {
    FrfNoiseBand band;
    band.first = edges[b];
    band.last = edges[b + 1];
    std::vector<double> x;
    for (std::size_t k : use) {
      if (in.line[k] < band.first || in.line[k] >= band.last) continue;
      const double vk = v(k);
      if (vk > 0) x.push_back(in.t[k] / vk);
    }
    if (static_cast<int>(x.size()) >= kMinBandTerms) {
      const double level = median(x) / medianConst;
      double sum = 0;
      int n = 0;
      for (double xi : x)
        if (xi / level < q) {
          sum += xi;
          ++n;
        }
      band.lines = n;
      if (n >= kMinBandTerms) {
        const double sc = sum / n / truncatedMean;
        if (std::abs(std::log(sc)) > kBandSignificance * std::sqrt(perTerm / n)) band.scale = sc;
      }
    }
    fit.bands.push_back(band);
  }
}

double truncatedMeanOf(double nu, double q) {
  // E[X | X < q] for X = chi2_nu / nu: P(nu/2 + 1, nu q / 2) / P(nu/2, nu q / 2).
  return (1.0 - chiSquareSurvival(nu * q, nu + 2.0)) / kInlierQuantile;
}

FrfNoiseFit fitVariance(const Terms& in, double nu, double inflation, const std::vector<Eigen::Index>& edges) {
  FrfNoiseFit fit;
  std::vector<std::size_t> use;
  for (std::size_t k = 0; k < in.t.size(); ++k)
    if (in.t[k] > 0 && std::isfinite(in.t[k]) && std::isfinite(in.gw[k])) use.push_back(k);
  if (static_cast<int>(use.size()) < kMinTerms) return fit;
  std::vector<double> gws;
  for (std::size_t k : use)
    if (in.gw[k] > 0) gws.push_back(in.gw[k]);
  const double gwMed = gws.empty() ? 0.0 : median(gws);
  const double gfMed = median([&] {
    std::vector<double> v;
    for (std::size_t k : use) v.push_back(in.gf[k]);
    return v;
  }());
  // Grid of rho = floor^2 / relative^2 (g = gw + rho gf): rho = 0 (relative
  // only), 10^-10 .. 10^3 of the median |H|^2 in steps of 10^0.1, and the
  // floor alone (rho = inf, coded as a negative value).
  std::vector<double> grid{0.0};
  if (gwMed > 0) {
    for (int e = -100; e <= 30; ++e) grid.push_back(gwMed / gfMed * std::pow(10.0, 0.1 * e));
  }
  grid.push_back(-1.0);
  auto g = [&](std::size_t k, double rho) { return rho < 0 ? in.gf[k] : in.gw[k] + rho * in.gf[k]; };
  const double medianConst = chiSquareQuantile(0.5, nu) / nu;  // median of chi2_nu / nu (ln 2 for nu = 2)
  // Stage 1: median regression of log t - log g.
  double bestObj = std::numeric_limits<double>::infinity(), bestRho = 0.0, bestLoc = 0.0;
  std::vector<double> l(use.size()), logT(use.size());
  for (std::size_t i = 0; i < use.size(); ++i) logT[i] = std::log(in.t[use[i]]);
  for (double rho : grid) {
    bool finite = true;
    for (std::size_t i = 0; i < use.size(); ++i) {
      const double gk = g(use[i], rho);
      if (!(gk > 0)) {
        finite = false;
        break;
      }
      l[i] = logT[i] - std::log(gk);
    }
    if (!finite) continue;
    const double loc = median(l);
    double obj = 0;
    for (double x : l) obj += std::abs(x - loc);
    if (obj < bestObj) {
      bestObj = obj;
      bestRho = rho;
      bestLoc = loc;
    }
  }
  if (!std::isfinite(bestObj)) return fit;
  double scale = std::exp(bestLoc) / medianConst, rho = bestRho;
  // Stage 2: trimmed maximum likelihood (NLL = sum log V + t / V), inliers fixed per pass.
  const double q = chiSquareQuantile(kInlierQuantile, nu) / nu;
  const double truncatedMean = truncatedMeanOf(nu, q);
  std::vector<std::size_t> inliers;
  auto selectInliers = [&] {
    inliers.clear();
    for (std::size_t k : use)
      if (in.t[k] / (scale * g(k, rho)) < q) inliers.push_back(k);
  };
  for (int pass = 0; pass < 2; ++pass) {
    selectInliers();
    if (static_cast<int>(inliers.size()) < kMinTerms) return fit;
    double bestNll = std::numeric_limits<double>::infinity();
    for (double r : grid) {
      double sum = 0, logSum = 0;
      bool finite = true;
      for (std::size_t k : inliers) {
        const double gk = g(k, r);
        if (!(gk > 0)) {
          finite = false;
          break;
        }
        sum += in.t[k] / gk;
        logSum += std::log(gk);
      }
      if (!finite) continue;
      const double c = sum / static_cast<double>(inliers.size()) / truncatedMean;
      const double nll = logSum + static_cast<double>(inliers.size()) * std::log(c) + sum / c;
      if (nll < bestNll) {
        bestNll = nll;
        rho = r;
        scale = c;
      }
    }
  }
  selectInliers();
  if (static_cast<int>(inliers.size()) < kMinTerms) return fit;
  fit.ok = true;
  if (rho < 0) {
    fit.relative = 0.0;
    fit.floor = std::sqrt(scale);
  } else {
    fit.relative = std::sqrt(scale);
    fit.floor = std::sqrt(scale * rho);
  }
  fit.lines = static_cast<int>(inliers.size());
  fit.outliers = static_cast<int>(use.size() - inliers.size());
  const double perTerm = inflation * 2.0 / nu;  // variance of one t / V, correlation included
  fit.logVariance = perTerm / fit.lines;
  bandScales(
      in, use, [&](std::size_t k) { return scale * g(k, rho); }, nu, perTerm, edges, fit);
  return fit;
}

}  // namespace

double FrfNoiseFit::sigma(Eigen::Index k, double mag2) const {
  double s = 1.0;
  for (const auto& b : bands)
    if (k >= b.first && k < b.last) s = b.scale;
  return std::sqrt(s * (relative * relative * mag2 + floor * floor));
}

namespace {

// Difference terms of order p of y (t_k, weights of the relative and floor
// parts) and the variance inflation of a mean of them.
Terms differenceTerms(const ComplexVector& y, const Vector& mag2, int order, double& inflation) {
  order = std::clamp(order, 1, 6);
  std::vector<double> c{1.0};
  for (int p = 0; p < order; ++p) {
    std::vector<double> next(c.size() + 1, 0.0);
    for (std::size_t j = 0; j < c.size(); ++j) {
      next[j] += c[j];
      next[j + 1] -= c[j];
    }
    c = next;
  }
  double c2 = 0;
  for (double x : c) c2 += x * x;
  // Correlation of neighbouring differences (they share lines): the variance
  // of a mean of t grows by 1 + 2 sum_l rho_l^2, rho_l = sum_j c_j c_{j+l} / sum c^2.
  inflation = 1.0;
  for (std::size_t lag = 1; lag < c.size(); ++lag) {
    double r = 0;
    for (std::size_t j = 0; j + lag < c.size(); ++j) r += c[j] * c[j + lag];
    inflation += 2.0 * (r / c2) * (r / c2);
  }
  Terms terms;
  const Eigen::Index n = y.size(), width = static_cast<Eigen::Index>(c.size());
  for (Eigen::Index k = 0; k + width <= n; ++k) {
    Complex d(0.0, 0.0);
    double gw = 0;
    for (Eigen::Index j = 0; j < width; ++j) {
      d += c[static_cast<std::size_t>(j)] * y[k + j];
      gw += c[static_cast<std::size_t>(j)] * c[static_cast<std::size_t>(j)] * mag2[k + j];
    }
    terms.t.push_back(0.5 * std::norm(d));
    terms.gw.push_back(gw);
    terms.gf.push_back(c2);
    terms.line.push_back(k + width / 2);
  }
  return terms;
}

}  // namespace

FrfNoiseFit estimateFrfNoise(const ComplexVector& y, const Vector& mag2, const std::vector<Eigen::Index>& bandEdges,
                             int order) {
  double inflation = 1.0;
  const Terms terms = differenceTerms(y, mag2, order, inflation);
  return fitVariance(terms, 2.0, inflation, bandEdges);
}

FrfNoiseFit rescaleFrfNoise(const FrfNoiseFit& shape, const ComplexVector& y, const Vector& mag2,
                            const std::vector<Eigen::Index>& bandEdges, int order) {
  if (!shape.ok) return shape;
  double inflation = 1.0;
  const Terms in = differenceTerms(y, mag2, order, inflation);
  const double nu = 2.0, q = chiSquareQuantile(kInlierQuantile, nu) / nu, truncatedMean = truncatedMeanOf(nu, q);
  auto v0 = [&](std::size_t k) {
    return shape.relative * shape.relative * in.gw[k] + shape.floor * shape.floor * in.gf[k];
  };
  // Two passes: inliers against the shape's level, the level, inliers again.
  double scale = 1.0;
  std::vector<std::size_t> inliers;
  for (int pass = 0; pass < 2; ++pass) {
    inliers.clear();
    double sum = 0;
    for (std::size_t k = 0; k < in.t.size(); ++k) {
      const double v = scale * v0(k);
      if (!(in.t[k] > 0) || !(v > 0) || !(in.t[k] / v < q)) continue;
      inliers.push_back(k);
      sum += in.t[k] / v0(k);
    }
    if (static_cast<int>(inliers.size()) < kMinTerms) return shape;
    scale = sum / static_cast<double>(inliers.size()) / truncatedMean;
  }
  FrfNoiseFit fit = shape;
  fit.relative = shape.relative * std::sqrt(scale);
  fit.floor = shape.floor * std::sqrt(scale);
  fit.lines = static_cast<int>(inliers.size());
  fit.outliers = static_cast<int>(in.t.size() - inliers.size());
  const double perTerm = inflation;
  fit.logVariance = perTerm / fit.lines;
  std::vector<std::size_t> use;
  for (std::size_t k = 0; k < in.t.size(); ++k)
    if (in.t[k] > 0) use.push_back(k);
  bandScales(
      in, use, [&](std::size_t k) { return scale * v0(k); }, nu, perTerm, bandEdges, fit);
  return fit;
}

FrfNoiseFit replicateFrfNoise(const std::vector<ComplexVector>& hits, const std::vector<Eigen::Index>& bandEdges) {
  const auto r = static_cast<double>(hits.size());
  if (hits.size() < 2) return {};
  const Eigen::Index n = hits[0].size();
  for (const auto& h : hits)
    if (h.size() != n) return {};
  Terms terms;
  for (Eigen::Index k = 0; k < n; ++k) {
    Complex mean(0.0, 0.0);
    for (const auto& h : hits) mean += h[k];
    mean /= r;
    double ss = 0;
    for (const auto& h : hits) ss += std::norm(h[k] - mean);
    // Per component, variance of the mean: ss / (2 (R - 1)) / R.
    terms.t.push_back(ss / (2.0 * (r - 1.0)) / r);
    terms.gw.push_back(std::norm(mean));
    terms.gf.push_back(1.0);
    terms.line.push_back(k);
  }
  return fitVariance(terms, 2.0 * (r - 1.0), 1.0, bandEdges);
}

}  // namespace mozzi::core::gap::structural
