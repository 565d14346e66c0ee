#include "core/signal/hit_quality.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "core/signal/fft.h"
#include "core/signal/sample_scan.h"

namespace mozzi::core::signal {

namespace {
std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string channelText(const TimeRecord& r, Eigen::Index c) {
  const auto& ch = r.channels[static_cast<std::size_t>(c)];
  return "channel " + std::to_string(c) + (ch.name.empty() ? std::string() : " '" + ch.name + "'") + " (" +
         formatDof(ch.dof) + ")";
}

// Linear interpolation of the crossing of `level` between samples i-1 and i
// of y (a = y[i-1] on one side, b = y[i] on the other); returns a fractional index.
double crossing(double a, double b, Eigen::Index i, double level) {
  if (a == b) return static_cast<double>(i);
  return static_cast<double>(i - 1) + (level - a) / (b - a);
}

// The force pulse and its spectrum, per thread: FFTW-aligned (the plan runs
// on them without a copy), kept between hits (no fresh pages per hit).
struct PulseWorkspace {
  AlignedBuffer<double> pulse;
  AlignedBuffer<std::complex<double>> spectrum;
};
PulseWorkspace& pulseWorkspace(Eigen::Index n) {
  thread_local PulseWorkspace ws;
  if (ws.pulse.size() < static_cast<std::size_t>(n)) ws.pulse = AlignedBuffer<double>(static_cast<std::size_t>(n));
  if (ws.spectrum.size() < static_cast<std::size_t>(n / 2 + 1)) {
    ws.spectrum = AlignedBuffer<std::complex<double>>(static_cast<std::size_t>(n / 2 + 1));
  }
  return ws;
}
}  // namespace

std::string HitQuality::verdictText() const {
  if (accepted) return "accepted";
  std::string s = "rejected: ";
  for (std::size_t i = 0; i < reasons.size(); ++i) s += (i ? "; " : "") + reasons[i];
  return s;
}

Result<HitQuality> assessHit(const TimeRecord& record, const HitQualityOptions& options) {
  if (!record.validateLayout()) return record.validate().error();  // its first offender
  const Eigen::Index n = record.sampleCount();
  // Each channel's extremes and finiteness in one pass; a NaN or an infinity
  // is named by validate(), as before the check was folded in here.
  std::vector<SampleExtremes> extremes;
  extremes.reserve(static_cast<std::size_t>(record.channelCount()));
  for (Eigen::Index c = 0; c < record.channelCount(); ++c) {
    extremes.push_back(scanSamples(record.samples.col(c).data(), n));
    if (!extremes.back().finite) return record.validate().error();
  }
  HitQuality q;
  if (options.referenceChannel) {
    if (*options.referenceChannel < 0 || *options.referenceChannel >= record.channelCount()) {
      return makeError(ErrorCode::InvalidArgument, "reference channel does not exist", "hit quality options");
    }
    q.referenceChannel = *options.referenceChannel;
  } else {
    auto ref = findForceChannel(record);
    if (!ref) return ref.error();
    q.referenceChannel = *ref;
  }
  const double fs = record.sampleRateHz;
  const Eigen::Index pre = record.preTriggerSamples;
  // Noise floor from the first 3/4 of the pre-trigger: the last quarter may
  // already hold the foot of the pulse (and the DAQ filter's pre-ringing).
  const Eigen::Index quiet = pre - pre / 4;

  // --- every channel: peak, noise floor, overload -----------------------------
  for (Eigen::Index c = 0; c < record.channelCount(); ++c) {
    const auto x = record.samples.col(c);
    ChannelQuality cq;
    cq.name = record.channels[static_cast<std::size_t>(c)].name;
    cq.dof = record.channels[static_cast<std::size_t>(c)].dof;
    const double hi = extremes[static_cast<std::size_t>(c)].max, lo = extremes[static_cast<std::size_t>(c)].min;
    cq.peak = std::max(std::abs(hi), std::abs(lo));  // max |x|
    if (quiet >= 2) {
      const auto head = x.head(quiet);
      const double mean = head.mean();
      cq.noiseRms = std::sqrt((head.array() - mean).square().sum() / static_cast<double>(quiet - 1));
    }
    if (cq.peak == 0.0) {
      q.reasons.push_back("no signal on " + channelText(record, c) + " (all samples are zero)");
      q.channels.push_back(cq);
      continue;
    }
    const double fullScale = record.channels[static_cast<std::size_t>(c)].fullScale;
    if (fullScale > 0.0) {
      const double limit = options.fullScaleMargin * fullScale;
      const ThresholdCounts beyond = countBeyond(x.data(), n, limit, -limit);  // |x| >= limit
      cq.clippedSamples = limit > 0.0 ? beyond.atOrAbove + beyond.atOrBelow : (std::isnan(limit) ? 0 : n);
    } else {
      // flat tops: runs of >= clipRunLength samples pinned at a significant extreme
      const double tol = 1e-9 * cq.peak;
      // No run can be longer than the samples near the extreme: one
      // vectorised count of them first (usually the peak alone), the run
      // scan only when there are enough. Counted within 2 tol, a bound on
      // those within tol whatever the rounding of x - extreme.
      const ThresholdCounts near = countBeyond(x.data(), n, hi - 2.0 * tol, lo + 2.0 * tol);
      const Eigen::Index nearHi = near.atOrAbove, nearLo = near.atOrBelow;
      for (const double extreme : {hi, lo}) {
        if (std::abs(extreme) < 0.5 * cq.peak) continue;
        if ((extreme == hi ? nearHi : nearLo) < options.clipRunLength) continue;
        Eigen::Index run = 0;
        for (Eigen::Index i = 0; i <= n; ++i) {
          if (i < n && std::abs(x[i] - extreme) <= tol) {
            ++run;
            continue;
          }
          if (run >= options.clipRunLength) cq.clippedSamples += run;
          run = 0;
        }
      }
    }
    if (cq.clippedSamples > 0) {
      cq.clipped = true;
      q.reasons.push_back("overload on " + channelText(record, c) + ": " + std::to_string(cq.clippedSamples) +
                          " samples clipped at " + fmt("%.4g", cq.peak) + " " +
                          record.channels[static_cast<std::size_t>(c)].transducer.unit);
    }
    q.channels.push_back(cq);
  }

  // --- force pulse ---------------------------------------------------------------
  const auto& refq = q.channels[static_cast<std::size_t>(q.referenceChannel)];
  if (refq.peak == 0.0) {
    q.accepted = false;
    return q;
  }
  PulseWorkspace& ws = pulseWorkspace(n);
  Eigen::Map<Vector> f(ws.pulse.data(), n);
  // The pre-trigger offset taken from the aligned copy (Eigen's sum starts
  // its packets at the first aligned sample: over the column itself the order
  // of adding, and the last bit, would depend on the column's address). max
  // |f| from the channel's extremes: x - offset rounds monotonically in x, so
  // the largest and smallest f are those of the largest and smallest x.
  f = record.samples.col(q.referenceChannel);
  const double offset = quiet >= 2 ? f.head(quiet).mean() : 0.0;
  if (quiet >= 2) f.array() -= offset;
  const SampleExtremes& forceRange = extremes[static_cast<std::size_t>(q.referenceChannel)];
  const double absMax = std::max(forceRange.max - offset, offset - forceRange.min);
  const double noise = refq.noiseRms.value_or(0.0);
  // Its first index (Eigen's maxCoeff(&index) takes the first too, but runs
  // scalar): a scan to it.
  Eigen::Index peakIdx = 0;
  while (peakIdx + 1 < n && std::abs(f[peakIdx]) != absMax) ++peakIdx;
  const double peak = f[peakIdx];
  q.peakForce = peak;
  const double sign = peak >= 0.0 ? 1.0 : -1.0;
  const auto s = [&](Eigen::Index i) { return f[i] * sign; };  // main pulse positive
  const double absPeak = std::abs(peak);
  if (noise > 0.0) q.forceSnrDb = 20.0 * std::log10(absPeak / noise);
  if (quiet < 2) q.notes.push_back("too few pre-trigger samples: noise floor unknown");

  const double trigger =
      options.triggerLevel.value_or(std::max(options.triggerFraction * absPeak, options.noiseFactor * noise));
  for (Eigen::Index i = 0; i < n; ++i) {
    if (s(i) >= trigger) {
      q.triggerSample = i;
      break;
    }
  }
  if (!q.triggerSample) {
    q.reasons.push_back("force never reaches the trigger level of " + fmt("%.4g", trigger) + " N");
  } else {
    q.preTriggerS = static_cast<double>(*q.triggerSample) / fs;
    if (*q.triggerSample < options.minPreTriggerSamples) {
      q.reasons.push_back("hit too early: " + std::to_string(*q.triggerSample) + " samples before the trigger, " +
                          std::to_string(options.minPreTriggerSamples) + " needed (the start of the pulse is lost)");
    }
  }
  if (q.forceSnrDb && *q.forceSnrDb < options.minForceSnrDb) {
    q.reasons.push_back("force too weak against noise: peak " + fmt("%.1f", *q.forceSnrDb) + " dB above the noise, " +
                        fmt("%.0f", options.minForceSnrDb) + " dB needed");
  }

  // pulse edges at max(edge fraction x peak, noise factor x noise)
  const double edge = std::max(options.pulseEdgeFraction * absPeak, options.noiseFactor * noise);
  Eigen::Index a = peakIdx, b = peakIdx;
  while (a > 0 && s(a - 1) >= edge) --a;
  while (b + 1 < n && s(b + 1) >= edge) ++b;
  const double start = a > 0 ? crossing(s(a - 1), s(a), a, edge) : 0.0;
  const double end = b + 1 < n ? crossing(s(b), s(b + 1), b + 1, edge) : static_cast<double>(n - 1);
  q.pulseWidthS = (end - start) / fs;

  // double hit: a second excursion after the main pulse has ended
  const double reboundLevel = std::max(options.doubleHitFraction * absPeak, options.noiseFactor * noise);
  // The largest |f| after the pulse (its first sample) when it reaches the
  // rebound level.
  Eigen::Index second = -1;
  double secondPeak = 0.0;
  if (b + 1 < n) {
    const SampleExtremes after = scanSamples(f.data() + b + 1, n - b - 1);
    const double m = std::max(after.max, -after.min);  // max |f| after the pulse
    if (m >= reboundLevel && m > 0.0) {
      secondPeak = m;
      second = b + 1;
      while (second + 1 < n && std::abs(f[second]) != m) ++second;
    }
  }
  if (second >= 0) {
    q.doubleHit = true;
    q.secondHitDelayS = static_cast<double>(second - peakIdx) / fs;
    q.secondHitRatio = secondPeak / absPeak;
    q.reasons.push_back("double hit: second impact " + fmt("%.1f", 1e3 * *q.secondHitDelayS) +
                        " ms after the first at " + fmt("%.0f", 100.0 * q.secondHitRatio) + "% of its peak");
  }

  // usable band from the energy spectrum of the main pulse: rectangular window
  // over [0, end + max(width, 4 samples)], zero elsewhere, full record length
  const Eigen::Index guard = std::max<Eigen::Index>(4, static_cast<Eigen::Index>(std::ceil(q.pulseWidthS * fs)));
  const Eigen::Index cut = std::min<Eigen::Index>(n, static_cast<Eigen::Index>(std::ceil(end)) + guard + 1);
  // f becomes the pulse alone, in place (it is not read after this).
  f.tail(n - cut).setZero();
  if (second >= 0 && second < cut) f.segment(b + 1, cut - b - 1).setZero();
  auto fft = RealFft::forLength(n);
  if (!fft) return fft.error();
  (*fft)->forward(f.data(), ws.spectrum.data());
  // |F(f)|^2 over the pulse's buffer, free now: no fresh pages per hit.
  Eigen::Map<Vector> energy(ws.pulse.data(), n / 2 + 1);
  energy = Eigen::Map<const ComplexVector>(ws.spectrum.data(), n / 2 + 1).cwiseAbs2();
  const double df = fs / static_cast<double>(n);
  // reference level: mean over the low-frequency plateau, f <= 0.1 / width
  const Eigen::Index plateau = std::clamp<Eigen::Index>(
      static_cast<Eigen::Index>(0.1 / std::max(q.pulseWidthS, 1.0 / fs) / df), 1, energy.size() - 1);
  const double ref = energy.head(plateau + 1).mean();
  auto fallsTo = [&](double ratio) -> std::optional<double> {
    const double level = ref * ratio;
    for (Eigen::Index k = 1; k < energy.size(); ++k) {
      if (energy[k] < level) {
        // interpolate in dB between lines k-1 and k
        const double la = 10.0 * std::log10(energy[k - 1]), lb = 10.0 * std::log10(std::max(energy[k], 1e-300));
        const double lt = 10.0 * std::log10(level);
        const double frac = la == lb ? 0.0 : (la - lt) / (la - lb);
        return (static_cast<double>(k - 1) + frac) * df;
      }
    }
    return std::nullopt;
  };
  if (ref > 0.0) {
    q.usableBand10dBHz = fallsTo(0.1);   // -10 dB in energy
    q.usableBand20dBHz = fallsTo(0.01);  // -20 dB
  }
  if (!q.usableBand10dBHz)
    q.notes.push_back("force spectrum stays within 10 dB up to Nyquist (tip harder than needed)");
  if (options.minUsableBandHz > 0.0 && q.usableBand10dBHz && *q.usableBand10dBHz < options.minUsableBandHz) {
    q.reasons.push_back("usable band too narrow: force spectrum 10 dB down at " + fmt("%.0f", *q.usableBand10dBHz) +
                        " Hz, " + fmt("%.0f", options.minUsableBandHz) + " Hz needed (use a harder tip)");
  }
  q.accepted = q.reasons.empty();
  return q;
}

}  // namespace mozzi::core::signal
