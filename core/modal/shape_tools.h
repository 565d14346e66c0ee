#pragma once
// Mode-shape tools: correlation (MAC, AutoMAC, COMAC), complexity (MPC, MPD),
// normalisation, mode indicator functions (CMIF, MIF). Definitions follow
// Allemang, "The modal assurance criterion - twenty years of use and abuse"
// (Sound and Vibration 2003) and Pappa et al. (MPC, J. Guidance 1993).

#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/modal/modal_model.h"

namespace mozzi::core::modal {

// MAC = |a^H b|^2 / ((a^H a)(b^H b)), in [0, 1]; 0 when either vector is zero.
double mac(const ComplexVectorRef& a, const ComplexVectorRef& b);
// MAC matrix between the columns of two shape sets (na x nb); AutoMAC = macMatrix(a, a).
Matrix macMatrix(const ComplexMatrixRef& a, const ComplexMatrixRef& b);
// COMAC per DOF for paired columns of a and b (same size, dofs x modes):
// COMAC_o = (sum_r |a_or conj(b_or)|)^2 / (sum_r |a_or|^2 sum_r |b_or|^2).
Result<Vector> comac(const ComplexMatrixRef& a, const ComplexMatrixRef& b);

// Modal phase collinearity (Pappa): with S = [Re; Im] [Re; Im]^T (2 x 2) and its
// eigenvalues s1 >= s2, MPC = ((s1 - s2) / (s1 + s2))^2; 1 for a real (monophase) mode.
double mpc(const ComplexVectorRef& shape);
// Mean phase deviation [deg]: amplitude-weighted mean angle between each component
// and the best straight line through the origin of the complex plane (first
// singular vector of [Re Im]); 0 for a monophase mode, at most 90.
double mpdDegrees(const ComplexVectorRef& shape);

enum class Normalisation {
  UnitModalMass,  // reference is a driving point: phi = 2 i omega_d R / sqrt(2 i omega_d R_dp)
  MaxComponent,   // largest |component| = 1, real and positive
};

struct ShapeSet {
  ComplexMatrix shapes;  // no x modes
  Normalisation normalisation = Normalisation::MaxComponent;
  Eigen::Index drivingPointResponse = -1;  // response index of the driving point, or -1
};

// Mode shapes from the residues of reference column `reference`. Unit modal
// mass when a response DOF equals the reference DOF (driving point; for a
// real, mass-normalised mode R_r = phi phi^T / (2 i omega_d), Ewins eq. 2.xx),
// else max-component. A driving-point residue of zero is a NumericalFailure.
Result<ShapeSet> modeShapes(const ModalModel& model, Eigen::Index reference);

// The shapes a modal result keeps, shows and checks (MPC, MPD, AutoMAC): along
// the longer side of the residue matrices. Along the responses when they are
// at least as many as the references (accelerometers roved or many, a shaker);
// along the references when those outnumber the responses (a roving hammer
// read by a few fixed accelerometers), where by reciprocity R_{r,oi} = R_{r,io}
// (thesis §1.6) the residues of one response over the references are the shape
// at the hammer DOFs. The DOF held is a driving point when one is measured
// and moves in every mode (its residue at least 1 % of its column's largest;
// unit modal mass, modeShapes); else each mode takes the held DOF where its
// residues are largest (one on a node of that mode would give noise) and is
// scaled to max-component.
struct MeasuredShapes {
  std::vector<Dof> dofs;         // the responses, or the references
  ShapeSet set;                  // dofs x modes
  bool alongReferences = false;  // a roving-hammer orientation
};
Result<MeasuredShapes> measuredShapes(const ModalModel& model);

// Scale each column so its largest |component| is 1 (real, positive).
ComplexMatrix normaliseMaxComponent(const ComplexMatrixRef& shapes);

// Complex mode indicator function: singular values of H(omega_k) (no x ni) per
// line, descending; nf x min(no, ni).
Result<Matrix> cmif(const FrfMatrix& frf);
// Real mode indicator function of one reference column (Allemang's MIF form):
// MIF(omega) = sum_o |Re H_o| |H_o| / sum_o |H_o|^2; dips towards 0 at lightly
// damped normal modes of receptance or accelerance FRFs (quadrature response).
Result<Vector> mif(const FrfMatrix& frf, Eigen::Index reference);

}  // namespace mozzi::core::modal
