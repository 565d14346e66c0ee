#pragma once
// Time data as exchanged with other software (CSV, MATLAB): evenly sampled
// channels in SI units with a name, a quantity and optionally a DOF each. A
// storage-level type of core/io; signal processing converts it to its own
// record type.

#include <optional>
#include <string>
#include <vector>

#include "core/common/dof.h"
#include "core/common/eigen_types.h"

namespace mozzi::core::io {

struct ExchangeChannel {
  std::string name;        // as it appeared in the file, e.g. "accel 21:+Z"
  std::optional<Dof> dof;  // from the name or the caller's channel map
  std::string quantity;    // "force", "acceleration", "velocity", "displacement", "" if unknown
  std::string unit;        // SI unit of the samples after import, e.g. "m/s^2"
};

struct TimeTable {
  double sampleRateHz = 0.0;  // > 0
  double startTimeS = 0.0;    // time of the first sample [s]
  std::vector<ExchangeChannel> channels;
  Matrix samples;  // sampleCount x channelCount, SI units
};

}  // namespace mozzi::core::io
