#include "app/cli/args.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "app/cli/command.h"

namespace mozzi::cli {

using core::ErrorCode;
using core::makeError;

namespace {

std::string numberText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream s(text);
  while (std::getline(s, item, sep)) out.push_back(item);
  if (!text.empty() && text.back() == sep) out.emplace_back();  // "1,2," has an empty last field
  if (text.empty()) out.emplace_back();
  return out;
}

}  // namespace

std::string NumberRange::text() const {
  std::string s = integer ? "whole number in " : "";
  s += (minOpen ? "(" : "[") + numberText(min) + ", " + numberText(max) + (maxOpen ? ")" : "]");
  if (!unit.empty()) s += " " + unit;
  return s;
}

bool NumberRange::contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (minOpen ? !(v > min) : !(v >= min)) return false;
  if (maxOpen ? !(v < max) : !(v <= max)) return false;
  if (integer && std::floor(v) != v) return false;
  return true;
}

NumberRange closed(double min, double max, std::string unit) {
  return NumberRange(min, max, false, false, false, std::move(unit));
}
NumberRange aboveTo(double min, double max, std::string unit) {
  return NumberRange(min, max, true, false, false, std::move(unit));
}
NumberRange wholeNumber(double min, double max) {
  return NumberRange(min, max, false, false, true);
}

std::string NumberOption::rangeText() const {
  if (fields.empty()) return range.text();
  std::string s;
  for (const auto& f : fields) s += (s.empty() ? "" : ", ") + f.name + " " + f.range.text();
  return s;
}

const NumberOption* OptionSpec::numberOption(const std::string& name) const {
  for (const auto& n : numbers) {
    if (n.name == name) return &n;
  }
  return nullptr;
}

std::string OptionSpec::helpText() const {
  std::ostringstream text;
  if (!numbers.empty()) text << "Numeric options and their valid ranges:\n";
  for (const auto& n : numbers) {
    std::string name = n.name;
    if (!n.fields.empty()) {
      std::string form;
      for (const auto& f : n.fields) form += (form.empty() ? "" : std::string(1, n.separator)) + f.name;
      name += " " + form + (n.repeated ? ",..." : "");
    }
    text << "  " << name << (name.size() < 28 ? std::string(28 - name.size(), ' ') : " ") << n.help << ": "
         << n.rangeText() << "\n";
  }
  if (!outputs.empty()) {
    text << "Files written (";
    bool first = true;
    for (const auto& o : outputs) {
      text << (first ? "" : ", ") << o;
      first = false;
    }
    text << ") go to a temporary file renamed into place; the input itself is refused (docs/cli.md).\n";
  }
  return text.str();
}

std::string quotedArg(const std::string& text) {
  constexpr std::size_t kShown = 40;
  if (text.size() <= kShown) return "'" + text + "'";
  return "'" + text.substr(0, kShown) + "...' (" + std::to_string(text.size()) + " characters)";
}

core::Result<double> parseInRange(const std::string& text, const NumberRange& range, const std::string& what) {
  if (text.empty()) return makeError(ErrorCode::InvalidArgument, what + " is empty; valid: " + range.text(), what);
  if (text.size() > 64) {
    return makeError(ErrorCode::InvalidArgument,
                     what + " is not a number: " + quotedArg(text) + "; valid: " + range.text(), what);
  }
  const char* begin = text.c_str();
  while (*begin == ' ' || *begin == '\t') ++begin;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  while (end && (*end == ' ' || *end == '\t' || *end == '\r')) ++end;
  if (end == begin || end != text.c_str() + text.size()) {
    return makeError(ErrorCode::InvalidArgument,
                     what + " is not a number: " + quotedArg(text) + "; valid: " + range.text(), what);
  }
  if (!std::isfinite(v) || errno == ERANGE || std::fpclassify(v) == FP_SUBNORMAL) {
    // ERANGE: 1e400 overflows to inf, 1e-320 underflows to a subnormal or 0;
    // no quantity here is meant that way.
    return makeError(ErrorCode::InvalidArgument,
                     what + " = " + quotedArg(text) + " is " +
                         (std::isnan(v)       ? "not a number"
                          : !std::isfinite(v) ? "infinite"
                          : std::abs(v) > 1.0 ? "beyond the range of a double"
                                              : "below the smallest normal double") +
                         "; valid: " + range.text(),
                     what);
  }
  if (auto r = checkInRange(v, range, what); !r) return r.error();
  return v;
}

core::Result<void> checkInRange(double value, const NumberRange& range, const std::string& what) {
  if (range.contains(value)) return {};
  return makeError(ErrorCode::InvalidArgument,
                   what + " = " + numberText(value) + " is out of range; valid: " + range.text(), what);
}

