#pragma once
// Structural models for the sim-to-real gap (docs/formats.md, "mozzi-model/1").
//
// A model is written in generalised coordinates q with an observation matrix T
// mapping q to the physical DOFs (x = T q):
//  - a spatial model (mozzi-model/1 JSON): q = x, T = I, matrices M, K and
//    either C or a viscous ratio per mode;
//  - a modal model (UFF 55): q = modal coordinates, T = mass-normalised shapes,
//    M_q = I, K_q = diag(omega_r^2), zeta_r per mode.
// Added masses and springs then act in either form the same way
// (M_q += dm t_d^T t_d, K_q += k (t_a - t_b)^T (t_a - t_b), t = rows of T): the
// Rayleigh-Ritz projection, exact for the spatial model.
//
// Named springs and masses are elements already contained in M and K; they
// give locations to the catalogue effects (element_stiffness,
// boundary_stiffness) and to the calibration parameters, which scale them:
// K(theta) = K + sum_p (theta_p - 1) K_p, M(theta) likewise (K_p = the named
// elements parameter p acts on). A parameter acting on "damping" scales C or
// every modal damping ratio; one acting on "stiffness" or "mass" scales the
// whole K or M (a model built from geometry whose section or material is known
// only roughly, e.g. EI and rho A of a beam).

#include <string>
#include <string_view>
#include <vector>

#include "core/common/dof.h"
#include "core/common/eigen_types.h"
#include "core/common/result.h"
#include "core/io/uff/uff.h"

namespace mozzi::core::gap::structural {

inline constexpr const char* kModelSchema = "mozzi-model/1";

struct Spring {
  std::string name;
  int a = -1;              // DOF index
  int b = -1;              // DOF index, -1 = ground
  double stiffness = 0.0;  // N/m (N m/rad for rotations)
  bool grounded() const { return b < 0; }
};

struct LumpedMass {
  std::string name;
  int dof = -1;
  double mass = 0.0;  // kg (kg m^2 for rotations)
};

struct ModelParameter {
  std::string name;
  std::vector<std::string> actsOn;  // spring / mass names, or "damping", "stiffness", "mass"
  double nominal = 1.0;             // scale factor of those elements
  double lower = 0.0;
  double upper = 0.0;
  double priorSigma = 0.0;  // 0: no prior
};

struct StructuralModel {
  std::string name;
  std::vector<Dof> dofs;            // physical DOFs (rows of t)
  std::vector<std::string> labels;  // the same DOFs as the file wrote them ("21+Z")
  Matrix t;                         // ndof x nq observation matrix (identity for spatial models)
  Matrix m, k;                      // nq x nq
  Matrix c;                         // nq x nq, empty when modalDamping is used
  Vector modalDamping;              // nq viscous ratios by ascending frequency, empty when c is used
  std::vector<Spring> springs;
  std::vector<LumpedMass> masses;
  std::vector<ModelParameter> parameters;

  int dofCount() const { return static_cast<int>(dofs.size()); }
  int coordinateCount() const { return static_cast<int>(m.rows()); }
  bool usesModalDamping() const { return c.size() == 0; }
  // Index of a DOF by its label (any form parseDof accepts); -1 when absent.
  int findDof(const Dof& dof) const;
};

// Label in the model's own format: "21+Z".
std::string modelDofLabel(const Dof& dof);

// mozzi-model/1 JSON text -> model. Every violation is an error naming the
// field and the index ("K[2][3]", "springs[1].b", ...): wrong schema, sizes,
// non-finite numbers, asymmetric M/K/C, M not positive definite, K or C not
// positive semi-definite, unknown or repeated DOF labels, both or neither of C
// and modal_damping, unknown element names in parameters, bounds that do not
// hold the nominal.
Result<StructuralModel> parseModelJson(std::string_view text, const std::string& where = "model");
Result<StructuralModel> readModelFile(const std::string& path);

// Writes a model (spatial form, t = identity) as mozzi-model/1 JSON.
Result<std::string> writeModelJson(const StructuralModel& model);

// Modal model from UFF 55 records: shapes mass-normalised with the records'
// modal masses (a mode without a modal mass is an error: FRFs cannot be
// predicted from max-normalised shapes), viscous ratios as modal damping.
Result<StructuralModel> modelFromModalData(const io::uff::ModalData& modal, const std::string& where = "UFF 55");

}  // namespace mozzi::core::gap::structural
