// Spatial modal models of the virtual specimens (devices/sim/specimen_models.h):
// every catalogue specimen lives on the mesh of its thesis set-up, its
// frequencies and damping are the tabulated ones (recovered here from the
// eigenvalues of the assembled system the hammer station integrates), the
// FRFs are reciprocal, the shapes do what the thesis says each mode does, and
// every tabulated mode is excited at the driving point.
#include "devices/sim/specimen_models.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/geometry/mesh_templates.h"

namespace mozzi::devices::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<std::string> modalKeys() {
  std::vector<std::string> keys;
  for (const auto& e : specimenCatalogue())
    if (!e.modes.empty()) keys.push_back(e.key);
  return keys;
}

// The plate model loaded away from its load point (a set-up that moves the
// load point): w(p)/F(q) = w(q)/F(p) (reciprocity, 1e-12 relative), at q =
// the load point the specimen's own receptance, statically the same field.
TEST(StaticSpecimens, PlateReceptanceFromAnyLoadPointIsReciprocal) {
  for (const auto& key : {"frame-a-front-constrained", "fork-a-with-wheel", "frame-c-with-engine"}) {
    auto spec = staticSpecimen(key);
    ASSERT_TRUE(spec.ok()) << key;
    const core::Vector2 p(0.07, -0.05), q(-0.03, 0.04);
    for (double f : {0.0, 5.0, 20.0}) {
      const auto pq = spec->receptance(p, q, f), qp = spec->receptance(q, p, f);
      EXPECT_LT(std::abs(pq - qp), 1e-12 * std::abs(pq)) << key << " " << f;
      const auto own = spec->receptance(p, spec->loadPoint, f);
      EXPECT_LT(std::abs(own - spec->receptance(p, f)), 1e-12 * std::abs(own)) << key << " " << f;
    }
    const double ws = spec->displacementAt(p, q, 100.0), wr = spec->displacementAt(q, p, 100.0);
    EXPECT_NEAR(ws, wr, 1e-12 * std::abs(ws)) << key;
    EXPECT_NEAR(spec->displacementAt(p, spec->loadPoint, 100.0), spec->displacementAt(p, 100.0),
                1e-15 + 1e-12 * std::abs(ws))
        << key;
  }
}

TEST(SpatialSpecimens, EverySpecimenLivesOnItsThesisMesh) {
  for (const auto& key : modalKeys()) {
    SCOPED_TRACE(key);
    auto m = modalSpecimen(key);
    ASSERT_TRUE(m.ok()) << m.error().describe();
    EXPECT_EQ(m->meshTemplate, meshTemplateKey(key));
    const auto* t = core::geometry::findMeshTemplate(m->meshTemplate);
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(m->dofs, t->measurementDofs);
    EXPECT_EQ(m->shapes.rows(), static_cast<Eigen::Index>(m->dofs.size()));
    EXPECT_EQ(m->shapes.cols(), static_cast<Eigen::Index>(m->frequencyHz.size()));
    EXPECT_EQ(m->modeShapes.size(), m->frequencyHz.size());
    EXPECT_TRUE(m->shapes.allFinite());
    // The tabulated frequencies and damping, unchanged (eta as zeta = eta / 2).
    const SpecimenEntry* e = findSpecimen(key);
    ASSERT_EQ(m->tabulatedModes, e->modes.size());
    for (std::size_t r = 0; r < e->modes.size(); ++r) {
      EXPECT_EQ(m->frequencyHz[r], e->modes[r].frequencyHz);
      EXPECT_EQ(m->zeta[r], e->zeta(r));
    }
    // Full column rank: a reduced positive-definite M and K with these
    // mass-normalised shapes exist (thesis eq. 1-2). With the columns scaled
    // to unit length, the smallest singular value above 0.02 keeps every
    // shape more than a degree away from the span of the others (the closest
    // are the steel fork's two torsional modes, §6.3, and a rear-constrained
    // frame's lateral mode against its lateral completion mode: 0.03-0.04).
    core::Matrix unit = m->shapes;
    for (Eigen::Index r = 0; r < unit.cols(); ++r) unit.col(r).normalize();
    Eigen::JacobiSVD<core::Matrix> svd(unit);
    const auto& sv = svd.singularValues();
    std::printf("%-34s %2td DOFs x %2td modes, smallest singular value of the unit shapes %.3f\n", key.c_str(),
                unit.rows(), unit.cols(), sv(sv.size() - 1));
    EXPECT_GT(sv(sv.size() - 1), 0.02);
  }
  EXPECT_EQ(meshTemplateKey("no-such-specimen"), "");
  EXPECT_EQ(meshTemplateKey("fork-a-with-wheel"), "motorcycle-fork-10-wheel-8");
  EXPECT_EQ(meshTemplateKey("frame-b-rear-constrained"), "motorcycle-frame-26");
}

