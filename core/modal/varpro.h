#pragma once
// Separable least squares of the modal model over a band: the engine of the
// refinement (refine.h). Variable projection (Golub and Pereyra, SIAM J.
// Numer. Anal. 10, 1973; Kaufman, BIT 15, 1975; O'Leary and Rust, Comput.
// Optim. Appl. 54, 2013): the poles enter nonlinearly, residues and residual
// terms linearly, so the linear part is eliminated in every evaluation.
//
// Real form, rows interleaved (Re, Im) per line, so that a column of complex
// FRF data is a column of Y without a copy:
//   Y (2 nf x m, m = no ni FRFs)  ~  Phi(theta) X,     theta = (f_1, zeta_1, ..., f_nm, zeta_nm)
// Columns of Phi (the LSFD basis of lsfd.h), per line of angular frequency w:
//   mode r:   fn (a + b),  i fn (a - b),   a = 1/(i w - lambda_r), b = 1/(i w - conj lambda_r)
//   upper residual:  fn, i fn;   lower residual:  fl, i fl;   fn = (i w)^n, fl = (i w)^(n-2)
// (n = 0, 1, 2 for receptance, mobility, accelerance). For fixed theta
// X = Phi^+ Y and the projected functional is
//   SSR(theta) = || P Y ||_F^2,   P = I - Q Q^T,   Phi = Q T (thin QR, T upper p x p,
// by CholeskyQR2 on the column-equilibrated basis, Householder when two
// columns are nearly dependent).
// Derivatives: the two columns of mode r depend only on (f_r, zeta_r);
// E (2 nf x 4 nm) holds d(column)/d(f_r), d(column)/d(zeta_r). With
// D_j = dPhi/dtheta_j and the residual R = P Y (data minus model):
//   Kaufman's Jacobian        J_K,j  = -P D_j X
//   Golub-Pereyra's Jacobian  J_GP,j = -P D_j X - Q T^-T D_j^T R   (exact d(PY)/dtheta_j)
// The two parts are orthogonal to each other and Q^T R = 0, hence
//   gradient      g_j = J^T r = -<D_j X, R> = -sum_c F_(j,c) . X_(row c of mode j)      (F = E^T R)
//                     = -sum_c E_(j,c)^T (R X^T)_(column c of mode j),
//                 R X^T = Y X^T - Q (Z X^T)  (only the modes' 2 nm columns)
//   J_K^T J_K     = sum_{c,c'} (E^T P E)_{(j,c),(l,c')} (X X^T)_{(j,c),(l,c')}
//   J_GP^T J_GP   = J_K^T J_K + <B_j, B_l>,   B_j = T^-T D_j^T R   (p x m)
// None of them needs J itself (2 nf m x 2 nm: 290 MB for 100 FRFs x 9,000
// lines and 10 modes): one product [Q, E]^T Y over the data per evaluation
// gives Z = Q^T Y and E^T Y, hence F = E^T R = E^T Y - (Q^T E)^T Z; with
// E^T P E = E^T E - (Q^T E)^T (Q^T E) P E is never formed. Everything else is
// p x m or (4 nm)^2 sized. SSR = ||Y||^2 - ||Z||^2.
//
// J_K^T J_K is the Schur complement of the full problem's Gauss-Newton matrix
// (nonlinear and linear parameters together) on the nonlinear block, so
// s^2 (J_K^T J_K)^-1 is the covariance of (f, zeta) with the residues and
// residual terms estimated as well.
//
// Workspaces are sized once at creation: an evaluation allocates nothing of
// the data's size (Eigen's matrix product may take its blocking buffer from
// the heap).

#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Householder>
#include <Eigen/QR>

#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/modal/modal_model.h"

namespace mozzi::core::modal {

// A run of consecutive lines of the FRF matrix.
struct LineSegment {
  Eigen::Index first = 0;  // index into frf.frequencyHz
  Eigen::Index count = 0;
};

class ModalVarpro {
 public:
  // Views `frf` (which must outlive this object; nothing is copied) over the
  // given segments (ascending, not overlapping, DC excluded by the caller).
  // Errors: too few lines for the unknowns per FRF, FRFs zero on the lines.
  // Without `derivatives` only evaluate(theta, false) is possible (LSFD at
  // fixed poles) and the workspace is about a third of the size.
  static Result<ModalVarpro> create(const FrfMatrix& frf, std::vector<LineSegment> segments, int modes,
                                    bool lowerResidual, bool upperResidual, bool derivatives = true);

  // What an evaluation computes besides SSR and X.
  enum class Derivatives {
    None,        // the LSFD at fixed poles
    Covariance,  // and J_K^T J_K (kaufman()): E and its products with Q and
                 // itself, no pass of E over the data (no gradient)
    Kaufman,     // and the gradient: a second pass over the data, Y X^T on
                 // the modes' rows of X (2 nm columns, half of E^T Y's 4 nm)
    Full,        // and the gradient and J_GP^T J_GP: the pass over the data is [Q, E]^T Y
  };
  // Evaluates at theta (2 nm: f [Hz], zeta per mode). False when a pole is
  // not admissible (f <= 0, zeta outside (0, 1)), the basis is rank
  // deficient (two equal poles: the caller treats it as a failed step), or
  // derivatives are asked of an object created without them.
  bool evaluate(const Eigen::Ref<const Vector>& theta, Derivatives what);
  bool evaluate(const Eigen::Ref<const Vector>& theta, bool withDerivatives) {
    return evaluate(theta, withDerivatives ? Derivatives::Full : Derivatives::None);
  }

