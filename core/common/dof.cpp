#include "core/common/dof.h"

#include <cctype>
#include <charconv>

namespace mozzi::core {

const char* directionName(Direction direction) {
  switch (direction) {
    case Direction::X: return "X";
    case Direction::Y: return "Y";
    case Direction::Z: return "Z";
    case Direction::RX: return "RX";
    case Direction::RY: return "RY";
    case Direction::RZ: return "RZ";
  }
  return "?";
}

Result<Dof> dofFromUff(int node, int directionCode) {
  const int magnitude = directionCode < 0 ? -directionCode : directionCode;
  if (magnitude < 1 || magnitude > 6) {
    return makeError(ErrorCode::InvalidArgument,
                     "direction code " + std::to_string(directionCode) + " is not one of +/-1..6",
                     "node " + std::to_string(node));
  }
  return Dof{node, static_cast<Direction>(magnitude), directionCode < 0};
}

std::string formatDof(const Dof& dof) {
  return std::to_string(dof.node) + ":" + (dof.negative ? "-" : "+") + directionName(dof.direction);
}

Result<Dof> parseDof(std::string_view text) {
  auto fail = [&](const std::string& why) -> Result<Dof> {
    return makeError(ErrorCode::ParseError, "'" + std::string(text) + "' is not a DOF label like 21:+Z (" + why + ")",
                     "DOF label");
  };
  std::size_t pos = 0;
  while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
  std::size_t end = text.size();
  while (end > pos && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  const std::string_view body = text.substr(pos, end - pos);

  int node = 0;
  const auto [nodeEnd, ec] = std::from_chars(body.data(), body.data() + body.size(), node);
  if (ec != std::errc() || nodeEnd == body.data()) return fail("no node number");
  std::string_view rest(nodeEnd, static_cast<std::size_t>(body.data() + body.size() - nodeEnd));
  if (!rest.empty() && rest.front() == ':') rest.remove_prefix(1);
  bool negative = false;
  if (!rest.empty() && (rest.front() == '+' || rest.front() == '-')) {
    negative = rest.front() == '-';
    rest.remove_prefix(1);
  }
  if (rest.empty()) return fail("no direction");

  if (std::isdigit(static_cast<unsigned char>(rest.front()))) {
    if (rest.size() != 1 || rest.front() < '1' || rest.front() > '6') return fail("direction code must be 1..6");
    return Dof{node, static_cast<Direction>(rest.front() - '0'), negative};
  }
  std::string upper;
  for (char c : rest) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  static constexpr Direction kAll[] = {Direction::X,  Direction::Y,  Direction::Z,
                                       Direction::RX, Direction::RY, Direction::RZ};
  for (Direction d : kAll) {
    if (upper == directionName(d)) return Dof{node, d, negative};
  }
  return fail("direction must be X, Y, Z, RX, RY or RZ");
}

}  // namespace mozzi::core