// Poles of the square system the hammer station integrates for a force at a
// DOF: the eigenvalues of A = [0 I; -M^-1 K  -M^-1 C] are
// -zeta w +/- i w sqrt(1 - zeta^2), so |lambda| / 2 pi and -Re(lambda) / |lambda|
// give back every frequency and damping ratio; relative 1e-9 (round-off of a
// 20 x 20 eigenproblem).
TEST(SpatialSpecimens, TheAssembledSystemHasTheTabulatedPoles) {
  for (const auto& key : modalKeys()) {
    SCOPED_TRACE(key);
    const auto m = modalSpecimen(key).value();
    for (Eigen::Index drive : {m.excitedDof, Eigen::Index(m.dofs.size() - 1)}) {
      const auto d = m.drivenSystem(drive);
      if (!d.excited) continue;
      const Eigen::Index n = d.system.dofCount();
      core::Matrix a = core::Matrix::Zero(2 * n, 2 * n);
      const core::Matrix mInv = d.system.mass.inverse();
      a.topRightCorner(n, n).setIdentity();
      a.bottomLeftCorner(n, n) = -mInv * d.system.stiffness;
      a.bottomRightCorner(n, n) = -mInv * d.system.damping;
      Eigen::EigenSolver<core::Matrix> es(a);
      std::vector<std::complex<double>> poles;
      for (Eigen::Index k = 0; k < 2 * n; ++k)
        if (es.eigenvalues()(k).imag() > 0) poles.push_back(es.eigenvalues()(k));
      ASSERT_EQ(poles.size(), static_cast<std::size_t>(n));
      for (std::size_t r = 0; r < m.frequencyHz.size(); ++r) {
        double best = 1e9, zeta = 0.0;
        for (const auto& p : poles) {
          const double f = std::abs(p) / (2 * kPi);
          if (std::abs(f - m.frequencyHz[r]) < std::abs(best - m.frequencyHz[r])) {
            best = f;
            zeta = -p.real() / std::abs(p);
          }
        }
        EXPECT_NEAR(best / m.frequencyHz[r], 1.0, 1e-9) << "mode " << r;
        EXPECT_NEAR(zeta / m.zeta[r], 1.0, 1e-9) << "mode " << r;
      }
    }
  }
}

// Reciprocity, through two different assembled systems: the response at j
// to a force at i (driven system of i) equals the response at i to a force
// at j (driven system of j), and both equal the modal sum of eq. 21. H(w) =
// output_j (K - w^2 M + i w C)^-1 e_0; relative 1e-9.
TEST(SpatialSpecimens, FrfsAreReciprocalAndEqualTheModalSum) {
  for (const auto& key : {"fork-a-with-wheel", "frame-b-front-constrained", "bicycle-steel", "swing-arm-b",
                          "tyre-120-70-r17", "bicycle-fork-steel-without-wheel"}) {
    SCOPED_TRACE(key);
    const auto m = modalSpecimen(key).value();
    const Eigen::Index nd = m.shapes.rows();
    const Eigen::Index pairs[][2] = {{m.excitedDof, nd - 1}, {1, nd / 2}, {nd / 3, 2 * nd / 3}};
    for (const auto& p : pairs) {
      const Eigen::Index i = p[0], j = p[1];
      const auto di = m.drivenSystem(i), dj = m.drivenSystem(j);
      ASSERT_TRUE(di.excited && dj.excited);
      for (std::size_t r = 0; r < m.tabulatedModes; ++r) {
        for (double factor : {0.5, 0.98, 1.0, 1.03}) {
          const double w = 2 * kPi * m.frequencyHz[r] * factor;
          auto frf = [w](const DrivenSystem& d, Eigen::Index out) {
            const core::ComplexMatrix z = d.system.stiffness.cast<std::complex<double>>() -
                                          w * w * d.system.mass.cast<std::complex<double>>() +
                                          std::complex<double>(0, w) * d.system.damping.cast<std::complex<double>>();
            const core::ComplexVector y = z.partialPivLu().solve(core::ComplexVector::Unit(z.rows(), 0));
            return (d.output.row(out).cast<std::complex<double>>() * y)(0);
          };
          const auto hij = frf(di, j), hji = frf(dj, i), modal = m.receptance(i, j, w);
          // Scale: the sum of the modal terms' magnitudes (|H| can cancel to ~0).
          double scale = 0.0;
          for (Eigen::Index q = 0; q < m.shapes.cols(); ++q) {
            const double wq = 2 * kPi * m.frequencyHz[static_cast<std::size_t>(q)];
            scale += std::abs(m.shapes(i, q) * m.shapes(j, q)) /
                     std::abs(std::complex<double>(wq * wq - w * w, 2 * m.zeta[static_cast<std::size_t>(q)] * wq * w));
          }
          EXPECT_LE(std::abs(hij - hji), 1e-9 * scale) << i << "," << j << " at " << w / 2 / kPi << " Hz";
          EXPECT_LE(std::abs(hij - modal), 1e-9 * scale) << i << "," << j;
        }
      }
    }
  }
}

