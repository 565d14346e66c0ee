#pragma once
// The part of the structural gap problems (structural_problem.h) that the FRF
// problem (frf_problem.cpp) and the modes problem (modes_problem.cpp) share:
// the candidate catalogue at the measured DOFs and the augmented model at
// (theta, candidate, phi) solved into undamped modal form. Internal to
// core/gap/structural.

#include <string>
#include <vector>

#include "core/common/dof.h"
#include "core/common/eigen_types.h"
#include "core/common/result.h"
#include "core/gap/gap_problem.h"
#include "core/gap/structural/model_file.h"

namespace mozzi::core::gap::structural::detail {

// a b without std::complex's recovery of NaN products (Annex G): the same
// value for finite operands, without its test and branch on every product.
inline Complex times(Complex a, Complex b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

enum class Effect { MassLoading, Boundary, Element, ResidualMode, Hysteretic, Window, Misalignment };

struct CandidateDef {
  Effect effect = Effect::MassLoading;
  int dof = -1;     // mass / residual-mode DOF, misaligned channel DOF
  int other = -1;   // DOF the misaligned channel leans towards
  int spring = -1;  // boundary / element spring
  Vector shape;     // residual-mode shape over all DOFs (max |.| = 1)
  double wTop = 1;  // residual mode: top of the band [rad/s] (curvature term reference)
  Candidate candidate;
};

// A measured DOF as seen by the model: index and the sign between the two
// (a channel "21-Z" against a model DOF "21+Z" reads -x).
struct ChannelMap {
  int dof = -1;
  double sign = 1.0;
};

Result<ChannelMap> mapDof(const StructuralModel& model, const Dof& dof, const std::string& what);

// The augmented model at (theta, candidate, phi), in undamped modal form.
struct ModalSystem {
  Vector w2;     // omega_r^2, ascending
  Matrix a;      // ndof x nq: T Phi, mass-normalised shapes at the physical DOFs
  Vector cdiag;  // modal viscous damping 2 zeta_r omega_r (diagonal part)
  Matrix cfull;  // Phi^T C Phi when not diagonal, else empty
  // Non-proportional damping: first-order (state-space) modes of
  // [0 I; -Omega^2 (1 + i eta), -Phi^T C Phi], so that
  // H(s) = sum_j left_j right_j / (s - pole_j) (Ewins ch. 2.7); empty when the
  // eigenvectors are too ill-conditioned (then a solve per line).
  ComplexVector ssPoles;
  ComplexMatrix ssLeft;   // ndof x 2nq
  ComplexMatrix ssRight;  // 2nq x ndof
  double eta = 0.0;       // hysteretic loss factor
  double decay = 0.0;     // exponential-window decay a [1/s]
  struct ResidualTerm {
    const CandidateDef* def = nullptr;
    double upper = 0.0, curvature = 0.0, lower = 0.0;
  };
  struct Tilt {
    int candidate = -1;  // index into the defs (locates the row of the DOF it leans to)
    const CandidateDef* def = nullptr;
    double angle = 0.0;  // rad
  };
  std::vector<ResidualTerm> residualTerms;  // residual-mode effects applied
  std::vector<Tilt> tilts;                  // misaligned channels
};

// The model, its element matrices and the candidate list: the part shared by
// the FRF and mode problems.
class StructuralCore {
 public:
  StructuralModel model;
  std::vector<Parameter> calibration;
  std::vector<CandidateDef> defs;
  std::vector<Matrix> springK;  // nq x nq per spring at scale 1
  std::vector<Matrix> massM;    // nq x nq per mass at scale 1

  explicit StructuralCore(const StructuralModel& m);

  Matrix springMatrix(int a, int b, double k) const;

  // Effective mass at a DOF: 1 / (t_d M_q^-1 t_d^T), the mass of a rigid
  // attachment that would move with that DOF alone (M_dd for a diagonal
  // spatial mass matrix).
  double effectiveMass(int d) const;

  // Candidates at the measured DOFs (`measured`: model DOF indices of all
  // channels, responses first; `responses`: the response channels).
  void buildCandidates(const std::vector<int>& measured, const std::vector<int>& responses,
                       const std::vector<int>& references, bool frfData, double bandHighHz, const Vector& nominalW2);

  std::string label(int d) const { return model.labels[static_cast<std::size_t>(d)]; }

  static double firstElastic(const Vector& w2);

  // Static flexibility of the elastic modes, sum_r a_r a_r^T / omega_r^2 (rigid
  // modes left out so free structures have one too).
  Matrix pseudoFlexibility(const Vector& w2) const;

  // Parameter count of a set of candidates (their phi concatenated).
  int phiCount(const std::vector<int>& combo) const {
    int q = 0;
    for (int c : combo) q += static_cast<int>(defs[static_cast<std::size_t>(c)].candidate.parameters.size());
    return q;
  }

  bool solve(const ModelPoint& at, ModalSystem& sys) const {
    static const std::vector<int> none;
    return at.candidate < 0 ? solve(at.theta, none, at.phi, sys)
                            : solve(at.theta, std::vector<int>{at.candidate}, at.phi, sys);
  }

  // Builds and solves the augmented model with the candidates in `combo` all
  // applied (phi concatenated in that order). False when it cannot be
  // evaluated (mass matrix no longer positive definite, non-finite values).
  bool solve(const double* theta, const std::vector<int>& combo, const double* phi, ModalSystem& sys) const;

  static ComplexMatrix dynamicStiffness(const ModalSystem& sys, Complex s);

  // The state-space expansion, kept only when it reproduces a direct solve at
  // the geometric mean of the natural frequencies to 1e-9 (repeated poles give
  // a defective eigenvector matrix; the per-line solve is then used).
  static void stateSpaceModes(ModalSystem& sys);

  // Receptance between model DOFs `resp` (rows) and `refs` (columns) in
  // pole-residue form H(s) = P diag(g(s)) Q, set up once per evaluation:
  // g_j = 1 / (s - pole_j) for the state-space modes, or
  // g_r = 1 / (omega_r^2 (1 + i eta) + s c_r + s^2) for diagonal modal
  // damping; a solve per line when the state-space modes were refused.
  class Receptance {
   public:
    Receptance(const ModalSystem& sys, const std::vector<int>& resp, const std::vector<int>& refs);

    // H at s into h (rows x refs), before type conversion.
    void at(Complex s, ComplexMatrix& h);

   private:
    const ModalSystem& sys_;
    const std::vector<int>& resp_;
    const std::vector<int>& refs_;
    bool direct_ = false;
    bool modal_ = false;
    ComplexMatrix p_, q_;
    ComplexVector g_, w_;
    std::vector<double> coef_, gRe_, gIm_;  // modal_: R_oir (i, o, r order) and g_r
  };
};

// "10-120 Hz".
std::string hzLabel(double lo, double hi);

// The model's calibration parameters at their nominal values.
std::vector<double> nominalTheta(const StructuralModel& model);

}  // namespace mozzi::core::gap::structural::detail
