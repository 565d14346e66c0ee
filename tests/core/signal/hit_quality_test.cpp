// Per-hit quality check: clean hits accepted, double hits and clipping flagged,
// pulse width, usable band and noise floor against the analytic half-sine.
#include "core/signal/hit_quality.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/signal/hit_synthesis.h"

namespace mozzi::core::signal {
namespace {

constexpr double kPi = 3.14159265358979323846;

LinearMdof twoDof() {
  LinearMdof s;
  s.mass = Eigen::Vector2d(1.0, 0.5).asDiagonal();
  s.stiffness.resize(2, 2);
  s.stiffness << 1.5e5, -5e4, -5e4, 5e4;
  s.damping = 2e-4 * s.stiffness;
  return s;
}

HammerHitSpec baseSpec(std::uint64_t seed) {
  HammerHitSpec spec;
  spec.sampleCount = 8192;  // 1 s at 8192 Hz keeps the test fast
  spec.forceNoiseRms = 0.02;
  spec.responseNoiseRms = 0.002;
  spec.seed = seed;
  return spec;
}

// |F(f)/F(0)| of a half-sine pulse of width Tp: cos(pi f Tp) / (1 - (2 f Tp)^2).
double halfSineRatio(double f, double tp) {
  const double x = 2 * f * tp;
  if (std::abs(x - 1.0) < 1e-9) return kPi / 4;
  return std::abs(std::cos(kPi * f * tp) / (1 - x * x));
}

// First f where the energy ratio |F/F0|^2 falls to `level` (bisection on the main lobe).
double analyticBandEdge(double tp, double level) {
  double lo = 0.0, hi = 1.5 / tp;  // first null at 1.5 / Tp
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (halfSineRatio(mid, tp) * halfSineRatio(mid, tp) > level ? lo : hi) = mid;
  }
  return lo;
}

TEST(HitQuality, CleanHitsAreNeverFlagged) {
  // 40 clean hits over seeds, tips (1..6 ms) and force levels
  for (int i = 0; i < 40; ++i) {
    HammerHitSpec spec = baseSpec(100 + static_cast<std::uint64_t>(i));
    spec.pulseWidthS = 1e-3 + 5e-3 * (i % 8) / 7.0;
    spec.peakForceN = 20.0 + 10.0 * (i % 5);
    auto rec = synthesizeHammerHit(twoDof(), spec);
    ASSERT_TRUE(rec.ok()) << rec.error().describe();
    auto q = assessHit(*rec);
    ASSERT_TRUE(q.ok()) << q.error().describe();
    EXPECT_TRUE(q->accepted) << "hit " << i << ": " << q->verdictText();
    EXPECT_FALSE(q->doubleHit);
    EXPECT_TRUE(q->reasons.empty());
  }
}

TEST(HitQuality, PulseWidthBandAndNoiseMatchTheHalfSine) {
  HammerHitSpec spec = baseSpec(7);
  spec.pulseWidthS = 2e-3;
  auto rec = synthesizeHammerHit(twoDof(), spec);
  ASSERT_TRUE(rec.ok());
  auto q = assessHit(*rec);
  ASSERT_TRUE(q.ok());
  ASSERT_TRUE(q->accepted) << q->verdictText();
  // Width at the 2% edges: Tp (1 - 2 asin(0.02) / pi) = 0.98727 Tp. The DAQ's
  // anti-aliasing filter (fc = 0.4 fs = 3.3 kHz) smooths the kinks at the
  // pulse feet over ~1 / (2 fc) = 0.15 ms, widening the 2% width by up to
  // ~0.1 ms: 5%.
  EXPECT_NEAR(q->pulseWidthS / (spec.pulseWidthS * (1 - 2 * std::asin(0.02) / kPi)), 1.0, 0.05);
  // Trigger: first sample above 5% of the peak, within a sample of where the
  // pulse reaches 5% (t0 + Tp asin(0.05) / pi).
  ASSERT_TRUE(q->triggerSample.has_value());
  const double tTrig = spec.preTriggerSamples / spec.sampleRateHz + spec.pulseWidthS * std::asin(0.05) / kPi;
  EXPECT_NEAR(*q->triggerSample / spec.sampleRateHz, tTrig, 1.0 / spec.sampleRateHz);
  // Usable band: analytic half-sine edges (f_10 = 509 Hz, f_20 = 653 Hz for
  // 2 ms); 1% covers the line spacing of 1 Hz and the dB interpolation.
  const double f10 = analyticBandEdge(spec.pulseWidthS, 0.1), f20 = analyticBandEdge(spec.pulseWidthS, 0.01);
  ASSERT_TRUE(q->usableBand10dBHz && q->usableBand20dBHz);
  std::printf("f10 %.1f Hz (analytic %.1f), f20 %.1f Hz (analytic %.1f), width %.4f ms\n", *q->usableBand10dBHz, f10,
              *q->usableBand20dBHz, f20, 1e3 * q->pulseWidthS);
  EXPECT_NEAR(*q->usableBand10dBHz / f10, 1.0, 0.01);
  EXPECT_NEAR(*q->usableBand20dBHz / f20, 1.0, 0.01);
  // Noise floor from 192 pre-trigger samples: the RMS estimate has relative
  // spread 1/sqrt(2 x 191) = 5.1%; 15% is 2.9 sigma.
  ASSERT_TRUE(q->channels[0].noiseRms.has_value());
  EXPECT_NEAR(*q->channels[0].noiseRms / spec.forceNoiseRms, 1.0, 0.15);
  EXPECT_NEAR(*q->channels[1].noiseRms / spec.responseNoiseRms, 1.0, 0.15);
  ASSERT_TRUE(q->forceSnrDb.has_value());
  EXPECT_NEAR(*q->forceSnrDb, 20 * std::log10(spec.peakForceN / spec.forceNoiseRms), 1.5);
}

TEST(HitQuality, DoubleHitIsFlaggedWithDelayAndRatio) {
  for (double delay : {4e-3, 15e-3, 60e-3}) {
    HammerHitSpec spec = baseSpec(9);
    spec.secondHitDelayS = delay;
    spec.secondHitFraction = 0.3;
    auto rec = synthesizeHammerHit(twoDof(), spec);
    ASSERT_TRUE(rec.ok());
    auto q = assessHit(*rec);
    ASSERT_TRUE(q.ok());
    EXPECT_FALSE(q->accepted);
    EXPECT_TRUE(q->doubleHit) << "delay " << delay;
    ASSERT_TRUE(q->secondHitDelayS.has_value());
    // rebound peak within one sample of the programmed delay; ratio within 2%
    // (the sampled peak of a 16-sample half-sine is within cos(pi/16) = 98% of the true peak)
    EXPECT_NEAR(*q->secondHitDelayS, delay, 1.0 / spec.sampleRateHz);
    EXPECT_NEAR(q->secondHitRatio, 0.3, 0.3 * 0.02);
    EXPECT_NE(q->verdictText().find("double hit"), std::string::npos) << q->verdictText();
  }
}

TEST(HitQuality, ClippingIsFlaggedOnEveryChannel) {
  for (Eigen::Index channel : {0, 1, 2}) {
    HammerHitSpec spec = baseSpec(11);
    spec.clipFraction = 0.8;
    spec.clipChannels = {channel};
    auto rec = synthesizeHammerHit(twoDof(), spec);
    ASSERT_TRUE(rec.ok());
    auto q = assessHit(*rec);
    ASSERT_TRUE(q.ok());
    EXPECT_FALSE(q->accepted);
    for (Eigen::Index c = 0; c < 3; ++c) {
      EXPECT_EQ(q->channels[static_cast<std::size_t>(c)].clipped, c == channel)
          << "clipped " << channel << ", checked " << c;
    }
    EXPECT_NE(q->verdictText().find("overload on channel " + std::to_string(channel)), std::string::npos)
        << q->verdictText();
  }
  // With the DAQ full scale known, reaching it is an overload even without a flat top.
  HammerHitSpec spec = baseSpec(12);
  spec.fullScale = 60.0;  // the 100 N hammer exceeds a 60 N range
  auto rec = synthesizeHammerHit(twoDof(), spec);
  ASSERT_TRUE(rec.ok());
  auto q = assessHit(*rec);
  ASSERT_TRUE(q.ok());
  EXPECT_FALSE(q->accepted);
  EXPECT_TRUE(q->channels[0].clipped);
  // Every sample at or beyond 0.999 of the range, counted one by one.
  const double limit = HitQualityOptions{}.fullScaleMargin * rec->channels[0].fullScale;
  const auto force = rec->samples.col(0);
  EXPECT_EQ(q->channels[0].clippedSamples, (force.array().abs() >= limit).count());
  EXPECT_GT(q->channels[0].clippedSamples, 0);
}

TEST(HitQuality, EarlyWeakAndNarrowHitsAreRejectedWithReasons) {
  HammerHitSpec early = baseSpec(13);
  early.preTriggerSamples = 2;
  auto r1 = assessHit(*synthesizeHammerHit(twoDof(), early));
  ASSERT_TRUE(r1.ok());
  EXPECT_FALSE(r1->accepted);
  EXPECT_NE(r1->verdictText().find("too early"), std::string::npos) << r1->verdictText();

  HammerHitSpec weak = baseSpec(14);
  weak.peakForceN = 0.5;  // 0.5 N against 0.02 N noise: 28 dB < 30 dB
  auto r2 = assessHit(*synthesizeHammerHit(twoDof(), weak));
  ASSERT_TRUE(r2.ok());
  EXPECT_FALSE(r2->accepted);
  EXPECT_NE(r2->verdictText().find("too weak"), std::string::npos) << r2->verdictText();

  HammerHitSpec soft = baseSpec(15);
  soft.pulseWidthS = 8e-3;  // soft tip: f_10 ~ 128 Hz
  HitQualityOptions opt;
  opt.minUsableBandHz = 400.0;
  auto r3 = assessHit(*synthesizeHammerHit(twoDof(), soft), opt);
  ASSERT_TRUE(r3.ok());
  EXPECT_FALSE(r3->accepted);
  EXPECT_NE(r3->verdictText().find("usable band too narrow"), std::string::npos) << r3->verdictText();
}

TEST(HitQuality, BadInputIsAnError) {
  auto rec = synthesizeHammerHit(twoDof(), baseSpec(16));
  ASSERT_TRUE(rec.ok());
  TimeRecord r = *rec;
  r.sampleRateHz = 0.0;
  EXPECT_FALSE(assessHit(r).ok());
  r = *rec;
  r.samples(100, 1) = std::nan("");
  auto e = assessHit(r);
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().where.find("sample 100"), std::string::npos) << e.error().describe();
  // The first offender channel by channel: a NaN in channel 1 before a bad
  // sensitivity in channel 2.
  r = *rec;
  r.samples(7, 1) = std::nan("");
  r.channels[2].transducer.sensitivityMvPerUnit = 0.0;
  e = assessHit(r);
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().where.find("sample 7"), std::string::npos) << e.error().describe();
  EXPECT_EQ(e.error().describe(), r.validate().error().describe());
  r = *rec;
  r.samples.resize(0, 3);
  EXPECT_FALSE(assessHit(r).ok());
  r = *rec;
  r.channels[0].transducer.kind = TransducerKind::Acceleration;  // no force channel
  EXPECT_FALSE(assessHit(r).ok());
  // zero force: a valid record, rejected with a reason (nothing to divide by)
  r = *rec;
  r.samples.col(0).setZero();
  auto z = assessHit(r);
  ASSERT_TRUE(z.ok());
  EXPECT_FALSE(z->accepted);
  EXPECT_NE(z->verdictText().find("no signal"), std::string::npos) << z->verdictText();
}

}  // namespace
}  // namespace mozzi::core::signal
