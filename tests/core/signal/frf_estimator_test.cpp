// H1/H2/Hv estimators, spectra scaling and the errors on bad input.
#include "core/signal/frf_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace mozzi::core::signal {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Force channel plus one response = gain x force delayed circularly by d
// samples: exactly H(f_k) = gain exp(-i 2 pi k d / n) at every line.
TimeRecord delayedRecord(Eigen::Index n, Eigen::Index d, double gain, std::uint64_t seed,
                         TransducerKind kind = TransducerKind::Acceleration) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  TimeRecord r;
  r.sampleRateHz = 1024.0;
  r.channels.resize(2);
  r.channels[0].transducer.kind = TransducerKind::Force;
  r.channels[0].dof = Dof{1, Direction::Z, false};
  r.channels[1].transducer.kind = kind;
  r.channels[1].dof = Dof{2, Direction::Y, true};
  r.samples.resize(n, 2);
  for (Eigen::Index i = 0; i < n; ++i) r.samples(i, 0) = normal(rng);
  for (Eigen::Index i = 0; i < n; ++i) r.samples(i, 1) = gain * r.samples((i - d + n) % n, 0);
  return r;
}

TEST(FrfEstimator, ExactOnNoiseFreeDelay) {
  const Eigen::Index n = 512, d = 5;
  std::vector<TimeRecord> hits = {delayedRecord(n, d, 2.5, 1), delayedRecord(n, d, 2.5, 2)};
  for (auto est : {FrfEstimator::H1, FrfEstimator::H2, FrfEstimator::Hv}) {
    FrfOptions opt;
    opt.estimator = est;
    auto frf = estimateFrf(hits, opt);
    ASSERT_TRUE(frf.ok()) << frf.error().describe();
    ASSERT_TRUE(frf->validate().ok());
    EXPECT_EQ(frf->references[0], (Dof{1, Direction::Z, false}));
    EXPECT_EQ(frf->responses[0], (Dof{2, Direction::Y, true}));
    EXPECT_EQ(frf->lineCount(), n / 2 + 1);
    EXPECT_DOUBLE_EQ(frf->frequencyHz[1], 2.0);  // fs / n
    for (Eigen::Index k = 0; k < frf->lineCount(); ++k) {
      const Complex h = 2.5 * std::polar(1.0, -2 * kPi * double(k * d) / double(n));
      ASSERT_LT(std::abs(frf->h[0](k, 0) - h), 1e-12) << frfEstimatorName(est) << " line " << k;
      ASSERT_NEAR(frf->coherence[0](k, 0), 1.0, 1e-12);
    }
  }
}

// Parseval: sum_k G_ff(f_k) df = sum_i f_i^2 / fs (energy [EU^2 s]) for the
// one-sided ESD scaling, and the same for G_xx.
TEST(FrfEstimator, EnergySpectraSatisfyParseval) {
  for (Eigen::Index n : {512, 511}) {
    const TimeRecord r = delayedRecord(n, 3, 0.5, 9);
    auto avg = SpectralAverager::create(r, FrfOptions{});
    ASSERT_TRUE(avg.ok());
    ASSERT_TRUE(avg->add(r).ok());
    const double df = r.sampleRateHz / double(n);
    EXPECT_NEAR(avg->gff().sum() * df / (r.samples.col(0).squaredNorm() / r.sampleRateHz), 1.0, 1e-12) << n;
    EXPECT_NEAR(avg->gxx().col(0).sum() * df / (r.samples.col(1).squaredNorm() / r.sampleRateHz), 1.0, 1e-12) << n;
    // cross spectrum of x = g f(t - d): G_fx = g exp(-i omega d) G_ff
    EXPECT_NEAR(std::abs(avg->gfx()(7, 0)) / avg->gff()[7], 0.5, 1e-12);
  }
}

// Coherence with uncorrelated output noise: gamma^2 -> S / (S + N); with white
// force and noise of variances 1 and 1/3 the expectation is 0.75 at every line.
TEST(FrfEstimator, CoherenceMeasuresTheNoiseShare) {
  const Eigen::Index n = 256;
  std::mt19937_64 rng(4);
  std::normal_distribution<double> noise(0.0, std::sqrt(1.0 / 3.0));
  std::vector<TimeRecord> hits;
  for (int h = 0; h < 400; ++h) {
    TimeRecord r = delayedRecord(n, 0, 1.0, 100 + static_cast<std::uint64_t>(h));
    for (Eigen::Index i = 0; i < n; ++i) r.samples(i, 1) += noise(rng);
    hits.push_back(r);
  }
  auto frf = estimateFrf(hits, FrfOptions{});
  ASSERT_TRUE(frf.ok());
  // mean over 127 inner lines of a 400-average estimate: spread ~0.001; 0.01 margin
  const double mean = frf->coherence[0].col(0).segment(1, n / 2 - 1).mean();
  EXPECT_NEAR(mean, 0.75, 0.01);
  // and H1 stays unbiased: mean |H1| within 1% of 1
  EXPECT_NEAR(frf->h[0].col(0).segment(1, n / 2 - 1).cwiseAbs().mean(), 1.0, 0.01);
}

