// Tyre test file readers (core/tire/tire_csv.h): values as written, and every
// bad input an error that names the file and line.
#include "core/tire/tire_csv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace mozzi::core::tire {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

void expectError(const std::string& text, const std::vector<std::string>& required, const std::string& what,
                 const std::string& where) {
  auto t = parseNumericTable(text, "f.csv", required);
  ASSERT_FALSE(t) << text;
  EXPECT_NE(t.error().message.find(what), std::string::npos) << t.error().describe();
  EXPECT_EQ(t.error().where, where) << t.error().describe();
}

TEST(TireCsv, ReadsNumbersUnderTheHeaderSkippingCommentsAndBlankLines) {
  auto t = parseNumericTable("# comment\r\n\r\n a , b \r\n1, 2.5e-1\r\n# again\n-3,4\n", "f.csv", {"b"});
  ASSERT_TRUE(t) << t.error().describe();
  EXPECT_EQ(t->header, (std::vector<std::string>{"a", "b"}));
  ASSERT_EQ(t->rows.size(), 2u);
  EXPECT_EQ(t->rows[0][1], 0.25);
  EXPECT_EQ(t->rows[1][0], -3.0);
  EXPECT_EQ(t->lines, (std::vector<int>{4, 6}));
  EXPECT_EQ(t->column("b"), 1);
  EXPECT_EQ(t->column("c"), -1);
}

TEST(TireCsv, BadTablesNameTheLine) {
  expectError("a,b\n1,2\n3\n", {}, "expected 2 columns, found 1", "f.csv:3");
  expectError("a,b\n1,x\n", {}, "column b is not a finite number: 'x'", "f.csv:2");
  expectError("a,b\n1,nan\n", {}, "not a finite number", "f.csv:2");
  expectError("a,b\n1,1e999\n", {}, "not a finite number", "f.csv:2");
  expectError("a,b\n1,\n", {}, "not a finite number", "f.csv:2");
  expectError("a,a\n1,2\n", {}, "appears twice", "f.csv:1");
  expectError("a,,b\n", {}, "empty column name", "f.csv:1");
  expectError("a,b\n1,2\n", {"c"}, "missing column 'c'", "f.csv");
  expectError("a,b\n", {}, "no data rows", "f.csv");
  expectError("# only a comment\n", {}, "no header", "f.csv");
  EXPECT_FALSE(readNumericTable("/nonexistent/yaw.csv", {}));
}

TEST(TireCsv, HarmonicYawRecordsSplitAtEachFrequency) {
  std::string text = "frequency_hz,time_s,yaw_rate_rad_s,lateral_force_n\n";
  for (int i = 0; i < 5; ++i) text += "0.84," + std::to_string(i * 0.01) + "," + std::to_string(i) + ",-1\n";
  for (int i = 0; i < 4; ++i) text += "1.68," + std::to_string(i * 0.02) + ",0," + std::to_string(i) + "\n";
  auto t = parseNumericTable(text, "y.csv", harmonicYawColumns());
  ASSERT_TRUE(t);
  auto r = harmonicYawRecords(*t, "y.csv");
  ASSERT_TRUE(r) << r.error().describe();
  ASSERT_EQ(r->size(), 2u);
  EXPECT_EQ((*r)[0].excitationFrequencyHz, 0.84);
  EXPECT_NEAR((*r)[0].sampleRateHz, 100.0, 1e-9);
  EXPECT_NEAR((*r)[1].sampleRateHz, 50.0, 1e-9);
  EXPECT_EQ((*r)[0].yawRate.size(), 5);
  EXPECT_EQ((*r)[0].yawRate[4], 4.0);
  EXPECT_EQ((*r)[1].lateralForce[3], 3.0);

  auto fewer = parseNumericTable("frequency_hz,time_s,yaw_rate_rad_s,lateral_force_n\n1,0,0,0\n1,0.1,0,0\n2,0,0,0\n",
                                 "y.csv", harmonicYawColumns());
  ASSERT_TRUE(fewer);
  auto e = harmonicYawRecords(*fewer, "y.csv");
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().where, "y.csv:2");
  auto jump = parseNumericTable(
      "frequency_hz,time_s,yaw_rate_rad_s,lateral_force_n\n1,0,0,0\n1,0.1,0,0\n1,0.3,0,0\n"
      "1,0.3,0,0\n",
      "y.csv", harmonicYawColumns());
  ASSERT_TRUE(jump);
  auto j = harmonicYawRecords(*jump, "y.csv");
  ASSERT_FALSE(j);
  EXPECT_NE(j.error().message.find("uniformly"), std::string::npos);
  EXPECT_EQ(j.error().where, "y.csv:4");
}

TEST(TireCsv, SteadyStateRowsGroupIntoSlipAndCamberSweeps) {
  const std::string text =
      "slip_deg,camber_deg,load_n,pressure_bar,force_n,torque_nm\n"
      "0,0,400,4,0,0\n1,0,400,4,70,-0.5\n2,0,400,4,140,-1\n3,0,400,4,210,-1.5\n"
      "0,2,400,4,10,0.1\n0,4,400,4,20,0.2\n0,6,400,4,30,0.3\n"
      "0,0,600,2,0,0\n1,0,600,2,90,-0.7\n2,0,600,2,180,-1.4\n3,0,600,2,270,-2.1\n";
  auto t = parseNumericTable(text, "s.csv", steadyStateColumns());
  ASSERT_TRUE(t);
  auto s = steadyStateSweeps(*t, "s.csv");
  ASSERT_TRUE(s) << s.error().describe();
  // Slip at 400 N (4 rows), camber at 400 N (the zero row + 3), slip at 600 N.
  ASSERT_EQ(s->size(), 3u);
  EXPECT_FALSE((*s)[0].camberSweep);
  EXPECT_EQ((*s)[0].sweep.verticalLoad, 400.0);
  EXPECT_EQ((*s)[0].sweep.pressure, 4e5);
  EXPECT_EQ((*s)[0].firstLine, 2);
  EXPECT_NEAR((*s)[0].sweep.angle[3], 3.0 * kDeg, 1e-15);
  EXPECT_TRUE((*s)[1].camberSweep);
  EXPECT_EQ((*s)[1].sweep.angle.size(), 4);
  EXPECT_NEAR((*s)[1].sweep.angle[3], 6.0 * kDeg, 1e-15);
  EXPECT_EQ((*s)[2].sweep.verticalLoad, 600.0);
  EXPECT_EQ((*s)[2].firstLine, 9);
  // The 600 N, 2 bar point 0,0 is a lone camber "sweep": left out.
  const auto pts = steadyStatePoints(*t);
  ASSERT_EQ(pts.size(), 11u);
  EXPECT_NEAR(pts[4].camber, 2.0 * kDeg, 1e-15);
  EXPECT_EQ(pts[8].pressure, 2e5);
}

TEST(TireCsv, NumberTuples) {
  auto t = parseNumberTuples("0:103:0.03, 1:140:0.02", 3, "--modes");
  ASSERT_TRUE(t) << t.error().describe();
  ASSERT_EQ(t->size(), 2u);
  EXPECT_EQ((*t)[1][1], 140.0);
  for (const char* bad : {"", "1:2", "1:2:3,", "1:2:x", "1::3", "1:2:3:4"}) {
    auto e = parseNumberTuples(bad, 3, "--modes");
    ASSERT_FALSE(e) << bad;
    EXPECT_EQ(e.error().where, "--modes");
  }
}

}  // namespace
}  // namespace mozzi::core::tire
