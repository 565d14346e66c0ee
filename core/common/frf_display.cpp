#include "core/common/frf_display.h"

#include <cmath>

#include "core/common/plot_math.h"

namespace mozzi::core {

const char* frfViewName(FrfView view) {
  switch (view) {
    case FrfView::MagnitudeLinear: return "magnitude";
    case FrfView::MagnitudeLog: return "magnitude (log)";
    case FrfView::MagnitudeDb: return "magnitude (dB)";
    case FrfView::PhaseWrapped: return "phase (deg)";
    case FrfView::PhaseUnwrapped: return "unwrapped phase (deg)";
    case FrfView::Real: return "real part";
    case FrfView::Imaginary: return "imaginary part";
    case FrfView::Nyquist: return "Nyquist";
    case FrfView::Coherence: return "coherence";
  }
  return "?";
}

bool frfViewIsLogarithmic(FrfView view) {
  return view == FrfView::MagnitudeLog;
}

Vector frfViewValues(const ComplexVectorRef& h, FrfView view) {
  switch (view) {
    case FrfView::MagnitudeLinear:
    case FrfView::MagnitudeLog: return h.cwiseAbs();
    case FrfView::MagnitudeDb: return magnitudeDb(h);
    case FrfView::PhaseWrapped: return phaseDegrees(h, false);
    case FrfView::PhaseUnwrapped: return phaseDegrees(h, true);
    case FrfView::Real: return h.real();
    case FrfView::Imaginary:
    case FrfView::Nyquist: return h.imag();
    case FrfView::Coherence: break;
  }
  return Vector::Constant(h.size(), std::nan(""));
}

std::vector<FrfPick> pickFrfs(const FrfMatrix& frf, const FrfFilter& filter) {
  std::vector<FrfPick> out;
  for (Eigen::Index i = 0; i < frf.referenceCount(); ++i) {
    const Dof& ref = frf.references[static_cast<std::size_t>(i)];
    if (filter.reference && !(*filter.reference == ref)) continue;
    for (Eigen::Index o = 0; o < frf.responseCount(); ++o) {
      const Dof& rsp = frf.responses[static_cast<std::size_t>(o)];
      if (filter.response && !(*filter.response == rsp)) continue;
      if (filter.node && rsp.node != *filter.node && ref.node != *filter.node) continue;
      out.push_back({o, i});
    }
  }
  return out;
}

namespace {

Result<void> checkPicks(const FrfMatrix& frf, const std::vector<FrfPick>& picks, const char* where) {
  if (picks.empty()) return makeError(ErrorCode::InvalidArgument, "no FRF chosen", where);
  for (const auto& p : picks) {
    if (p.response < 0 || p.response >= frf.responseCount() || p.reference < 0 || p.reference >= frf.referenceCount() ||
        static_cast<std::size_t>(p.reference) >= frf.h.size()) {
      return makeError(ErrorCode::InvalidArgument,
                       "FRF (response " + std::to_string(p.response) + ", reference " + std::to_string(p.reference) +
                           ") is not in the set of " + std::to_string(frf.responseCount()) + " x " +
                           std::to_string(frf.referenceCount()),
                       where);
    }
  }
  return {};
}

}  // namespace

Result<ComplexVector> frfSum(const FrfMatrix& frf, const std::vector<FrfPick>& picks) {
  MOZZI_TRY(checkPicks(frf, picks, "FRF sum"));
  ComplexVector sum = ComplexVector::Zero(frf.lineCount());
  for (const auto& p : picks) sum += frf.h[static_cast<std::size_t>(p.reference)].col(p.response);
  return sum;
}

Result<Vector> frfMagnitudeSum(const FrfMatrix& frf, const std::vector<FrfPick>& picks) {
  MOZZI_TRY(checkPicks(frf, picks, "FRF magnitude sum"));
  Vector sum = Vector::Zero(frf.lineCount());
  for (const auto& p : picks) sum += frf.h[static_cast<std::size_t>(p.reference)].col(p.response).cwiseAbs();
  return sum;
}

Result<FrfMatrix> frfSubset(const FrfMatrix& frf, const std::vector<FrfPick>& picks) {
  MOZZI_TRY(checkPicks(frf, picks, "FRF selection"));
  std::vector<Eigen::Index> rsp, ref;
  auto slot = [](std::vector<Eigen::Index>& v, Eigen::Index k) {
    for (std::size_t q = 0; q < v.size(); ++q) {
      if (v[q] == k) return static_cast<Eigen::Index>(q);
    }
    v.push_back(k);
    return static_cast<Eigen::Index>(v.size() - 1);
  };
  for (const auto& p : picks) {
    slot(rsp, p.response);
    slot(ref, p.reference);
  }
  FrfMatrix out;
  out.frequencyHz = frf.frequencyHz;
  out.type = frf.type;
  for (Eigen::Index o : rsp) out.responses.push_back(frf.responses[static_cast<std::size_t>(o)]);
  for (Eigen::Index i : ref) out.references.push_back(frf.references[static_cast<std::size_t>(i)]);
  const auto no = static_cast<Eigen::Index>(rsp.size());
  out.h.assign(ref.size(), ComplexMatrix::Zero(frf.lineCount(), no));
  for (const auto& p : picks) {
    out.h[static_cast<std::size_t>(slot(ref, p.reference))].col(slot(rsp, p.response)) =
        frf.h[static_cast<std::size_t>(p.reference)].col(p.response);
  }
  return out;
}

int nearestMode(const std::vector<double>& modeFrequenciesHz, double frequencyHz) {
  int best = -1;
  for (std::size_t r = 0; r < modeFrequenciesHz.size(); ++r) {
    if (best < 0 || std::abs(modeFrequenciesHz[r] - frequencyHz) < std::abs(modeFrequenciesHz[best] - frequencyHz)) {
      best = static_cast<int>(r);
    }
  }
  return best;
}

}  // namespace mozzi::core
