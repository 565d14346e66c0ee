#include <algorithm>
#include <cmath>

#include "core/common/text.h"
#include "core/gap/structural/structural_core.h"
#include "core/gap/structural/structural_problem.h"
#include "core/modal/assignment.h"
#include "core/modal/sdof.h"
#include "core/modal/shape_tools.h"

// The modes problem of structural_problem.h: identified modes (frequency,
// damping, shapes) against the structural model, paired by MAC.

namespace mozzi::core::gap::structural {

using detail::ChannelMap;
using detail::mapDof;
using detail::ModalSystem;
using detail::nominalTheta;
using detail::StructuralCore;

namespace {

// z of a chi-square sum of n whitened residuals against its expectation n.
double chiSquareZ(double chi2, double n) {
  return n > 0 ? (chi2 - n) / std::sqrt(2.0 * n) : 0.0;
}

struct ModeData {
  Vector f, zeta;
  Matrix shapes;  // measured DOFs x modes, real
};

class ModesProblem final : public GapProblem {
 public:
  ModesProblem(std::shared_ptr<const StructuralCore> core, ModeData data, std::vector<ChannelMap> channels,
               std::vector<int> pairs, StructuralOptions options)
      : core_(std::move(core)),
        data_(std::move(data)),
        ch_(std::move(channels)),
        pairs_(std::move(pairs)),
        options_(std::move(options)) {
    for (const auto& c : ch_) dofs_.push_back(c.dof);
    for (std::size_t r = 0; r < pairs_.size(); ++r)
      if (pairs_[r] >= 0) paired_.push_back(static_cast<int>(r));
  }

  std::string dataKind() const override { return "modes"; }
  NoiseModel noiseModel() const override {
    NoiseModel n;
    n.source = "floors";
    n.description = "Sigma floors of GAP.md step 0: frequency " + formatNumber(100 * options_.frequencySigmaFloor, 3) +
                    "%, damping " + formatNumber(100 * options_.dampingSigmaFloor, 3) +
                    "% of the measured ratio (at least 1e-4), shape components " +
                    formatNumber(100 * options_.shapeSigma, 3) + "% of each mode's largest component.";
    n.entries.push_back({"frequency", "", options_.frequencySigmaFloor, 0.0, "Hz", 0});
    n.entries.push_back({"damping ratio", "", options_.dampingSigmaFloor, 1e-4, "", 0});
    n.entries.push_back({"shape", "", options_.shapeSigma, 0.0, "", 0});
    return n;
  }
  std::vector<Parameter> calibrationParameters() const override { return core_->calibration; }
  std::vector<Candidate> candidates() const override {
    std::vector<Candidate> out;
    for (const auto& d : core_->defs) out.push_back(d.candidate);
    return out;
  }
  int residualCount() const override { return static_cast<int>(paired_.size() * (2 + ch_.size())); }

  struct Predicted {
    std::vector<double> f, zeta;
    Matrix shapes;  // channels x model modes
  };

  bool predict(const ModelPoint& at, Predicted& p) const {
    ModalSystem sys;
    if (!core_->solve(at, sys)) return false;
    const Eigen::Index nq = sys.w2.size();
    p.f.resize(static_cast<std::size_t>(nq));
    p.zeta.resize(static_cast<std::size_t>(nq));
    p.shapes.resize(static_cast<Eigen::Index>(ch_.size()), nq);
    for (Eigen::Index r = 0; r < nq; ++r) {
      const double w = std::sqrt(sys.w2[r]);
      // Modal damping from the diagonal of Phi^T C Phi (the coupling terms of
      // a non-proportional C change zeta only to second order) plus eta / 2.
      const double zeta = w > 0 ? sys.cdiag[r] / (2 * w) + sys.eta / 2 : 0.0;
      if (!(zeta < 1)) return false;
      const Complex lambda = modal::poleFromFrequencyDamping(w / (2 * M_PI), zeta) - sys.decay;
      p.f[static_cast<std::size_t>(r)] = modal::poleFrequencyHz(lambda);
      p.zeta[static_cast<std::size_t>(r)] = modal::poleZeta(lambda);
      for (std::size_t c = 0; c < ch_.size(); ++c) {
        double v = sys.a(ch_[c].dof, r);
        for (const auto& tilt : sys.tilts)
          if (ch_[c].dof == tilt.def->dof)
            v = std::cos(tilt.angle) * sys.a(ch_[c].dof, r) + std::sin(tilt.angle) * sys.a(tilt.def->other, r);
        p.shapes(static_cast<Eigen::Index>(c), r) = v * ch_[c].sign;
      }
    }
    return p.shapes.allFinite();
  }

