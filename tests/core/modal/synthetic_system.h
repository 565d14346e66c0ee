#pragma once
// Shared by the modal tests: a 6-DOF proportionally damped system built from
// chosen modes (so the truth is known exactly) and its accelerances computed
// directly from (K - w^2 M + i w C)^-1, independent of the modal code.

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/modal/modal_model.h"

namespace mozzi::core::modal::testing {

struct SyntheticSystem {
  Matrix m, c, k;
  Vector fn;  // Hz
  Vector zeta;
  Matrix phi;  // mass-normalised shapes, columns
};

// Six modes like the forks of thesis Tables 19 and 20: two modes 1.5% apart at
// 83.4 and 84.7 Hz (steel fork, Table 19) and damping from 0.5% to 10%.
inline SyntheticSystem sixModeSystem() {
  SyntheticSystem s;
  s.fn.resize(6);
  s.fn << 41.0, 83.4, 84.7, 150.0, 214.1, 300.0;
  s.zeta.resize(6);
  s.zeta << 0.02, 0.0135, 0.0157, 0.005, 0.10, 0.03;
  std::mt19937 rng(12345);
  std::normal_distribution<double> nd(0.0, 1.0);
  Matrix a(6, 6);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) a(i, j) = nd(rng);
  const Matrix q = Eigen::HouseholderQR<Matrix>(a).householderQ();
  Vector mass(6);
  mass << 1.2, 0.8, 2.0, 1.5, 0.6, 1.0;  // kg
  const Vector mhalfInv = mass.cwiseSqrt().cwiseInverse();
  s.phi = mhalfInv.asDiagonal() * q;  // phi^T M phi = Q^T Q = I
  const Matrix pinv = s.phi.inverse();
  Vector w = 2.0 * M_PI * s.fn;
  s.m = mass.asDiagonal();
  s.k = pinv.transpose() * w.cwiseAbs2().asDiagonal() * pinv;
  s.c = pinv.transpose() * (2.0 * s.zeta.cwiseProduct(w)).asDiagonal() * pinv;
  s.k = 0.5 * (s.k + s.k.transpose()).eval();
  s.c = 0.5 * (s.c + s.c.transpose()).eval();
  return s;
}

inline std::vector<Dof> sixDofs() {
  std::vector<Dof> d;
  for (int i = 1; i <= 6; ++i) d.push_back(Dof{i, Direction::Z, false});
  return d;
}

// Accelerance column of reference `refs` on a 0.1 Hz grid from fLo to fHi, with
// complex Gaussian noise of relative standard deviation `noise` per line.
inline FrfMatrix accelerances(const SyntheticSystem& s, const std::vector<int>& refs, double fLo, double fHi, double df,
                              double noise, unsigned seed) {
  FrfMatrix frf;
  const int nf = static_cast<int>(std::round((fHi - fLo) / df)) + 1;
  frf.frequencyHz = Vector::LinSpaced(nf, fLo, fLo + df * (nf - 1));
  frf.responses = sixDofs();
  for (int r : refs) frf.references.push_back(frf.responses[static_cast<std::size_t>(r)]);
  frf.type = FrfType::Accelerance;
  std::mt19937 rng(seed);
  std::normal_distribution<double> nd(0.0, 1.0);
  for (int r : refs) {
    ComplexMatrix h(nf, 6);
    for (int kk = 0; kk < nf; ++kk) {
      const double w = 2.0 * M_PI * frf.frequencyHz[kk];
      const ComplexMatrix rec = spatialReceptance(s.m, s.c, s.k, w);
      for (int o = 0; o < 6; ++o) {
        const Complex a = -w * w * rec(o, r);
        h(kk, o) = a * Complex(1.0 + noise / std::sqrt(2.0) * nd(rng), noise / std::sqrt(2.0) * nd(rng));
      }
    }
    frf.h.push_back(std::move(h));
  }
  return frf;
}

// Complex Gaussian noise only (unit variance per part), 0 .. 400 Hz at 0.1 Hz,
// six responses, one reference: no mode to find.
inline FrfMatrix pureNoise(unsigned seed) {
  FrfMatrix frf;
  frf.frequencyHz = Vector::LinSpaced(4001, 0.0, 400.0);
  frf.responses = sixDofs();
  frf.references = {frf.responses[0]};
  std::mt19937 rng(seed);
  std::normal_distribution<double> nd(0.0, 1.0);
  ComplexMatrix h(4001, 6);
  for (Eigen::Index k = 0; k < h.rows(); ++k)
    for (Eigen::Index o = 0; o < 6; ++o) h(k, o) = Complex(nd(rng), nd(rng));
  frf.h.push_back(h);
  return frf;
}

}  // namespace mozzi::core::modal::testing
