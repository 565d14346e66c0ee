// UffHitReader (core/io/uff_hits.h): hits streamed from UFF 58 time records,
// one per load case; a hit handed out stays intact while the next two are read
// (`mozzi-cli frf` averages it on another thread meanwhile), and the length
// of the first record is announced before its samples are read.
#include "core/io/uff_hits.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/io/uff/uff.h"

namespace mozzi::core::io {
namespace {

namespace fs = std::filesystem;

// Sample i of channel c of load case h: distinct for every hit, channel and sample.
double sampleValue(int h, Eigen::Index c, Eigen::Index i) {
  return 1000.0 * h + 100.0 * static_cast<double>(c) + 0.25 * static_cast<double>(i);
}

constexpr Eigen::Index kSamples = 64;
constexpr Eigen::Index kChannels = 2;

// `hits` load cases of force (node 1 +Z) and acceleration (node 2 +Z).
std::string writeHits(const std::string& name, int hits) {
  uff::UffFile file;
  for (int h = 1; h <= hits; ++h) {
    for (Eigen::Index c = 0; c < kChannels; ++c) {
      uff::Function58 f;
      f.idLines = {"hit " + std::to_string(h), "uff_hits_test", "NONE", "NONE", "NONE"};
      f.functionType = uff::FunctionType::TimeResponse;
      f.functionId = static_cast<int>(c + 1);
      f.loadCase = h;
      f.response = uff::Channel58::fromDof(Dof{static_cast<int>(c + 1), Direction::Z});
      f.ordinateType = uff::OrdinateType::RealDouble;
      f.abscissaMin = -8.0 / 1024.0;
      f.abscissaIncrement = 1.0 / 1024.0;
      f.abscissaAxis.specificDataType = 17;
      f.ordinateNumerator.specificDataType = c == 0 ? 13 : 12;
      f.ordinateNumerator.unitsLabel = c == 0 ? "N" : "m/s^2";
      f.real.resize(kSamples);
      for (Eigen::Index i = 0; i < kSamples; ++i) f.real[i] = sampleValue(h, c, i);
      f.binary = true;
      file.datasets.push_back(uff::makeDataset(std::move(f)));
    }
  }
  const fs::path path = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()) + ".uff");
  auto ok = uff::writeFile(path.string(), file);
  EXPECT_TRUE(ok) << (ok ? "" : ok.error().describe());
  return path.string();
}

void expectHit(const UffHit& hit, int h, const std::string& when) {
  ASSERT_EQ(hit.loadCase, h) << when;
  ASSERT_EQ(hit.record.samples.rows(), kSamples) << when;
  ASSERT_EQ(hit.record.samples.cols(), kChannels) << when;
  ASSERT_EQ(hit.record.channelCount(), kChannels) << when;
  for (Eigen::Index c = 0; c < kChannels; ++c) {
    EXPECT_EQ(hit.record.channels[static_cast<std::size_t>(c)].dof, (Dof{static_cast<int>(c + 1), Direction::Z}))
        << when;
    for (Eigen::Index i = 0; i < kSamples; ++i) {
      ASSERT_EQ(hit.record.samples(i, c), sampleValue(h, c, i)) << when << ", channel " << c << ", sample " << i;
    }
  }
  EXPECT_EQ(hit.record.preTriggerSamples, 8) << when;
  EXPECT_EQ(hit.record.channels[0].transducer.kind, signal::TransducerKind::Force) << when;
}

TEST(UffHitReader, AHitStaysIntactWhileTheNextTwoAreRead) {
  const std::string path = writeHits("uff_hits_intact", 6);
  auto reader = UffHitReader::open(path);
  ASSERT_TRUE(reader) << reader.error().describe();
  const UffHit* twoBefore = nullptr;
  const UffHit* previous = nullptr;
  for (int h = 1; h <= 6; ++h) {
    auto hit = reader->next();
    ASSERT_TRUE(hit) << hit.error().describe();
    ASSERT_NE(*hit, nullptr) << "hit " << h;
    expectHit(**hit, h, "hit " + std::to_string(h) + " when handed out");
    // The two before it were read while this one was: they must be untouched
    // (the first record of hit h + 1 is already read into a buffer by now);
    // `mozzi-cli frf` averages them meanwhile.
    if (previous != nullptr) expectHit(*previous, h - 1, "hit " + std::to_string(h - 1) + " after the next call");
    if (twoBefore != nullptr) {
      expectHit(*twoBefore, h - 2, "hit " + std::to_string(h - 2) + " after the second call after it");
    }
    twoBefore = previous;
    previous = *hit;
  }
  auto end = reader->next();
  ASSERT_TRUE(end);
  EXPECT_EQ(*end, nullptr);
  expectHit(*previous, 6, "the last hit after the end");
  expectHit(*twoBefore, 5, "the hit before the last after the end");
  fs::remove(path);
}

TEST(UffHitReader, AnnouncesTheFirstLengthOnceBeforeTheFirstHit) {
  const std::string path = writeHits("uff_hits_length", 3);
  auto reader = UffHitReader::open(path);
  ASSERT_TRUE(reader) << reader.error().describe();
  std::vector<Eigen::Index> lengths;
  reader->onFirstLength([&](Eigen::Index n) { lengths.push_back(n); });
  auto first = reader->next();
  ASSERT_TRUE(first && *first);
  EXPECT_EQ(lengths, std::vector<Eigen::Index>{kSamples});
  while (true) {
    auto hit = reader->next();
    ASSERT_TRUE(hit);
    if (*hit == nullptr) break;
  }
  EXPECT_EQ(lengths.size(), 1u);
  fs::remove(path);
}

}  // namespace
}  // namespace mozzi::core::io
