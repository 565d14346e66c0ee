// What the identification page shows of a selection, without a widget
// (core/modal/pole_selection.h): the modal table's derived columns, the
// residual per FRF, the same-mode warnings, and the removal of an exponential
// window's decay (the CLI's --store and the page's table and save use it).
#include "core/modal/pole_selection.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/modal/modal_model.h"
#include "core/signal/window.h"

namespace mozzi::core::modal {
namespace {

// One mode at 50 Hz, zeta 0.02, real residues 1, 2, -1 over three responses:
// a real (normal) mode, so MPC is 1, MPD 0 and complexity 0; eta = 2 zeta.
TEST(PoleSelection, ModalTableOfARealMode) {
  ModalModel m;
  m.responses = {Dof{1, Direction::Z}, Dof{2, Direction::Z}, Dof{3, Direction::Z}};
  m.references = {m.responses[0]};
  Mode mode;
  mode.pole = poleFromFrequencyDamping(50.0, 0.02);
  mode.residue = ComplexMatrix(3, 1);
  // Receptance residues of a real mode are purely imaginary: R = phi phi_ref / (2 i omega_d).
  mode.residue << Complex(0, -1.0), Complex(0, -2.0), Complex(0, 1.0);
  m.modes.push_back(mode);
  auto rows = modalTableRows(m, {0.01}, {0.001});
  ASSERT_TRUE(rows.ok()) << rows.error().describe();
  ASSERT_EQ(rows->size(), 1u);
  const auto& r = (*rows)[0];
  EXPECT_NEAR(r.frequencyHz, 50.0, 1e-12);
  EXPECT_NEAR(r.zeta, 0.02, 1e-14);
  EXPECT_DOUBLE_EQ(r.eta, 2.0 * r.zeta);
  EXPECT_NEAR(r.mpc, 1.0, 1e-12);
  EXPECT_NEAR(r.mpdDegrees, 0.0, 1e-9);
  EXPECT_NEAR(r.complexity, 0.0, 1e-12);
  ASSERT_TRUE(r.frequencyStdHz && r.zetaStd && r.etaStd);
  EXPECT_DOUBLE_EQ(*r.etaStd, 0.002);
}

// Synthesis = measured x (1 + 0.1 i) on FRF (0, 0), exact elsewhere: residual
// |0.1 i| = 0.1 there, 0 elsewhere; a band with no line is an error.
TEST(PoleSelection, ResidualPerFrfIsTheRelativeErrorOverTheBand) {
  FrfMatrix a;
  a.frequencyHz = Vector::LinSpaced(11, 0.0, 10.0);
  a.responses = {Dof{1, Direction::Z}, Dof{2, Direction::Z}};
  a.references = {a.responses[0]};
  a.h.push_back(ComplexMatrix::Constant(11, 2, Complex(1.0, 2.0)));
  FrfMatrix b = a;
  b.h[0].col(0) *= Complex(1.0, 0.1);
  auto r = residualPerFrf(a, b, 2.0, 8.0);
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR((*r)(0, 0), 0.1, 1e-15);
  EXPECT_EQ((*r)(1, 0), 0.0);
  EXPECT_FALSE(residualPerFrf(a, b, 20.0, 30.0).ok());
}

// A window of tau = 0.5 s adds 1/tau = 2 1/s to every decay: removing it gives
// back the poles put in (core::signal's closed forms, to rounding), for table
// rows and stored modes alike; tau = 0 changes nothing; a pole less damped
// than the window itself cannot be corrected and the error names the mode.
TEST(PoleSelection, RemovingTheExponentialWindowGivesBackTheTruePoles) {
  const double tau = 0.5;
  const double f[2] = {22.3, 67.2}, z[2] = {0.024, 0.059};
  std::vector<ModalTableRow> rows(2);
  io::ModalTable table;
  table.modes.resize(2);
  for (int i = 0; i < 2; ++i) {
    auto w = signal::applyExponentialWindowDamping({f[i], z[i]}, tau).value();
    // The bias is about 1 / (tau omega): 0.014 on 0.024 at 22.3 Hz, 0.0047 on 0.059 at 67.2 Hz.
    EXPECT_NEAR(w.zeta - z[i], 1.0 / (tau * 2.0 * M_PI * f[i]), 0.02 / (tau * 2.0 * M_PI * f[i]));
    rows[static_cast<std::size_t>(i)] = {w.naturalFrequencyHz, w.zeta, 2 * w.zeta, std::nullopt, 1e-4,
                                         std::nullopt,         1.0,    0.0,        0.0};
    table.modes[static_cast<std::size_t>(i)].frequencyHz = w.naturalFrequencyHz;
    table.modes[static_cast<std::size_t>(i)].dampingRatio = w.zeta;
  }
  auto unchanged = rows;
  ASSERT_TRUE(removeExponentialWindow(unchanged, 0.0).ok());
  EXPECT_EQ(unchanged[0].zeta, rows[0].zeta);
  ASSERT_TRUE(removeExponentialWindow(rows, tau).ok());
  ASSERT_TRUE(removeExponentialWindow(table, tau).ok());
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(rows[i].frequencyHz, f[i], 1e-9 * f[i]);
    EXPECT_NEAR(rows[i].zeta, z[i], 1e-9 * z[i]);
    EXPECT_DOUBLE_EQ(rows[i].eta, 2.0 * rows[i].zeta);
    EXPECT_DOUBLE_EQ(*rows[i].etaStd, 2e-4);
    EXPECT_EQ(table.modes[i].frequencyHz, rows[i].frequencyHz);
    EXPECT_EQ(table.modes[i].dampingRatio, rows[i].zeta);
  }
  std::vector<ModalTableRow> light(1);
  light[0].frequencyHz = 100.0;
  light[0].zeta = 0.001;  // decay 0.63 1/s < 1/tau
  auto e = removeExponentialWindow(light, tau);
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().message.find("mode 1"), std::string::npos) << e.error().describe();
}

// Two chosen poles 0.16 Hz apart at 1 Hz resolution are one mode (the
// 958.42 / 958.58 Hz case): one warning naming both; a third far away none.
TEST(PoleSelection, WarnsAboutTwoPolesOfOneMode) {
  SameModeCriteria c;
  c.resolutionHz = 1.0;
  const std::vector<ModeCandidate> chosen = {{958.42, {}}, {958.58, {}}, {1200.0, {}}};
  const auto w = selectionWarnings(chosen, c);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].first, 0u);
  EXPECT_EQ(w[0].second, 1u);
  EXPECT_NE(w[0].text.find("958.42"), std::string::npos) << w[0].text;
  EXPECT_NE(w[0].text.find("958.58"), std::string::npos) << w[0].text;
}

}  // namespace
}  // namespace mozzi::core::modal
