#include "devices/common/calibration.h"

#include <algorithm>
#include <cmath>

namespace mozzi::devices {

std::int32_t ChannelChain::correctedCode(std::int32_t raw) const {
  const double c = std::round(calibration.slope * static_cast<double>(raw) + calibration.intercept);
  return static_cast<std::int32_t>(std::clamp(c, 0.0, static_cast<double>(maxCode())));
}

double ChannelChain::voltsFromCode(std::int32_t corrected) const {
  // Linear over the range: code 0 = minVolts, code 2^bits = maxVolts (offset
  // binary; for +/-10 V, code 32768 = 0 V and one LSB = 20 V / 65536).
  const double lsb = (range.maxVolts - range.minVolts) / static_cast<double>(std::int64_t{1} << resolutionBits);
  return range.minVolts + lsb * static_cast<double>(corrected);
}

double ChannelChain::engineeringFromVolts(double daqVolts) const {
  // EU = 1000 * V_sensor / sensitivity[mV/EU], V_sensor = V_daq / gain.
  return 1000.0 * (daqVolts / conditionerGain) / transducer.sensitivityMvPerUnit;
}

std::int32_t ChannelChain::rawFromEngineering(double value) const {
  const double volts = value * transducer.sensitivityMvPerUnit / 1000.0 * conditionerGain;
  const double lsb = (range.maxVolts - range.minVolts) / static_cast<double>(std::int64_t{1} << resolutionBits);
  const double corrected = std::clamp(std::round((volts - range.minVolts) / lsb), 0.0, static_cast<double>(maxCode()));
  // Invert the device calibration so that correctedCode(raw) returns `corrected`
  // (up to one code where the slope stretches the scale).
  const double raw = std::round((corrected - calibration.intercept) / calibration.slope);
  return static_cast<std::int32_t>(std::clamp(raw, 0.0, static_cast<double>(maxCode())));
}

double ChannelChain::fullScaleEngineering() const {
  // The smaller magnitude of the two end codes (for +/-10 V: 10 V - 1 LSB), so
  // that a clipped sample, which reads exactly the end code, counts as >= full scale.
  const double top = std::abs(engineeringFromVolts(voltsFromCode(maxCode())));
  const double bottom = std::abs(engineeringFromVolts(voltsFromCode(0)));
  return std::min(top, bottom);
}

core::Result<void> validateChain(const ChannelChain& chain, const std::string& where) {
  auto bad = [&](const std::string& m) { return core::makeError(core::ErrorCode::InvalidArgument, m, where); };
  if (!(chain.range.maxVolts > chain.range.minVolts)) return bad("the input range is empty");
  if (chain.resolutionBits < 1 || chain.resolutionBits > 24) return bad("the ADC resolution must be 1 to 24 bits");
  if (!std::isfinite(chain.conditionerGain) || chain.conditionerGain <= 0.0)
    return bad("the conditioner gain must be positive");
  if (!std::isfinite(chain.transducer.sensitivityMvPerUnit) || chain.transducer.sensitivityMvPerUnit <= 0.0)
    return bad("the transducer sensitivity must be positive (mV per engineering unit)");
  if (!std::isfinite(chain.calibration.slope) || chain.calibration.slope == 0.0 ||
      !std::isfinite(chain.calibration.intercept))
    return bad("the device calibration slope must be finite and non-zero");
  return {};
}

}  // namespace mozzi::devices