  double sigmaF(int j) const { return options_.frequencySigmaFloor * data_.f[j]; }
  // 15% of the measured ratio, and never below 1e-4 absolute (an identified
  // zeta of exactly 0 must not get an infinite weight).
  double sigmaZ(int j) const { return std::max(options_.dampingSigmaFloor * data_.zeta[j], 1e-4); }
  double sigmaPhi(int j) const { return options_.shapeSigma * data_.shapes.col(j).cwiseAbs().maxCoeff(); }

  // Model shape scaled onto the measured one (least squares).
  static Vector scaled(const Vector& model, const Vector& meas) {
    const double mm = model.squaredNorm();
    return mm > 0 ? Vector(model * (model.dot(meas) / mm)) : model;
  }

  bool residuals(const ModelPoint& at, double* r) const override {
    Predicted p;
    if (!predict(at, p)) return false;
    std::size_t k = 0;
    for (int m : paired_) {
      const int j = pairs_[static_cast<std::size_t>(m)];
      r[k++] = (p.f[static_cast<std::size_t>(m)] - data_.f[j]) / sigmaF(j);
      r[k++] = (p.zeta[static_cast<std::size_t>(m)] - data_.zeta[j]) / sigmaZ(j);
      const Vector s = scaled(p.shapes.col(m), data_.shapes.col(j));
      const double sp = sigmaPhi(j);
      for (Eigen::Index c = 0; c < s.size(); ++c) r[k++] = (s[c] - data_.shapes(c, j)) / sp;
    }
    for (std::size_t q = 0; q < k; ++q)
      if (!std::isfinite(r[q])) return false;
    return true;
  }

  std::vector<int> folds() const override {
    std::vector<int> f;
    const int nfold = std::max(1, options_.folds);
    const int np = static_cast<int>(paired_.size());
    for (int q = 0; q < np; ++q) {
      const int fold = np > 0 ? (q * nfold) / np : 0;
      for (std::size_t c = 0; c < 2 + ch_.size(); ++c) f.push_back(fold);
    }
    return f;
  }

  std::unique_ptr<GapProblem> simulated(const ModelPoint& at, std::mt19937_64& rng) const override {
    Predicted p;
    ModeData sim = data_;
    std::normal_distribution<double> nd(0.0, 1.0);
    if (predict(at, p)) {
      for (int m : paired_) {
        const int j = pairs_[static_cast<std::size_t>(m)];
        sim.f[j] = p.f[static_cast<std::size_t>(m)] + sigmaF(j) * nd(rng);
        sim.zeta[j] = std::max(0.0, p.zeta[static_cast<std::size_t>(m)] + sigmaZ(j) * nd(rng));
        const Vector s = scaled(p.shapes.col(m), data_.shapes.col(j));
        const double sp = sigmaPhi(j);
        for (Eigen::Index c = 0; c < s.size(); ++c) sim.shapes(c, j) = s[c] + sp * nd(rng);
      }
    }
    return std::make_unique<ModesProblem>(core_, std::move(sim), ch_, pairs_, options_);
  }