core::Result<ParsedArgs> ParsedArgs::parse(const std::vector<std::string>& args, const OptionSpec& spec) {
  ParsedArgs parsed;
  bool onlyPositional = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    auto tooLong = [&](const std::string& what, const std::string& text) {
      return makeError(ErrorCode::InvalidArgument,
                       what + " is " + std::to_string(text.size()) + " characters long; at most " +
                           std::to_string(kMaxArgumentLength) + " are accepted",
                       what);
    };
    if (onlyPositional || arg.size() < 2 || arg.compare(0, 2, "--") != 0) {
      if (arg.size() > kMaxArgumentLength)
        return tooLong("argument " + std::to_string(i + 1) + " " + quotedArg(arg), arg);
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
    if (name.size() > 64) return makeError(ErrorCode::ParseError, "unknown option " + quotedArg(name), quotedArg(name));
    if (spec.flags.count(name)) {
      if (inlineValue) return makeError(ErrorCode::ParseError, "option " + name + " takes no value", arg);
      parsed.flags_.insert(name);
    } else if (spec.valued.count(name) || spec.numberOption(name)) {
      if (inlineValue) {
        parsed.values_[name] = *inlineValue;
      } else if (i + 1 < args.size()) {
        parsed.values_[name] = args[++i];
      } else {
        return makeError(ErrorCode::ParseError, "option " + name + " needs a value", arg);
      }
      if (parsed.values_[name].size() > kMaxArgumentLength) {
        return tooLong("the value of option " + name, parsed.values_[name]);
      }
    } else {
      return makeError(ErrorCode::ParseError, "unknown option " + quotedArg(name), name);
    }
  }
  // Numeric options: every value checked against its declared range now,
  // before the command does any work.
  for (const auto& option : spec.numbers) {
    const auto it = parsed.values_.find(option.name);
    if (it == parsed.values_.end()) continue;
    std::vector<double> values;
    if (option.fields.empty()) {
      auto v = parseInRange(it->second, option.range, "option " + option.name);
      if (!v) return v.error();
      values.push_back(*v);
    } else {
      const auto tuples = option.repeated ? split(it->second, ',') : std::vector<std::string>{it->second};
      if (tuples.size() > option.maxTuples) {
        return makeError(ErrorCode::InvalidArgument,
                         "option " + option.name + " lists " + std::to_string(tuples.size()) + " items; at most " +
                             std::to_string(option.maxTuples) + " are accepted",
                         option.name);
      }
      std::string form;
      for (const auto& f : option.fields) form += (form.empty() ? "" : std::string(1, option.separator)) + f.name;
      for (std::size_t t = 0; t < tuples.size(); ++t) {
        const auto fields = split(tuples[t], option.separator);
        if (fields.size() != option.fields.size()) {
          return makeError(ErrorCode::InvalidArgument,
                           "option " + option.name + " needs " + form + (option.repeated ? "[,...]" : "") + ", got " +
                               quotedArg(option.repeated ? tuples[t] : it->second),
                           option.name);
        }
        for (std::size_t f = 0; f < fields.size(); ++f) {
          const std::string what = "option " + option.name + " " + option.fields[f].name +
                                   (option.repeated ? " (item " + std::to_string(t + 1) + ")" : "");
          auto v = parseInRange(fields[f], option.fields[f].range, what);
          if (!v) return v.error();
          values.push_back(*v);
        }
      }
    }
    parsed.numbers_[option.name] = std::move(values);
  }
  return parsed;
}

std::optional<std::string> ParsedArgs::value(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

core::Result<std::optional<double>> ParsedArgs::number(const std::string& name) const {
  if (const auto it = numbers_.find(name); it != numbers_.end() && it->second.size() == 1) {
    return std::optional<double>{it->second.front()};
  }
  const auto text = value(name);
  if (!text) return std::optional<double>{};
  char* end = nullptr;
  const double v = std::strtod(text->c_str(), &end);
  if (text->empty() || end != text->c_str() + text->size() || !std::isfinite(v)) {
    return makeError(ErrorCode::InvalidArgument, "option " + name + " needs a finite number, got " + quotedArg(*text),
                     name);
  }
  return std::optional<double>{v};
}

std::vector<double> ParsedArgs::numbers(const std::string& name) const {
  const auto it = numbers_.find(name);
  return it == numbers_.end() ? std::vector<double>{} : it->second;
}

int exitCodeFor(const core::Error& e) {
  return e.code == ErrorCode::ParseError ? kExitUsage : kExitFailure;
}

}  // namespace mozzi::cli
