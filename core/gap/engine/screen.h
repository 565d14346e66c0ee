#pragma once
// Linear screen of the candidate effects at the calibrated baseline (GAP.md
// step 3). With the whitened Jacobian J of theta (data rows plus prior rows)
// and a candidate's signature S = dr/du_phi at phi nominal, what calibration
// cannot absorb is B = P S with P = I - J (J'J)^-1 J' (applied through a
// column-pivoted Householder QR of J, never the normal equations). Near the
// baseline the data see the effect only through B: its smallest singular value
// against the noise scale (1, the residuals being whitened) decides whether
// the candidate is identifiable, and the cosines between the columns spaces
// of different B say which candidates are confusable.

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "core/gap/engine/fit.h"

namespace mozzi::core::gap::engine {

struct ScreenedCandidate {
  int index = -1;                     // into problem.candidates()
  std::vector<Scaled> phi;            // scaled effect parameters
  Eigen::MatrixXd projected;          // B = P S (augmented rows), u units of phi
  Eigen::MatrixXd gram;               // B'B
  Eigen::MatrixXd basis;              // orthonormal basis of range(B), for confusability
  double sigmaMin = 0.0;              // smallest singular value of B diag(span)
  double absorbedFraction = 0.0;      // 1 - sigma_min(B) / sigma_min(S): how much calibration absorbs
  std::vector<double> projectedNorm;  // |B_j| per parameter (u units)
  bool identifiable = false;
  std::string reason;                   // why not, in words
  Eigen::VectorXd jointSingularValues;  // of the whitened [J S] in u units
  Eigen::VectorXd nullDirection;        // right singular vector of the smallest one (theta then phi)
};

struct Screen {
  Eigen::MatrixXd basis;  // thin Q of the augmented baseline Jacobian (its numerical rank)
  int thetaRank = 0;
  int augmentedRows = 0;  // residualCount + theta prior rows
  std::vector<ScreenedCandidate> candidates;
  Eigen::MatrixXd confusability;  // |cos| of the principal angle between range(B_k) and range(B_l)

  // Linearised best improvement 2 (NLL_0 - NLL_k) of candidate c for an
  // augmented baseline residual vector r (box-constrained in phi), and the
  // corresponding step in u; used for fit seeds and the linear bootstrap.
  double linearRatio(int c, const Eigen::VectorXd& r, Eigen::VectorXd* step = nullptr) const;
  // Augmented residual vector [data; theta priors] at u of the baseline model.
  static bool augmentedResiduals(const Model& baseline, const Eigen::VectorXd& u, Eigen::VectorXd& r);
};

// Linear screen at the baseline optimum u0 of `baseline`. `phi` holds the
// scaled parameters of every candidate screened (index into candidates()).
Result<Screen> screenCandidates(const Model& baseline, const Eigen::VectorXd& u0,
                                const std::vector<std::pair<int, std::vector<Scaled>>>& phi);

}  // namespace mozzi::core::gap::engine
