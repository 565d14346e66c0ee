#pragma once
// A measurement degree of freedom: node id plus signed direction in the node's
// coordinate system, as in UFF (direction codes 1..6 = X, Y, Z, RX, RY, RZ,
// negative code = negative direction).

#include <string>
#include <string_view>

#include "core/common/result.h"

namespace mozzi::core {

enum class Direction { X = 1, Y = 2, Z = 3, RX = 4, RY = 5, RZ = 6 };

struct Dof {
  int node = 0;
  Direction direction = Direction::X;
  bool negative = false;

  // UFF direction code: +/-1..6.
  int uffCode() const { return negative ? -static_cast<int>(direction) : static_cast<int>(direction); }
  bool isRotation() const { return static_cast<int>(direction) >= 4; }

  friend bool operator==(const Dof& a, const Dof& b) {
    return a.node == b.node && a.direction == b.direction && a.negative == b.negative;
  }
  friend bool operator!=(const Dof& a, const Dof& b) { return !(a == b); }
  friend bool operator<(const Dof& a, const Dof& b) {
    if (a.node != b.node) return a.node < b.node;
    if (a.direction != b.direction) return a.direction < b.direction;
    return a.negative < b.negative;
  }
};

const char* directionName(Direction direction);  // "X", ..., "RZ"

// From a UFF direction code (+/-1..6); 0 and other values are an error.
Result<Dof> dofFromUff(int node, int directionCode);

// Canonical text "21:+Z". parseDof also accepts "21+Z", "21:Z", "21Z", "21-RX",
// "21:-3" (UFF code) and lower case; anything else is a parse error naming the text.
std::string formatDof(const Dof& dof);
Result<Dof> parseDof(std::string_view text);

}  // namespace mozzi::core
