#include "core/modal/shape_tools.h"

#include <Eigen/Dense>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <string>

namespace mozzi::core::modal {

double mac(const ComplexVectorRef& a, const ComplexVectorRef& b) {
  if (a.size() != b.size() || a.size() == 0) return 0.0;
  const double na = a.squaredNorm(), nb = b.squaredNorm();
  if (!(na > 0.0) || !(nb > 0.0)) return 0.0;
  return std::norm(a.dot(b)) / (na * nb);  // dot() conjugates the first argument: a^H b
}

Matrix macMatrix(const ComplexMatrixRef& a, const ComplexMatrixRef& b) {
  Matrix out(a.cols(), b.cols());
  for (Eigen::Index i = 0; i < a.cols(); ++i)
    for (Eigen::Index j = 0; j < b.cols(); ++j) out(i, j) = mac(a.col(i), b.col(j));
  return out;
}

Result<Vector> comac(const ComplexMatrixRef& a, const ComplexMatrixRef& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.size() == 0) {
    return makeError(ErrorCode::InvalidArgument, "COMAC needs two shape sets of the same size (dofs x paired modes)",
                     "COMAC");
  }
  Vector out(a.rows());
  for (Eigen::Index o = 0; o < a.rows(); ++o) {
    double num = 0.0;
    for (Eigen::Index r = 0; r < a.cols(); ++r) num += std::abs(a(o, r) * std::conj(b(o, r)));
    const double den = a.row(o).squaredNorm() * b.row(o).squaredNorm();
    out[o] = den > 0.0 ? num * num / den : 0.0;
  }
  return out;
}

double mpc(const ComplexVectorRef& shape) {
  const Vector re = shape.real(), im = shape.imag();
  const double sxx = re.squaredNorm(), syy = im.squaredNorm(), sxy = re.dot(im);
  // Eigenvalues of [sxx sxy; sxy syy]: difference = sqrt((sxx - syy)^2 + 4 sxy^2).
  const double sum = sxx + syy;
  if (!(sum > 0.0)) return 0.0;
  const double diff = std::sqrt((sxx - syy) * (sxx - syy) + 4.0 * sxy * sxy);
  return (diff / sum) * (diff / sum);
}

double mpdDegrees(const ComplexVectorRef& shape) {
  const Eigen::Index n = shape.size();
  if (n == 0) return 0.0;
  Eigen::MatrixX2d x(n, 2);
  x.col(0) = shape.real();
  x.col(1) = shape.imag();
  Eigen::JacobiSVD<Eigen::MatrixX2d> svd(x, Eigen::ComputeFullV);
  const Eigen::Vector2d u = svd.matrixV().col(0);  // best line direction (cos t, sin t)
  double num = 0.0, den = 0.0;
  for (Eigen::Index o = 0; o < n; ++o) {
    const double amp = std::abs(shape[o]);
    if (!(amp > 0.0)) continue;
    // Distance of the point from the line / amplitude = sin(angle to the line).
    const double cross = std::abs(shape[o].real() * u[1] - shape[o].imag() * u[0]);
    num += amp * std::asin(std::min(1.0, cross / amp));
    den += amp;
  }
  return den > 0.0 ? num / den * 180.0 / M_PI : 0.0;
}

ComplexMatrix normaliseMaxComponent(const ComplexMatrixRef& shapes) {
  ComplexMatrix out = shapes;
  for (Eigen::Index r = 0; r < out.cols(); ++r) {
    Eigen::Index idx = 0;
    const double mx = out.col(r).cwiseAbs().maxCoeff(&idx);
    if (mx > 0.0) out.col(r) /= out(idx, r);
  }
  return out;
}

Result<ShapeSet> modeShapes(const ModalModel& model, Eigen::Index reference) {
  MOZZI_TRY(model.validate());
  if (reference < 0 || reference >= model.referenceCount()) {
    return makeError(ErrorCode::NotFound, "reference index out of range", "mode shapes");
  }
  const Eigen::Index no = model.responseCount();
  const Eigen::Index nm = static_cast<Eigen::Index>(model.modes.size());
  ShapeSet set;
  set.shapes.resize(no, nm);
  const Dof& ref = model.references[static_cast<std::size_t>(reference)];
  for (Eigen::Index o = 0; o < no; ++o) {
    if (model.responses[static_cast<std::size_t>(o)] == ref) set.drivingPointResponse = o;
  }
  // Modal constant A = 2 i omega_d R (real for a real mode): A_oi = phi_o phi_i.
  for (Eigen::Index r = 0; r < nm; ++r) {
    const auto& md = model.modes[static_cast<std::size_t>(r)];
    set.shapes.col(r) = Complex(0.0, 2.0 * md.pole.imag()) * md.residue.col(reference);
  }
  if (set.drivingPointResponse >= 0) {
    set.normalisation = Normalisation::UnitModalMass;
    for (Eigen::Index r = 0; r < nm; ++r) {
      const Complex adp = set.shapes(set.drivingPointResponse, r);
      if (std::abs(adp) == 0.0) {
        return makeError(ErrorCode::NumericalFailure,
                         "driving-point residue is zero: the reference is a node of the mode",
                         "mode shapes, mode " + std::to_string(r + 1));
      }
      // phi_o = A_oi / phi_i with phi_i = sqrt(A_ii) (unit modal mass).
      set.shapes.col(r) /= std::sqrt(adp);
    }
  } else {
    set.normalisation = Normalisation::MaxComponent;
    set.shapes = normaliseMaxComponent(set.shapes);
  }
  return set;
}

