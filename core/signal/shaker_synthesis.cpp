#include "core/signal/shaker_synthesis.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "core/signal/fft.h"

namespace mozzi::core::signal {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

Result<std::vector<TimeRecord>> synthesizeShakerBlocks(const LinearMdof& system, const ShakerTestSpec& spec) {
  const std::string where = "shaker test synthesis";
  const Eigen::Index nd = system.dofCount();
  const auto nr = static_cast<Eigen::Index>(spec.forcedDofs.size());
  if (nr < 1) return makeError(ErrorCode::InvalidArgument, "no forced DOF", where);
  for (std::size_t i = 0; i < spec.forcedDofs.size(); ++i) {
    const Eigen::Index d = spec.forcedDofs[i];
    if (d < 0 || d >= nd) return makeError(ErrorCode::InvalidArgument, "forced DOF index outside the system", where);
    if (std::count(spec.forcedDofs.begin(), spec.forcedDofs.end(), d) > 1) {
      return makeError(ErrorCode::InvalidArgument, "a DOF is forced twice", where);
    }
  }
  if (spec.blockSamples < 4 || spec.oversampling < 1 || spec.settleBlocks < 0 || spec.blocks < 1 ||
      !(spec.sampleRateHz > 0.0) || !std::isfinite(spec.sampleRateHz) || !(spec.forceRmsN > 0.0)) {
    return makeError(ErrorCode::InvalidArgument,
                     "block length, oversampling, block count, rate or force level out of range", where);
  }
  if (!spec.dofLabels.empty() && static_cast<Eigen::Index>(spec.dofLabels.size()) != nd) {
    return makeError(ErrorCode::InvalidArgument, "one DOF label per system DOF expected", where);
  }
  const Eigen::Index n = spec.blockSamples, nFine = n * spec.oversampling, nf = n / 2 + 1;
  const Eigen::Index periods = spec.settleBlocks + 1;
  MOZZI_TRY_ASSIGN(auto fft, RealFft::forLength(nFine));
  std::mt19937_64 rng(spec.seed);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * kPi);
  std::normal_distribution<double> normal;
  // nf lines of amplitude a (cos amplitude; a real line contributes a^2, the
  // others a^2 / 2 to the mean square) give about forceRms^2 = nf a^2 / 2
  const double lineAmp = spec.forceRmsN * std::sqrt(2.0 / static_cast<double>(nf));
  const auto fineN = static_cast<double>(nFine);

  TimeRecord layout;
  layout.sampleRateHz = spec.sampleRateHz;
  const auto label = [&](Eigen::Index d) {
    return spec.dofLabels.empty() ? Dof{static_cast<int>(d) + 1, Direction::Z, false}
                                  : spec.dofLabels[static_cast<std::size_t>(d)];
  };
  for (Eigen::Index i = 0; i < nr; ++i) {
    Channel ch;
    ch.transducer.kind = TransducerKind::Force;
    ch.transducer.unit = "N";
    ch.dof = label(spec.forcedDofs[static_cast<std::size_t>(i)]);
    ch.name = "force " + formatDof(ch.dof);
    layout.channels.push_back(ch);
  }
  for (Eigen::Index d = 0; d < nd; ++d) {
    Channel ch;
    ch.transducer.kind = spec.responseKind;
    ch.dof = label(d);
    ch.name = "response " + formatDof(ch.dof);
    layout.channels.push_back(ch);
  }

  std::vector<TimeRecord> blocks;
  std::vector<double> firstPhases(static_cast<std::size_t>(nf));
  ComplexVector spectrum(nFine / 2 + 1);
  Vector period(nFine);
  for (int b = 0; b < spec.blocks; ++b) {
    Matrix force = Matrix::Zero(nFine * periods, nd);
    for (Eigen::Index i = 0; i < nr; ++i) {
      spectrum.setZero();
      for (Eigen::Index k = 0; k < nf; ++k) {
        double p = phase(rng);
        if (i == 0) firstPhases[static_cast<std::size_t>(k)] = p;
        if (i > 0 && k >= spec.correlatedFromLine && k <= spec.correlatedToLine)
          p = firstPhases[static_cast<std::size_t>(k)];
        // a cos(2 pi k t / T + p) has DFT coefficient (a N / 2) e^{ip}; a real
        // line (DC, Nyquist) a cos(p) N
        const bool realLine = k == 0 || (n % 2 == 0 && k == nf - 1);
        spectrum[k] = realLine ? Complex(lineAmp * std::cos(p) * fineN, 0.0) : std::polar(lineAmp * 0.5 * fineN, p);
      }
      if (!fft->inverse(spectrum.data(), period.data())) {  // unnormalised: n x(t)
        return makeError(ErrorCode::NumericalFailure, "FFTW could not plan the inverse FFT", "shaker synthesis");
      }
      period /= fineN;
      for (Eigen::Index p = 0; p < periods; ++p) {
        force.col(spec.forcedDofs[static_cast<std::size_t>(i)]).segment(p * nFine, nFine) = period;
      }
    }
    MOZZI_TRY_ASSIGN(auto resp, simulateMdof(system, force, spec.sampleRateHz * static_cast<double>(spec.oversampling),
                                             ForceHold::FirstOrder));
    const Matrix& y = spec.responseKind == TransducerKind::Displacement ? resp.displacement
                      : spec.responseKind == TransducerKind::Velocity   ? resp.velocity
                                                                        : resp.acceleration;
    TimeRecord rec = layout;
    rec.samples.resize(n, nr + nd);
    const Eigen::Index first = spec.settleBlocks * nFine;
    for (Eigen::Index j = 0; j < n; ++j) {
      const Eigen::Index t = first + j * spec.oversampling;
      for (Eigen::Index i = 0; i < nr; ++i) rec.samples(j, i) = force(t, spec.forcedDofs[static_cast<std::size_t>(i)]);
      rec.samples.row(j).tail(nd) = y.row(t);
    }
    if (spec.responseNoiseRms > 0.0) {
      for (Eigen::Index j = 0; j < n; ++j) {
        for (Eigen::Index d = 0; d < nd; ++d) rec.samples(j, nr + d) += spec.responseNoiseRms * normal(rng);
      }
    }
    blocks.push_back(std::move(rec));
  }
  return blocks;
}

}  // namespace mozzi::core::signal
