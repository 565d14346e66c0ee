#include "core/common/enum_names.h"

#include <gtest/gtest.h>

namespace mozzi::core {
namespace {

enum class Colour { Red, Green, Blue };

constexpr auto kColourNames =
    enumTable<Colour>({{Colour::Red, "red"}, {Colour::Green, "green"}, {Colour::Blue, "blue"}}, "?");
constexpr auto kColourCodes = enumTable<Colour>({{Colour::Red, 8}, {Colour::Green, 11}}, 0);

// Both directions are constant expressions.
static_assert(kColourCodes.of(Colour::Green) == 11);
static_assert(kColourCodes.of(Colour::Blue) == 0);  // not in the table: the fallback
static_assert(*kColourCodes.find(8) == Colour::Red);
static_assert(!kColourCodes.find(12).has_value());

TEST(EnumNames, NameOfValueAndValueOfName) {
  EXPECT_STREQ(kColourNames.of(Colour::Blue), "blue");
  EXPECT_STREQ(kColourNames.of(static_cast<Colour>(7)), "?");
  EXPECT_EQ(kColourNames.find("green"), Colour::Green);
  EXPECT_FALSE(kColourNames.find("Green").has_value());
  EXPECT_EQ(kColourNames.find("GrEeN", NameCase::Ignore), Colour::Green);
  EXPECT_FALSE(kColourNames.find("gree", NameCase::Ignore).has_value());
}

TEST(EnumNames, ParseErrorNamesTheTextAndTheAcceptedNames) {
  EXPECT_EQ(acceptedNames(kColourNames), "red, green or blue");
  const auto ok = parseEnum(kColourNames, "BLUE", "colour", "test", NameCase::Ignore);
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(*ok, Colour::Blue);
  const auto bad = parseEnum(kColourNames, "BLUE", "colour", "test");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().code, ErrorCode::ParseError);
  EXPECT_EQ(bad.error().message, "unknown colour 'BLUE' (expected red, green or blue)");
  EXPECT_EQ(bad.error().where, "test");
}

}  // namespace
}  // namespace mozzi::core
