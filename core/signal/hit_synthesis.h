#pragma once
// Synthetic impact-hammer hits on a linear MDOF system, for tests and the
// simulated rigs: a half-sine force pulse (the usual model of a hammer tip
// contact, thesis §1.4, §1.6), optional rebound (double hit), white measurement
// noise on every channel and optional clipping.
//
// The response is simulated exactly (mdof_simulation.h, first-order hold) on a
// grid `oversampling` times finer than the DAQ rate and then sampled at the DAQ
// rate. Every channel passes the same anti-aliasing filter on the fine grid, a
// zero-phase 4th-order Butterworth magnitude 1/sqrt(1 + (f/fc)^8) with
// fc = 0.4 fs (as a DAQ's filter, it cancels in H = X/F and keeps the force
// pulse's spectrum above fs/2 from aliasing into the band). The pulse starts at
// the trigger instant t = preTriggerSamples / fs.

#include <cstdint>
#include <optional>
#include <vector>

#include "core/signal/mdof_simulation.h"
#include "core/signal/time_record.h"

namespace mozzi::core::signal {

struct HammerHitSpec {
  double sampleRateHz = 8192.0;
  Eigen::Index sampleCount = 32768;
  Eigen::Index preTriggerSamples = 256;
  Eigen::Index oversampling = 8;  // simulation grid = sampleRateHz * oversampling
  double peakForceN = 100.0;
  double pulseWidthS = 2e-3;               // half-sine contact time
  Eigen::Index excitedDof = 0;             // index into the system's DOFs
  std::vector<Eigen::Index> measuredDofs;  // response channels; empty = every DOF
  TransducerKind responseKind = TransducerKind::Acceleration;
  double forceNoiseRms = 0.0;     // white noise added to the force channel [N]
  double responseNoiseRms = 0.0;  // white noise added to each response [EU]
  std::uint64_t seed = 1;
  std::optional<double> secondHitDelayS;   // rebound: a second half-sine this long after the first
  double secondHitFraction = 0.5;          // its peak relative to the first
  double clipFraction = 0.0;               // > 0: channels clamped at this fraction of their peak |x|
  std::vector<Eigen::Index> clipChannels;  // record channel indices to clip (0 = force); empty = all
  std::vector<Dof> dofLabels;              // DOF of each system DOF; default node i+1, +Z
  double fullScale = 0.0;                  // copied to every channel (0 = unknown)
};

Result<TimeRecord> synthesizeHammerHit(const LinearMdof& system, const HammerHitSpec& spec);

}  // namespace mozzi::core::signal