  GapMetrics metrics(const ModelPoint& at) const override {
    GapMetrics out;
    out.residualName = "mode_residual";
    Predicted p;
    if (!predict(at, p)) {
      out.overall = std::numeric_limits<double>::quiet_NaN();
      return out;
    }
    std::vector<double> r(static_cast<std::size_t>(residualCount()));
    if (!residuals(at, r.data())) {
      out.overall = std::numeric_limits<double>::quiet_NaN();
      return out;
    }
    double chi2 = 0;
    for (double x : r) chi2 += x * x;
    // The overall gap of mode data: RMS of the whitened residuals (frequency,
    // damping and shape misfits in units of their sigma; about 1 at a fit
    // within noise).
    out.overall = r.empty() ? 0.0 : std::sqrt(chi2 / static_cast<double>(r.size()));

    for (int m : paired_) {
      const int j = pairs_[static_cast<std::size_t>(m)];
      const double fp = p.f[static_cast<std::size_t>(m)], zp = p.zeta[static_cast<std::size_t>(m)];
      const double fz = (fp - data_.f[j]) / sigmaF(j), zz = (zp - data_.zeta[j]) / sigmaZ(j);
      const double macValue = modal::mac(p.shapes.col(m).cast<Complex>(), data_.shapes.col(j).cast<Complex>());
      GapEntry e;
      e.kind = "mode";
      e.label = "mode " + std::to_string(j + 1) + " (" + formatNumber(data_.f[j], 4) + " Hz)";
      e.value = 100 * (fp - data_.f[j]) / data_.f[j];
      // The mode's z: the largest of its frequency and damping z (two-sided,
      // as a magnitude) so a damping-only gap is flagged too.
      e.z = std::max(std::abs(fz), std::abs(zz));
      e.details = {{"measured_hz", data_.f[j]},
                   {"predicted_hz", fp},
                   {"frequency_error_pct", e.value},
                   {"frequency_z", fz},
                   {"measured_zeta", data_.zeta[j]},
                   {"predicted_zeta", zp},
                   {"zeta_error_pct", data_.zeta[j] > 0 ? 100 * (zp - data_.zeta[j]) / data_.zeta[j] : 0.0},
                   {"zeta_z", zz},
                   {"mac", macValue},
                   {"model_mode", static_cast<double>(m + 1)}};
      out.entries.push_back(e);
    }
    for (Eigen::Index j = 0; j < data_.f.size(); ++j) {
      if (std::find(pairs_.begin(), pairs_.end(), static_cast<int>(j)) != pairs_.end()) continue;
      GapEntry e;
      e.kind = "mode";
      e.label = "mode " + std::to_string(j + 1) + " (" + formatNumber(data_.f[j], 4) + " Hz) unpaired";
      e.flagged = true;
      e.details = {{"measured_hz", data_.f[j]}};
      out.entries.push_back(e);
    }
    for (std::size_t c = 0; c < ch_.size(); ++c) {
      double c2 = 0, rel2 = 0;
      for (int m : paired_) {
        const int j = pairs_[static_cast<std::size_t>(m)];
        const Vector s = scaled(p.shapes.col(m), data_.shapes.col(j));
        const double d = s[static_cast<Eigen::Index>(c)] - data_.shapes(static_cast<Eigen::Index>(c), j);
        c2 += std::pow(d / sigmaPhi(j), 2);
        rel2 += std::pow(d / data_.shapes.col(j).cwiseAbs().maxCoeff(), 2);
      }
      const double n = static_cast<double>(paired_.size());
      GapEntry e;
      e.kind = "dof";
      e.label = core_->label(ch_[c].dof);
      e.value = n > 0 ? std::sqrt(rel2 / n) : 0.0;  // shape misfit relative to each mode's largest component
      e.z = chiSquareZ(c2, n);
      e.oneSided = true;
      out.entries.push_back(e);
    }
    return out;
  }

