// Validation of the simulated Mototiremeter (thesis §1.8, §1.9, §5.1): its
// acquisition stream, analysed by core/tire, gives back the tyre it was
// configured with. Harmonic yaw (1.5 deg, 0.42..2.10 Hz, 10 cycles each, 5 km/h)
// -> relaxation length by the phase-lag method (relaxation_length.h, thesis
// eq. 28 corrected); steady side-slip and camber sweeps -> cornering and
// camber stiffness by the slope at the origin (steady_state.h, appendix 2).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/tire/relaxation_length.h"
#include "core/tire/relaxation_prediction.h"
#include "core/tire/ring_model.h"
#include "core/tire/steady_state.h"
#include "core/tire/thesis_tyres.h"
#include "devices/sim/sim_drivers.h"
#include "devices_campaign.h"

namespace mozzi::devices {
namespace {

using namespace std::chrono_literals;
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

ChannelConfig channel(int input, const char* name, core::signal::TransducerKind kind, double mvPerUnit,
                      const char* unit) {
  ChannelConfig c;
  c.input = input;
  c.name = name;
  c.rangeCode = 0;  // +/-10 V
  c.transducer = core::signal::Transducer{kind, "", "", mvPerUnit, unit, false};
  return c;
}

std::optional<testing::Acquired> acquire(AcquisitionConfig cfg) {
  cfg.parameters["sim.realtime"] = false;
  auto dev = sim::makeTyreTesterDriver()->create(DeviceDescriptor{"sim-tyre-tester", "", 0, 0, "", "sim:0"}).value();
  auto run = testing::acquire(*dev, cfg, 60s);
  if (run) {
    EXPECT_EQ(run->end.reason, EndReason::Completed);
    EXPECT_TRUE(run->overloads.empty());
  }
  return run;
}

// The thesis yaw programme on one tyre; sigma from the analysis of the stream.
core::tire::HarmonicYawResult harmonicYaw(const std::string& tyre, double pressureBar, double sigma,
                                          double* halfLength) {
  const double fs = 200.0;
  const double freqs[] = {0.42, 0.84, 1.26, 1.68, 2.10};
  double duration = 0.0;
  for (double f : freqs) duration += 10.0 / f;
  AcquisitionConfig cfg;
  cfg.sampleRateHz = fs;
  cfg.scanCount = static_cast<std::int64_t>(std::ceil(duration * fs));
  cfg.channels = {channel(0, "gyro", core::signal::TransducerKind::AngularRate, 1000.0, "rad/s"),
                  channel(1, "Fy", core::signal::TransducerKind::Force, 2.0, "N")};
  cfg.parameters["tyre"] = tyre;
  cfg.parameters["tyre.pressure_bar"] = pressureBar;
  if (sigma > 0) cfg.parameters["tyre.relaxation_length"] = sigma;
  auto run = acquire(cfg);
  EXPECT_TRUE(run.has_value());
  EXPECT_EQ(run->triggers.size(), 5u);
  std::vector<core::tire::HarmonicYawRecord> records;
  for (std::size_t k = 0; k < run->triggers.size(); ++k) {
    const double f = run->triggers[k].level;  // the tester marks each step with its frequency
    // Drop the first cycle: the start of each step excites the lag's transient.
    const auto start = run->triggers[k].sample + static_cast<std::int64_t>(std::llround(fs / f));
    const auto end = k + 1 < run->triggers.size() ? run->triggers[k + 1].sample : run->values.rows();
    core::tire::HarmonicYawRecord r;
    r.excitationFrequencyHz = f;
    r.sampleRateHz = fs;
    r.yawRate = run->values.col(0).segment(start, end - start);
    r.lateralForce = run->values.col(1).segment(start, end - start);
    records.push_back(r);
  }
  auto setup = sim::tyreTesterSetup(cfg.parameters);
  EXPECT_TRUE(setup.ok());
  *halfLength = setup->halfLength;
  core::tire::HarmonicYawSettings st;
  st.speed = 5.0 / 3.6;
  st.halfLength = setup->halfLength;
  auto res = core::tire::relaxationFromHarmonicYaw(records, st);
  EXPECT_TRUE(res.ok()) << res.error().describe();
  return res.ok() ? *res : core::tire::HarmonicYawResult{};
}

TEST(DevicesTyreTester, HarmonicYawGivesBackTheConfiguredRelaxationLength) {
  double a = 0.0;
  // An arbitrary sigma, set explicitly: 0.25 m on the 180/55 R17 at 2 bar.
  const auto res = harmonicYaw("tyre-180-55-r17", 2.0, 0.25, &a);
  EXPECT_DOUBLE_EQ(a, 0.065);  // Table 17 at 2 bar
  for (const auto& p : res.points)
    std::printf("f = %.2f Hz: lag %.4f rad, sigma %.5f m\n", p.frequencyHz, p.phaseLagRad, p.sigma);
  // 1%: the sine fits see 0.2% force noise; the gyro and load cell are
  // quantised at 0.3 mrad/s and 0.15 N; the RK4 integration error of the lag
  // is below 1e-6 of sigma.
  EXPECT_EQ(res.pointsInBand, 3);
  EXPECT_NEAR(res.meanSigma / 0.25, 1.0, 0.01);
  for (const auto& p : res.points) EXPECT_NEAR(p.sigma / 0.25, 1.0, 0.02) << p.frequencyHz << " Hz";
}

TEST(DevicesTyreTester, DefaultRelaxationLengthIsTheThesisPrediction) {
  // Eq. 48 for the 120/70 R17 at 1 bar, computed here from the tables:
  // ring of Table 16 with the assumed mass, a of Table 17 at 1 bar (0.088 m),
  // C = 13 F_z, F_z = 1500 N.
  const auto& t = core::tire::thesisTyres()[0];
  auto ring =
      core::tire::ringModelFromStiffness({{0, 1906e3, 0.03}, {1, 463e3, 0.03}, {2, 1239e3, 0.03}, {3, 4690e3, 0.03}},
                                         core::tire::RingModelSettings{t.tyreMass, 0.8, t.outerRadius});
  ASSERT_TRUE(ring.ok());
  core::tire::ContactPatchInputs cp;
  cp.halfLength = 0.088;
  cp.corneringStiffness = 13.0 * 1500.0;
  cp.verticalLoad = 1500.0;
  auto pred = core::tire::predictRelaxationLength(*ring, cp);
  ASSERT_TRUE(pred.ok());
  double a = 0.0;
  const auto res = harmonicYaw("tyre-120-70-r17", 1.0, 0.0, &a);
  std::printf("120/70 R17 at 1 bar: predicted sigma %.4f m, identified %.4f m\n", pred->total(), res.meanSigma);
  EXPECT_DOUBLE_EQ(a, 0.088);
  EXPECT_NEAR(res.meanSigma / pred->total(), 1.0, 0.01);  // as above
}

// A steady sweep: the falling branch (+max -> -max) of one triangle period.
core::tire::SteadyStateSweep sweep(const std::string& mode, int angleInput, double loadN, double* cornering,
                                   double* camber) {
  const double fs = 50.0, period = 60.0;
  AcquisitionConfig cfg;
  cfg.sampleRateHz = fs;
  cfg.scanCount = static_cast<std::int64_t>(period * fs);
  cfg.channels = {channel(angleInput, "angle", core::signal::TransducerKind::Other, 10000.0, "rad"),
                  channel(1, "Fy", core::signal::TransducerKind::Force, 2.0, "N"),
                  channel(2, "Mz", core::signal::TransducerKind::Other, 100.0, "N m")};
  cfg.parameters["mode"] = mode;
  cfg.parameters["tyre"] = std::string("tyre-110-70-16");
  cfg.parameters["tyre.load"] = loadN;
  cfg.parameters["sweep.period_s"] = period;
  auto setup = sim::tyreTesterSetup(cfg.parameters);
  EXPECT_TRUE(setup.ok());
  *cornering = setup->corneringStiffness;
  *camber = setup->camberStiffness;
  auto run = acquire(cfg);
  EXPECT_TRUE(run.has_value());
  const Eigen::Index from = static_cast<Eigen::Index>(period * fs / 4) + 1,
                     to = static_cast<Eigen::Index>(3 * period * fs / 4);
  // configure() orders the channels by input: find them by name.
  auto column = [&](const char* name) {
    for (std::size_t c = 0; c < run->header.channels.size(); ++c)
      if (run->header.channels[c].name == name) return static_cast<Eigen::Index>(c);
    ADD_FAILURE() << "no channel " << name;
    return Eigen::Index{0};
  };
  core::tire::SteadyStateSweep s;
  s.angle = run->values.col(column("angle")).segment(from, to - from).reverse();
  s.force = run->values.col(column("Fy")).segment(from, to - from).reverse();
  s.torque = run->values.col(column("Mz")).segment(from, to - from).reverse();
  s.verticalLoad = loadN;
  return s;
}

TEST(DevicesTyreTester, SideSlipSweepGivesBackTheCorneringStiffness) {
  double c = 0.0, cg = 0.0;
  const auto s = sweep("slip-sweep", 4, 1200.0, &c, &cg);
  EXPECT_DOUBLE_EQ(c, 13.0 * 1200.0);  // the assumed 13 F_z /rad
  auto ch = core::tire::characteriseSweep(s, 3.0 * kDeg, 3);
  ASSERT_TRUE(ch.ok()) << ch.error().describe();
  std::printf("cornering stiffness %.0f N/rad (configured %.0f), aligning stiffness %.1f N m/rad\n",
              ch->forceSlope.slope, c, ch->torqueSlope.slope);
  // 1%: a cubic over +/-3 deg leaves the Magic Formula's fifth-order term
  // (B alpha = 0.5 at the window's edge) below 0.5% of the slope; the lag of
  // the slip behind the sweep, (sigma + a) psi'/V = 0.06 deg, shifts the
  // curve, not its slope.
  EXPECT_NEAR(ch->forceSlope.slope / c, 1.0, 0.01);
  EXPECT_LT(ch->torqueSlope.slope, 0.0);  // the aligning torque opposes the slip (M_z = -t F_y + M_zr)
}

TEST(DevicesTyreTester, CamberSweepGivesBackTheCamberStiffness) {
  double c = 0.0, cg = 0.0;
  const auto s = sweep("camber-sweep", 5, 1500.0, &c, &cg);
  auto ch = core::tire::characteriseSweep(s, 10.0 * kDeg, 1);
  ASSERT_TRUE(ch.ok()) << ch.error().describe();
  std::printf("camber stiffness %.1f N/rad (configured %.1f)\n", ch->forceSlope.slope, cg);
  // The camber thrust is linear (pVy3 gamma F_z): 1% bounds the load-cell
  // noise (2 N) and quantisation over a 10 deg window.
  EXPECT_NEAR(ch->forceSlope.slope / cg, 1.0, 0.01);
  EXPECT_NEAR(cg, 0.9 * 1500.0, 1e-9);
}

TEST(DevicesTyreTester, ServoLimitsAndBadProgrammesAreRefused) {
  auto dev = sim::makeTyreTesterDriver()->create(DeviceDescriptor{"sim-tyre-tester", "", 0, 0, "", "sim:0"}).value();
  ASSERT_TRUE(dev->open().ok());
  AcquisitionConfig cfg;
  cfg.sampleRateHz = 100.0;
  cfg.channels = {channel(1, "Fy", core::signal::TransducerKind::Force, 2.0, "N")};
  cfg.parameters["yaw.amplitude_deg"] = 8.0;  // beyond the default 6 deg safety limit (§1.8)
  auto r = dev->configure(cfg);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("servo limit"), std::string::npos) << r.error().describe();
  cfg.parameters["servo.yaw_limit_deg"] = 10.0;  // the machine's own limit allows it
  EXPECT_TRUE(dev->configure(cfg).ok());
  cfg.parameters["yaw.frequencies_hz"] = std::string("0.42, fast");
  r = dev->configure(cfg);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().describe().find("yaw.frequencies_hz"), std::string::npos) << r.error().describe();
}

}  // namespace
}  // namespace mozzi::devices
