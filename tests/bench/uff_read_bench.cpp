// Reading speed of 58b (binary, real single) and ASCII 58 (real single, E13.5)
// files, against the I/O floor of reading the same bytes with no parsing (the
// work of `cat FILE > /dev/null`). Targets (issue 4): binary >= 500 MB/s,
// ASCII >= 100 MB/s.
//
// The files are generated once into /tmp and reused. Size from the
// environment: MOZZI_BENCH_UFF_MB (default 8, so the ctest smoke run stays
// within a few seconds); the figures in docs/performance/uff.md come from
//   MOZZI_BENCH_UFF_MB=100 tests/uff_read_bench
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/io/uff/uff.h"

namespace {

namespace uff = mozzi::core::io::uff;
namespace fs = std::filesystem;

std::size_t targetBytes() {
  const char* env = std::getenv("MOZZI_BENCH_UFF_MB");
  const long mb = env ? std::strtol(env, nullptr, 10) : 8;
  return static_cast<std::size_t>(mb > 0 ? mb : 8) << 20;
}

// A file of `records` time records (real single, even), each of `points`
// samples: a decaying 37 Hz sine with a little deterministic noise.
std::string ensureFile(bool binary) {
  const std::size_t bytes = targetBytes();
  const std::string path =
      "/tmp/mozzi_bench_uff_" + std::string(binary ? "bin" : "ascii") + "_" + std::to_string(bytes >> 20) + "MB.uff";
  if (fs::exists(path)) return path;
  // Binary: 4 bytes per point; ASCII: 13 bytes per point plus a newline per 6.
  const double perPoint = binary ? 4.0 : 13.0 + 1.0 / 6.0;
  const Eigen::Index points = 1 << 18;  // 262144 samples per record
  const std::size_t records = std::max<std::size_t>(1, static_cast<std::size_t>(bytes / (perPoint * points)));
  uff::Function58 f;
  f.idLines = {"Benchmark record", "NONE", "21-Nov-26 06:00:00", "Mozzi", "NONE"};
  f.functionType = uff::FunctionType::TimeResponse;
  f.ordinateType = uff::OrdinateType::RealSingle;
  f.evenSpacing = true;
  f.abscissaIncrement = 1.0 / 51200.0;
  f.abscissaAxis = uff::AxisInfo{17, 0, 0, 0, "Time", "s"};
  f.ordinateNumerator = uff::AxisInfo{12, 0, 0, 0, "Acceleration", "m/s^2"};
  f.real.resize(points);
  std::uint32_t noise = 12345;
  for (Eigen::Index k = 0; k < points; ++k) {
    noise = noise * 1664525u + 1013904223u;
    const double t = static_cast<double>(k) / 51200.0;
    f.real[k] = static_cast<float>(std::exp(-3.0 * t) * std::sin(2 * 3.141592653589793 * 37.0 * t) +
                                   1e-3 * (static_cast<double>(noise >> 8) / 16777216.0 - 0.5));
  }
  const std::string tmp = path + ".part";
  std::ofstream out(tmp, std::ios::binary);
  uff::WriteOptions opt;
  opt.encoding = binary ? uff::Encoding58::Binary : uff::Encoding58::Ascii;
  for (std::size_t r = 0; r < records; ++r) {
    f.response = uff::Channel58{"ACC", static_cast<int>(r + 1), 3};
    if (!uff::writeDataset(out, uff::makeDataset(f), opt)) return {};
  }
  out.close();
  fs::rename(tmp, path);
  return path;
}

void readBench(benchmark::State& state, bool binary) {
  const std::string path = ensureFile(binary);
  if (path.empty()) {
    state.SkipWithError("could not generate the benchmark file");
    return;
  }
  const auto size = static_cast<std::int64_t>(fs::file_size(path));
  std::int64_t points = 0;
  for (auto _ : state) {
    auto reader = uff::DatasetReader::open(path);
    if (!reader) {
      state.SkipWithError(reader.error().describe().c_str());
      return;
    }
    points = 0;
    // Streaming: one record at a time, as a 1 GB file would be read.
    for (;;) {
      auto d = reader->next();
      if (!d || !d->has_value()) break;
      points += (*d)->get<uff::Function58>()->pointCount();
    }
    benchmark::DoNotOptimize(points);
  }
  state.SetBytesProcessed(state.iterations() * size);
  state.counters["file_MB"] = static_cast<double>(size) / 1e6;
  state.counters["points"] = static_cast<double>(points);
}

// The I/O floor: the bytes read in 1 MiB blocks and dropped, as cat > /dev/null.
void catBench(benchmark::State& state, bool binary) {
  const std::string path = ensureFile(binary);
  const auto size = static_cast<std::int64_t>(fs::file_size(path));
  std::vector<char> buf(1 << 20);
  for (auto _ : state) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    std::size_t total = 0;
    while (std::size_t n = std::fread(buf.data(), 1, buf.size(), f)) total += n;
    std::fclose(f);
    benchmark::DoNotOptimize(total);
  }
  state.SetBytesProcessed(state.iterations() * size);
}

void BM_UffRead58Binary(benchmark::State& state) {
  readBench(state, true);
}
void BM_UffRead58Ascii(benchmark::State& state) {
  readBench(state, false);
}
void BM_CatFloor58Binary(benchmark::State& state) {
  catBench(state, true);
}
void BM_CatFloor58Ascii(benchmark::State& state) {
  catBench(state, false);
}

BENCHMARK(BM_UffRead58Binary)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CatFloor58Binary)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_UffRead58Ascii)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CatFloor58Ascii)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