// Static compliance at the driving point is 1/k_lat for every specimen with
// static data (thesis §1: the sum of the modal compliances); tyres keep the
// ring modal masses of eq. 45 with shapes normalised at point 100 (§5.3), so
// the driving-point modal stiffness of mode k is C_k = m_k w_k^2 (eq. 46).
TEST(SpatialSpecimens, StaticComplianceAndTyreModalMasses) {
  for (const auto& e : specimenCatalogue()) {
    if (e.modes.empty()) continue;
    const auto m = modalSpecimen(e.key).value();
    const Eigen::Index d = m.excitedDof;
    if (e.statics) {
      EXPECT_NEAR(m.staticCompliance(d, d) * e.statics->lateralStiffness, 1.0, 1e-12) << e.key;
    }
    if (e.kind == "tyre") {
      EXPECT_EQ(m.dofs[static_cast<std::size_t>(d)], core::parseDof("100:+Z").value());
      for (std::size_t r = 0; r < e.modes.size(); ++r) {
        const double phi = m.shapes(d, static_cast<Eigen::Index>(r));
        EXPECT_NEAR(1.0 / (phi * phi), e.modalMass[r], 1e-12 * e.modalMass[r]) << e.key << " mode " << r;
      }
    }
  }
}

// Every tabulated mode shows at the driving point with at least 5% of its
// largest component: a hit there excites it, so the thesis's campaigns
// (hammer fixed at the driving point, accelerometer roving) see every mode.
TEST(SpatialSpecimens, TheDrivingPointExcitesEveryTabulatedMode) {
  for (const auto& key : modalKeys()) {
    const auto m = modalSpecimen(key).value();
    for (std::size_t r = 0; r < m.tabulatedModes; ++r) {
      const auto col = m.shapes.col(static_cast<Eigen::Index>(r));
      EXPECT_GT(std::abs(col(m.excitedDof)), 0.05 * col.cwiseAbs().maxCoeff())
          << key << " mode " << r << " (" << m.modeShapes[r] << ") at " << core::formatDof(m.dofs[m.excitedDof]);
    }
  }
}

// ---------------------------------------------------------------- shapes against the thesis's words

struct ShapeProbe {
  const ModalSpecimen& m;
  const core::geometry::MeshTemplate& t;
  Eigen::Index mode;

  double at(int node, core::Direction d) const {
    auto row = m.findDof(core::Dof{node, d, false});
    EXPECT_TRUE(row.ok()) << node;
    return row ? row->sign * m.shapes(row->row, mode) : 0.0;
  }
  // Share of the shape's squared norm in one direction.
  double share(core::Direction d) const {
    double in = 0.0, all = 0.0;
    for (std::size_t j = 0; j < m.dofs.size(); ++j) {
      const double v = m.shapes(static_cast<Eigen::Index>(j), mode);
      all += v * v;
      if (m.dofs[j].direction == d) in += v * v;
    }
    return in / all;
  }
  // Share of the squared norm on a group's nodes.
  double groupShare(const std::string& group) const {
    const auto* g = t.group(group);
    EXPECT_NE(g, nullptr) << group;
    double in = 0.0, all = 0.0;
    for (std::size_t j = 0; j < m.dofs.size(); ++j) {
      const double v = m.shapes(static_cast<Eigen::Index>(j), mode);
      all += v * v;
      if (g && std::find(g->nodes.begin(), g->nodes.end(), m.dofs[j].node) != g->nodes.end()) in += v * v;
    }
    return in / all;
  }
  // Mean of one component over a group's nodes.
  double groupMean(const std::string& group, core::Direction d) const {
    const auto* g = t.group(group);
    double s = 0.0;
    for (int n : g->nodes) s += at(n, d);
    return s / static_cast<double>(g->nodes.size());
  }
};

