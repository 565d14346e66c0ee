#pragma once
// Rig parameters as data (STYLE 2): a device declares what can be set, with
// type, unit, range and choices, so the GUI builds its forms and the CLI its
// options from the same list, and configure() validates against it.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/common/result.h"

namespace mozzi::devices {

enum class ParameterType { Bool, Integer, Real, Choice, Text };

const char* parameterTypeName(ParameterType type);  // "bool", "integer", ...

using ParameterValue = std::variant<bool, std::int64_t, double, std::string>;

struct ParameterSpec {
  std::string key;    // stable identifier, e.g. "fault.double_hit_probability"
  std::string label;  // short English label (views translate)
  ParameterType type = ParameterType::Real;
  std::string unit;           // SI unit text, e.g. "Hz", "N", "" for none
  std::optional<double> min;  // inclusive bounds for Integer and Real
  std::optional<double> max;
  std::vector<std::string> choices;  // for Choice
  ParameterValue defaultValue = 0.0;
  std::string help;  // one sentence: what it does and where the default comes from
};

using ParameterMap = std::map<std::string, ParameterValue>;

// Checks one value against its spec (type, bounds, choices); integers are
// accepted for Real parameters. The error names the key.
core::Result<ParameterValue> validateParameter(const ParameterSpec& spec, const ParameterValue& value);

// Every key in `values` must be declared in `specs`; missing keys take their
// defaults. Returns the complete applied map.
core::Result<ParameterMap> applyParameters(const std::vector<ParameterSpec>& specs, const ParameterMap& values);

// Typed reads from an applied map (the key must be present and of that type).
double parameterReal(const ParameterMap& map, const std::string& key, double fallback);
std::int64_t parameterInteger(const ParameterMap& map, const std::string& key, std::int64_t fallback);
bool parameterBool(const ParameterMap& map, const std::string& key, bool fallback);
std::string parameterText(const ParameterMap& map, const std::string& key, const std::string& fallback);

}  // namespace mozzi::devices
