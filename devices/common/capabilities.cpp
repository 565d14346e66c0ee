#include "devices/common/capabilities.h"

#include <cmath>

namespace mozzi::devices {

const char* couplingName(Coupling coupling) {
  return coupling == Coupling::Dc ? "DC" : "AC";
}

const char* triggerKindName(TriggerKind kind) {
  switch (kind) {
    case TriggerKind::Immediate: return "immediate";
    case TriggerKind::Software: return "software level";
    case TriggerKind::ExternalEdge: return "external edge";
    case TriggerKind::ExternalLevel: return "external level";
  }
  return "unknown";
}

core::Result<double> quantiseRate(const RateSpec& spec, double requestedHz) {
  if (!std::isfinite(requestedHz) || requestedHz <= 0.0)
    return core::makeError(core::ErrorCode::InvalidArgument, "the sample rate must be a positive number",
                           "sample rate");
  if (requestedHz < spec.minHz * (1.0 - 1e-12) || requestedHz > spec.maxHz * (1.0 + 1e-12))
    return core::makeError(core::ErrorCode::InvalidArgument,
                           "sample rate " + std::to_string(requestedHz) + " Hz is outside " +
                               std::to_string(spec.minHz) + " to " + std::to_string(spec.maxHz) + " Hz",
                           "sample rate");
  if (spec.timebaseHz <= 0.0) return requestedHz;
  const double divisor = std::max(1.0, std::round(spec.timebaseHz / requestedHz));
  return spec.timebaseHz / divisor;
}

}  // namespace mozzi::devices
