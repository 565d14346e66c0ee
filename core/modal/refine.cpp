#include "core/modal/refine.h"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <memory>
#include <string>

#include "core/modal/lsfd.h"

namespace mozzi::core::modal {

namespace {
constexpr double kTwoPi = 2.0 * M_PI;

struct Problem {
  const FrfMatrix* frf = nullptr;
  LsfdOptions lsfd;
  Eigen::Index k0 = 0, nf = 0;
  double scale = 1.0;  // data RMS
  int modes = 0;
};

std::vector<Complex> polesFrom(double const* const* p, int modes) {
  std::vector<Complex> out;
  for (int r = 0; r < modes; ++r) out.push_back(poleFromFrequencyDamping(p[r][0], p[r][1]));
  return out;
}

// Projected residual: data minus the LSFD fit for these poles.
bool projectedResidual(const Problem& pb, const std::vector<Complex>& poles, double* res, ModalModel* fitOut) {
  for (const auto& l : poles) {
    if (!(l.real() < 0.0) || !(l.imag() > 0.0)) return false;
  }
  auto fit = lsfd(*pb.frf, poles, pb.lsfd);
  if (!fit) return false;
  const FrfMatrix& frf = *pb.frf;
  Eigen::Index idx = 0;
  for (Eigen::Index i = 0; i < frf.referenceCount(); ++i) {
    for (Eigen::Index o = 0; o < frf.responseCount(); ++o) {
      for (Eigen::Index k = pb.k0; k < pb.k0 + pb.nf; ++k) {
        const Complex d =
            frf.h[static_cast<std::size_t>(i)](k, o) - synthesize(*fit, o, i, kTwoPi * frf.frequencyHz[k], frf.type);
        res[idx++] = d.real() / pb.scale;
        res[idx++] = d.imag() / pb.scale;
      }
    }
  }
  if (fitOut) *fitOut = std::move(fit).value();
  return true;
}

struct Functor {
  const Problem* pb;
  bool operator()(double const* const* p, double* res) const {
    return projectedResidual(*pb, polesFrom(p, pb->modes), res, nullptr);
  }
};
}  // namespace

Result<RefineResult> refineModalModel(const FrfMatrix& frf, const ModalModel& initial, const RefineOptions& opt) {
  const std::string where = "modal refinement";
  if (auto ok = frf.validate(); !ok) return ok.error();
  if (auto ok = initial.validate(); !ok) return ok.error();
  if (initial.modes.empty()) return makeError(ErrorCode::InvalidArgument, "no modes to refine", where);
  Problem pb;
  pb.frf = &frf;
  pb.lsfd = LsfdOptions{opt.bandLowHz, opt.bandHighHz, opt.lowerResidual, opt.upperResidual};
  while (pb.k0 < frf.lineCount() && (frf.frequencyHz[pb.k0] < opt.bandLowHz || frf.frequencyHz[pb.k0] == 0.0)) ++pb.k0;
  Eigen::Index k = pb.k0;
  while (k < frf.lineCount() && frf.frequencyHz[k] <= opt.bandHighHz) ++k;
  pb.nf = k - pb.k0;
  pb.modes = static_cast<int>(initial.modes.size());
  const Eigen::Index nres = 2 * pb.nf * frf.responseCount() * frf.referenceCount();
  const Eigen::Index nlin = frf.responseCount() * frf.referenceCount() *
                            (2 * pb.modes + (opt.lowerResidual ? 2 : 0) + (opt.upperResidual ? 2 : 0));
  const Eigen::Index npar = 2 * pb.modes + nlin;
  if (nres <= npar) {
    return makeError(
        ErrorCode::InvalidArgument,
        "band holds " + std::to_string(pb.nf) + " lines, too few for " + std::to_string(npar) + " parameters",
        where + ", band");
  }
  double ss = 0.0;
  for (const auto& h : frf.h) ss += h.middleRows(pb.k0, pb.nf).squaredNorm();
  pb.scale = std::sqrt(ss / static_cast<double>(nres / 2));
  if (!(pb.scale > 0.0)) return makeError(ErrorCode::InvalidArgument, "FRFs are zero in the band", where);

  std::vector<std::array<double, 2>> params(static_cast<std::size_t>(pb.modes));
  std::vector<Complex> poles0;
  for (int r = 0; r < pb.modes; ++r) {
    params[static_cast<std::size_t>(r)] = {initial.modes[static_cast<std::size_t>(r)].frequencyHz(),
                                           initial.modes[static_cast<std::size_t>(r)].zeta()};
    poles0.push_back(initial.modes[static_cast<std::size_t>(r)].pole);
  }
  Vector r0(nres);
  if (!projectedResidual(pb, poles0, r0.data(), nullptr)) {
    return makeError(ErrorCode::NumericalFailure, "LSFD fails for the initial poles", where);
  }

  auto* cost = new ceres::DynamicNumericDiffCostFunction<Functor, ceres::CENTRAL>(new Functor{&pb});
  for (int r = 0; r < pb.modes; ++r) cost->AddParameterBlock(2);
  cost->SetNumResiduals(static_cast<int>(nres));
  ceres::Problem problem;
  std::vector<double*> blocks;
  for (auto& p : params) blocks.push_back(p.data());
  problem.AddResidualBlock(cost, nullptr, blocks);
  for (auto* b : blocks) {
    problem.SetParameterLowerBound(b, 0, 1e-6);
    problem.SetParameterLowerBound(b, 1, 1e-7);
    problem.SetParameterUpperBound(b, 1, 0.99);
  }
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = opt.maxIterations;
  so.logging_type = ceres::SILENT;
  so.function_tolerance = 1e-12;
  so.parameter_tolerance = 1e-12;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  if (!summary.IsSolutionUsable()) {
    return makeError(ErrorCode::NumericalFailure, "Ceres did not converge: " + summary.message, where);
  }

  RefineResult out;
  out.iterations = static_cast<int>(summary.iterations.size());
  out.initialRelativeError = r0.norm() / std::sqrt(static_cast<double>(nres / 2));
  std::vector<Complex> poles;
  for (const auto& p : params) poles.push_back(poleFromFrequencyDamping(p[0], p[1]));
  Vector rf(nres);
  if (!projectedResidual(pb, poles, rf.data(), &out.model)) {
    return makeError(ErrorCode::NumericalFailure, "LSFD fails for the refined poles", where);
  }
  out.finalRelativeError = rf.norm() / std::sqrt(static_cast<double>(nres / 2));
  for (std::size_t r = 0; r < out.model.modes.size(); ++r) {
    out.model.modes[r].participation = initial.modes[r].participation;
  }

  // Final Jacobian of the projected residual (Ceres' own evaluation).
  ceres::CRSMatrix crs;
  double finalCost = 0.0;
  problem.Evaluate(ceres::Problem::EvaluateOptions(), &finalCost, nullptr, nullptr, &crs);
  Matrix jac = Matrix::Zero(crs.num_rows, crs.num_cols);
  for (int row = 0; row < crs.num_rows; ++row)
    for (int q = crs.rows[static_cast<std::size_t>(row)]; q < crs.rows[static_cast<std::size_t>(row) + 1]; ++q)
      jac(row, crs.cols[static_cast<std::size_t>(q)]) = crs.values[static_cast<std::size_t>(q)];
  const Matrix jtj = jac.transpose() * jac;
  Eigen::LDLT<Matrix> ldlt(jtj);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0.0)) {
    return makeError(ErrorCode::NumericalFailure, "J^T J is singular: a frequency or damping is not identifiable",
                     where);
  }
  const Matrix cov = ldlt.solve(Matrix::Identity(jtj.rows(), jtj.cols()));
  // s^2 in the scaled units: SSR / (N - P); the parameters are in Hz and zeta directly.
  const double s2 = rf.squaredNorm() / static_cast<double>(nres - npar);
  for (int r = 0; r < pb.modes; ++r) {
    out.frequencyStdHz.push_back(std::sqrt(s2 * cov(2 * r, 2 * r)));
    out.zetaStd.push_back(std::sqrt(s2 * cov(2 * r + 1, 2 * r + 1)));
  }
  return out;
}

}  // namespace mozzi::core::modal
