#pragma once
// Campaigns on the simulated rigs for the validation tests: a hammer campaign
// through the driver (calibration pipeline, quantisation), the software
// trigger with 10% pre-trigger, H1 averaging and pLSCF identification; and a
// static ramp on the stiffness rig processed by the static twist test.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "core/modal/plscf.h"
#include "core/signal/frf_estimator.h"
#include "core/stiffness/plate_motion.h"
#include "devices/common/trigger.h"
#include "devices/mcc_usb1608fsplus/usb1608fsplus_protocol.h"
#include "devices/sim/sim_drivers.h"
#include "devices/sim/specimen_models.h"

namespace mozzi::devices::testing {

// One acquisition on an opened-or-not device: open, configure, start, wait for
// the end, stop; what the stream held. nullopt (with the failure reported)
// when any step fails.
struct Acquired {
  StreamHeader header;
  core::Matrix values;
  std::vector<TriggerEvent> triggers;
  std::vector<OverloadEvent> overloads;
  StreamEnd end;
};

inline std::optional<Acquired> acquire(Device& dev, const AcquisitionConfig& cfg,
                                       std::chrono::seconds timeout = std::chrono::seconds(120)) {
  auto opened = dev.open();
  EXPECT_TRUE(opened.ok()) << opened.error().describe();
  auto applied = dev.configure(cfg);
  EXPECT_TRUE(applied.ok()) << applied.error().describe();
  StreamCollector col;
  if (!opened || !applied || !dev.start(col.sink()).ok() || !col.waitForEnd(timeout)) {
    ADD_FAILURE() << "the acquisition on " << dev.descriptor().label() << " did not run to its end";
    dev.stop();
    return std::nullopt;
  }
  dev.stop();
  EXPECT_TRUE(col.orderedAndContiguous());
  return Acquired{*col.header(), col.values(), col.triggers(), col.overloads(), *col.end()};
}

struct HammerCampaign {
  std::string specimen;
  double sampleRateHz = 1024.0;
  double recordSeconds = 2.0;  // one hit per recordSeconds + 1 s
  int hits = 5;
  double peakForceN = 200.0;
  std::uint8_t responseRange = 4;  // USB-1608FS-Plus range code of the accelerometers
  double bandLowHz = 0.0, bandHighHz = 0.0;
  int maxOrder = 30;
  std::uint64_t seed = 11;
};

struct CampaignResult {
  core::modal::PlscfResult identification;
  std::vector<core::signal::TimeRecord> hits;  // the triggered records, in order
  int records = 0;
  bool overloaded = false;
};

// The smallest range of the DAQ that holds `peak` [V] with a factor 2 margin.
inline std::uint8_t rangeFor(double peakVolts) {
  std::uint8_t best = 0;
  for (const auto& r : mcc::ranges())
    if (r.maxVolts >= 2.0 * peakVolts && r.maxVolts < mcc::ranges()[best].maxVolts) best = r.code;
  return best;
}

// Accelerometer rows that see every tabulated mode of a spatial specimen: the
// driving point first, then, greedily, the row that most raises the weakest
// mode's best relative amplitude (|phi_jr| / max_j |phi_jr|) over the rows
// chosen so far.
inline std::vector<Eigen::Index> observingRows(const sim::ModalSpecimen& spec, std::size_t count) {
  std::vector<Eigen::Index> rows = {spec.excitedDof};
  const Eigen::Index nm = static_cast<Eigen::Index>(spec.tabulatedModes);
  core::Matrix rel(spec.shapes.rows(), nm);
  for (Eigen::Index r = 0; r < nm; ++r)
    rel.col(r) = spec.shapes.col(r).cwiseAbs() / spec.shapes.col(r).cwiseAbs().maxCoeff();
  core::Vector best = rel.row(spec.excitedDof).transpose();
  while (rows.size() < count) {
    Eigen::Index pick = 0;
    double score = -1.0;
    for (Eigen::Index j = 0; j < rel.rows(); ++j) {
      if (std::find(rows.begin(), rows.end(), j) != rows.end()) continue;
      const double s = best.cwiseMax(rel.row(j).transpose()).minCoeff() + 1e-3 * rel.row(j).sum();
      if (s > score) {
        score = s;
        pick = j;
      }
    }
    rows.push_back(pick);
    best = best.cwiseMax(rel.row(pick).transpose());
  }
  return rows;
}

// Hammer (input 0) at the specimen's driving point and three accelerometers
// (inputs 1-3) on observingRows, one hit every recordSeconds + 1 s.
inline std::optional<AcquisitionConfig> hammerConfig(const HammerCampaign& c) {
  const double interval = c.recordSeconds + 1.0;
  AcquisitionConfig cfg;
  cfg.sampleRateHz = c.sampleRateHz;
  cfg.scanCount = static_cast<std::int64_t>(std::llround(c.hits * interval * c.sampleRateHz));
  auto spec = sim::modalSpecimen(c.specimen);
  EXPECT_TRUE(spec.ok());
  if (!spec) return std::nullopt;
  ChannelConfig f;
  f.input = 0;
  f.name = "hammer";
  f.rangeCode = 4;  // +/-1.25 V: 555 N full scale at 2.25 mV/N
  f.transducer = core::signal::Transducer{core::signal::TransducerKind::Force, "PCB 086C03", "", 2.25, "N", true};
  f.dof = spec->dofs[static_cast<std::size_t>(spec->excitedDof)];
  cfg.channels.push_back(f);
  const auto rows = observingRows(*spec, 3);
  std::string responseDofs;
  for (int i = 1; i <= 3; ++i) {
    const core::Dof dof = spec->dofs[static_cast<std::size_t>(rows[static_cast<std::size_t>(i - 1)])];
    ChannelConfig a;
    a.input = i;
    a.name = "acc " + core::formatDof(dof);
    a.rangeCode = c.responseRange;
    a.transducer =
        core::signal::Transducer{core::signal::TransducerKind::Acceleration, "PCB M352C65", "", 10.0, "m/s^2", true};
    a.dof = dof;
    cfg.channels.push_back(a);
    responseDofs += (i > 1 ? "," : "") + core::formatDof(dof);
  }
  cfg.parameters["response.dofs"] = responseDofs;
  cfg.parameters["sim.realtime"] = false;
  cfg.parameters["specimen"] = c.specimen;
  cfg.parameters["hammer.interval_s"] = interval;
  cfg.parameters["hammer.peak_force"] = c.peakForceN;
  cfg.parameters["sim.seed"] = static_cast<std::int64_t>(c.seed);
  return cfg;
}

// H1 averaging of the hits and pLSCF over the campaign's band.
inline std::optional<core::modal::PlscfResult> identifyHits(const std::vector<core::signal::TimeRecord>& hits,
                                                            const HammerCampaign& c) {
  std::optional<core::signal::SpectralAverager> avg;
  for (const auto& tr : hits) {
    if (!avg) {
      auto a = core::signal::SpectralAverager::create(tr, core::signal::FrfOptions{});
      EXPECT_TRUE(a.ok()) << a.error().describe();
      if (!a) return std::nullopt;
      avg = std::move(*a);
    }
    auto added = avg->add(tr);
    EXPECT_TRUE(added.ok()) << added.error().describe();
  }
  if (!avg) return std::nullopt;
  auto frf = avg->frf();
  EXPECT_TRUE(frf.ok()) << frf.error().describe();
  if (!frf) return std::nullopt;
  core::modal::PlscfOptions opt;
  opt.bandLowHz = c.bandLowHz;
  opt.bandHighHz = c.bandHighHz;
  opt.maxOrder = c.maxOrder;
  auto id = core::modal::identifyPlscf(*frf, opt);
  EXPECT_TRUE(id.ok()) << id.error().describe();
  if (!id) return std::nullopt;
  return std::move(*id);
}

inline std::optional<CampaignResult> runHammerCampaign(const HammerCampaign& c) {
  auto cfg = hammerConfig(c);
  if (!cfg) return std::nullopt;
  auto dev = sim::makeHammerStationDriver()->create(DeviceDescriptor{"sim-hammer", "", 0, 0, "", "sim:0"}).value();
  auto run = acquire(*dev, *cfg);
  if (!run) return std::nullopt;
  EXPECT_EQ(run->end.reason, EndReason::Completed);

  CampaignResult out;
  out.overloaded = !run->overloads.empty();
  const StreamHeader& header = run->header;
  SoftwareTriggerConfig tc;
  tc.channel = 0;
  tc.level = 0.05 * c.peakForceN;  // far above the 0.05 N noise
  tc.recordScans = static_cast<std::int64_t>(std::llround(c.recordSeconds * c.sampleRateHz));
  tc.preTriggerFraction = 0.1;
  for (const auto& ch : header.channels) tc.fullScale.push_back(ch.fullScale);
  auto trig = SoftwareTrigger::create(tc, 4);
  EXPECT_TRUE(trig.ok());
  if (!trig) return std::nullopt;
  for (const auto& r : trig->feed(0, run->values)) {
    out.overloaded = out.overloaded || r.overloaded;
    core::signal::TimeRecord tr;
    tr.sampleRateHz = header.sampleRateHz;
    tr.preTriggerSamples = r.preTriggerScans;
    tr.channels = header.channels;
    tr.samples = r.samples;
    out.hits.push_back(std::move(tr));
  }
  out.records = static_cast<int>(out.hits.size());
  auto id = identifyHits(out.hits, c);
  if (!id) return std::nullopt;
  out.identification = std::move(*id);
  return out;
}

struct StaticRamp {
  std::string specimen;
  double maxForceN = 0.0;  // 0: the specimen's thesis range
  double sampleRateHz = 100.0;
  std::int64_t scans = 2000;  // one 20 s period: 0 -> +F -> -F -> 0
};

inline std::optional<core::stiffness::StaticTwistResult> runStaticRamp(const StaticRamp& r) {
  using namespace std::chrono_literals;
  AcquisitionConfig cfg;
  cfg.sampleRateHz = r.sampleRateHz;
  cfg.scanCount = r.scans;
  ChannelConfig lc;
  lc.input = 0;
  lc.name = "load cell";
  lc.transducer = core::signal::Transducer{
      core::signal::TransducerKind::Force, "load cell +/-200 kg", "", 10000.0 / (200 * 9.80665), "N", false};
  cfg.channels.push_back(lc);
  for (int i = 1; i <= 4; ++i) {
    ChannelConfig l;
    l.input = i;
    l.name = "laser " + std::to_string(i);
    l.transducer = core::signal::Transducer{
        core::signal::TransducerKind::Displacement, "laser 20 mm", "", 1e6, "m", false};  // 1 V/mm
    cfg.channels.push_back(l);
  }
  cfg.parameters["sim.realtime"] = false;
  cfg.parameters["specimen"] = r.specimen;
  cfg.parameters["static.max_force"] = r.maxForceN;

  auto dev = sim::makeStiffnessRigDriver()->create(DeviceDescriptor{"sim-stiffness", "", 0, 0, "", "sim:0"}).value();
  auto run = acquire(*dev, cfg, std::chrono::seconds(60));
  if (!run) return std::nullopt;
  EXPECT_EQ(run->end.reason, EndReason::Completed);
  const core::Matrix& v = run->values;
  const auto spec = sim::staticSpecimen(r.specimen).value();
  const core::Vector force = v.col(0);
  const core::Matrix disp = v.rightCols(4);
  auto res = core::stiffness::staticTwistTest(spec.laserPoints, force, disp, spec.loadPoint);
  EXPECT_TRUE(res.ok()) << res.error().describe();
  if (!res) return std::nullopt;
  return *res;
}

}  // namespace mozzi::devices::testing
