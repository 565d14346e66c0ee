#include "core/modal/modal_model.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/modal/lsfd.h"
#include "core/modal/shape_tools.h"
#include "core/modal/synthetic_system.h"

namespace mozzi::core::modal {
namespace {

using testing::sixDofs;
using testing::sixModeSystem;

// A non-proportionally damped 3-DOF chain (complex modes).
struct Chain {
  Matrix m, c, k;
};
Chain chain() {
  Chain s;
  s.m = Vector3(2.0, 1.0, 1.5).asDiagonal();
  s.k.resize(3, 3);
  s.k << 3e4, -1e4, 0, -1e4, 2.5e4, -1.5e4, 0, -1.5e4, 1.5e4;
  s.c.resize(3, 3);
  s.c << 12.0, -2.0, 0, -2.0, 2.0, 0, 0, 0, 5.0;  // not proportional to M or K
  return s;
}

std::vector<Dof> threeDofs() {
  return {Dof{1, Direction::Z}, Dof{2, Direction::Z}, Dof{3, Direction::Z}};
}

// Synthesis from the modal model must equal (K - w^2 M + i w C)^-1 (thesis
// eq. 19) at any frequency: both are exact, tolerance is rounding (1e-9 rel).
TEST(ModalModel, SpatialToModalReproducesReceptance) {
  const Chain s = chain();
  auto model = modalFromSpatial(s.m, s.c, s.k, threeDofs());
  ASSERT_TRUE(model.ok()) << model.error().describe();
  ASSERT_EQ(model->modes.size(), 3u);
  for (double fHz : {3.0, 17.5, 24.0, 80.0}) {
    const double w = 2 * M_PI * fHz;
    const ComplexMatrix ref = spatialReceptance(s.m, s.c, s.k, w);
    for (Eigen::Index o = 0; o < 3; ++o)
      for (Eigen::Index i = 0; i < 3; ++i) {
        const Complex h = synthesize(*model, o, i, w, FrfType::Receptance);
        EXPECT_LT(std::abs(h - ref(o, i)), 1e-9 * ref.cwiseAbs().maxCoeff()) << fHz << " Hz";
        // Accelerance = -w^2 receptance.
        const Complex a = synthesize(*model, o, i, w, FrfType::Accelerance);
        EXPECT_LT(std::abs(a + w * w * ref(o, i)), 1e-9 * w * w * ref.cwiseAbs().maxCoeff());
      }
  }
}

// Complete modal model -> spatial (state-space orthogonality) returns M, C, K.
TEST(ModalModel, ModalToSpatialRoundTrip) {
  const Chain s = chain();
  auto model = modalFromSpatial(s.m, s.c, s.k, threeDofs());
  ASSERT_TRUE(model.ok());
  auto back = spatialFromModal(*model);
  ASSERT_TRUE(back.ok()) << back.error().describe();
  EXPECT_LT((back->m - s.m).norm(), 1e-8 * s.m.norm());
  EXPECT_LT((back->k - s.k).norm(), 1e-8 * s.k.norm());
  EXPECT_LT((back->c - s.c).norm(), 1e-7 * s.c.norm());
  // An incomplete model is refused with a message.
  ModalModel partial = *model;
  partial.modes.pop_back();
  auto bad = spatialFromModal(partial);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("complete"), std::string::npos);
}

// Proportional system built from chosen modes: the modal model returns them.
TEST(ModalModel, ProportionalSystemPolesAreTheChosenModes) {
  const auto sys = sixModeSystem();
  auto model = modalFromSpatial(sys.m, sys.c, sys.k, sixDofs());
  ASSERT_TRUE(model.ok());
  for (int r = 0; r < 6; ++r) {
    EXPECT_NEAR(model->modes[static_cast<std::size_t>(r)].frequencyHz(), sys.fn[r], 1e-9 * sys.fn[r]);
    EXPECT_NEAR(model->modes[static_cast<std::size_t>(r)].zeta(), sys.zeta[r], 1e-9);
    EXPECT_NEAR(model->modes[static_cast<std::size_t>(r)].eta(), 2 * sys.zeta[r], 2e-9);
  }
  // Unit-modal-mass shapes from the residues equal the mass-normalised shapes.
  auto shapes = modeShapes(*model, 1);
  ASSERT_TRUE(shapes.ok());
  for (int r = 0; r < 6; ++r) {
    EXPECT_GT(mac(shapes->shapes.col(r), sys.phi.col(r).cast<Complex>()), 1 - 1e-12);
    EXPECT_NEAR(std::abs(shapes->shapes(3, r)), std::abs(sys.phi(3, r)), 1e-9);
  }
}

// A roving hammer over the six DOFs read by one accelerometer at DOF 4 (the
// rows of the complete model's residues for that response): the shapes lie
// along the hammer points. With the accelerometer's DOF among them (a driving
// point) they are the mass-normalised shapes themselves; without it, the same
// shapes at the five others (MAC 1). A held DOF on a node of a mode (its
// residues zeroed here) gives way to one that moves.
TEST(ModalModel, RovingHammerShapesLieAlongTheHammerPoints) {
  const auto sys = sixModeSystem();
  auto full = modalFromSpatial(sys.m, sys.c, sys.k, sixDofs());
  ASSERT_TRUE(full.ok());
  auto subModel = [&](std::vector<int> rows, std::vector<int> cols) {
    ModalModel m;
    for (int o : rows) m.responses.push_back(full->responses[static_cast<std::size_t>(o)]);
    for (int i : cols) m.references.push_back(full->references[static_cast<std::size_t>(i)]);
    for (const Mode& md : full->modes) {
      Mode cut{md.pole, ComplexMatrix(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(cols.size())),
               ComplexVector()};
      for (std::size_t a = 0; a < rows.size(); ++a)
        for (std::size_t b = 0; b < cols.size(); ++b)
          cut.residue(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) = md.residue(rows[a], cols[b]);
      m.modes.push_back(cut);
    }
    return m;
  };
  const ModalModel withDrivingPoint = subModel({3}, {0, 1, 2, 3, 4, 5});
  auto shapes = measuredShapes(withDrivingPoint);
  ASSERT_TRUE(shapes.ok()) << shapes.error().describe();
  EXPECT_TRUE(shapes->alongReferences);
  EXPECT_EQ(shapes->dofs, sixDofs());
  EXPECT_EQ(shapes->set.normalisation, Normalisation::UnitModalMass);
  for (int r = 0; r < 6; ++r) {
    // phi itself up to one sign per mode (the root of the driving point's
    // modal constant): relative signs and phases too, not only magnitudes.
    const double sign = shapes->set.shapes(3, r).real() * sys.phi(3, r) > 0.0 ? 1.0 : -1.0;
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(std::abs(shapes->set.shapes(i, r) - sign * sys.phi(i, r)), 0.0, 1e-9);
  }
  // The driving point on a node of mode 2 (its residues there zeroed): no unit
  // modal mass from it, the max-component shapes instead, mode 2 whole.
  ModalModel onNode = withDrivingPoint;
  onNode.modes[1].residue(0, 3) = 0.0;
  shapes = measuredShapes(onNode);
  ASSERT_TRUE(shapes.ok()) << shapes.error().describe();
  EXPECT_EQ(shapes->set.normalisation, Normalisation::MaxComponent);
  ComplexVector phi2(5);
  for (int i = 0, k = 0; i < 6; ++i)
    if (i != 3) phi2[k++] = sys.phi(i, 1);
  ComplexVector shape2(5);
  for (int i = 0, k = 0; i < 6; ++i)
    if (i != 3) shape2[k++] = shapes->set.shapes(i, 1);
  EXPECT_GT(mac(shape2, phi2), 1 - 1e-12);
  const ModalModel noDrivingPoint = subModel({3}, {0, 1, 2, 4, 5});
  shapes = measuredShapes(noDrivingPoint);
  ASSERT_TRUE(shapes.ok());
  EXPECT_EQ(shapes->set.normalisation, Normalisation::MaxComponent);
  ASSERT_EQ(shapes->dofs.size(), 5u);
  const std::vector<int> hammer{0, 1, 2, 4, 5};
  for (int r = 0; r < 6; ++r) {
    ComplexVector phi(5);
    for (int i = 0; i < 5; ++i) phi[i] = sys.phi(hammer[static_cast<std::size_t>(i)], r);
    EXPECT_GT(mac(shapes->set.shapes.col(r), phi), 1 - 1e-12) << "mode " << r + 1;
  }
  ModalModel twoAccelerometers = subModel({0, 3}, {1, 2, 4, 5});
  twoAccelerometers.modes[2].residue.row(0).setZero();  // accelerometer 1 on a node of mode 3
  shapes = measuredShapes(twoAccelerometers);
  ASSERT_TRUE(shapes.ok());
  ComplexVector phi3(4);
  for (int i = 0; i < 4; ++i) phi3[i] = sys.phi(std::vector<int>{1, 2, 4, 5}[static_cast<std::size_t>(i)], 2);
  EXPECT_GT(mac(shapes->set.shapes.col(2), phi3), 1 - 1e-12);
  // At least as many responses as references: the column, as before.
  shapes = measuredShapes(subModel({0, 1, 2, 3, 4, 5}, {1}));
  ASSERT_TRUE(shapes.ok());
  EXPECT_FALSE(shapes->alongReferences);
  EXPECT_EQ(shapes->dofs, sixDofs());
  EXPECT_EQ(shapes->set.normalisation, Normalisation::UnitModalMass);
}

// Thesis eq. 1 and 2 (hysteretic damping): Phi^T M Phi = I,
// Phi^T (K + iD) Phi = diag(w^2 (1 + i eta)), and back to M, K, D.
TEST(ModalModel, HystereticEquationsOneAndTwo) {
  const Chain s = chain();
  Matrix d = 0.02 * s.k;
  d(0, 0) += 300.0;  // non-proportional structural damping
  auto hm = hystereticModalFromSpatial(s.m, s.k, d);
  ASSERT_TRUE(hm.ok()) << hm.error().describe();
  const ComplexMatrix orthoM = hm->phi.transpose() * s.m.cast<Complex>() * hm->phi;
  EXPECT_LT((orthoM - ComplexMatrix::Identity(3, 3)).norm(), 1e-10);
  const ComplexMatrix kd = s.k.cast<Complex>() + Complex(0, 1) * d.cast<Complex>();
  const ComplexMatrix orthoK = hm->phi.transpose() * kd * hm->phi;
  for (int r = 0; r < 3; ++r) {
    EXPECT_NEAR(orthoK(r, r).real(), hm->omega2[r], 1e-9 * hm->omega2[r]);
    EXPECT_NEAR(orthoK(r, r).imag(), hm->omega2[r] * hm->eta[r], 1e-9 * hm->omega2[r]);
    EXPECT_GT(hm->eta[r], 0.0);
  }
  auto back = spatialFromHystereticModal(*hm);
  ASSERT_TRUE(back.ok());
  EXPECT_LT((back->m - s.m).norm(), 1e-9 * s.m.norm());
  EXPECT_LT((back->k - s.k).norm(), 1e-9 * s.k.norm());
  EXPECT_LT((back->d - d).norm(), 1e-8 * d.norm());
  // Response model equals (K + iD - w^2 M)^-1.
  const double w = 2 * M_PI * 20.0;
  const ComplexMatrix direct = (kd - w * w * s.m.cast<Complex>()).inverse();
  EXPECT_LT((hystereticReceptance(*hm, w) - direct).norm(), 1e-9 * direct.norm());
}

// LSFD with exact poles recovers residues and the residual terms exactly when
// the data follow its model (noise-free: rounding-level tolerance 1e-6 rel).
TEST(Lsfd, RecoversResiduesAndResiduals) {
  const auto sys = sixModeSystem();
  auto full = modalFromSpatial(sys.m, sys.c, sys.k, sixDofs());
  ASSERT_TRUE(full.ok());
  ModalModel truth = *full;
  truth.references = {full->references[2]};
  for (auto& md : truth.modes) md.residue = ComplexMatrix(md.residue.col(2));
  truth.lowerResidual = ComplexMatrix::Constant(6, 1, Complex(0.05, 0.0));  // 1/kg
  truth.upperResidual = ComplexMatrix::Constant(6, 1, Complex(2e-7, 0.0));  // m/N
  auto frf = synthesizeFrf(truth, Vector::LinSpaced(3001, 30.0, 330.0), FrfType::Mobility);
  ASSERT_TRUE(frf.ok()) << frf.error().describe();
  std::vector<Complex> all;
  for (const auto& md : truth.modes) all.push_back(md.pole);
  LsfdOptions opt;
  opt.bandLowHz = 30.0;
  opt.bandHighHz = 330.0;
  auto exact = lsfd(*frf, all, opt);
  ASSERT_TRUE(exact.ok()) << exact.error().describe();
  for (int r = 0; r < 6; ++r) {
    const ComplexVector a = exact->modes[static_cast<std::size_t>(r)].residue.col(0);
    const ComplexVector b = truth.modes[static_cast<std::size_t>(r)].residue.col(0);
    EXPECT_LT((a - b).norm(), 1e-6 * b.norm()) << "mode " << r + 1;
  }
  EXPECT_LT((exact->lowerResidual - truth.lowerResidual).norm(), 1e-6 * truth.lowerResidual.norm());
  EXPECT_LT((exact->upperResidual - truth.upperResidual).norm(), 1e-6 * truth.upperResidual.norm());
  auto err = relativeFitError(*frf, *exact, 30.0, 330.0);
  ASSERT_TRUE(err.ok());
  EXPECT_LT(*err, 1e-8);
  // Truncated band: the residual terms absorb out-of-band modes, so the fit with
  // residuals is better than without.
  std::vector<Complex> inBand(all.begin() + 1, all.begin() + 5);  // 83.4 .. 214.1 Hz
  opt.bandLowHz = 70.0;
  opt.bandHighHz = 250.0;
  auto withRes = lsfd(*frf, inBand, opt);
  opt.lowerResidual = opt.upperResidual = false;
  auto noRes = lsfd(*frf, inBand, opt);
  ASSERT_TRUE(withRes.ok() && noRes.ok());
  const double eWith = relativeFitError(*frf, *withRes, 70.0, 250.0).value();
  const double eNo = relativeFitError(*frf, *noRes, 70.0, 250.0).value();
  EXPECT_LT(eWith, 0.5 * eNo) << eWith << " vs " << eNo;
  // Errors: no poles; duplicate poles.
  EXPECT_FALSE(lsfd(*frf, {}, opt).ok());
  auto dup = lsfd(*frf, {all[0], all[0]}, opt);
  ASSERT_FALSE(dup.ok());
  EXPECT_EQ(dup.error().code, ErrorCode::NumericalFailure);
}

// Shape tools against hand-computed values.
TEST(ShapeTools, MacMpcMpdComac) {
  ComplexVector a(3), b(3);
  a << 1.0, 2.0, -1.0;
  b << 2.0, 4.0, -2.0;
  EXPECT_NEAR(mac(a, b), 1.0, 1e-15);
  b << 1.0, 0.0, 1.0;  // orthogonal to a
  EXPECT_NEAR(mac(a, b), 0.0, 1e-15);
  b << 1.0, 1.0, 0.0;  // (a.b)^2 / (|a|^2 |b|^2) = 9 / (6 * 2)
  EXPECT_NEAR(mac(a, b), 0.75, 1e-15);
  // Real mode rotated by any phase: MPC 1, MPD 0.
  const ComplexVector rot = a * std::polar(1.0, 0.7);
  EXPECT_NEAR(mpc(rot), 1.0, 1e-12);
  EXPECT_NEAR(mpdDegrees(rot), 0.0, 1e-6);
  // Circular (travelling-wave) shape 1, i: MPC 0, MPD 45 deg (equal weights).
  ComplexVector c(2);
  c << Complex(1, 0), Complex(0, 1);
  EXPECT_NEAR(mpc(c), 0.0, 1e-12);
  EXPECT_NEAR(mpdDegrees(c), 45.0, 1e-6);
  // AutoMAC of orthonormal real shapes is the identity; COMAC of identical sets is 1.
  const auto sys = sixModeSystem();
  const ComplexMatrix q = (sys.m.cwiseSqrt() * sys.phi).cast<Complex>();
  EXPECT_LT((macMatrix(q, q) - Matrix::Identity(6, 6)).norm(), 1e-12);
  auto cm = comac(q, q);
  ASSERT_TRUE(cm.ok());
  EXPECT_LT((cm.value() - Vector::Ones(6)).norm(), 1e-12);
  // Max-component normalisation.
  const ComplexMatrix nrm = normaliseMaxComponent(ComplexMatrix(rot));
  EXPECT_NEAR(std::abs(nrm(1, 0) - Complex(1, 0)), 0.0, 1e-15);
}

// CMIF peaks at the natural frequency; MIF dips there.
TEST(ShapeTools, ModeIndicatorFunctions) {
  const auto sys = sixModeSystem();
  auto model = modalFromSpatial(sys.m, sys.c, sys.k, sixDofs());
  ASSERT_TRUE(model.ok());
  ModalModel one = *model;
  one.references = {model->references[2]};
  for (auto& md : one.modes) md.residue = ComplexMatrix(md.residue.col(2));
  auto frf = synthesizeFrf(one, Vector::LinSpaced(1001, 130.0, 170.0), FrfType::Accelerance);
  ASSERT_TRUE(frf.ok());
  auto c = cmif(*frf);
  auto m = mif(*frf, 0);
  ASSERT_TRUE(c.ok() && m.ok());
  Eigen::Index kc = 0, km = 0;
  c->col(0).maxCoeff(&kc);
  m->minCoeff(&km);
  // 150 Hz mode with zeta 0.5%: peak and dip within 2 lines (0.08 Hz) of 150 Hz.
  EXPECT_NEAR(frf->frequencyHz[kc], 150.0, 0.08);
  EXPECT_NEAR(frf->frequencyHz[km], 150.0, 0.08);
  EXPECT_LT((*m)[km], 0.05);
}

}  // namespace
}  // namespace mozzi::core::modal
