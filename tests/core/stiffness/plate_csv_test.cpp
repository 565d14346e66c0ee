// The plate CSV reader the CLI (`mozzi-cli twist`, `mozzi`) and the Twist
// Axes page share (docs/cli/stiffness.md): geometry rows, headers kept, bad
// rows named by file and line, the kind told from the columns and the header,
// and the three interpretations against hand-worked values.
#include "core/stiffness/plate_csv.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mozzi::core::stiffness {
namespace {

const char* kGeometry = "sensor,0.2,-0.3\nsensor,0,-0.3\nsensor,0,0\nload,0,-0.5\n";

TEST(PlateCsv, GeometryHeaderAndRows) {
  const auto csv = parsePlateCsv(
      std::string("# a comment\n\n") + kGeometry + "force_N,d1_m,d2_m,d3_m\n300,1.0e-3,0.6e-3,0.2e-3\n", "s.csv", true);
  ASSERT_TRUE(csv.ok()) << csv.error().describe();
  ASSERT_EQ(csv->sensors.size(), 3u);
  EXPECT_EQ(csv->load, Vector2(0, -0.5));
  EXPECT_TRUE(csv->hasLoad);
  EXPECT_EQ(csv->header, (std::vector<std::string>{"force_N", "d1_m", "d2_m", "d3_m"}));
  ASSERT_EQ(csv->rows.size(), 1u);
  EXPECT_EQ(csv->rowLines, std::vector<int>{8});
  EXPECT_EQ(csv->where(), "s.csv:8");
  EXPECT_EQ(*guessPlateCsvKind(*csv), PlateCsvKind::Static);
  // notes.md eq. 5: the plane 0.2 mm + 2 u - 1.3333 v [mm/m] gives x_lat = 0.8667 mm at (0, -0.5).
  const auto r = staticTwistFromCsv(*csv);
  ASSERT_TRUE(r.ok()) << r.error().describe();
  EXPECT_NEAR(r->lateralStiffness, 300.0 / 0.8666666666666667e-3, 1e-6);
}

TEST(PlateCsv, BadRowsNameFileAndLine) {
  auto check = [](const std::string& text, const std::string& where, const std::string& what) {
    const auto csv = parsePlateCsv(text, "bad.csv", true);
    ASSERT_FALSE(csv.ok()) << text;
    EXPECT_EQ(csv.error().where, where) << csv.error().describe();
    EXPECT_NE(csv.error().message.find(what), std::string::npos) << csv.error().describe();
  };
  check(std::string(kGeometry) + "1,2,3,4\n1,nan,3,4\n", "bad.csv:6", "column 2");
  check(std::string(kGeometry) + "1,2,3,4\n1,x,3,4\n", "bad.csv:6", "column 2 is not a number: 'x'");
  check(std::string(kGeometry) + "1,2,3,4\n1,2,3\n", "bad.csv:6", "row has 3 fields, expected 4");
  check(std::string(kGeometry) + "1,2e10,3,4\n", "bad.csv:5", "out of range; valid: [-1e+09, 1e+09]");
  check("sensor,0,1\nsensor,0\n", "bad.csv:2", "expected 'sensor,u,v' with numbers");
  check("sensor,0,1000\n", "bad.csv:1", "sensor position = 1000 is out of range; valid: [-100, 100] m");
  check("sensor,0,0\nsensor,1,0\n1,2,3\n", "bad.csv", "at least 3 'sensor,u,v' rows");
  check(kGeometry, "bad.csv", "no data rows");
  EXPECT_FALSE(readPlateCsv("/nonexistent/plate.csv", true).ok());
  // Read without asking for sensors (as `mozzi` does), a file has none for the twist readers.
  const auto bare = parsePlateCsv("5,1,0,1,0,1,0\n", "bare.csv", false);
  ASSERT_TRUE(bare.ok());
  const auto sweep = sweepFromCsv(*bare);
  const auto modal = modalFrfFromCsv(*bare, FrfType::Receptance);
  const auto statics = staticTwistFromCsv(*bare);
  ASSERT_FALSE(sweep.ok() || modal.ok() || statics.ok());
  for (const Error& e : {sweep.error(), modal.error(), statics.error()}) {
    EXPECT_EQ(e.where, "bare.csv");
    EXPECT_NE(e.message.find("at least 3 'sensor,u,v' rows"), std::string::npos) << e.describe();
  }
}

TEST(PlateCsv, KindFromColumnsAndHeader) {
  auto kind = [](const std::string& rows) {
    auto csv = parsePlateCsv(std::string(kGeometry) + rows, "k.csv", true);
    EXPECT_TRUE(csv.ok());
    return guessPlateCsvKind(*csv);
  };
  EXPECT_EQ(*kind("1,2,3,4\n"), PlateCsvKind::Static);
  EXPECT_EQ(*kind("5,1,0,1,0,1,0,300,0\n"), PlateCsvKind::Dynamic);  // with the force columns
  EXPECT_EQ(*kind("freq_Hz,A1,phi1,A2,phi2,A3,phi3\n5,1,0,1,0,1,0\n"), PlateCsvKind::Dynamic);
  EXPECT_EQ(*kind("freq_Hz,Re1,Im1,Re2,Im2,Re3,Im3\n5,1,0,1,0,1,0\n"), PlateCsvKind::Modal);
  const auto ambiguous = kind("5,1,0,1,0,1,0\n");
  ASSERT_FALSE(ambiguous.ok());
  EXPECT_EQ(ambiguous.error().where, "k.csv:5");
  EXPECT_NE(ambiguous.error().message.find("choose the kind"), std::string::npos);
  EXPECT_FALSE(kind("1,2\n").ok());
}

TEST(PlateCsv, SweepPhasesInRadiansAndModalFrfs) {
  auto csv = parsePlateCsv(std::string(kGeometry) + "5,1e-3,90,2e-3,-45,3e-3,180,300,10\n", "d.csv", true);
  ASSERT_TRUE(csv.ok());
  const auto sweep = sweepFromCsv(*csv);
  ASSERT_TRUE(sweep.ok());
  ASSERT_EQ(sweep->size(), 1u);
  EXPECT_DOUBLE_EQ((*sweep)[0].phase(0), std::acos(-1.0) / 2);
  EXPECT_DOUBLE_EQ((*sweep)[0].amplitude(2), 3e-3);
  EXPECT_DOUBLE_EQ((*sweep)[0].forceAmplitude, 300.0);

  auto m = parsePlateCsv(std::string(kGeometry) +
                             "10,1,0,1,0,1,0\n20,5,1,1,0,2,0\n30,1,0,1,0,1,0\n40,1,0,3,4,1,0\n"
                             "50,1,0,1,0,1,0\n",
                         "m.csv", true);
  ASSERT_TRUE(m.ok());
  const auto frf = modalFrfFromCsv(*m, FrfType::Receptance);
  ASSERT_TRUE(frf.ok()) << frf.error().describe();
  EXPECT_EQ(frf->responseCount(), 3);
  EXPECT_EQ(frf->h[0](1, 0), Complex(5, 1));
  // Peaks of sum |H|: 20 Hz (|5+i| + 1 + 2 = 8.10) and 40 Hz (1 + 5 + 1 = 7), ascending.
  EXPECT_EQ(frfPeakFrequencies(*frf, 2), (std::vector<double>{20, 40}));
  EXPECT_EQ(frfPeakFrequencies(*frf, 1), (std::vector<double>{20}));
  auto back = parsePlateCsv(std::string(kGeometry) + "10,1,0,1,0,1,0\n10,1,0,1,0,1,0\n", "b.csv", true);
  const auto bad = modalFrfFromCsv(*back, FrfType::Receptance);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().where, "b.csv:6");
}

}  // namespace
}  // namespace mozzi::core::stiffness
