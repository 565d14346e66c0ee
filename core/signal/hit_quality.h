#pragma once
// Per-hit quality check for impact-hammer campaigns (thesis §1.4, §1.6): the
// technician needs one verdict per hit, accept or reject, with reasons.
//
// Checks, on the reference (force) channel unless stated:
//  - trigger: first sample with |f| >= trigger level; the samples before it
//    must include the requested pre-trigger (else the pulse start was lost);
//  - pulse: peak, width of the main pulse between the crossings of the pulse
//    threshold max(pulseEdgeFraction * peak, noiseFactor * noise RMS);
//  - double hit: after the main pulse has ended, a second excursion above
//    doubleHitFraction * peak (and above the noise threshold);
//  - overload, on every channel: samples at or beyond the channel's full scale
//    when it is known, else a run of at least clipRunLength consecutive samples
//    pinned at the channel's extreme value (a flat top);
//  - usable band: the force energy spectrum |F(f)|^2 of the main pulse
//    (rectangular window over pre-trigger + pulse + guard) falls 10 dB and
//    20 dB below its low-frequency level at f_10 and f_20;
//  - noise floor: RMS of every channel over the first 3/4 of the pre-trigger
//    samples (the last quarter may hold the pulse's foot); the force
//    peak must exceed the force noise by minForceSnrDb.

#include <optional>
#include <string>
#include <vector>

#include "core/signal/time_record.h"

namespace mozzi::core::signal {

struct HitQualityOptions {
  std::optional<Eigen::Index> referenceChannel;  // default: the one Force channel
  std::optional<double> triggerLevel;            // absolute [EU]; default triggerFraction * peak
  double triggerFraction = 0.05;
  Eigen::Index minPreTriggerSamples = 8;  // samples needed before the trigger
  double pulseEdgeFraction = 0.02;        // pulse edges at 2% of the peak
  double noiseFactor = 6.0;               // thresholds stay above 6 x noise RMS
  double doubleHitFraction = 0.10;        // rebound above 10% of the peak = double hit
  Eigen::Index clipRunLength = 3;         // flat top of >= 3 samples at the extreme = clipped
  double fullScaleMargin = 0.999;         // |x| >= 0.999 full scale = overload
  double minForceSnrDb = 30.0;            // force peak over pre-trigger noise RMS
  double minUsableBandHz = 0.0;           // reject when f_10 is below this
};

struct ChannelQuality {
  std::string name;
  Dof dof;
  bool clipped = false;
  Eigen::Index clippedSamples = 0;  // samples in flat tops or beyond full scale
  std::optional<double> noiseRms;   // pre-trigger RMS [EU]; empty without pre-trigger
  double peak = 0.0;                // max |x| [EU]
};

struct HitQuality {
  bool accepted = false;
  std::vector<std::string> reasons;  // why rejected (empty when accepted)
  std::vector<std::string> notes;    // remarks that do not reject
  Eigen::Index referenceChannel = 0;
  std::optional<Eigen::Index> triggerSample;
  double preTriggerS = 0.0;  // time recorded before the trigger
  double peakForce = 0.0;    // [N], signed value at the peak
  double pulseWidthS = 0.0;  // main pulse width at the edge threshold
  bool doubleHit = false;
  std::optional<double> secondHitDelayS;   // from the main peak to the rebound peak
  double secondHitRatio = 0.0;             // rebound peak / main peak
  std::optional<double> usableBand10dBHz;  // first frequency 10 dB down
  std::optional<double> usableBand20dBHz;  // first frequency 20 dB down
  std::optional<double> forceSnrDb;        // 20 log10(peak / force noise RMS)
  std::vector<ChannelQuality> channels;

  std::string verdictText() const;  // "accepted" or "rejected: reason; reason"
};

// Errors only for unusable input (invalid record, no reference channel); a hit
// with problems is a valid HitQuality with accepted = false.
Result<HitQuality> assessHit(const TimeRecord& record, const HitQualityOptions& options = {});

}  // namespace mozzi::core::signal
