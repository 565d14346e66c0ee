#include "core/common/dof.h"

#include <gtest/gtest.h>

namespace mozzi::core {
namespace {

TEST(Dof, ParsesEveryAcceptedSpelling) {
  struct Case {
    const char* text;
    int node;
    Direction direction;
    bool negative;
  };
  const Case cases[] = {
      {"21:+Z", 21, Direction::Z, false},   {"21+Z", 21, Direction::Z, false},     {"21Z", 21, Direction::Z, false},
      {"21:z", 21, Direction::Z, false},    {"7-RX", 7, Direction::RX, true},      {"7:-4", 7, Direction::RX, true},
      {" 3:+ry ", 3, Direction::RY, false}, {"1001:-Y", 1001, Direction::Y, true},
  };
  for (const auto& c : cases) {
    const auto dof = parseDof(c.text);
    ASSERT_TRUE(dof.ok()) << c.text << ": " << dof.error().describe();
    EXPECT_EQ(dof->node, c.node) << c.text;
    EXPECT_EQ(dof->direction, c.direction) << c.text;
    EXPECT_EQ(dof->negative, c.negative) << c.text;
  }
}

TEST(Dof, FormatThenParseIsIdentityForAllUffCodes) {
  for (int code = -6; code <= 6; ++code) {
    if (code == 0) continue;
    const auto dof = dofFromUff(42, code);
    ASSERT_TRUE(dof.ok());
    EXPECT_EQ(dof->uffCode(), code);
    const auto back = parseDof(formatDof(*dof));
    ASSERT_TRUE(back.ok()) << formatDof(*dof);
    EXPECT_EQ(*back, *dof);
  }
  EXPECT_EQ(formatDof(Dof{21, Direction::Z, false}), "21:+Z");
  EXPECT_EQ(formatDof(Dof{5, Direction::RX, true}), "5:-RX");
}

TEST(Dof, RejectsMalformedLabelsWithTheTextInTheMessage) {
  for (const char* bad : {"", "Z", "21", "21:", "21:W", "21:+7", "21:0", "x21:+Z", "21:+ZZ"}) {
    const auto dof = parseDof(bad);
    ASSERT_FALSE(dof.ok()) << "accepted '" << bad << "'";
    EXPECT_EQ(dof.error().code, ErrorCode::ParseError);
    EXPECT_NE(dof.error().message.find(std::string("'") + bad + "'"), std::string::npos) << dof.error().message;
  }
  EXPECT_FALSE(dofFromUff(1, 0).ok());
  EXPECT_FALSE(dofFromUff(1, 7).ok());
  EXPECT_FALSE(dofFromUff(1, -7).ok());
}

}  // namespace
}  // namespace mozzi::core
