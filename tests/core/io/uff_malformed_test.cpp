// Malformed universal files: truncated, wrong field widths, NaN, absurd sizes.
// Each gives an Error naming the dataset number and the line, without a large
// allocation; vendor habits that are not errors give a warning instead.
#include "core/io/uff/uff.h"

#include <gtest/gtest.h>
#include <malloc.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace mozzi::core::io::uff {
namespace {

std::string readText(const std::string& name) {
  std::ifstream in(std::string(MOZZI_SHARED_DATA_DIR) + "/uff/" + name, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A small valid ASCII 58 (real single, even, 8 points).
const char* const kSmall58 =
    "    -1\n"
    "    58\n"
    "Small record\n"
    "NONE\n"
    "21-Nov-26 05:40:00\n"
    "NONE\n"
    "NONE\n"
    "    1         0    0         0 NONE              21   3 NONE               1   3\n"
    "         2         8         1  0.00000E+00  1.00000E-03  0.00000E+00\n"
    "        17    0    0    0 Time                 s                   \n"
    "        12    0    0    0 Acceleration         m/s^2               \n"
    "         0    0    0    0 NONE                 NONE                \n"
    "         0    0    0    0 NONE                 NONE                \n"
    "  1.00000E+00  2.00000E+00  3.00000E+00  4.00000E+00  5.00000E+00  6.00000E+00\n"
    "  7.00000E+00  8.00000E+00\n"
    "    -1\n";

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

// The message must name the dataset number and the line.
void expectNamed(const Result<UffFile>& r, int dataset, int line, const std::string& words) {
  ASSERT_FALSE(r.ok()) << "expected an error mentioning '" << words << "'";
  const std::string text = r.error().describe();
  EXPECT_NE(text.find("dataset " + std::to_string(dataset)), std::string::npos) << text;
  EXPECT_NE(text.find("line " + std::to_string(line)), std::string::npos) << text;
  EXPECT_NE(text.find(words), std::string::npos) << text;
}

// Heap in use now (glibc): checks that a hostile header did not allocate.
std::size_t heapInUse() {
  struct mallinfo2 mi = mallinfo2();
  return mi.uordblks + mi.hblkhd;
}

TEST(UffMalformed, TheValidSnippetReads) {
  auto r = readBytes(kSmall58);
  ASSERT_TRUE(r.ok()) << r.error().describe();
  const auto* f = r->datasets.at(0).get<Function58>();
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->real, (Vector(8) << 1, 2, 3, 4, 5, 6, 7, 8).finished());
  EXPECT_EQ(f->response.dof().value(), (Dof{21, Direction::Z, false}));
  EXPECT_TRUE(r->warnings.empty());
}

TEST(UffMalformed, TruncatedFilesAreErrors) {
  const std::string full = kSmall58;
  // Cut inside the data (after "  7.00000E+00"): end of file, 7 of 8 points.
  expectNamed(readBytes(full.substr(0, full.find("  8.00000E+00"))), 58, 15, "file truncated");
  // Cut inside the header records (after record 7).
  expectNamed(readBytes(full.substr(0, full.find("        17"))), 58, 9, "file truncated");
  // A binary block shorter than its header says.
  const std::string bin = readText("binary8byte.uff");
  expectNamed(readBytes(bin.substr(0, 1500)), 58, 13, "declares 2000 bytes of binary data");
  // Vendor file cut in its middle.
  const std::string ascii = readText("Sample_UFF58_ascii.uff");
  const std::string half = ascii.substr(0, ascii.size() / 2);
  // The error is on the last (partial) line of what is left.
  const int lastLine = static_cast<int>(std::count(half.begin(), half.end(), '\n')) + 1;
  expectNamed(readBytes(half), 58, lastLine, "file truncated");
}

TEST(UffMalformed, WrongFieldWidthsAreErrors) {
  // Two E13.5 fields run together without a sign between them.
  expectNamed(readBytes(replaced(kSmall58, "  2.00000E+00  3.00000E+00", "  2.00000E+003.00000E+00   ")), 58, 14,
              "malformed data value");
  // Record 6 shifted so that a name lands in a numeric column and no
  // blank-separated reading makes sense either.
  expectNamed(readBytes(replaced(kSmall58, "    1         0    0         0 NONE              21   3",
                                 "  FRF         0    0         0 NONE              21   3")),
              58, 8, "record 6");
  // Record 7 with a letter in the point count.
  expectNamed(readBytes(replaced(kSmall58, "         8         1  0.00000E+00", "         8x        1  0.00000E+00")),
              58, 9, "record 7");
  // A node record of dataset 15 with a missing coordinate.
  expectNamed(readBytes("    -1\n    15\n         1         0         0         1  1.0E+00  2.0E+00\n    -1\n"), 15, 3,
              "expected 4 integers and 3 coordinates");
}

TEST(UffMalformed, NanAndInfinityAreErrors) {
  expectNamed(readBytes(replaced(kSmall58, "  5.00000E+00", "          NaN")), 58, 14, "not a finite number");
  expectNamed(readBytes(replaced(kSmall58, "  5.00000E+00", "  1.00000E+999")), 58, 14, "not a finite number");
  expectNamed(readBytes("    -1\n  2411\n         1         0         0        11\n"
                        "   1.0D+00   nan   0.0D+00\n    -1\n"),
              2411, 4, "not a finite number");
  // A NaN inside a binary block (IEEE quiet NaN, little endian double). The
  // file ends with the 2000-byte block and "    -1\r\n".
  const std::string bin = readText("binary8byte.uff");
  const std::size_t block = bin.size() - 8 - 2000;
  std::string withNan = bin;
  withNan.replace(block + 8 * 3, 8, std::string("\x00\x00\x00\x00\x00\x00\xf8\x7f", 8));
  expectNamed(readBytes(withNan), 58, 13, "not a finite number");
}

TEST(UffMalformed, AbsurdSizesAreErrorsWithoutLargeAllocations) {
  const std::size_t before = heapInUse();
  // ASCII header claiming 10^12 points: refused before reading data.
  auto ascii = readBytes(replaced(kSmall58, "         2         8         1", "         2 1000000000000         1"));
  expectNamed(ascii, 58, 9, "declares 1000000000000 points");
  // A binary header claiming 10^12 points and 8 * 10^12 bytes.
  std::string bin = readText("binary8byte.uff");
  bin = replaced(bin, "         4       250", "         4 1000000000000");
  bin = replaced(bin, "          11        2000", "          11 8000000000000");
  auto binary = readBytes(bin);
  expectNamed(binary, 58, 2, "declares 8000000000000 bytes");
  // Same claim under the size limit but beyond the file: truncated.
  ReadOptions generous;
  generous.maxDatasetBytes = std::uint64_t{1} << 50;
  expectNamed(readBytes(bin, generous), 58, 13, "only");
  // 55 with an absurd number of values per node, 82 with an absurd node count.
  expectNamed(readBytes("    -1\n    55\nA\nB\nC\nD\nE\n         1         2         2         8         2 999999999\n"
                        "    -1\n"),
              55, 8, "values per node 999999999");
  expectNamed(readBytes("    -1\n    82\n         1 2000000000         8\nX\n         1\n    -1\n"), 82, 3,
              "node count 2000000000");
  // The heap grew by less than a megabyte over all of that (the test data
  // strings themselves are freed again).
  EXPECT_LT(heapInUse(), before + (std::size_t{1} << 20));
}

TEST(UffMalformed, FewerPointsThanDeclaredIsAWarningWhenTheDatasetIsClosed) {
  // The vendor habit of dataset_milestone_in_header.uff: the dataset closes
  // with -1 before the declared count. Read with a warning on record 7.
  auto r = readBytes(replaced(kSmall58, "         2         8         1", "         2        10         1"));
  ASSERT_TRUE(r.ok()) << r.error().describe();
  EXPECT_EQ(r->datasets.at(0).get<Function58>()->pointCount(), 8);
  ASSERT_EQ(r->warnings.size(), 1u);
  EXPECT_EQ(r->warnings[0].describe(),
            "dataset 58, line 9: record 7 declares 10 points, the data hold 8; the record is read with 8");
  // More values than declared cannot be assigned to points: an error.
  expectNamed(readBytes(replaced(kSmall58, "         2         8         1", "         2         6         1")), 58, 15,
              "more data values than the 6 points");
}

TEST(UffMalformed, ShortLinesAndMissingColumnsAreWarnings) {
  // Record 6 cut after the response direction; records 8-11 cut after the
  // data type; record 7 without its z value.
  std::string s = replaced(kSmall58, "    1         0    0         0 NONE              21   3 NONE               1   3",
                           "    1         0    0         0 NONE              21   3");
  s = replaced(s, "        17    0    0    0 Time                 s                   ", "        17");
  s = replaced(s, "  1.00000E-03  0.00000E+00", "  1.00000E-03");
  auto r = readBytes(s);
  ASSERT_TRUE(r.ok()) << r.error().describe();
  const auto* f = r->datasets.at(0).get<Function58>();
  EXPECT_EQ(f->reference.node, 0);
  EXPECT_EQ(f->abscissaAxis.specificDataType, 17);
  EXPECT_EQ(f->abscissaAxis.label, "NONE");
  std::vector<std::int64_t> lines;
  for (const auto& w : r->warnings) {
    EXPECT_EQ(w.datasetType, 58);
    lines.push_back(w.line);
  }
  EXPECT_EQ(lines, (std::vector<std::int64_t>{8, 9, 10}));
}

TEST(UffMalformed, UnknownDatasetsAreSkippedAndGarbageIsAnError) {
  auto r = readBytes("    -1\n  2467\n  whatever\n  1 2 3\n    -1\n    -1\n  1858\n    -1\n" + std::string(kSmall58));
  ASSERT_TRUE(r.ok()) << r.error().describe();
  ASSERT_EQ(r->datasets.size(), 3u);
  EXPECT_EQ(r->datasets[0].type, 2467);
  EXPECT_EQ(r->datasets[1].type, 1858);
  EXPECT_EQ(r->datasets[0].get<SkippedDataset>()->lineCount, 2);
  ASSERT_EQ(r->warnings.size(), 2u);
  EXPECT_EQ(r->warnings[0].describe(),
            "dataset 2467, line 2: dataset type 2467 is not used by Mozzi; skipped (2 lines)");

  auto junk = readBytes("This is not a universal file\n");
  ASSERT_FALSE(junk.ok());
  EXPECT_NE(junk.error().describe().find("line 1: expected the dataset delimiter"), std::string::npos);
  auto junkAfter = readBytes(std::string(kSmall58) + "garbage\n");
  ASSERT_FALSE(junkAfter.ok());
  EXPECT_NE(junkAfter.error().describe().find("after dataset 58 (ended at line 16)"), std::string::npos)
      << junkAfter.error().describe();
  // An unsupported ordinate type is named as such.
  auto r3 = readBytes(replaced(kSmall58, "         2         8         1", "         3         8         1"));
  ASSERT_FALSE(r3.ok());
  EXPECT_EQ(r3.error().code, ErrorCode::Unsupported);
}

TEST(UffMalformed, MissingFileIsNotFound) {
  auto r = readFile("/nonexistent/dir/file.uff");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::NotFound);
  EXPECT_NE(r.error().where.find("/nonexistent/dir/file.uff"), std::string::npos);
}

}  // namespace
}  // namespace mozzi::core::io::uff
