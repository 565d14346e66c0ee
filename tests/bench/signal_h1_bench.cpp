// H1 over 4 channels (1 force + 3 responses) x 65536 samples x 10 hits
// (issue 3 speed target): the whole estimate against the FFTs it needs, the
// physical floor of the computation (40 real FFTs of 65536 points). The same
// estimate in SciPy: tests/bench/signal_h1_scipy.py. Figures in
// docs/performance/signal.md and docs/performance.md.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "core/signal/fft.h"
#include "core/signal/frf_estimator.h"

namespace {

namespace sg = mozzi::core::signal;
constexpr Eigen::Index kSamples = 65536;
constexpr int kChannels = 4;
constexpr int kHits = 10;

// Random data (the content does not change the cost); built once.
const std::vector<sg::TimeRecord>& hits() {
  static const std::vector<sg::TimeRecord> data = [] {
    std::vector<sg::TimeRecord> v;
    std::mt19937_64 rng(1);
    std::normal_distribution<double> normal;
    for (int h = 0; h < kHits; ++h) {
      sg::TimeRecord r;
      r.sampleRateHz = 8192.0;
      r.channels.resize(kChannels);
      r.channels[0].transducer.kind = sg::TransducerKind::Force;
      for (int c = 0; c < kChannels; ++c) {
        r.channels[static_cast<std::size_t>(c)].dof = mozzi::core::Dof{c + 1, mozzi::core::Direction::Z, false};
        if (c > 0) r.channels[static_cast<std::size_t>(c)].transducer.kind = sg::TransducerKind::Acceleration;
      }
      r.samples.resize(kSamples, kChannels);
      for (Eigen::Index i = 0; i < r.samples.size(); ++i) r.samples.data()[i] = normal(rng);
      v.push_back(std::move(r));
    }
    return v;
  }();
  return data;
}

// The whole H1 estimate: windows, 40 FFTs, auto/cross spectra, H1 and coherence.
void BM_H1_4ch_65536_10hits(benchmark::State& state) {
  const auto& data = hits();
  for (auto _ : state) {
    auto avg = sg::SpectralAverager::create(data.front(), sg::FrfOptions{});
    for (const auto& h : data) {
      auto ok = avg->add(h);
      benchmark::DoNotOptimize(ok);
    }
    auto frf = avg->frf(sg::FrfEstimator::H1);
    benchmark::DoNotOptimize(frf);
  }
}
BENCHMARK(BM_H1_4ch_65536_10hits)->Unit(benchmark::kMillisecond);

// Same with a force window and an exponential window (the hammer set-up).
void BM_H1_4ch_65536_10hits_windowed(benchmark::State& state) {
  const auto& data = hits();
  const auto opt = sg::FrfOptions::hammer(sg::FrfEstimator::H1, 0.01, 0.005, 0.5);
  for (auto _ : state) {
    auto avg = sg::SpectralAverager::create(data.front(), opt);
    for (const auto& h : data) {
      auto ok = avg->add(h);
      benchmark::DoNotOptimize(ok);
    }
    auto frf = avg->frf(sg::FrfEstimator::H1);
    benchmark::DoNotOptimize(frf);
  }
}
BENCHMARK(BM_H1_4ch_65536_10hits_windowed)->Unit(benchmark::kMillisecond);

// The same with the averager set up once and reset per campaign (a roving
// hammer campaign reuses it point after point): no allocation in the loop
// except the FRF result.
void BM_H1_4ch_65536_10hits_reused(benchmark::State& state) {
  const auto& data = hits();
  auto avg = sg::SpectralAverager::create(data.front(), sg::FrfOptions{});
  for (auto _ : state) {
    avg->reset();
    for (const auto& h : data) {
      auto ok = avg->add(h);
      benchmark::DoNotOptimize(ok);
    }
    auto frf = avg->frf(sg::FrfEstimator::H1);
    benchmark::DoNotOptimize(frf);
  }
}
BENCHMARK(BM_H1_4ch_65536_10hits_reused)->Unit(benchmark::kMillisecond);

// Two references (shakers) and two responses on the same data: the
// multiple-input H1 = Gyf Gff^-1 with conditioning check and multiple
// coherence per line (4 accumulated cross columns plus a 2 x 2 Hermitian
// eigen-solve per line).
void BM_H1_2ref_2resp_65536_10hits(benchmark::State& state) {
  const auto& data = hits();
  sg::FrfOptions opt;
  opt.referenceChannels = {0, 1};
  std::vector<sg::TimeRecord> twoRef = data;
  for (auto& r : twoRef) r.channels[1].transducer.kind = sg::TransducerKind::Force;
  for (auto _ : state) {
    auto avg = sg::SpectralAverager::create(twoRef.front(), opt);
    for (const auto& h : twoRef) {
      auto ok = avg->add(h);
      benchmark::DoNotOptimize(ok);
    }
    auto frf = avg->frf(sg::FrfEstimator::H1);
    if (!frf) state.SkipWithError(frf.error().message.c_str());
    benchmark::DoNotOptimize(frf);
  }
}
BENCHMARK(BM_H1_2ref_2resp_65536_10hits)->Unit(benchmark::kMillisecond);

// The floor: the 40 forward FFTs alone, same plan, each sample column copied
// into FFTW-aligned input (as any caller holding Eigen data must) and
// transformed into one output buffer.
void BM_FftFloor_40x65536(benchmark::State& state) {
  const auto& data = hits();
  auto fft = sg::RealFft::forLength(kSamples);
  sg::AlignedBuffer<double> in(kSamples);
  sg::AlignedBuffer<std::complex<double>> out(kSamples / 2 + 1);
  for (auto _ : state) {
    for (const auto& h : data) {
      for (int c = 0; c < kChannels; ++c) {
        const double* x = h.samples.col(c).data();
        std::copy(x, x + kSamples, in.data());
        (*fft)->forward(in.data(), out.data());
        benchmark::DoNotOptimize(out.data());
      }
    }
  }
}
BENCHMARK(BM_FftFloor_40x65536)->Unit(benchmark::kMillisecond);

// The strict floor: the 40 FFTs straight from the record's columns, no copy
// (FFTW reads an Eigen column in place when its alignment matches the plan's,
// as the averager does for rectangular windows).
void BM_FftFloorInPlace_40x65536(benchmark::State& state) {
  const auto& data = hits();
  auto fft = sg::RealFft::forLength(kSamples);
  sg::AlignedBuffer<std::complex<double>> out(kSamples / 2 + 1);
  for (auto _ : state) {
    for (const auto& h : data) {
      for (int c = 0; c < kChannels; ++c) {
        (*fft)->forward(h.samples.col(c).data(), out.data());
        benchmark::DoNotOptimize(out.data());
      }
    }
  }
}
BENCHMARK(BM_FftFloorInPlace_40x65536)->Unit(benchmark::kMillisecond);

}  // namespace
