// Validation of the spatial virtual specimens through the simulated hammer
// station: a hit at a DOF other than the driving point ("hammer.point"),
// accelerometers at DOFs of the mesh named by "response.dofs", acquired through
// the driver (calibration pipeline, 16-bit quantisation), cut by the software
// trigger and averaged into H1 accelerances, gives the analytic accelerance
// -w^2 sum_r phi_ir phi_jr / (w_r^2 - w^2 + 2 i zeta_r w_r w) of the modal
// model (thesis eq. 21) at every line where it is not near an antiresonance.
#include <algorithm>
#include <cstdio>

#include "devices_campaign.h"

namespace mozzi::devices {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct SpatialHit {
  const char* specimen;
  const char* hammerPoint;
  std::vector<const char*> responses;
  double bandLowHz, bandHighHz;
};

// H1 of `hits` hits on the station, compared line by line with the model.
void checkAgainstModel(const SpatialHit& c) {
  SCOPED_TRACE(c.specimen);
  const auto spec = sim::modalSpecimen(c.specimen).value();
  const double fs = 4096.0, recordS = 4.0, interval = 5.0;
  const int hits = 4;
  const auto drive = spec.findDof(c.hammerPoint).value();
  // Accelerometer ranges from a bound on the peak acceleration of a 1 ms
  // half-sine of 200 N (+10% for the hand): the mass line during the contact,
  // F sum_r |phi_er phi_jr|, plus the ringing after it, I sum_r |phi_er
  // phi_jr| w_r with the impulse I = 2 F T / pi.
  const double force = 1.1 * 200.0;
  const double impulse = 2.0 * force * 1e-3 / kPi;
  std::vector<double> peaks;
  std::vector<sim::DofRow> rows;
  std::string labels;
  for (const char* r : c.responses) {
    rows.push_back(spec.findDof(r).value());
    labels += (labels.empty() ? "" : ",") + std::string(r);
    double a = 0.0, mass = 0.0;
    for (Eigen::Index q = 0; q < spec.shapes.cols(); ++q) {
      const double pp = std::abs(spec.shapes(drive.row, q) * spec.shapes(rows.back().row, q));
      a += pp * 2 * kPi * spec.frequencyHz[static_cast<std::size_t>(q)];
      mass += pp;
    }
    peaks.push_back(force * mass + impulse * a);
  }
  AcquisitionConfig cfg;
  cfg.sampleRateHz = fs;
  cfg.scanCount = static_cast<std::int64_t>(hits * interval * fs);
  ChannelConfig f;
  f.input = 0;
  f.name = "hammer";
  f.rangeCode = 4;
  f.transducer = core::signal::Transducer{core::signal::TransducerKind::Force, "PCB 086C03", "", 2.25, "N", true};
  f.dof = core::parseDof(c.hammerPoint).value();
  cfg.channels.push_back(f);
  for (std::size_t i = 0; i < c.responses.size(); ++i) {
    ChannelConfig a;
    a.input = static_cast<int>(i + 1);
    a.name = std::string("acc ") + c.responses[i];
    a.rangeCode = testing::rangeFor(peaks[i] * 0.010);  // each accelerometer on its own range
    a.transducer =
        core::signal::Transducer{core::signal::TransducerKind::Acceleration, "PCB M352C65", "", 10.0, "m/s^2", true};
    a.dof = core::parseDof(c.responses[i]).value();
    cfg.channels.push_back(a);
  }
  cfg.parameters["sim.realtime"] = false;
  cfg.parameters["specimen"] = std::string(c.specimen);
  cfg.parameters["hammer.interval_s"] = interval;
  cfg.parameters["hammer.point"] = std::string(c.hammerPoint);
  cfg.parameters["response.dofs"] = labels;
  cfg.parameters["sim.seed"] = std::int64_t{5};
  auto dev = sim::makeHammerStationDriver()->create(DeviceDescriptor{"sim-hammer", "", 0, 0, "", "sim:0"}).value();
  auto run = testing::acquire(*dev, cfg);
  ASSERT_TRUE(run.has_value());
  EXPECT_TRUE(run->overloads.empty());

  SoftwareTriggerConfig tc;
  tc.channel = 0;
  tc.level = 10.0;
  tc.recordScans = static_cast<std::int64_t>(recordS * fs);
  tc.preTriggerFraction = 0.1;
  for (const auto& ch : run->header.channels) tc.fullScale.push_back(ch.fullScale);
  auto trig = SoftwareTrigger::create(tc, static_cast<int>(cfg.channels.size())).value();
  std::optional<core::signal::SpectralAverager> avg;
  for (const auto& r : trig.feed(0, run->values)) {
    core::signal::TimeRecord tr;
    tr.sampleRateHz = fs;
    tr.preTriggerSamples = r.preTriggerScans;
    tr.channels = run->header.channels;
    tr.samples = r.samples;
    if (!avg) avg = core::signal::SpectralAverager::create(tr, core::signal::FrfOptions{}).value();
    ASSERT_TRUE(avg->add(tr).ok());
  }
  ASSERT_TRUE(avg.has_value());
  EXPECT_EQ(avg->hitCount(), hits);
  const auto frf = avg->frf().value();
  ASSERT_EQ(frf.type, core::FrfType::Accelerance);

  for (std::size_t o = 0; o < rows.size(); ++o) {
    // Analytic accelerance A = -w^2 H (with the signs of the labels).
    std::vector<std::complex<double>> model(static_cast<std::size_t>(frf.lineCount()));
    double top = 0.0;
    for (Eigen::Index k = 0; k < frf.lineCount(); ++k) {
      const double w = 2 * kPi * frf.frequencyHz(k);
      model[static_cast<std::size_t>(k)] =
          -w * w * drive.sign * rows[o].sign * spec.receptance(drive.row, rows[o].row, w);
      if (frf.frequencyHz(k) >= c.bandLowHz && frf.frequencyHz(k) <= c.bandHighHz)
        top = std::max(top, std::abs(model[static_cast<std::size_t>(k)]));
    }
    ASSERT_GT(top, 0.0) << c.responses[o] << ": no mode couples it to the hammer point";
    // Per line, the H1 magnitude's normalised random error (Bendat & Piersol):
    // eps = sqrt(1 - g^2) / (|g| sqrt(2 n)), g^2 the coherence, n the hits.
    // Every line where the model is at least 5% of its in-band peak (away
    // from antiresonances) must be within 5 eps + 0.5% of it (5 eps: one in
    // 10^6 lines of Gaussian error; 0.5%: quantisation and the anti-aliasing
    // filter's 1e-4 ripple in band), and the median error within 1%.
    std::vector<double> errors;
    double worst = 0.0, worstHz = 0.0;
    for (Eigen::Index k = 0; k < frf.lineCount(); ++k) {
      const double hz = frf.frequencyHz(k);
      const auto& m = model[static_cast<std::size_t>(k)];
      if (hz < c.bandLowHz || hz > c.bandHighHz || std::abs(m) < 0.05 * top) continue;
      const double e = std::abs(frf.h[0](k, static_cast<Eigen::Index>(o)) - m) / std::abs(m);
      const double g2 = frf.coherence[0](k, static_cast<Eigen::Index>(o));
      const double eps = std::sqrt(std::max(0.0, 1.0 - g2)) / (std::sqrt(g2) * std::sqrt(2.0 * hits));
      EXPECT_LT(e, 5.0 * eps + 0.005) << c.responses[o] << " at " << hz << " Hz, coherence " << g2;
      errors.push_back(e);
      if (e > worst) {
        worst = e;
        worstHz = hz;
      }
    }
    ASSERT_GT(errors.size(), 20u);
    std::nth_element(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(errors.size() / 2), errors.end());
    const double median = errors[errors.size() / 2];
    std::printf("%-26s hit %-6s response %-6s: %4zu lines, median |H1 - H| / |H| %.4f, worst %.4f at %.2f Hz\n",
                c.specimen, c.hammerPoint, c.responses[o], errors.size(), median, worst, worstHz);
    EXPECT_LT(median, 0.01) << c.responses[o];
  }
}

TEST(DevicesHammerSpatial, HitAtAnyDofGivesTheModelFrf) {
  // Fork A with wheel (Table 11 right): the hammer on the rim at 135 degrees
  // (above the axle, in front), accelerometers on a fork foot, a leg (y,
  // negative), the rim laterally and the rim in x.
  checkAgainstModel({"fork-a-with-wheel", "14:+Z", {"9:+Z", "7:-Z", "16:+Z", "13:+X"}, 15.0, 100.0});
  // Steel bicycle (Table 18): hammer on the top tube, accelerometers on the
  // rear hub, a fork tip, the seat cluster and a fork blade (y).
  checkAgainstModel({"bicycle-steel", "5:+Z", {"100:+Z", "16:+Z", "4:+Z", "2:-Z"}, 8.0, 80.0});
  // Frame B rear-constrained: the hammer on the tail, lateral.
  checkAgainstModel({"frame-b-rear-constrained", "24:+Z", {"2:+Z", "11:+Z", "25:+X"}, 25.0, 130.0});
}

// Unknown DOF labels fail configure() naming the label and the specimen.
TEST(DevicesHammerSpatial, UnknownDofLabelsAreClearErrors) {
  AcquisitionConfig cfg;
  cfg.sampleRateHz = 1024.0;
  cfg.scanCount = 1024;
  ChannelConfig f;
  f.input = 0;
  f.name = "hammer";
  f.transducer = core::signal::Transducer{core::signal::TransducerKind::Force, "PCB 086C03", "", 2.25, "N", true};
  cfg.channels.push_back(f);
  cfg.parameters["sim.realtime"] = false;
  cfg.parameters["specimen"] = std::string("swing-arm-a");
  auto dev = sim::makeHammerStationDriver()->create(DeviceDescriptor{"sim-hammer", "", 0, 0, "", "sim:0"}).value();
  ASSERT_TRUE(dev->open().ok());
  ASSERT_TRUE(dev->configure(cfg).ok());
  auto bad = cfg;
  bad.parameters["hammer.point"] = std::string("42:+Z");
  auto e1 = dev->configure(bad);
  ASSERT_FALSE(e1.ok());
  EXPECT_NE(e1.error().message.find("42:+Z"), std::string::npos) << e1.error().describe();
  EXPECT_NE(e1.error().where.find("swing-arm-a"), std::string::npos) << e1.error().describe();
  bad = cfg;
  bad.parameters["response.dofs"] = std::string("1:+Z, 3:+Q");
  auto e2 = dev->configure(bad);
  ASSERT_FALSE(e2.ok());
  EXPECT_NE(e2.error().message.find("3:+Q"), std::string::npos) << e2.error().describe();
  bad.parameters["response.dofs"] = std::string("1:+X,1:+Y,1:+Z,2:+X,2:+Y,2:+Z,3:+X,3:+Y");
  auto e3 = dev->configure(bad);
  ASSERT_FALSE(e3.ok());
  EXPECT_EQ(e3.error().where, "parameter response.dofs");
  bad.parameters["response.dofs"] = std::string("6:-Z, 5:+X");
  EXPECT_TRUE(dev->configure(bad).ok());
}

}  // namespace
}  // namespace mozzi::devices