Result<MeasuredShapes> measuredShapes(const ModalModel& model) {
  MOZZI_TRY(model.validate());
  MeasuredShapes out;
  out.alongReferences = model.referenceCount() > model.responseCount();
  // The model seen from the side the shapes lie along: its "responses" are the
  // shape's DOFs, its "references" the DOFs that may be held.
  ModalModel along;
  if (out.alongReferences) {
    along.responses = model.references;
    along.references = model.responses;
    for (const Mode& m : model.modes) along.modes.push_back({m.pole, m.residue.transpose(), ComplexVector()});
  }
  const ModalModel& view = out.alongReferences ? along : model;
  out.dofs = view.responses;
  // A driving point scales to unit modal mass only where it moves in every
  // mode: its residue at least 1 % of the largest of its column (a node of a
  // mode would divide that mode's shape by the square root of noise).
  constexpr double kDrivingPointShare = 0.01;
  for (Eigen::Index held = 0; held < view.referenceCount(); ++held) {
    const Dof& dof = view.references[static_cast<std::size_t>(held)];
    const auto at = std::find(view.responses.begin(), view.responses.end(), dof);
    if (at == view.responses.end()) continue;
    const auto row = static_cast<Eigen::Index>(at - view.responses.begin());
    bool movesInEveryMode = true;
    for (const Mode& md : view.modes) {
      const double largest = md.residue.col(held).cwiseAbs().maxCoeff();
      movesInEveryMode =
          movesInEveryMode && std::abs(md.residue(row, held)) >= kDrivingPointShare * largest && largest > 0.0;
    }
    if (!movesInEveryMode) continue;
    MOZZI_TRY_ASSIGN(out.set, modeShapes(view, held));
    return out;
  }
  const Eigen::Index nm = static_cast<Eigen::Index>(view.modes.size());
  out.set.shapes.resize(view.responseCount(), nm);
  for (Eigen::Index r = 0; r < nm; ++r) {
    const Mode& md = view.modes[static_cast<std::size_t>(r)];
    Eigen::Index held = 0;
    md.residue.colwise().squaredNorm().maxCoeff(&held);
    out.set.shapes.col(r) = Complex(0.0, 2.0 * md.pole.imag()) * md.residue.col(held);  // A = 2 i omega_d R
  }
  out.set.normalisation = Normalisation::MaxComponent;
  out.set.shapes = normaliseMaxComponent(out.set.shapes);
  return out;
}

Result<Matrix> cmif(const FrfMatrix& frf) {
  MOZZI_TRY(frf.validate());
  const Eigen::Index nf = frf.lineCount(), no = frf.responseCount(), ni = frf.referenceCount();
  Matrix out(nf, std::min(no, ni));
  ComplexMatrix hk(no, ni);
  for (Eigen::Index k = 0; k < nf; ++k) {
    for (Eigen::Index i = 0; i < ni; ++i) hk.col(i) = frf.h[static_cast<std::size_t>(i)].row(k).transpose();
    Eigen::JacobiSVD<ComplexMatrix> svd(hk);
    out.row(k) = svd.singularValues().transpose();
  }
  return out;
}

Result<Vector> mif(const FrfMatrix& frf, Eigen::Index reference) {
  MOZZI_TRY(frf.validate());
  if (reference < 0 || reference >= frf.referenceCount()) {
    return makeError(ErrorCode::NotFound, "reference index out of range", "MIF");
  }
  const ComplexMatrix& h = frf.h[static_cast<std::size_t>(reference)];
  Vector out(frf.lineCount());
  for (Eigen::Index k = 0; k < frf.lineCount(); ++k) {
    double num = 0.0, den = 0.0;
    for (Eigen::Index o = 0; o < h.cols(); ++o) {
      num += std::abs(h(k, o).real()) * std::abs(h(k, o));
      den += std::norm(h(k, o));
    }
    out[k] = den > 0.0 ? num / den : 1.0;
  }
  return out;
}

}  // namespace mozzi::core::modal