struct Probed {
  ModalSpecimen m;
  const core::geometry::MeshTemplate* t;
  ShapeProbe mode(const std::string& shape) const {
    const SpecimenEntry* e = findSpecimen(m.key);
    for (std::size_t r = 0; r < e->modes.size(); ++r)
      if (e->modes[r].shape == shape) return ShapeProbe{m, *t, static_cast<Eigen::Index>(r)};
    ADD_FAILURE() << m.key << " has no mode " << shape;
    return ShapeProbe{m, *t, 0};
  }
};

Probed probe(const std::string& key) {
  Probed p{modalSpecimen(key).value(), nullptr};
  p.t = core::geometry::findMeshTemplate(p.m.meshTemplate);
  return p;
}

using core::Direction;

// §2.1, §2.2: lateral modes move in z, largest away from the clamp;
// torsional modes move the upper and lower parts in opposition (frame B: the
// lower part against the tail, the thick upper tube almost still).
TEST(SpatialShapes, FramesLateralLongitudinalTorsional) {
  for (const char* key : {"frame-a-front-constrained", "frame-a-rear-constrained", "frame-b-front-constrained",
                          "frame-b-rear-constrained", "frame-c-without-engine", "frame-c-with-engine"}) {
    SCOPED_TRACE(key);
    const auto p = probe(key);
    const bool rear = std::string(key).find("rear") != std::string::npos;
    const auto lat = p.mode("Lateral");
    EXPECT_GT(lat.share(Direction::Z), 0.95);
    const std::string clamp = rear ? "swing-arm pivot" : "steering head";
    const std::string loaded = rear ? "steering head" : "swing-arm pivot";
    EXPECT_GT(std::abs(lat.groupMean(loaded, Direction::Z)), 10 * std::abs(lat.groupMean(clamp, Direction::Z)));
    if (rear) {
      // "the steering head exhibits the maximum displacement" (§2.1).
      const double headZ = std::max(std::abs(lat.at(1, Direction::Z)), std::abs(lat.at(2, Direction::Z)));
      for (const auto& n : p.t->mesh.nodes)
        EXPECT_LE(std::abs(lat.at(n.label, Direction::Z)), headZ * (1 + 1e-12)) << "node " << n.label;
    }
    const auto tors = p.mode("Torsional");
    if (std::string(key).rfind("frame-b", 0) == 0) {
      EXPECT_LT(tors.groupMean("lower", Direction::Z) * tors.groupMean("tail", Direction::Z), 0.0)
          << "lower part and tail in opposition";
      EXPECT_LT(std::abs(tors.at(21, Direction::Z)), 0.3 * std::abs(tors.groupMean("lower", Direction::Z)))
          << "the square upper tube almost still";
    } else {
      EXPECT_LT(tors.groupMean("upper", Direction::Z) * tors.groupMean("lower", Direction::Z), 0.0)
          << "upper and lower parts in opposition";
    }
  }
  const auto a = probe("frame-a-front-constrained");
  EXPECT_GT(a.mode("Longitudinal").share(Direction::Y), 0.9);
}

// §3.1, §3.2: bending (lateral, the hub moves most) and torsion (left and
// right stems move in opposition).
TEST(SpatialShapes, SwingArmsBendingAndTorsion) {
  for (const char* key : {"swing-arm-a", "swing-arm-b"}) {
    SCOPED_TRACE(key);
    const auto p = probe(key);
    const auto bend = p.mode("Bending");
    EXPECT_GT(bend.share(Direction::Z), 0.99);
    EXPECT_GT(std::abs(bend.groupMean("axle", Direction::Z)),
              10 * std::abs(bend.groupMean("swing-arm pivot", Direction::Z)));
    const auto tors = p.mode("Torsional");
    EXPECT_LT(tors.groupMean("left stem", Direction::X) * tors.groupMean("right stem", Direction::X), 0.0);
  }
}