  // After evaluate(): SSR = ||Y - Phi X||^2 in the data's units squared.
  double ssr() const { return ssr_; }
  // ||Y||^2 over the lines (the relative error is sqrt(ssr / dataNorm2)).
  double dataNorm2() const { return yNorm2_; }
  // SSR computed from the explicit residual (one more pass over the data;
  // exact where ssr() loses digits to the subtraction, i.e. almost noise-free data).
  double explicitSsr();
  // The same per FRF: out[i no + o] = ||Y_c - Phi X_c||^2, c = i no + o (m
  // values; resized). One pass over the data in blocks of lines (up to about
  // 4 MB of model values Q Z, one matrix product per block).
  void explicitSsrPerFrf(Vector& out);
  // Linear parameters X (p x m): rows 2r, 2r+1 = Re, Im of mode r's residue,
  // then Re, Im of the upper residual, then of the lower residual; column
  // i no + o = FRF (response o, reference i).
  const Matrix& linear() const { return x_; }
  // The model's FRFs Phi X on the lines, one nf x no matrix per reference
  // (resized as needed; no other allocation).
  void modelValues(std::vector<ComplexMatrix>& out) const;
  // The model of one FRF (response o, reference i) on the lines, Q z_c with
  // c = i no + o: a column of modelValues() without the others (resized).
  void modelValues(Eigen::Index response, Eigen::Index reference, ComplexVector& out) const;
  // With Derivatives::Full: J^T r (2 nm), J_GP^T J_GP and J_K^T J_K (2 nm x
  // 2 nm); Kaufman: J^T r and J_K^T J_K; Covariance: J_K^T J_K.
  const Vector& gradient() const { return grad_; }
  const Matrix& gaussNewton() const { return jtjGp_; }
  const Matrix& kaufman() const { return jtjK_; }

  // Residual vector r = vec(R) (column by column, each column interleaved
  // Re, Im per line) and, when asked, the dense Jacobians J_GP and J_K
  // (2 nf m x 2 nm). For tests on small problems (the sizes are not checked).
  void denseResidual(const Eigen::Ref<const Vector>& theta, Vector& r, Matrix* jGp, Matrix* jK);

  Eigen::Index lineCount() const { return nf_; }
  const std::vector<LineSegment>& segments() const { return segments_; }
  Eigen::Index frfCount() const { return m_; }
  Eigen::Index linearCount() const { return p_; }  // per FRF
  int modeCount() const { return nm_; }
  bool lowerResidual() const { return lower_; }
  bool upperResidual() const { return upper_; }

 private:
  ModalVarpro() = default;
  bool fillBasis(const Eigen::Ref<const Vector>& theta, bool withDerivatives);
  // Phi (left block of A) -> Q in place, R into r_. False when rank deficient.
  bool orthogonalize(const Eigen::Ref<const Vector>& theta);
  // Y segment s of reference i: 2 count x no, a view into frf.h[i].
  Eigen::Map<const Matrix, 0, Eigen::OuterStride<>> ySegment(std::size_t s, Eigen::Index i) const;

  const FrfMatrix* frf_ = nullptr;
  std::vector<LineSegment> segments_;
  std::vector<Eigen::Index> segmentRow_;  // first row of each segment in Phi
  int nm_ = 0;
  bool lower_ = true, upper_ = true;
  Eigen::Index nf_ = 0, p_ = 0, m_ = 0, no_ = 0, ni_ = 0;
  double yNorm2_ = 0.0;
  Vector omega_;           // rad/s per selected line
  ComplexVector fn_, fl_;  // (i w)^n and (i w)^(n-2) per line
  Matrix a_;               // 2 nf x (p + 4 nm): [Phi, E] filled, then [Q, E]

  struct ModeTerms {
    double wn, s, sigma, wd;  // 2 pi f, sqrt(1 - zeta^2), zeta wn, wn s (lambda = -sigma + i wd)
    Complex dlf, dlz;         // d lambda / d f, d lambda / d zeta
  };
  std::vector<ModeTerms> modeTerms_;  // per mode, of the theta being filled in

  Matrix r_;                         // p x p: Phi = Q R
  Matrix rTmp_, gram_;               // p x p
  Eigen::LLT<Matrix> llt_;           // of the Gram matrix (CholeskyQR2)
  Eigen::HouseholderQR<Matrix> qr_;  // fallback for nearly dependent columns, sized when first needed
  Vector hWork_;                     // Householder workspace
  Matrix blockWork_;                 // rows of a block x no: model values of a block of lines (explicitSsr)
  Matrix w_;                         // (p + 4 nm) x m: [Z; F]
  Matrix x_;                         // p x m
  Matrix qtE_;                       // p x 4 nm
  Matrix epe_;                       // 4 nm x 4 nm: E^T P E
  Matrix g_;                         // p x p: X X^T
  Matrix b_;                         // p x (m 2 nm): B_j side by side
  Matrix rx_;                        // up to 1024 rows x 2 nm: Y X_m^T on a block of rows (X_m: the modes' rows of X)
  Matrix zx_;                        // p x 2 nm: Z X_m^T
  Matrix ezx_;                       // 4 nm x 2 nm: (Q^T E)^T Z X_m^T
  Vector colNorm_;
  Vector grad_;
  Matrix jtjGp_, jtjK_;
  double ssr_ = 0.0;
  bool derivatives_ = false;     // the last evaluation has them
  bool withDerivatives_ = true;  // workspace for them
};

// The modal model of an evaluation: `poles` (one per mode, in theta's order)
// with the residues and residual terms of vp.linear().
ModalModel modalModelFromLinear(const ModalVarpro& vp, const FrfMatrix& frf, const std::vector<Complex>& poles);

}  // namespace mozzi::core::modal