TEST(FrfEstimator, FrfTypeFollowsTheResponseTransducer) {
  auto v = estimateFrf({delayedRecord(64, 1, 1.0, 1, TransducerKind::Velocity)}, FrfOptions{});
  ASSERT_TRUE(v.ok());
  EXPECT_EQ(v->type, FrfType::Mobility);
  auto d = estimateFrf({delayedRecord(64, 1, 1.0, 1, TransducerKind::Displacement)}, FrfOptions{});
  ASSERT_TRUE(d.ok());
  EXPECT_EQ(d->type, FrfType::Receptance);
  EXPECT_FALSE(estimateFrf({delayedRecord(64, 1, 1.0, 1, TransducerKind::Other)}, FrfOptions{}).ok());
  // accelerance -> receptance (thesis eq. 7: divide by -omega^2) once DC is dropped
  auto a = estimateFrf({delayedRecord(64, 0, 3.0, 1)}, FrfOptions{});
  ASSERT_TRUE(a.ok());
  EXPECT_FALSE(a->convertedTo(FrfType::Receptance).ok());  // DC line
  auto band = selectBand(*a, 1.0, 1e9);
  ASSERT_TRUE(band.ok());
  EXPECT_EQ(band->lineCount(), a->lineCount() - 1);
  auto rec = band->convertedTo(FrfType::Receptance);
  ASSERT_TRUE(rec.ok());
  const double w = 2 * kPi * rec->frequencyHz[3];
  EXPECT_NEAR(std::abs(rec->h[0](3, 0) - Complex(-3.0 / (w * w), 0.0)), 0.0, 1e-12);
  EXPECT_FALSE(selectBand(*a, 1e6, 2e6).ok());
}

TEST(FrfEstimator, EstimatorNamesParse) {
  EXPECT_EQ(*parseFrfEstimator("h1"), FrfEstimator::H1);
  EXPECT_EQ(*parseFrfEstimator("H2"), FrfEstimator::H2);
  EXPECT_EQ(*parseFrfEstimator("HV"), FrfEstimator::Hv);
  EXPECT_FALSE(parseFrfEstimator("H3").ok());
}

