#pragma once
// The one calibration pipeline every driver uses (simulated ones too):
//   raw ADC code -> device calibration (corrected = slope * code + intercept,
//   rounded and clamped to the code range, as the USB-1608FS-Plus firmware
//   tables define it) -> volts at the DAQ input (linear over the range) ->
//   volts at the transducer (divided by the external conditioner's gain) ->
//   engineering units (EU = 1000 V / sensitivity [mV/EU], the transducer's
//   data-sheet sensitivity, e.g. 10 mV/(m/s^2) for the PCB M352C65 of §1.4).

#include <cstdint>

#include "core/signal/time_record.h"
#include "devices/common/capabilities.h"

namespace mozzi::devices {

struct DeviceCalibration {
  double slope = 1.0;      // per channel and range, read from the device
  double intercept = 0.0;  // [codes]
};

struct ChannelChain {
  InputRange range;
  DeviceCalibration calibration;
  int resolutionBits = 16;
  double conditionerGain = 1.0;         // V at the DAQ per V from the sensor (IEPE conditioner gain)
  core::signal::Transducer transducer;  // sensitivity mV/EU and unit

  std::int32_t maxCode() const { return (std::int32_t{1} << resolutionBits) - 1; }

  // Calibrated code, rounded half away from zero and clamped to [0, maxCode].
  std::int32_t correctedCode(std::int32_t raw) const;
  double voltsFromCode(std::int32_t corrected) const;  // at the DAQ input [V]
  double engineeringFromVolts(double daqVolts) const;  // [EU]
  double engineeringFromRaw(std::int32_t raw) const { return engineeringFromVolts(voltsFromCode(correctedCode(raw))); }
  // Inverse path for simulators: the raw code a device with this calibration
  // would send for a physical value [EU] (quantised, clamped at full scale).
  std::int32_t rawFromEngineering(double value) const;
  // |EU| at which the range saturates: the smaller magnitude of the values of
  // the two end codes (a clipped sample reads exactly one of them).
  double fullScaleEngineering() const;
  // A corrected code at either end of the range counts as "at full scale".
  bool atFullScale(std::int32_t corrected) const { return corrected <= 0 || corrected >= maxCode(); }
};

// Checks a chain before use: range non-empty, bits 1..24, gain > 0 and finite,
// sensitivity > 0 and finite, slope finite and non-zero. The error names `where`.
core::Result<void> validateChain(const ChannelChain& chain, const std::string& where);

}  // namespace mozzi::devices
