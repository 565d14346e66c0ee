#pragma once
// Multi-channel time records of one hit or one acquisition block (thesis §1.4,
// §1.6): sample rate, pre-trigger, per-channel transducer and measurement DOF.
// Samples are stored in engineering units (N, m/s^2, m/s, m, rad/s, ...), one
// column per channel, so a channel is a contiguous Eigen column.

#include <string>
#include <vector>

#include "core/common/dof.h"
#include "core/common/eigen_types.h"
#include "core/common/result.h"

namespace mozzi::core::signal {

// What a channel measures; decides the FRF type of a response (acceleration ->
// accelerance, velocity -> mobility, displacement -> receptance).
enum class TransducerKind { Force, Acceleration, Velocity, Displacement, AngularRate, Other };

const char* transducerKindName(TransducerKind kind);  // "force", "acceleration", ...

struct Transducer {
  TransducerKind kind = TransducerKind::Other;
  std::string model;  // e.g. "PCB 086C03" (thesis §1.6 hammer)
  std::string serial;
  double sensitivityMvPerUnit = 1.0;  // mV per engineering unit, e.g. 10 mV/(m/s^2) for PCB M352C65 (§1.4)
  std::string unit;                   // engineering unit text, e.g. "N", "m/s^2"
  bool iepe = false;                  // constant-current (IEPE/ICP) supply on
};

struct Channel {
  std::string name;
  Transducer transducer;
  Dof dof;                 // measurement DOF: node + direction
  double fullScale = 0.0;  // |EU| at which the DAQ range saturates; 0 = unknown
};

struct TimeRecord {
  double sampleRateHz = 0.0;
  Eigen::Index preTriggerSamples = 0;  // samples recorded before the trigger instant
  std::vector<Channel> channels;
  Matrix samples;  // n x channels, engineering units

  Eigen::Index sampleCount() const { return samples.rows(); }
  Eigen::Index channelCount() const { return static_cast<Eigen::Index>(channels.size()); }
  double durationS() const { return sampleRateHz > 0.0 ? static_cast<double>(sampleCount()) / sampleRateHz : 0.0; }

  // Sample rate finite and > 0, at least 2 samples, one column per channel,
  // pre-trigger inside the record, every channel's sensitivity > 0 and
  // samples finite. The error names the first offender (channel name and
  // sample index).
  Result<void> validate() const;
  // validate() without the samples, for a caller that checks them in a pass
  // of its own (assessHit) and calls validate() for the error when one is
  // not, or when this fails (validate() names the first offender).
  Result<void> validateLayout() const;
};

// Volts from the DAQ into engineering units: EU = 1000 V / sensitivity[mV/EU].
Result<Vector> engineeringFromVolts(const VectorRef& volts, const Transducer& transducer);

// Index of the one channel of kind Force; an error when there is none or more
// than one (then the caller must name the reference).
Result<Eigen::Index> findForceChannel(const TimeRecord& record);

}  // namespace mozzi::core::signal