// Issue 3: bad input gives a clear error, never NaN results or a crash.
TEST(FrfEstimator, BadInputIsAClearError) {
  const TimeRecord good = delayedRecord(128, 2, 1.0, 5);
  auto describe = [](const Result<FrfMatrix>& r) { return r.ok() ? std::string("ok") : r.error().describe(); };

  EXPECT_FALSE(estimateFrf({}, FrfOptions{}).ok());  // no hits

  TimeRecord empty = good;
  empty.samples.resize(0, 2);
  auto e1 = estimateFrf({empty}, FrfOptions{});
  ASSERT_FALSE(e1.ok());
  EXPECT_NE(e1.error().message.find("empty"), std::string::npos) << describe(e1);

  TimeRecord shorter = delayedRecord(100, 2, 1.0, 6);
  auto e2 = estimateFrf({good, shorter}, FrfOptions{});
  ASSERT_FALSE(e2.ok());
  EXPECT_NE(e2.error().message.find("mismatched lengths"), std::string::npos) << describe(e2);
  EXPECT_NE(e2.error().where.find("hit 2"), std::string::npos) << describe(e2);

  TimeRecord columns = good;
  columns.samples.conservativeResize(128, 1);
  EXPECT_FALSE(estimateFrf({columns}, FrfOptions{}).ok());

  TimeRecord zero = good;
  zero.samples.col(0).setZero();
  auto e3 = estimateFrf({zero}, FrfOptions{});
  ASSERT_FALSE(e3.ok());
  EXPECT_NE(e3.error().message.find("force is zero"), std::string::npos) << describe(e3);

  TimeRecord nan = good;
  nan.samples(77, 1) = std::nan("");
  auto e4 = estimateFrf({good, nan}, FrfOptions{});
  ASSERT_FALSE(e4.ok());
  EXPECT_NE(e4.error().where.find("sample 77"), std::string::npos) << describe(e4);
  EXPECT_NE(e4.error().where.find("channel 1"), std::string::npos) << describe(e4);

  TimeRecord inf = good;
  inf.samples(3, 0) = INFINITY;
  EXPECT_FALSE(estimateFrf({inf}, FrfOptions{}).ok());

  TimeRecord rate = good;
  rate.sampleRateHz = 0.0;
  auto e5 = estimateFrf({rate}, FrfOptions{});
  ASSERT_FALSE(e5.ok());
  EXPECT_NE(e5.error().message.find("sample rate"), std::string::npos) << describe(e5);
  auto e6 = estimateFrf({good, rate}, FrfOptions{});
  EXPECT_FALSE(e6.ok());

  TimeRecord moved = good;
  moved.channels[1].dof.node = 9;
  EXPECT_FALSE(estimateFrf({good, moved}, FrfOptions{}).ok());

  FrfOptions badRef;
  badRef.referenceChannel = 5;
  EXPECT_FALSE(estimateFrf({good}, badRef).ok());

  TimeRecord twoForces = good;
  twoForces.channels[1].transducer.kind = TransducerKind::Force;
  EXPECT_FALSE(estimateFrf({twoForces}, FrfOptions{}).ok());

  // a silent response: H1 = 0 with coherence 0 (valid), H2 and Hv divide by zero
  TimeRecord silent = good;
  silent.samples.col(1).setZero();
  auto h1 = estimateFrf({silent}, FrfOptions{});
  ASSERT_TRUE(h1.ok());
  EXPECT_EQ(h1->coherence[0].maxCoeff(), 0.0);
  EXPECT_TRUE(h1->validate().ok());
  FrfOptions h2;
  h2.estimator = FrfEstimator::H2;
  EXPECT_FALSE(estimateFrf({silent}, h2).ok());

  // a failed hit leaves the average untouched
  auto avg = SpectralAverager::create(good, FrfOptions{});
  ASSERT_TRUE(avg.ok());
  ASSERT_TRUE(avg->add(good).ok());
  EXPECT_FALSE(avg->add(nan).ok());
  EXPECT_EQ(avg->hitCount(), 1);
  EXPECT_TRUE(avg->gxx().allFinite());
}

// Two forces and two responses built from circular delays, y1 = 2 f1(t-3) +
// 0.5 f2(t-1) and y2 = -f2(t-4): the exact H matrix is known at every line, so
// H = Gyf Gff^-1 must return it to rounding once two or more blocks make Gff
// invertible; one block leaves Gff of rank 1 (an error).
TEST(FrfEstimator, SeveralReferencesRecoverAnExactMatrix) {
  const Eigen::Index n = 256;
  std::vector<TimeRecord> blocks;
  std::mt19937_64 rng(4);
  std::normal_distribution<double> normal;
  for (int b = 0; b < 3; ++b) {
    TimeRecord r;
    r.sampleRateHz = 1024.0;
    r.channels.resize(4);
    for (int c = 0; c < 4; ++c) {
      r.channels[static_cast<std::size_t>(c)].dof = Dof{c + 1, Direction::X, false};
      r.channels[static_cast<std::size_t>(c)].transducer.kind =
          c < 2 ? TransducerKind::Force : TransducerKind::Velocity;
    }
    r.samples.resize(n, 4);
    for (Eigen::Index i = 0; i < n; ++i) r.samples(i, 0) = normal(rng), r.samples(i, 1) = normal(rng);
    for (Eigen::Index i = 0; i < n; ++i) {
      r.samples(i, 2) = 2.0 * r.samples((i - 3 + n) % n, 0) + 0.5 * r.samples((i - 1 + n) % n, 1);
      r.samples(i, 3) = -r.samples((i - 4 + n) % n, 1);
    }
    blocks.push_back(std::move(r));
  }
  auto avg = SpectralAverager::create(blocks[0], FrfOptions{});  // both Force channels become references
  ASSERT_TRUE(avg.ok()) << avg.error().describe();
  EXPECT_EQ(avg->referenceCount(), 2);
  ASSERT_TRUE(avg->add(blocks[0]).ok());
  auto rankOne = avg->frf();
  ASSERT_FALSE(rankOne.ok());
  EXPECT_NE(rankOne.error().message.find("ill-conditioned"), std::string::npos);
  // a copy is independent of the original (accumulators are not shared)
  SpectralAverager copy = *avg;
  ASSERT_TRUE(avg->add(blocks[1]).ok());
  ASSERT_TRUE(avg->add(blocks[2]).ok());
  EXPECT_EQ(copy.hitCount(), 1);
  EXPECT_FALSE(copy.frf().ok());
  auto frf = avg->frf();
  ASSERT_TRUE(frf.ok()) << frf.error().describe();
  EXPECT_EQ(frf->type, FrfType::Mobility);
  ASSERT_TRUE(frf->validate().ok());
  for (Eigen::Index k = 0; k < frf->lineCount(); ++k) {
    const auto delay = [&](double d) { return std::polar(1.0, -2 * kPi * double(k) * d / double(n)); };
    EXPECT_LT(std::abs(frf->h[0](k, 0) - 2.0 * delay(3)), 1e-10) << k;
    EXPECT_LT(std::abs(frf->h[1](k, 0) - 0.5 * delay(1)), 1e-10) << k;
    EXPECT_LT(std::abs(frf->h[0](k, 1)), 1e-10) << k;
    EXPECT_LT(std::abs(frf->h[1](k, 1) + delay(4)), 1e-10) << k;
    EXPECT_NEAR(frf->coherence[0](k, 0), 1.0, 1e-10);  // multiple coherence
    EXPECT_EQ(frf->coherence[1](k, 0), frf->coherence[0](k, 0));
  }
  // Gff at a line is Hermitian, with the single-reference scaling on its diagonal
  const ComplexMatrix g = avg->referenceSpectralMatrix(10);
  EXPECT_LT((g - g.adjoint()).norm(), 1e-15 * g.norm());
  EXPECT_DOUBLE_EQ(g(0, 0).real(), avg->gff()[10]);

  // explicit reference lists: checked
  FrfOptions dup;
  dup.referenceChannels = {0, 0};
  EXPECT_FALSE(SpectralAverager::create(blocks[0], dup).ok());
  FrfOptions range;
  range.referenceChannels = {0, 7};
  EXPECT_FALSE(SpectralAverager::create(blocks[0], range).ok());
  FrfOptions one;
  one.referenceChannels = {0};  // the other force is then a response of kind Force: no FRF type
  EXPECT_FALSE(SpectralAverager::create(blocks[0], one).ok());
}