// Chapter 4, §6.2, §6.3: lateral (z) and longitudinal (y) bending with the
// legs in phase; torsion with the legs in opposition in y; with the wheel,
// the wheel's own mode rotates it about its horizontal diameter while the
// fork is almost still.
TEST(SpatialShapes, ForksLegsInPhaseInOppositionAndWheelModes) {
  struct ForkCase {
    const char* key;
    std::string left, right;  // leg/blade groups
    int leftTip, rightTip;
  };
  const ForkCase cases[] = {
      {"fork-a-without-wheel", "left leg", "right leg", 9, 10},
      {"fork-b-with-wheel", "left leg", "right leg", 9, 10},
      {"bicycle-fork-carbon-without-wheel", "left blade", "right blade", 4, 8},
      {"bicycle-fork-steel-without-wheel", "left blade", "right blade", 4, 8},
      {"bicycle-fork-carbon-with-wheel", "left blade", "right blade", 4, 8},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.key);
    const auto p = probe(c.key);
    const SpecimenEntry* e = findSpecimen(c.key);
    for (const auto& mode : e->modes) {
      const auto s = p.mode(mode.shape);
      if (mode.shape == "Lateral") {
        EXPECT_GT(s.share(Direction::Z), 0.8);
        EXPECT_GT(s.at(c.leftTip, Direction::Z) * s.at(c.rightTip, Direction::Z), 0.0) << "legs in phase";
      } else if (mode.shape == "Longitudinal") {
        EXPECT_GT(s.share(Direction::Y) + s.share(Direction::X), 0.8);
        EXPECT_GT(s.at(c.leftTip, Direction::Y) * s.at(c.rightTip, Direction::Y), 0.0) << "legs in phase";
      } else if (mode.shape.find("orsional") != std::string::npos) {
        EXPECT_LT(s.at(c.leftTip, Direction::Y) * s.at(c.rightTip, Direction::Y), 0.0) << "legs in opposition";
        if (p.t->group("wheel")) {
          // §6.2: "the wheel follows rigidly ... a large deformation in the outer
          // points": front and rear of the rim move laterally in opposition.
          const auto& w = p.t->group("wheel")->nodes;
          EXPECT_LT(s.at(w[2], Direction::Z) * s.at(w[6], Direction::Z), 0.0);
          EXPECT_GT(s.groupShare("wheel"), 0.5);
        }
      } else {  // wheel modes
        EXPECT_GT(s.groupShare("wheel"), 0.95) << "the fork almost still";
        const auto& w = p.t->group("wheel")->nodes;
        EXPECT_LT(s.at(w[0], Direction::Z) * s.at(w[4], Direction::Z), 0.0)
            << "lowest and highest rim points in opposition: rotation about the horizontal diameter";
      }
    }
  }
  // Steel fork without wheel (§6.3): the first torsional mode is localised at
  // the tips, the second involves the whole blade.
  const auto steel = probe("bicycle-fork-steel-without-wheel");
  const auto t1 = steel.mode("First torsional"), t2 = steel.mode("Second torsional");
  EXPECT_LT(std::abs(t1.at(2, Direction::Y) / t1.at(4, Direction::Y)),
            0.5 * std::abs(t2.at(2, Direction::Y) / t2.at(4, Direction::Y)));
}

// §5.3: ring mode k has the lateral belt shape cos(k phi), so going round the
// six points its sign changes 2k times (k = 0 lateral, 1 camber, 2 C-shaped,
// 3 S-shaped: "even points and odd points move in opposition").
TEST(SpatialShapes, TyreRingModesHaveTheirWaveNumber) {
  for (const auto& key : tyreSpecimenKeys()) {
    SCOPED_TRACE(key);
    const auto p = probe(key);
    const int ks[] = {0, 1, 2, 3};
    const char* names[] = {"lateral", "camber", "C-shaped", "S-shaped"};
    for (int i = 0; i < 4; ++i) {
      const auto s = p.mode(names[i]);
      int changes = 0;
      for (int n = 0; n < 6; ++n) {
        const double a = s.at(100 + n, Direction::Z), b = s.at(100 + (n + 1) % 6, Direction::Z);
        if (a * b < 0) ++changes;
        EXPECT_NEAR(a / s.at(100, Direction::Z), std::cos(ks[i] * n * kPi / 3.0), 1e-12);
      }
      EXPECT_EQ(changes, 2 * ks[i]) << names[i];
    }
  }
}

