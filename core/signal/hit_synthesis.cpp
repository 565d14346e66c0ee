#include "core/signal/hit_synthesis.h"

#include "core/signal/fft.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace mozzi::core::signal {

namespace {
constexpr double kPi = 3.14159265358979323846;

// Half-sine pulse P sin(pi (t - t0) / Tp) on [t0, t0 + Tp], else 0.
double halfSine(double t, double t0, double width, double peak) {
  const double u = t - t0;
  return (u >= 0.0 && u <= width) ? peak * std::sin(kPi * u / width) : 0.0;
}
}  // namespace

Result<TimeRecord> synthesizeHammerHit(const LinearMdof& system, const HammerHitSpec& spec) {
  const std::string where = "hammer hit synthesis";
  const Eigen::Index n = system.dofCount();
  if (spec.excitedDof < 0 || spec.excitedDof >= n) {
    return makeError(ErrorCode::InvalidArgument, "excited DOF index outside the system", where);
  }
  if (spec.sampleCount < 2 || spec.oversampling < 1 || spec.preTriggerSamples < 0 ||
      spec.preTriggerSamples >= spec.sampleCount) {
    return makeError(ErrorCode::InvalidArgument, "sample count, pre-trigger or oversampling out of range", where);
  }
  if (!(spec.pulseWidthS > 0.0) || !(spec.sampleRateHz > 0.0) || !std::isfinite(spec.peakForceN)) {
    return makeError(ErrorCode::InvalidArgument, "pulse width and sample rate must be positive", where);
  }
  if (!spec.dofLabels.empty() && static_cast<Eigen::Index>(spec.dofLabels.size()) != n) {
    return makeError(ErrorCode::InvalidArgument, "one DOF label per system DOF expected", where);
  }
  std::vector<Eigen::Index> measured = spec.measuredDofs;
  if (measured.empty()) {
    for (Eigen::Index i = 0; i < n; ++i) measured.push_back(i);
  }
  for (auto d : measured) {
    if (d < 0 || d >= n) return makeError(ErrorCode::InvalidArgument, "measured DOF index outside the system", where);
  }
  auto label = [&](Eigen::Index i) {
    return spec.dofLabels.empty() ? Dof{static_cast<int>(i + 1), Direction::Z, false}
                                  : spec.dofLabels[static_cast<std::size_t>(i)];
  };

  const double fsFine = spec.sampleRateHz * static_cast<double>(spec.oversampling);
  // Guard of 64 DAQ samples before and after the record: the (circular)
  // anti-aliasing filter's ringing at the record ends falls in the guards,
  // which are dropped.
  const Eigen::Index guard = spec.oversampling > 1 ? 64 : 0;
  const Eigen::Index nFine = (spec.sampleCount + 2 * guard) * spec.oversampling;
  const double t0 = static_cast<double>(spec.preTriggerSamples + guard) / spec.sampleRateHz;
  auto pulse = [&](double t) {
    double f = halfSine(t, t0, spec.pulseWidthS, spec.peakForceN);
    if (spec.secondHitDelayS) {
      f += halfSine(t, t0 + *spec.secondHitDelayS, spec.pulseWidthS, spec.secondHitFraction * spec.peakForceN);
    }
    return f;
  };
  Matrix forceFine = Matrix::Zero(nFine, n);
  for (Eigen::Index i = 0; i < nFine; ++i) forceFine(i, spec.excitedDof) = pulse(static_cast<double>(i) / fsFine);
  MOZZI_TRY_ASSIGN(auto sim, simulateMdof(system, forceFine, fsFine, ForceHold::FirstOrder));

  TimeRecord rec;
  rec.sampleRateHz = spec.sampleRateHz;
  rec.preTriggerSamples = spec.preTriggerSamples;
  Channel force;
  force.name = "force";
  force.transducer = Transducer{TransducerKind::Force, "synthetic hammer", "sim-0", 2.25, "N", true};
  force.dof = label(spec.excitedDof);
  force.fullScale = spec.fullScale;
  rec.channels.push_back(force);
  const Matrix* source = &sim.acceleration;
  const char* unit = "m/s^2";
  if (spec.responseKind == TransducerKind::Velocity) {
    source = &sim.velocity;
    unit = "m/s";
  } else if (spec.responseKind == TransducerKind::Displacement) {
    source = &sim.displacement;
    unit = "m";
  } else if (spec.responseKind != TransducerKind::Acceleration) {
    return makeError(ErrorCode::Unsupported, "responses can be acceleration, velocity or displacement", where);
  }
  for (auto d : measured) {
    Channel c;
    c.name = "response " + formatDof(label(d));
    c.transducer = Transducer{spec.responseKind, "synthetic sensor", "sim-" + std::to_string(d + 1), 10.0, unit, true};
    c.dof = label(d);
    c.fullScale = spec.fullScale;
    rec.channels.push_back(c);
  }
  // Every channel on the fine grid, through the DAQ's anti-aliasing filter,
  // then sampled at the DAQ rate.
  Matrix fine(nFine, rec.channelCount());
  fine.col(0) = forceFine.col(spec.excitedDof);
  for (std::size_t j = 0; j < measured.size(); ++j)
    fine.col(static_cast<Eigen::Index>(j + 1)) = source->col(measured[j]);
  if (spec.oversampling > 1) {
    MOZZI_TRY_ASSIGN(auto fft, RealFft::forLength(nFine));
    ComplexVector spectrum(fft->lineCount());
    const double fc = 0.4 * spec.sampleRateHz;
    for (Eigen::Index c = 0; c < fine.cols(); ++c) {
      Vector col = fine.col(c);
      fft->forward(col.data(), spectrum.data());
      for (Eigen::Index k = 0; k < spectrum.size(); ++k) {
        // |G(f)| = 1 / sqrt(1 + (f / fc)^8): zero-phase 4th-order Butterworth magnitude
        const double r = static_cast<double>(k) * fsFine / static_cast<double>(nFine) / fc;
        spectrum[k] *= 1.0 / std::sqrt(1.0 + std::pow(r, 8)) / static_cast<double>(nFine);
      }
      if (!fft->inverse(spectrum.data(), col.data())) {
        return makeError(ErrorCode::NumericalFailure, "FFTW could not plan the inverse FFT", "hammer hit synthesis");
      }
      fine.col(c) = col;
    }
  }
  rec.samples.resize(spec.sampleCount, rec.channelCount());
  std::mt19937_64 rng(spec.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (Eigen::Index k = 0; k < spec.sampleCount; ++k) {
    const Eigen::Index at = (k + guard) * spec.oversampling;
    rec.samples(k, 0) = fine(at, 0) + spec.forceNoiseRms * normal(rng);
    for (std::size_t j = 0; j < measured.size(); ++j) {
      const auto c = static_cast<Eigen::Index>(j + 1);
      rec.samples(k, c) = fine(at, c) + spec.responseNoiseRms * normal(rng);
    }
  }
  if (spec.clipFraction > 0.0) {
    for (Eigen::Index c = 0; c < rec.channelCount(); ++c) {
      if (!spec.clipChannels.empty() &&
          std::find(spec.clipChannels.begin(), spec.clipChannels.end(), c) == spec.clipChannels.end()) {
        continue;
      }
      const double level = spec.clipFraction * rec.samples.col(c).cwiseAbs().maxCoeff();
      rec.samples.col(c) = rec.samples.col(c).cwiseMax(-level).cwiseMin(level);
    }
  }
  return rec;
}

}  // namespace mozzi::core::signal
