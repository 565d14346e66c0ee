// mozzi-cli twist / mozzi / stiffness / fork as a user runs them: documented
// CSV inputs (docs/cli/stiffness.md), thesis numbers in the output, exit codes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/cli/command.h"
#include "cli_run.h"
#include "core/io/csv/csv_exchange.h"

namespace mozzi::cli {
namespace {

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = std::string(MOZZI_BINARY_DIR) + "/stiffness_cli_" + name;
  std::ofstream(path) << text;
  return path;
}

// notes.md eq. 5 example: the axis crosses z = 0 at x = -0.10 m, so with the load
// at (0, -0.5) ... checked through the JSON point/direction.
TEST(StiffnessCli, TwistStaticSingleLoadJson) {
  const auto f = writeTemp("static.csv",
                           "# notes.md eq. 5 example\nsensor,0.2,-0.3\nsensor,0,-0.3\nsensor,0,0\nload,0,-0.5\n"
                           "force_N,d1_m,d2_m,d3_m\n300,1.0e-3,0.6e-3,0.2e-3\n");
  const auto r = run({"twist", "static", f, "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double pu = j["axis"]["point_m"][0], pv = j["axis"]["point_m"][1];
  const double du = j["axis"]["direction"][0], dv = j["axis"]["direction"][1];
  // Crossing of z = 0 (v = 0) at x = -0.10 m.
  EXPECT_NEAR(pu + (0.0 - pv) / dv * du, -0.10, 1e-12);
  // x_lat at (0, -0.5): plane 0.2 mm + 2 x - 1.3333 z [mm] -> 0.8667 mm; k_lat = 300 / x_lat.
  EXPECT_NEAR(j["lateral_stiffness_N_per_m"].get<double>(), 300.0 / 0.8666666666666667e-3, 1e-3);
}

TEST(StiffnessCli, TwistStaticRampTable) {
  // Ramp of +-300 N, k_lat = 167 kN/m at the load point, rigid rotation about z = -0.1 (beta = 90 deg).
  std::ostringstream csv;
  csv.precision(17);  // round-trip doubles, so the exact synthetic values come back
  csv << "sensor,0.2,-0.3\nsensor,0,-0.3\nsensor,0,0\nsensor,0.2,0\nload,0.1,-0.651\n";
  for (int k = 0; k <= 20; ++k) {
    const double f = -300 + 30 * k;
    const double theta = f / 167e3 / 0.551;  // arm 0.551 m from z = -0.1 to z = -0.651
    csv << f;
    for (double z : {-0.3, -0.3, 0.0, 0.0}) csv << "," << theta * (-(z + 0.1));
    csv << "\n";
  }
  const auto f = writeTemp("ramp.csv", csv.str());
  const auto r = run({"twist", "static", f, "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["lateral_stiffness_N_per_m"].get<double>(), 167e3, 1e-3);
  EXPECT_NEAR(j["twist_arm_m"].get<double>(), 0.551, 1e-9);
  EXPECT_NEAR(j["twist_stiffness_Nm_per_rad"].get<double>(), 167e3 * 0.551 * 0.551, 1e-3);
}

TEST(StiffnessCli, TwistDynamicAndModal) {
  const auto d = writeTemp("dyn.csv",
                           "sensor,0.2,-0.3\nsensor,0,-0.3\nsensor,0,0\nload,0,-0.5\n"
                           "freq_Hz,A1,phi1,A2,phi2,A3,phi3\n5,1.0e-3,10,0.6e-3,10,0.2e-3,10\n"
                           "10,1.0e-3,10,0.6e-3,100,0.2e-3,10\n");
  const auto r = run({"twist", "dynamic", d, "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.size(), 2u);
  EXPECT_EQ(j[0]["method"], "in-phase");
  EXPECT_EQ(j[1]["method"], "three-instant");
  // Modal: receptance given directly, in phase at 67 Hz.
  const auto m = writeTemp("modal.csv",
                           "sensor,0.2,-0.3\nsensor,0,-0.3\nsensor,0,0\n"
                           "60,1e-6,0,0.6e-6,0,0.2e-6,0\n70,1e-6,0,0.6e-6,0,0.2e-6,0\n");
  const auto r2 = run({"twist", "modal", m, "--freq", "67", "--type", "receptance"});
  ASSERT_EQ(r2.code, kExitOk) << r2.err;
  EXPECT_NE(r2.out.find("in-phase case"), std::string::npos);
  EXPECT_EQ(run({"twist", "modal", m}).code, kExitUsage);                     // --freq missing
  EXPECT_EQ(run({"twist", "modal", m, "--freq", "500"}).code, kExitFailure);  // outside band
}

TEST(StiffnessCli, MozziScrewAxisJson) {
  // notes.md example: w = (0.001, 0.002, 0.010), d_O = (0.5, -0.2, 0.3) mm.
  std::ostringstream csv;
  csv << "x,y,z,dx,dy,dz\n";
  const double w[3] = {0.001, 0.002, 0.010}, dO[3] = {0.5e-3, -0.2e-3, 0.3e-3};
  const double pts[4][3] = {{0.2, 0, -0.3}, {0, 0, -0.3}, {0, 0, 0}, {0.2, 0.05, 0}};
  csv.precision(17);
  for (const auto& p : pts) {
    const double c[3] = {w[1] * p[2] - w[2] * p[1], w[2] * p[0] - w[0] * p[2], w[0] * p[1] - w[1] * p[0]};
    csv << p[0] << "," << p[1] << "," << p[2] << "," << dO[0] + c[0] << "," << dO[1] + c[1] << "," << dO[2] + c[2]
        << "\n";
  }
  const auto f = writeTemp("mozzi.csv", csv.str());
  const auto r = run({"mozzi", f, "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["pitch_m_per_rad"].get<double>(), 0.0295238095238095, 1e-12);
  EXPECT_NEAR(j["point_m"][0].get<double>(), 0.0247619047619048, 1e-12);
  // Collinear points: exit 1 with the reason.
  const auto bad = writeTemp("collinear.csv", "0,0,0,0,0,1e-3\n0.1,0,0,0,0,2e-3\n0.2,0,0,0,0,3e-3\n");
  const auto rb = run({"mozzi", bad});
  EXPECT_EQ(rb.code, kExitFailure);
  EXPECT_NE(rb.err.find("collinear"), std::string::npos);
  EXPECT_EQ(run({"mozzi", "/nonexistent.csv"}).code, kExitFailure);
}

// Table 13 through the command line: 35 and 6 kNm/rad.
TEST(StiffnessCli, DecomposeForkTable13) {
  const auto r = run({"stiffness", "decompose", "--k-twist", "22330.3", "--a-twist", "0.452", "--a-bend", "0.528",
                      "--a-tors", "0.083", "--fork", "--alpha-deg", "41.2", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["bending_stiffness_Nm_per_rad"].get<double>(), 35e3, 500);
  EXPECT_NEAR(j["torsion_stiffness_Nm_per_rad"].get<double>(), 6e3, 500);
  EXPECT_EQ(run({"stiffness", "decompose", "--k-twist", "1"}).code, kExitUsage);
  EXPECT_EQ(run({"stiffness", "decompose", "--k-twist", "1", "--a-twist", "0.5", "--a-bend", "0.5", "--a-tors", "0.1",
                 "--fork", "--alpha-deg", "0"})
                .code,
            kExitFailure);
}

// Table 12 and §6.4 through the command line.
TEST(StiffnessCli, ForkLumpedAndBicycle) {
  const auto r = run({"fork", "lumped", "--k", "28000", "--l1", "0.670", "--l2", "0.846", "--wheel-centre", "0.265",
                      "--mass", "11", "--wheel-inertia", "0.278", "--freq", "22.3", "--zeta", "0.024", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["model2"]["stiffness_Nm_per_rad"].get<double>(), 78.4e3, 0.002 * 78.4e3);
  EXPECT_NEAR(j["model3"]["inertia_kgm2"].get<double>(), 1.426, 0.0005);
  const auto b = run({"fork",
                      "bicycle",
                      "--fork-mass",
                      "0.393",
                      "--wheel-mass",
                      "1.334",
                      "--wheel-radius",
                      "0.35",
                      "--hub-mass",
                      "0.094",
                      "--hub-radius",
                      "0.004",
                      "--hub-length",
                      "0.225",
                      "--tip-distance",
                      "0.06",
                      "--f-tors-wheel",
                      "19.3",
                      "--eta-tors-wheel",
                      "0.1004",
                      "--f-tors-alone",
                      "191.2",
                      "--f-bend-wheel",
                      "21.3",
                      "--eta-bend-wheel",
                      "0.0424",
                      "--f-bend-alone",
                      "64",
                      "--json"});
  ASSERT_EQ(b.code, kExitOk) << b.err;
  const auto jb = nlohmann::json::parse(b.out);
  EXPECT_NEAR(jb["torsion"]["stiffness_with_wheel_Nm_per_rad"].get<double>(), 1208.0, 0.002 * 1208.0);
  EXPECT_EQ(run({"fork", "lumped"}).code, kExitUsage);
  EXPECT_EQ(run({"fork", "nothing"}).code, kExitUsage);
}

// Modal axis from FRFs in the shared CSV exchange format (core/io/csv): three
// accelerances of one real mode shape; the in-phase axis is the shape's axis
// (the notes.md eq. 5 plane, crossing z = 0 at x = -0.10 m).
TEST(StiffnessCli, TwistModalReadsTheSharedFrfCsv) {
  core::FrfMatrix frf;
  frf.type = core::FrfType::Accelerance;
  frf.frequencyHz = core::Vector::LinSpaced(11, 60.0, 70.0);
  for (int i = 0; i < 3; ++i) frf.responses.push_back(core::Dof{21 + i, core::Direction::Y, false});
  frf.references.push_back(core::Dof{1, core::Direction::Y, false});
  const double shape[3] = {1.0e-3, 0.6e-3, 0.2e-3};
  core::ComplexMatrix h(11, 3);
  for (int k = 0; k < 11; ++k) {
    const double r = frf.frequencyHz(k) / 65.0;
    const core::Complex q = 1.0 / core::Complex(1 - r * r, 0.04 * r);
    for (int i = 0; i < 3; ++i) h(k, i) = q * shape[i];
  }
  frf.h.push_back(h);
  const std::string frfPath = std::string(MOZZI_BINARY_DIR) + "/stiffness_cli_frf.csv";
  ASSERT_TRUE(core::io::csv::exportFrfCsv(frf, frfPath).ok());
  const auto geom = writeTemp("geom.csv", "sensor,0.2,-0.3\nsensor,0,-0.3\nsensor,0,0\nload,0,-0.5\n");
  const auto r =
      run({"twist", "modal", geom, "--frf", frfPath, "--freq", "65", "--responses", "21:+Y,22:+Y,23:+Y", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["method"], "in-phase");
  const double pu = j["axis"]["point_m"][0], pv = j["axis"]["point_m"][1];
  const double du = j["axis"]["direction"][0], dv = j["axis"]["direction"][1];
  EXPECT_NEAR(pu + (0.0 - pv) / dv * du, -0.10, 1e-9);
  EXPECT_EQ(run({"twist", "modal", geom, "--frf", frfPath, "--freq", "65", "--responses", "99:+Y,22:+Y,23:+Y"}).code,
            kExitFailure);
}

}  // namespace
}  // namespace mozzi::cli