// §6.1, Table 18 and Figure 46, for each bicycle: the words of the thesis
// turned into signs and shares of the lateral (z) motion.
TEST(SpatialShapes, BicycleModes) {
  for (const char* key : {"bicycle-steel", "bicycle-ergal", "bicycle-carbon-monocoque", "bicycle-carbon-banded"}) {
    SCOPED_TRACE(key);
    const auto p = probe(key);
    const int hub = 100, chainStay = 1, crank = 2, seatStay = 3, seat = 4, head = 6, forkTip = 16;
    const auto yaw = p.mode("Tire dominated - Yaw");
    EXPECT_LT(yaw.at(hub, Direction::Z) * yaw.at(head, Direction::Z), 0.0) << "rigid yaw: rear and front opposite";
    const auto roll = p.mode("Tire dominated - Roll");
    EXPECT_LT(roll.at(hub, Direction::Z) * roll.at(seat, Direction::Z), 0.0)
        << "rigid roll about a line near the top tube: below and above opposite";
    const auto tors = p.mode("Torsion");
    EXPECT_GT(tors.at(forkTip, Direction::Z) * tors.at(crank, Direction::Z), 0.0) << "fork tips with the crank set";
    EXPECT_LT(tors.at(forkTip, Direction::Z) * tors.at(seatStay, Direction::Z), 0.0) << "against the seat stays";
    EXPECT_LT(tors.at(forkTip, Direction::Z) * tors.at(chainStay, Direction::Z), 0.0) << "against the chain stays";
    const auto bend = p.mode("First bending");
    EXPECT_GT(bend.at(hub, Direction::Z) * bend.at(head, Direction::Z), 0.0) << "antinodes at hub and head";
    EXPECT_LT(bend.at(hub, Direction::Z) * bend.at(crank, Direction::Z), 0.0) << "a nodal line between";
    const auto fork = p.mode("Fork lateral");
    EXPECT_GT(fork.groupShare("fork"), 0.5);
    EXPECT_LT(fork.at(head, Direction::Z) * fork.at(seat, Direction::Z), 0.0) << "head and saddle in opposition";
    const auto second = p.mode("Second bending");
    EXPECT_LT(second.at(hub, Direction::Z) * second.at(crank, Direction::Z), 0.0) << "rear hub against crank set";
    EXPECT_LT(second.groupShare("fork"), 0.01) << "fork still";
    if (std::string(key) != "bicycle-carbon-banded") {
      const auto st = p.mode("Seat tube, rear frame");
      EXPECT_LT(st.groupShare("fork"), 0.01);
      EXPECT_GT(std::abs(st.at(seat, Direction::Z)), std::abs(st.at(head, Direction::Z)));
    }
  }
}

TEST(SpatialSpecimens, DofLabelsAreFoundWithTheirSignOrNamed) {
  const auto m = modalSpecimen("fork-a-with-wheel").value();
  auto plus = m.findDof("12:+Y");
  ASSERT_TRUE(plus.ok());
  EXPECT_EQ(m.dofs[static_cast<std::size_t>(plus->row)], core::parseDof("12:+Y").value());
  EXPECT_EQ(plus->sign, 1.0);
  auto minus = m.findDof("12:-Y");
  ASSERT_TRUE(minus.ok());
  EXPECT_EQ(minus->row, plus->row);
  EXPECT_EQ(minus->sign, -1.0);
  auto missing = m.findDof("99:+Z");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("99:+Z"), std::string::npos) << missing.error().describe();
  EXPECT_NE(missing.error().where.find("fork-a-with-wheel"), std::string::npos);
  EXPECT_FALSE(m.findDof("twelve").ok());
  // The driven system at a point with -Y is the +Y one with the force
  // reversed: the static response to a unit force flips sign.
  const auto a = m.drivenSystem(plus->row, 1.0), b = m.drivenSystem(plus->row, -1.0);
  const core::Vector ya = a.system.stiffness.partialPivLu().solve(core::Vector::Unit(a.system.dofCount(), 0));
  const core::Vector yb = b.system.stiffness.partialPivLu().solve(core::Vector::Unit(b.system.dofCount(), 0));
  const core::Vector xa = a.output * ya, xb = b.output * yb;
  EXPECT_TRUE(xa.isApprox(-xb, 1e-9));
  EXPECT_NEAR(xa(plus->row), m.staticCompliance(plus->row, plus->row), 1e-9 * xa(plus->row));
}

}  // namespace
}  // namespace mozzi::devices::sim
