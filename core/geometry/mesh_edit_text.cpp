// The text forms of the mesh editor's DOF lists and slave rules
// (core/geometry/mesh_edit.h): parsing what the user types, formatting what the
// tables show.

#include "core/geometry/mesh_edit.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace mozzi::core::geometry {

namespace {

std::vector<std::string> tokens(std::string_view text, bool splitOnSigns) {
  std::vector<std::string> out;
  std::string current;
  auto flush = [&]() {
    if (!current.empty()) out.push_back(current);
    current.clear();
  };
  for (char c : text) {
    if (c == ' ' || c == '\t' || c == ',' || c == ';' || c == '*') {
      flush();
    } else if (splitOnSigns && (c == '+' || c == '-') && current.empty()) {
      out.push_back(std::string(1, c));
    } else {
      current += c;
    }
  }
  flush();
  return out;
}

}  // namespace

Result<std::vector<Dof>> parseNodeDofs(int node, std::string_view text) {
  std::vector<Dof> out;
  for (const auto& token : tokens(text, false)) {
    auto dof = parseDof(std::to_string(node) + ":" + token);
    if (!dof) {
      return makeError(ErrorCode::ParseError, "'" + token + "' is not a direction (X, Y, Z, RX, RY, RZ with + or -)",
                       "node " + std::to_string(node));
    }
    out.push_back(*dof);
  }
  return out;
}

std::string formatNodeDofs(const std::vector<Dof>& dofs) {
  std::string text;
  for (const auto& d : dofs) {
    if (!text.empty()) text += ' ';
    text += (d.negative ? "-" : "+");
    text += directionName(d.direction);
  }
  return text;
}

Result<io::SlavedDof> parseSlaveRule(std::string_view text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string_view::npos) {
    return makeError(ErrorCode::ParseError, "a rule reads 'slave = weight master + ...'",
                     std::string(text.substr(0, 60)));
  }
  const auto left = tokens(text.substr(0, eq), false);
  if (left.size() != 1) return makeError(ErrorCode::ParseError, "one slave DOF before '='", "slave rule");
  auto slave = parseDof(left.front());
  if (!slave) return makeError(ErrorCode::ParseError, "'" + left.front() + "' is not a DOF such as 5:+Z", "slave rule");
  io::SlavedDof rule;
  rule.slave = *slave;
  // Terms: [sign] [weight] DOF. A DOF token has a ':' or a direction letter
  // after the node number; a weight is a plain number.
  const std::string rest(text.substr(eq + 1));
  std::vector<std::string> parts;
  {
    // Split signs only where they start a term: after '=' or after a DOF.
    std::string current;
    for (std::size_t i = 0; i < rest.size(); ++i) {
      const char c = rest[i];
      const bool signStartsTerm = (c == '+' || c == '-') && (i == 0 || rest[i - 1] == ' ' || rest[i - 1] == '\t') &&
                                  (i + 1 < rest.size() && (rest[i + 1] == ' ' || rest[i + 1] == '\t'));
      if (signStartsTerm) {
        if (!current.empty()) parts.push_back(current);
        parts.push_back(std::string(1, c));
        current.clear();
      } else if (c == ' ' || c == '\t' || c == '*') {
        if (!current.empty()) parts.push_back(current);
        current.clear();
      } else {
        current += c;
      }
    }
    if (!current.empty()) parts.push_back(current);
  }
  double sign = 1.0;
  std::optional<double> weight;
  for (const auto& part : parts) {
    if (part == "+" || part == "-") {
      if (weight) return makeError(ErrorCode::ParseError, "a weight needs a DOF after it", "slave rule");
      if (part == "-") sign = -sign;
      continue;
    }
    if (part.find(':') == std::string::npos) {
      char* end = nullptr;
      const double v = std::strtod(part.c_str(), &end);
      if (end && *end == '\0' && std::isfinite(v)) {
        if (weight) return makeError(ErrorCode::ParseError, "two weights in a row: '" + part + "'", "slave rule");
        weight = v;
        continue;
      }
    }
    auto master = parseDof(part);
    if (!master) {
      return makeError(ErrorCode::ParseError, "'" + part.substr(0, 40) + "' is neither a weight nor a DOF",
                       "slave rule");
    }
    rule.masters.push_back({*master, sign * weight.value_or(1.0)});
    sign = 1.0;
    weight.reset();
  }
  if (weight) return makeError(ErrorCode::ParseError, "the last weight has no DOF", "slave rule");
  if (rule.masters.empty()) return makeError(ErrorCode::ParseError, "no master DOF after '='", "slave rule");
  return rule;
}

std::string formatSlaveRule(const io::SlavedDof& rule) {
  std::string text = formatDof(rule.slave) + " =";
  bool first = true;
  for (const auto& [master, weight] : rule.masters) {
    char buffer[48];
    const double w = first ? weight : std::abs(weight);
    std::snprintf(buffer, sizeof buffer, "%.17g", w);
    if (!first) text += weight < 0 ? " -" : " +";
    text += std::string(" ") + buffer + " " + formatDof(master);
    first = false;
  }
  return text;
}

}  // namespace mozzi::core::geometry
