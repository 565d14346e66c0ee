// mozzi-cli tire / wheelchair as a user runs them: CSV in, numbers out.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/cli/command.h"
#include "cli_run.h"
#include "core/tire/magic_formula.h"

namespace mozzi::cli {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string tempPath(const std::string& name) {
  return std::string(MOZZI_BINARY_DIR) + "/tire_cli_" + name;
}

// First-order tyre, sigma = 0.15 m, a = 0.07 m, V = 5 km/h, 10 cycles at
// each §5.1 frequency, 200 Hz, no noise.
std::string writeYawTest() {
  const std::string path = tempPath("yaw.csv");
  std::ofstream f(path);
  f << std::setprecision(17) << "# synthetic harmonic yaw test\nfrequency_hz,time_s,yaw_rate_rad_s,lateral_force_n\n";
  const double V = 5.0 / 3.6, a = 0.07, sigma = 0.15, psi0 = 1.5 * kPi / 180;
  for (double fr : {0.42, 0.84, 1.26, 1.68, 2.10}) {
    const double w = 2 * kPi * fr;
    const std::complex<double> h = 19500.0 * std::complex<double>(V, -w * a) / std::complex<double>(V, w * sigma);
    const int n = static_cast<int>(std::round(10 * 200.0 / fr));
    for (int i = 0; i < n; ++i) {
      const double t = i / 200.0;
      f << fr << "," << t << "," << psi0 * w * std::cos(w * t) << ","
        << std::abs(h) * psi0 * std::sin(w * t + std::arg(h)) << "\n";
    }
  }
  return path;
}

TEST(TireCli, RelaxationRecoversSigmaFromACsvTest) {
  const auto r = run({"tire", "relaxation", writeYawTest(), "--half-length", "0.07", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["mean_sigma_m"].get<double>(), 0.15, 1e-9);  // exact sines, 17-digit CSV
  EXPECT_EQ(j["points_in_band"].get<int>(), 3);
  EXPECT_EQ(j["points"].size(), 5u);
}

TEST(TireCli, RelaxationReportsBadInput) {
  EXPECT_EQ(run({"tire", "relaxation", writeYawTest()}).code, kExitUsage);  // no --half-length
  const auto missing = run({"tire", "relaxation", tempPath("absent.csv"), "--half-length", "0.07"});
  EXPECT_EQ(missing.code, kExitFailure);
  EXPECT_NE(missing.err.find("cannot open"), std::string::npos);
  const auto still = run({"tire", "relaxation", writeYawTest(), "--half-length", "0.07", "--speed", "0"});
  EXPECT_EQ(still.code, kExitFailure);
  EXPECT_NE(still.err.find("speed"), std::string::npos);
  const std::string bad = tempPath("bad.csv");
  std::ofstream(bad) << "frequency_hz,time_s,yaw_rate_rad_s,lateral_force_n\n1,0,0.1,abc\n";
  const auto parse = run({"tire", "relaxation", bad, "--half-length", "0.07"});
  EXPECT_EQ(parse.code, kExitFailure);
  EXPECT_NE(parse.err.find(":2"), std::string::npos) << parse.err;  // names the line
}

TEST(TireCli, PredictThesisTyreGivesTheEquation48Terms) {
  const auto r = run({"tire", "predict", "--thesis-tyre", "120/70 R17", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["pressures"].size(), 7u);
  const auto& p2 = j["pressures"][4];  // 2 bar
  EXPECT_DOUBLE_EQ(p2["pressure_bar"].get<double>(), 2.0);
  // eq. 48 by hand with Table 16/17 and the documented assumptions
  // (C = 13 x 1500 N/rad, lambda = 1): m = 1 - 19500 tan(1.5 deg)/4500.
  const double C = 19500, m = 1 - C * std::tan(1.5 * kPi / 180) / 4500.0;
  const double sigma = 0.070 * m + C * (1 / 1906e3 + 1 / 463e3 + 1 / 1239e3 + 1 / 4690e3);
  EXPECT_NEAR(p2["sigma_m"].get<double>(), sigma, 1e-12);
}

TEST(TireCli, RingPrintsModalStiffness) {
  const auto r = run({"tire", "ring", "--modes", "0:100:0.02,1:80:0.03", "--mass", "4", "--radius", "0.3", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double w0 = 2 * kPi * 100;
  EXPECT_NEAR(j["modes"][0]["modal_stiffness_n_per_m"].get<double>(), 3.2 * w0 * w0, 1e-6);  // eq. 46, m_0 = 0.8 x 4
  EXPECT_EQ(run({"tire", "ring", "--modes", "0:100", "--mass", "4", "--radius", "0.3"}).code, kExitFailure);
}

TEST(TireCli, SteadyGivesCorneringStiffnessAndRejectsNonMonotonicSweeps) {
  const std::string path = tempPath("sweep.csv");
  {
    std::ofstream f(path);
    f << std::setprecision(17) << "slip_deg,camber_deg,load_n,pressure_bar,force_n,torque_nm\n";
    for (int i = 0; i <= 5; ++i)
      f << i << ",0,400,4," << 4000.0 * i * kPi / 180 << "," << -30.0 * i * kPi / 180 << "\n";
    for (int i = 1; i <= 10; ++i)
      f << "0," << i << ",400,4," << 300.0 * i * kPi / 180 << "," << 2.0 * i * kPi / 180 << "\n";
  }
  const auto r = run({"tire", "steady", path, "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  bool slip = false, camber = false;
  for (const auto& s : j["sweeps"]) {
    if (s["sweep"] == "slip") {
      slip = true;
      EXPECT_NEAR(s["cornering_stiffness_n_per_rad"].get<double>(), 4000.0, 1e-6);  // exact linear data
      EXPECT_NEAR(s["aligning_torque_stiffness_nm_per_rad"].get<double>(), -30.0, 1e-8);
    } else {
      camber = true;
      EXPECT_NEAR(s["camber_stiffness_n_per_rad"].get<double>(), 300.0, 1e-6);
    }
  }
  EXPECT_TRUE(slip && camber);
  const std::string bad = tempPath("sweep_bad.csv");
  std::ofstream(bad) << "slip_deg,camber_deg,load_n,pressure_bar,force_n,torque_nm\n0,0,400,4,0,0\n2,0,400,4,10,1\n"
                        "1,0,400,4,5,1\n3,0,400,4,15,1\n4,0,400,4,20,1\n";
  const auto nm = run({"tire", "steady", bad});
  EXPECT_EQ(nm.code, kExitFailure);
  EXPECT_NE(nm.err.find("monotonic"), std::string::npos) << nm.err;
}

TEST(TireCli, SteadyMagicFormulaFitsOneSweepAndHoldsWhatItCannotDetermine) {
  // One two-sided slip sweep (-10..10 deg) at 1500 N, 2 bar, camber 0 from a
  // known set whose held coefficients equal the defaults: the free ones are
  // recovered (exact data, 17 digits: 1e-6 relative).
  namespace tr = core::tire;
  tr::MfLateralCoefficients p = tr::mfLateralDefaults();
  p[0] = 1.35, p[1] = 1.1, p[8] = 14.0;  // pCy1, pDy1, pKy1
  tr::MfAligningCoefficients q = tr::mfAligningDefaults();
  q[8] = 0.08;    // qDz1
  q[12] = 0.003;  // qDz6: with M_zr = 0 (qDz6 = 0) qBz9 has no effect and the covariance is singular
  const tr::MfConstants c{1500.0, 2e5, 0.3};
  const std::string path = tempPath("mf.csv");
  {
    std::ofstream f(path);
    f << std::setprecision(17) << "slip_deg,camber_deg,load_n,pressure_bar,force_n,torque_nm\n";
    for (int i = -10; i <= 10; ++i) {
      const double a = i * kPi / 180;
      f << i << ",0,1500,2," << tr::mfLateralForce(p, c, a, 0, 1500, 2e5) << ","
        << tr::mfAligningTorque(q, p, c, a, 0, 1500, 2e5) << "\n";
    }
  }
  const auto r = run({"tire", "steady", path, "--magic-formula", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out)["magic_formula"];
  EXPECT_NEAR(j["lateral"]["pKy1"]["value"].get<double>(), 14.0, 1e-6 * 14);
  EXPECT_NEAR(j["lateral"]["pDy1"]["value"].get<double>(), 1.1, 1e-6 * 1.1);
  EXPECT_NEAR(j["aligning"]["qDz1"]["value"].get<double>(), 0.08, 1e-6 * 0.08);
  EXPECT_FALSE(j["lateral"]["ppy1"]["free"].get<bool>());
  EXPECT_FALSE(j["aligning"]["qBz10"]["free"].get<bool>());
  // The user can hold more: qEz4 at its default 0 (its true value).
  const auto h = run({"tire", "steady", path, "--magic-formula", "--hold", "qEz4,pHy1", "--json"});
  ASSERT_EQ(h.code, kExitOk) << h.err;
  const auto k = nlohmann::json::parse(h.out)["magic_formula"];
  EXPECT_FALSE(k["aligning"]["qEz4"]["free"].get<bool>());
  EXPECT_FALSE(k["lateral"]["pHy1"]["free"].get<bool>());
  EXPECT_EQ(run({"tire", "steady", path, "--magic-formula", "--hold", "zz9"}).code, kExitUsage);
}

TEST(WheelchairCli, SteadyAndSensitivity) {
  const auto r = run({"wheelchair", "steady", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["radius_m"].get<double>(), 0.5);
  const auto s = run({"wheelchair", "sensitivity", "--stiffness", "aligning", "--json", "--duration", "12"});
  ASSERT_EQ(s.code, kExitOk) << s.err;
  const auto k = nlohmann::json::parse(s.out);
  ASSERT_EQ(k.size(), 3u);
  EXPECT_LT(k[0]["steady"]["radius_m"].get<double>(), k[2]["steady"]["radius_m"].get<double>());  // §7.4
  EXPECT_EQ(run({"wheelchair", "steady", "--speed", "0"}).code, kExitFailure);
  EXPECT_EQ(run({"wheelchair", "sensitivity"}).code, kExitUsage);
  const auto shortRun = run({"wheelchair", "sensitivity", "--stiffness", "cornering", "--duration", "8"});
  EXPECT_EQ(shortRun.code, kExitFailure);  // 2 cycles at 0.25 Hz
  EXPECT_NE(shortRun.err.find("3 cycles"), std::string::npos);
}

TEST(WheelchairCli, SlalomAmplitudeMatchesTheLinearisedModel) {
  // Independent route: the §7.2 equations linearised (small angles, wheel
  // speeds u, linear tyres) and solved in the frequency domain for the
  // differential torque T0 cos wt. With z = v - b r, I = I_z + 2 J_s w^2/R_w^2:
  //   i w z = -2 C_alpha z/(m u) - u r - b i w r
  //   i w I r = w T0/R_w + 2 (b C_alpha + C_M) z/u
  //   y = (u r/(i w) + v)/(i w)
  // The CLI integrates the nonlinear model in time. Neglected by the
  // linearisation: heading psi0 = 0.07 rad (psi0^2/6 < 0.1%) and wheel speeds
  // (r w/u)^2 < 0.1% at T0 = 2 N m; 1% allowed.
  const std::string hist = tempPath("slalom.csv");
  const auto r = run(
      {"wheelchair", "slalom", "--torque", "2", "--frequency", "0.25", "--duration", "16", "--out", hist, "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  using C = std::complex<double>;
  // WheelchairParameters defaults (core/stability/wheelchair_model.h).
  const double m = 110.0, u = 4.0 / 3.6, b = 0.13, Ca = 4000.0, Cm = 30.0, Rw = 0.305, halfTrack = 0.28;
  const double inertia = 7.0 + 2 * 0.10 * halfTrack * halfTrack / (Rw * Rw), w = 2 * kPi * 0.25;
  const C iw(0.0, w);
  const C zPerR = -(u + iw * b) / (iw + 2 * Ca / (m * u));
  const C rHat = halfTrack * 2.0 / Rw / (iw * inertia - 2 * (b * Ca + Cm) / u * zPerR);
  const C yHat = (u * rHat / iw + zPerR * rHat + b * rHat) / iw;
  EXPECT_NEAR(j["lateral_amplitude_m"].get<double>(), std::abs(yHat), 0.01 * std::abs(yHat));
  std::printf("slalom lateral amplitude: CLI %.5f m, linearised %.5f m\n", j["lateral_amplitude_m"].get<double>(),
              std::abs(yHat));
  // Right slip mean positive, left negative (§7.3).
  EXPECT_GT(j["slip_mean_right_rad"].get<double>(), 0.0);
  EXPECT_LT(j["slip_mean_left_rad"].get<double>(), 0.0);
  // The history: header, one row per 10 ms, torques T_R - T_L = 2 cos(wt).
  std::ifstream f(hist);
  std::string line;
  std::getline(f, line);
  EXPECT_EQ(line.rfind("t_s,x_m,y_m,psi_rad,", 0), 0u);
  int rows = 0;
  double t = 0, tr = 0, tl = 0;
  while (std::getline(f, line)) {
    ++rows;
    std::sscanf(line.c_str(), "%lf,%*f,%*f,%*f,%*f,%*f,%*f,%*f,%*f,%*f,%*f,%lf,%lf", &t, &tr, &tl);
  }
  EXPECT_EQ(rows, 1601);
  EXPECT_NEAR(t, 16.0, 1e-9);
  EXPECT_NEAR(tr - tl, 2.0 * std::cos(w * 16.0), 1e-9);
  // Bad input: no frequency, too short to settle and measure.
  const auto still = run({"wheelchair", "slalom", "--frequency", "0"});
  EXPECT_EQ(still.code, kExitFailure);
  EXPECT_NE(still.err.find("--frequency = 0 is out of range"), std::string::npos) << still.err;
  EXPECT_EQ(run({"wheelchair", "slalom", "--duration", "10"}).code, kExitFailure);  // 2.5 cycles at 0.25 Hz
}

TEST(WheelchairCli, PrescribedYawRateAndWholeTyreScaling) {
  // Round trip: the default steady turn (6 N m) and the path it produces,
  // prescribed with --yaw-rate, must need the same 6 N m (Newton vs closed
  // form; JSON prints 17 significant digits, so 1e-9 is rounding).
  const auto r = run({"wheelchair", "steady", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  char rate[64];
  std::snprintf(rate, sizeof rate, "%.17g", j["yaw_rate_rad_s"].get<double>());
  const auto p = run({"wheelchair", "steady", "--yaw-rate", rate, "--json"});
  ASSERT_EQ(p.code, kExitOk) << p.err;
  const auto k = nlohmann::json::parse(p.out);
  EXPECT_NEAR(k["differential_torque_nm"].get<double>(), 6.0, 6e-9);
  EXPECT_NEAR(k["slip_right_rad"].get<double>(), j["slip_right_rad"].get<double>(),
              1e-9 * std::abs(j["slip_right_rad"].get<double>()));
  EXPECT_EQ(run({"wheelchair", "steady", "--yaw-rate", "1", "--torque", "3"}).code, kExitUsage);
  EXPECT_EQ(run({"wheelchair", "steady", "--yaw-rate", "10"}).code, kExitFailure);  // inner wheel stopped
  // Whole tyre halved (trail held): slip angles exactly double (the model's
  // closed form, docs/validation/tire.md).
  const auto t = run({"wheelchair", "sensitivity", "--stiffness", "tyre", "--json", "--duration", "12"});
  ASSERT_EQ(t.code, kExitOk) << t.err;
  const auto c = nlohmann::json::parse(t.out);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_NEAR(c[0]["steady"]["slip_left_rad"].get<double>() / c[1]["steady"]["slip_left_rad"].get<double>(), 2.0, 2e-9);
}

}  // namespace
}  // namespace mozzi::cli
