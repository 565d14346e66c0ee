#include "app/cli/args.h"

#include <cmath>
#include <cstdlib>

namespace mozzi::cli {

using core::ErrorCode;
using core::makeError;

core::Result<ParsedArgs> ParsedArgs::parse(const std::vector<std::string>& args, const OptionSpec& spec) {
  ParsedArgs parsed;
  bool onlyPositional = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (onlyPositional || arg.size() < 2 || arg.compare(0, 2, "--") != 0) {
      parsed.positional_.push_back(arg);
      continue;
    }
    if (arg == "--") {
      onlyPositional = true;
      continue;
    }
    std::string name = arg;
    std::optional<std::string> inlineValue;
    if (const auto eq = arg.find('='); eq != std::string::npos) {
      name = arg.substr(0, eq);
      inlineValue = arg.substr(eq + 1);
    }
    if (spec.flags.count(name)) {
      if (inlineValue) return makeError(ErrorCode::InvalidArgument, "option " + name + " takes no value", arg);
      parsed.flags_.insert(name);
    } else if (spec.valued.count(name)) {
      if (inlineValue) {
        parsed.values_[name] = *inlineValue;
      } else if (i + 1 < args.size()) {
        parsed.values_[name] = args[++i];
      } else {
        return makeError(ErrorCode::InvalidArgument, "option " + name + " needs a value", arg);
      }
    } else {
      return makeError(ErrorCode::InvalidArgument, "unknown option " + name, arg);
    }
  }
  return parsed;
}

std::optional<std::string> ParsedArgs::value(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

core::Result<std::optional<double>> ParsedArgs::number(const std::string& name) const {
  const auto text = value(name);
  if (!text) return std::optional<double>{};
  char* end = nullptr;
  const double v = std::strtod(text->c_str(), &end);
  if (text->empty() || end != text->c_str() + text->size() || !std::isfinite(v)) {
    return makeError(ErrorCode::InvalidArgument, "option " + name + " needs a finite number, got '" + *text + "'",
                     name);
  }
  return std::optional<double>{v};
}

}  // namespace mozzi::cli
