#pragma once
// Synthetic FRFs shared by the modal benchmarks (modal_plscf_bench,
// modal_refine_bench, cli_commands_bench): 20 modes at 80 + 90 r Hz with
// zeta = 0.005 + 0.001 r, random real shapes over 100 DOFs (seed 3),
// accelerances H = -w^2 sum_r [R_r / (iw - lambda_r) + conj] with
// R_r = phi_or phi_ar / (2 i Im lambda_r), times (1 + 1% complex noise).
// `no` responses (DOFs 1..no), `refs` references (DOF 17 i + 4), `nf` lines
// from df to nf df.

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/modal/modal_model.h"

namespace mozzi::core::modal::bench {

constexpr int kSyntheticModes = 20;
inline double syntheticFrequencyHz(int r) {
  return 80.0 + 90.0 * r;
}
inline double syntheticZeta(int r) {
  return 0.005 + 0.001 * r;
}

inline FrfMatrix syntheticFrfs(int no, int nf, double df, int refs = 1) {
  std::mt19937 rng(3);
  std::normal_distribution<double> nd(0.0, 1.0);
  const int dofs = 100, nm = kSyntheticModes;
  Matrix phi(dofs, nm);
  for (int o = 0; o < dofs; ++o)
    for (int r = 0; r < nm; ++r) phi(o, r) = nd(rng);
  FrfMatrix frf;
  frf.frequencyHz = Vector::LinSpaced(nf, df, df * nf);
  for (int o = 0; o < no; ++o) frf.responses.push_back(Dof{o + 1, Direction::Z, false});
  for (int i = 0; i < refs; ++i) frf.references.push_back(Dof{17 * i + 4, Direction::Z, false});
  frf.type = FrfType::Accelerance;
  std::vector<Complex> poles;
  for (int r = 0; r < nm; ++r) poles.push_back(poleFromFrequencyDamping(syntheticFrequencyHz(r), syntheticZeta(r)));
  for (int i = 0; i < refs; ++i) {
    const int ref = 17 * i + 3;
    ComplexMatrix h(nf, no);
    for (int k = 0; k < nf; ++k) {
      const double w = 2 * M_PI * frf.frequencyHz[k];
      const Complex iw(0.0, w);
      for (int o = 0; o < no; ++o) {
        Complex acc(0.0, 0.0);
        for (int r = 0; r < nm; ++r) {
          const Complex lam = poles[static_cast<std::size_t>(r)];
          const Complex res = phi(o, r) * phi(ref, r) / Complex(0.0, 2.0 * lam.imag());
          acc += res / (iw - lam) + std::conj(res) / (iw - std::conj(lam));
        }
        h(k, o) = -w * w * acc * Complex(1.0 + 0.01 * nd(rng), 0.01 * nd(rng));
      }
    }
    frf.h.push_back(std::move(h));
  }
  return frf;
}

}  // namespace mozzi::core::modal::bench
