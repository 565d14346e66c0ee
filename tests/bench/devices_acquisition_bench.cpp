// Sustained acquisition from an emulated USB-1608FS-Plus at 8 channels x
// 50 kS/s (400 kS/s, the device's aggregate limit) through the same stages
// the driver runs on its acquisition thread: 64-byte bulk packets -> scan
// assembly -> device calibration -> volts -> EU (calibration pipeline) ->
// overload detection -> software trigger with 10% pre-trigger -> a consumer.
// The emulated device produces its packets from a simulated clock (sample k
// of channel c is a known code), so dropped or reordered samples are detected
// exactly. USB itself (libusb over umockdev) is exercised by
// tests/devices/mcc_usb1608fsplus/usb1608fsplus_umockdev_test.cpp.
//
// Real-time budget: one second of data must take well under one second of
// CPU. Counter data_s_per_cpu_s = seconds of data processed per CPU second.
// BM_SustainedMinutes runs MOZZI_BENCH_DATA_MINUTES (default 0.05) minutes of
// data in one go and checks zero dropped samples; run with
// MOZZI_BENCH_DATA_MINUTES=10 for the 10-minute figure in docs/performance/devices.md.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <ctime>

#include "devices/common/acquisition.h"
#include "devices/common/trigger.h"
#include "devices/mcc_usb1608fsplus/usb1608fsplus_protocol.h"

namespace mozzi::devices {
namespace {

constexpr int kChannels = 8;
constexpr double kRate = 50e3;
constexpr std::int64_t kBlockScans = 2500;  // 50 ms, the driver's default block

std::uint16_t deviceCode(std::int64_t k, int c) {
  // Channel 0 carries a hammer-like pulse every 0.5 s (to exercise the
  // trigger), the others a ramp pattern; all codes are predictable.
  if (c == 0) return (k % 25000) < 50 ? 60000 : 32768;
  return static_cast<std::uint16_t>((k * 37 + c * 8191 + 1234) & 0xFFFF);
}

struct Pipeline {
  std::vector<ChannelChain> chains;
  mcc::ScanAssembler assembler{kChannels};
  std::vector<std::int32_t> pending;
  std::int64_t pendingScans = 0;
  std::int64_t delivered = 0;
  std::int64_t nextExpected = 0;
  bool intact = true;
  double consumerSum = 0.0;
  std::int64_t records = 0;
  SoftwareTrigger trigger;

  static SoftwareTrigger makeTrigger() {
    SoftwareTriggerConfig tc;
    tc.channel = 0;
    tc.level = 1.0;  // V (1000 mV per unit below): the pulse reads 8.3 V
    tc.recordScans = 8192;
    return *SoftwareTrigger::create(tc, kChannels);
  }

  Pipeline() : trigger(makeTrigger()) {
    for (int c = 0; c < kChannels; ++c) {
      ChannelChain ch;
      ch.range = *mcc::rangeForCode(0);
      ch.calibration = DeviceCalibration{1.0001, -2.0};
      ch.transducer.sensitivityMvPerUnit = 1000.0;
      chains.push_back(ch);
    }
  }

  void packet(const std::uint8_t* data, int n) {
    pendingScans += assembler.append(data, n, pending);
    while (pendingScans >= kBlockScans) {
      DataBlock b;
      b.firstSample = delivered;
      b.raw.assign(pending.begin(), pending.begin() + kBlockScans * kChannels);
      pending.erase(pending.begin(), pending.begin() + kBlockScans * kChannels);
      pendingScans -= kBlockScans;
      b.values.resize(kBlockScans, kChannels);
      for (std::int64_t s = 0; s < kBlockScans; ++s)
        for (int c = 0; c < kChannels; ++c) {
          const std::int32_t code = b.raw[static_cast<std::size_t>(s * kChannels + c)];
          if (code != deviceCode(b.firstSample + s, c)) intact = false;
          b.values(s, c) = chains[static_cast<std::size_t>(c)].engineeringFromRaw(code);
        }
      delivered += kBlockScans;
      if (b.firstSample != nextExpected) intact = false;
      nextExpected = b.firstSample + kBlockScans;
      benchmark::DoNotOptimize(detectOverloads(b, chains));
      for (const auto& r : trigger.feed(b.firstSample, b.values)) {
        ++records;
        consumerSum += r.samples.col(1).sum();
      }
    }
  }
};

// The emulated device: 64-byte packets from the simulated clock.
struct EmulatedDevice {
  std::int64_t next = 0;
  std::vector<std::uint8_t> fifo;
  void fill(std::int64_t scans) {
    for (std::int64_t i = 0; i < scans; ++i, ++next)
      for (int c = 0; c < kChannels; ++c) {
        const std::uint16_t v = deviceCode(next, c);
        fifo.push_back(static_cast<std::uint8_t>(v & 0xFF));
        fifo.push_back(static_cast<std::uint8_t>(v >> 8));
      }
  }
};

void runSeconds(Pipeline& p, EmulatedDevice& d, double seconds) {
  const auto scans = static_cast<std::int64_t>(seconds * kRate);
  // Bulk transfers of 100 ms (the driver's default) split into 64-byte packets.
  const std::int64_t perTransfer = static_cast<std::int64_t>(0.1 * kRate);
  for (std::int64_t done = 0; done < scans; done += perTransfer) {
    d.fifo.clear();
    d.fill(std::min(perTransfer, scans - done));
    for (std::size_t o = 0; o < d.fifo.size(); o += mcc::kPacketBytes)
      p.packet(d.fifo.data() + o, static_cast<int>(std::min<std::size_t>(mcc::kPacketBytes, d.fifo.size() - o)));
  }
}

double cpuSeconds() {
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

void BM_OneSecondOfData(benchmark::State& state) {
  Pipeline p;
  EmulatedDevice d;
  const double c0 = cpuSeconds();
  for (auto _ : state) runSeconds(p, d, 1.0);
  const double cpu = cpuSeconds() - c0;
  state.counters["data_s_per_cpu_s"] = static_cast<double>(state.iterations()) / std::max(cpu, 1e-9);
  state.counters["cpu_ms_per_data_s"] = 1000.0 * cpu / static_cast<double>(state.iterations());
  state.counters["intact"] = p.intact ? 1 : 0;
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kRate) * kChannels);
  if (!p.intact) state.SkipWithError("dropped or reordered samples");
}
BENCHMARK(BM_OneSecondOfData)->Unit(benchmark::kMillisecond);

void BM_SustainedMinutes(benchmark::State& state) {
  const char* env = std::getenv("MOZZI_BENCH_DATA_MINUTES");
  const double minutes = env ? std::atof(env) : 0.05;
  for (auto _ : state) {
    Pipeline p;
    EmulatedDevice d;
    const double c0 = cpuSeconds();
    runSeconds(p, d, 60.0 * minutes);
    const double cpu = cpuSeconds() - c0;
    const auto expected = static_cast<std::int64_t>(60.0 * minutes * kRate) / kBlockScans * kBlockScans;
    state.counters["data_minutes"] = minutes;
    state.counters["dropped_samples"] = static_cast<double>((expected - p.delivered) * kChannels);
    state.counters["cpu_ms_per_data_s"] = 1000.0 * cpu / (60.0 * minutes);
    state.counters["records"] = static_cast<double>(p.records);
    if (!p.intact || p.delivered != expected) state.SkipWithError("dropped or reordered samples");
  }
}
BENCHMARK(BM_SustainedMinutes)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace mozzi::devices
