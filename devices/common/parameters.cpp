#include "devices/common/parameters.h"

#include <algorithm>
#include <cmath>

namespace mozzi::devices {

const char* parameterTypeName(ParameterType type) {
  switch (type) {
    case ParameterType::Bool: return "bool";
    case ParameterType::Integer: return "integer";
    case ParameterType::Real: return "real";
    case ParameterType::Choice: return "choice";
    case ParameterType::Text: return "text";
  }
  return "unknown";
}

namespace {

core::Error bad(const ParameterSpec& spec, const std::string& what) {
  return core::makeError(core::ErrorCode::InvalidArgument, what, "parameter " + spec.key);
}

core::Result<void> checkBounds(const ParameterSpec& spec, double v) {
  if (!std::isfinite(v)) return bad(spec, "value is not finite");
  if (spec.min && v < *spec.min)
    return bad(spec,
               "value " + std::to_string(v) + " is below the minimum " + std::to_string(*spec.min) + " " + spec.unit);
  if (spec.max && v > *spec.max)
    return bad(spec,
               "value " + std::to_string(v) + " is above the maximum " + std::to_string(*spec.max) + " " + spec.unit);
  return {};
}

}  // namespace

core::Result<ParameterValue> validateParameter(const ParameterSpec& spec, const ParameterValue& value) {
  switch (spec.type) {
    case ParameterType::Bool:
      if (!std::holds_alternative<bool>(value)) return bad(spec, "expected true or false");
      return value;
    case ParameterType::Integer: {
      if (!std::holds_alternative<std::int64_t>(value)) return bad(spec, "expected an integer");
      auto ok = checkBounds(spec, static_cast<double>(std::get<std::int64_t>(value)));
      if (!ok) return ok.error();
      return value;
    }
    case ParameterType::Real: {
      double v = 0.0;
      if (std::holds_alternative<double>(value))
        v = std::get<double>(value);
      else if (std::holds_alternative<std::int64_t>(value))
        v = static_cast<double>(std::get<std::int64_t>(value));
      else
        return bad(spec, "expected a number");
      auto ok = checkBounds(spec, v);
      if (!ok) return ok.error();
      return ParameterValue(v);
    }
    case ParameterType::Choice: {
      if (!std::holds_alternative<std::string>(value)) return bad(spec, "expected one of the listed choices");
      const auto& s = std::get<std::string>(value);
      if (std::find(spec.choices.begin(), spec.choices.end(), s) == spec.choices.end())
        return bad(spec, "'" + s + "' is not one of the choices");
      return value;
    }
    case ParameterType::Text:
      if (!std::holds_alternative<std::string>(value)) return bad(spec, "expected text");
      return value;
  }
  return bad(spec, "unknown parameter type");
}

core::Result<ParameterMap> applyParameters(const std::vector<ParameterSpec>& specs, const ParameterMap& values) {
  ParameterMap applied;
  for (const auto& [key, value] : values) {
    auto it = std::find_if(specs.begin(), specs.end(), [&](const ParameterSpec& s) { return s.key == key; });
    if (it == specs.end())
      return core::makeError(core::ErrorCode::InvalidArgument, "the device has no parameter with this key",
                             "parameter " + key);
    auto v = validateParameter(*it, value);
    if (!v) return v.error();
    applied[key] = *v;
  }
  for (const auto& spec : specs)
    if (!applied.count(spec.key)) applied[spec.key] = spec.defaultValue;
  return applied;
}

double parameterReal(const ParameterMap& map, const std::string& key, double fallback) {
  auto it = map.find(key);
  if (it == map.end()) return fallback;
  if (std::holds_alternative<double>(it->second)) return std::get<double>(it->second);
  if (std::holds_alternative<std::int64_t>(it->second)) return static_cast<double>(std::get<std::int64_t>(it->second));
  return fallback;
}

std::int64_t parameterInteger(const ParameterMap& map, const std::string& key, std::int64_t fallback) {
  auto it = map.find(key);
  if (it == map.end() || !std::holds_alternative<std::int64_t>(it->second)) return fallback;
  return std::get<std::int64_t>(it->second);
}

bool parameterBool(const ParameterMap& map, const std::string& key, bool fallback) {
  auto it = map.find(key);
  if (it == map.end() || !std::holds_alternative<bool>(it->second)) return fallback;
  return std::get<bool>(it->second);
}

std::string parameterText(const ParameterMap& map, const std::string& key, const std::string& fallback) {
  auto it = map.find(key);
  if (it == map.end() || !std::holds_alternative<std::string>(it->second)) return fallback;
  return std::get<std::string>(it->second);
}

}  // namespace mozzi::devices