 private:
  std::shared_ptr<const StructuralCore> core_;
  ModeData data_;
  std::vector<ChannelMap> ch_;
  std::vector<int> dofs_;
  std::vector<int> pairs_;   // per model mode: measured mode or -1
  std::vector<int> paired_;  // model modes that have a partner
  StructuralOptions options_;
};

}  // namespace

Result<std::unique_ptr<GapProblem>> makeModesProblem(const StructuralModel& model, const io::uff::ModalData& measured,
                                                     const StructuralOptions& options) {
  const auto nm = measured.frequencyHz.size();
  if (nm == 0) return makeError(ErrorCode::InvalidArgument, "no measured modes", "measured modes");
  if (measured.shapes.rows() != static_cast<Eigen::Index>(measured.dofs.size()) || measured.shapes.cols() != nm ||
      measured.dampingRatio.size() != nm) {
    return makeError(ErrorCode::InvalidArgument, "mode shapes, frequencies and damping disagree in size",
                     "measured modes");
  }
  // Measured DOFs the model does not have (a 3-DOF-per-node file against a
  // planar model) are left out; at least one must remain.
  std::vector<ChannelMap> channels;
  std::vector<Eigen::Index> rows;
  for (std::size_t i = 0; i < measured.dofs.size(); ++i) {
    auto c = mapDof(model, measured.dofs[i], "measured");
    if (!c) continue;
    channels.push_back(*c);
    rows.push_back(static_cast<Eigen::Index>(i));
  }
  if (channels.empty()) {
    return makeError(ErrorCode::NotFound, "no measured DOF matches a DOF of the model", "measured modes");
  }
  std::vector<Eigen::Index> modes;
  for (Eigen::Index j = 0; j < nm; ++j) {
    const double f = measured.frequencyHz[j], z = measured.dampingRatio[j];
    if (!(std::isfinite(f) && f > 0 && std::isfinite(z) && z >= 0)) {
      return makeError(ErrorCode::InvalidArgument, "frequency or damping not valid",
                       "measured mode " + std::to_string(j + 1));
    }
    if (f >= options.bandLowHz && f <= options.bandHighHz) modes.push_back(j);
  }
  if (modes.empty()) return makeError(ErrorCode::InvalidArgument, "no measured mode in the band", "--band");
  ModeData data;
  const auto nd = static_cast<Eigen::Index>(channels.size()), nk = static_cast<Eigen::Index>(modes.size());
  data.f.resize(nk);
  data.zeta.resize(nk);
  data.shapes.resize(nd, nk);
  for (Eigen::Index q = 0; q < nk; ++q) {
    const Eigen::Index j = modes[static_cast<std::size_t>(q)];
    data.f[q] = measured.frequencyHz[j];
    data.zeta[q] = measured.dampingRatio[j];
    ComplexVector col(nd);
    for (Eigen::Index c = 0; c < nd; ++c) col[c] = measured.shapes(rows[static_cast<std::size_t>(c)], j);
    Eigen::Index big = 0;
    col.cwiseAbs().maxCoeff(&big);
    if (!col.allFinite() || std::abs(col[big]) == 0) {
      return makeError(ErrorCode::InvalidArgument, "mode shape is zero or not finite at the model's DOFs",
                       "measured mode " + std::to_string(j + 1));
    }
    // Rotate to the real line through the largest component (normal modes).
    data.shapes.col(q) = (col * (std::abs(col[big]) / col[big])).real();
  }
  auto core = std::make_shared<StructuralCore>(model);
  const auto theta = nominalTheta(model);
  ModalSystem nominal;
  if (!core->solve({theta.data(), -1, nullptr}, nominal)) {
    return makeError(ErrorCode::NumericalFailure, "the model cannot be solved at its nominal parameters", model.name);
  }
  std::vector<int> dofs;
  for (const auto& c : channels) dofs.push_back(c.dof);
  core->buildCandidates(dofs, dofs, {}, false, options.bandHighHz, nominal.w2);
  ComplexMatrix modelShapes(nd, nominal.w2.size());
  for (Eigen::Index c = 0; c < nd; ++c)
    for (Eigen::Index r = 0; r < nominal.w2.size(); ++r)
      modelShapes(c, r) =
          nominal.a(channels[static_cast<std::size_t>(c)].dof, r) * channels[static_cast<std::size_t>(c)].sign;
  const Vector modelHz = nominal.w2.cwiseSqrt() / (2 * M_PI);
  const std::vector<int> pairs =
      modal::pairModesByMac(modelShapes, data.shapes.cast<Complex>(), options.macPairing, modelHz, data.f);
  if (std::count_if(pairs.begin(), pairs.end(), [](int p) { return p >= 0; }) == 0) {
    return makeError(
        ErrorCode::NumericalFailure,
        "no measured mode pairs with a model mode (every MAC below " + formatNumber(options.macPairing) + ")",
        "measured modes");
  }
  return std::unique_ptr<GapProblem>(
      std::make_unique<ModesProblem>(std::move(core), std::move(data), std::move(channels), pairs, options));
}

}  // namespace mozzi::core::gap::structural