// Three references go through the general path (eigen decomposition of the
// normalised Gff instead of the 2 x 2 closed form): y = f1(t-1) - 2 f2(t-2) +
// 0.25 f3(t-5), exact to rounding from four blocks.
TEST(FrfEstimator, ThreeReferencesRecoverAnExactRow) {
  const Eigen::Index n = 128;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal;
  auto avg = Result<SpectralAverager>(makeError(ErrorCode::InvalidArgument, "unset", "test"));
  for (int b = 0; b < 4; ++b) {
    TimeRecord r;
    r.sampleRateHz = 256.0;
    r.channels.resize(4);
    for (int c = 0; c < 4; ++c) {
      r.channels[static_cast<std::size_t>(c)].dof = Dof{c + 1, Direction::Y, false};
      r.channels[static_cast<std::size_t>(c)].transducer.kind =
          c < 3 ? TransducerKind::Force : TransducerKind::Acceleration;
    }
    r.samples.resize(n, 4);
    for (Eigen::Index i = 0; i < n; ++i) {
      for (int c = 0; c < 3; ++c) r.samples(i, c) = normal(rng);
    }
    for (Eigen::Index i = 0; i < n; ++i) {
      r.samples(i, 3) =
          r.samples((i - 1 + n) % n, 0) - 2.0 * r.samples((i - 2 + n) % n, 1) + 0.25 * r.samples((i - 5 + n) % n, 2);
    }
    if (b == 0) avg = SpectralAverager::create(r, FrfOptions{});
    ASSERT_TRUE(avg.ok());
    ASSERT_TRUE(avg->add(r).ok());
  }
  auto frf = avg->frf();
  ASSERT_TRUE(frf.ok()) << frf.error().describe();
  ASSERT_EQ(frf->referenceCount(), 3);
  const double gain[3] = {1.0, -2.0, 0.25};
  const double delay[3] = {1.0, 2.0, 5.0};
  for (Eigen::Index k = 0; k < frf->lineCount(); ++k) {
    for (int i = 0; i < 3; ++i) {
      const Complex h = gain[i] * std::polar(1.0, -2 * kPi * double(k) * delay[i] / double(n));
      EXPECT_LT(std::abs(frf->h[static_cast<std::size_t>(i)](k, 0) - h), 1e-9) << k << " ref " << i;
    }
    EXPECT_NEAR(frf->coherence[0](k, 0), 1.0, 1e-9);
  }
  EXPECT_LT(avg->referenceConditionNumber().maxCoeff(), 1e3);
}

}  // namespace
}  // namespace mozzi::core::signal
