#pragma once
// The campaign a technician would set up on a virtual specimen with the
// simulated hammer station (sim-hammer): roving hammer over the specimen's
// measurement DOFs, a PCB 086C03 hammer (2.25 mV/N, thesis §1.6) and PCB
// M352C65 accelerometers (10 mV/(m/s^2), §1.4) at fixed DOFs that see every
// mode, input ranges set as after a test hit (twice the largest expected
// peak), acquisition as a technician sets it (4096 Hz, 2 s records, 10%
// pre-trigger, rectangular windows: the records decay to e^-6 or less).
// The rate, 4096 Hz, puts four samples on the 1 ms contact of the station's
// plastic tip: at 1024 Hz the contact is one sample and the anti-aliasing
// filter's ringing after it (13% of the peak 1 ms later) reads as a double hit.

#include <cstdint>
#include <string>

#include "devices/campaign/campaign_definition.h"

namespace mozzi::devices::campaign {

struct VirtualCampaignOptions {
  int hitsPerPoint = 5;
  std::uint64_t seed = 1;
  double sampleRateHz = 4096.0;
  double recordSeconds = 2.0;
  int accelerometers = 3;     // fixed response channels (1..7)
  double peakForceN = 200.0;  // the simulated hand's nominal hit (less where the accelerometers would clip)
  double minCoherence = 0.0;  // poor-coherence rule (0 = off)
  // The simulated hand: a hit rebounds (double hit) or is struck 30 times
  // too hard (overload) with these probabilities; the rules reject them.
  double doubleHitProbability = 0.05;
  double overloadProbability = 0.02;
};

// Errors: unknown specimen key (the message lists `mozzi-cli rig list`).
core::Result<CampaignDefinition> virtualSpecimenCampaign(const std::string& specimenKey,
                                                         const VirtualCampaignOptions& options = {});

// Peak acceleration bound [m/s^2] at response row i for a half-sine hit of
// `peakForceN` lasting `pulseWidthS` at row j of a modal model (mass-
// normalised shapes, frequencies, zetas): sum_r |phi_ir phi_jr| max|q_r''|,
// q_r'' the acceleration of mode r's unit-mass oscillator under the pulse.
double peakAccelerationBound(const core::Matrix& shapes, const std::vector<double>& frequencyHz,
                             const std::vector<double>& zeta, Eigen::Index i, Eigen::Index j, double peakForceN,
                             double pulseWidthS);

}  // namespace mozzi::devices::campaign
