#pragma once
// Synthetic blocks of a multiple-shaker test (periodic random excitation) on a
// linear MDOF system, for tests of the multiple-reference FRF estimator and
// the simulated rigs.
//
// Per block, each force is a multisine on every DFT line of the block (DC and
// Nyquist included) with equal line power and its own random phases, so the
// forces are uncorrelated over blocks. The system starts from rest, runs
// settleBlocks periods until the transient has decayed and the next period is
// recorded: every block is periodic and leakage-free with rectangular windows.
// The response is the exact state-transition simulation (mdof_simulation.h,
// first-order hold) on a grid `oversampling` times finer than the DAQ rate,
// sampled at the DAQ instants, so the recorded force samples are the
// multisine's own values; the hold applies the piecewise-linear interpolant,
// which scales the line at f by sinc^2(pi f h) ~ 1 - (pi f h)^2 / 3 with
// h = 1 / (oversampling fs) (2e-4 at fs / 4 for oversampling 32).

#include <cstdint>
#include <vector>

#include "core/signal/mdof_simulation.h"
#include "core/signal/time_record.h"

namespace mozzi::core::signal {

struct ShakerTestSpec {
  double sampleRateHz = 512.0;
  Eigen::Index blockSamples = 1024;
  Eigen::Index oversampling = 32;
  Eigen::Index settleBlocks = 3;         // periods run before the recorded one
  std::vector<Eigen::Index> forcedDofs;  // one shaker per entry (system DOF index)
  double forceRmsN = 10.0;               // RMS of each force
  int blocks = 16;
  std::uint64_t seed = 1;
  TransducerKind responseKind = TransducerKind::Acceleration;  // of every DOF's response channel
  double responseNoiseRms = 0.0;                               // white noise added to each response [EU]
  // Lines [correlatedFromLine, correlatedToLine] on which every force takes
  // the first force's phases (coherent references there); empty when from > to.
  Eigen::Index correlatedFromLine = 1;
  Eigen::Index correlatedToLine = 0;
  std::vector<Dof> dofLabels;  // DOF of each system DOF; default node i+1, +Z
};

// Channels: the forces (kind Force, at their DOFs), then one response per
// system DOF. Errors: no or repeated forced DOF, DOF outside the system,
// sizes or rates not positive, simulation errors.
Result<std::vector<TimeRecord>> synthesizeShakerBlocks(const LinearMdof& system, const ShakerTestSpec& spec);

}  // namespace mozzi::core::signal
