// A value with its standard uncertainty: two significant digits of the
// uncertainty, the value to the same decimal place (GUM 7.2.6), the cases a
// stiffness table meets (N/m in tens of thousands, degrees, a rounding that
// carries into a new digit, no uncertainty).
#include "core/common/text.h"

#include <gtest/gtest.h>

#include <limits>

namespace mozzi::core {
namespace {

TEST(Text, MeasuredValueToTheUncertaintysSecondDigit) {
  auto m = formatMeasured(55996.04, 6.1756);
  EXPECT_EQ(m.value, "55996.0");
  EXPECT_EQ(m.uncertainty, "6.2");
  m = formatMeasured(121337.0, 3421.0);
  EXPECT_EQ(m.value, "121300");
  EXPECT_EQ(m.uncertainty, "3400");
  m = formatMeasured(45.5321, 0.1234);
  EXPECT_EQ(m.value, "45.53");
  EXPECT_EQ(m.uncertainty, "0.12");
  m = formatMeasured(-0.004567, 0.000996);  // 0.000996 rounds to 0.0010: one place fewer
  EXPECT_EQ(m.value, "-0.0046");
  EXPECT_EQ(m.uncertainty, "0.0010");
  m = formatMeasured(0.1, 0.125);  // the uncertainty rounded once, up: 0.13
  EXPECT_EQ(m.uncertainty, "0.13");
  m = formatMeasured(-0.004, 0.3);  // rounds to zero: no sign
  EXPECT_EQ(m.value, "0.00");
  m = formatMeasured(3e-17, 1e-18);  // past 1e-9: significant digits, not zeros
  EXPECT_EQ(m.value, "3e-17");
  EXPECT_EQ(m.uncertainty, "1e-18");
  m = formatMeasured(1e70, 1.0);  // a diverged fit: its magnitude, not a cut string
  EXPECT_EQ(m.value, "1e+70");
  EXPECT_EQ(m.uncertainty, "1");
  m = formatMeasured(53485.2, 0.0);
  EXPECT_EQ(m.value, "53485");
  EXPECT_EQ(m.uncertainty, "");
  m = formatMeasured(1.0, std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(m.uncertainty, "");
}

}  // namespace
}  // namespace mozzi::core
