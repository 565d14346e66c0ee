#include "core/common/frf_matrix.h"

#include <cmath>
#include <string>

namespace mozzi::core {

FrfMatrix FrfMatrix::transposed() const {
  FrfMatrix t;
  t.frequencyHz = frequencyHz;
  t.responses = references;
  t.references = responses;
  t.type = type;
  const Eigen::Index nf = lineCount(), no = responseCount(), ni = referenceCount();
  t.h.assign(static_cast<std::size_t>(no), ComplexMatrix(nf, ni));
  if (!coherence.empty()) t.coherence.assign(static_cast<std::size_t>(no), Matrix(nf, ni));
  for (Eigen::Index i = 0; i < ni && static_cast<std::size_t>(i) < h.size(); ++i) {
    const auto iu = static_cast<std::size_t>(i);
    for (Eigen::Index o = 0; o < no && o < h[iu].cols(); ++o) {
      t.h[static_cast<std::size_t>(o)].col(i) = h[iu].col(o);
      if (!coherence.empty() && iu < coherence.size())
        t.coherence[static_cast<std::size_t>(o)].col(i) = coherence[iu].col(o);
    }
  }
  return t;
}

Result<void> FrfMatrix::validate() const {
  const std::string where = "FRF matrix";
  if (frequencyHz.size() == 0) return makeError(ErrorCode::InvalidArgument, "no frequency lines", where);
  if (responses.empty() || references.empty()) {
    return makeError(ErrorCode::InvalidArgument, "no response or no reference DOF", where);
  }
  for (Eigen::Index k = 0; k < frequencyHz.size(); ++k) {
    if (!std::isfinite(frequencyHz[k]) || frequencyHz[k] < 0.0) {
      return makeError(ErrorCode::InvalidArgument, "frequency is negative or not finite",
                       where + ", line " + std::to_string(k));
    }
    if (k > 0 && !(frequencyHz[k] > frequencyHz[k - 1])) {
      return makeError(ErrorCode::InvalidArgument, "frequencies are not strictly ascending",
                       where + ", line " + std::to_string(k));
    }
  }
  if (h.size() != references.size()) {
    return makeError(
        ErrorCode::InvalidArgument,
        "expected one block per reference (" + std::to_string(references.size()) + "), got " + std::to_string(h.size()),
        where);
  }
  if (!coherence.empty() && coherence.size() != h.size()) {
    return makeError(ErrorCode::InvalidArgument, "coherence blocks do not match FRF blocks", where);
  }
  for (std::size_t i = 0; i < h.size(); ++i) {
    const std::string ref = where + ", reference " + formatDof(references[i]);
    if (h[i].rows() != lineCount() || h[i].cols() != responseCount()) {
      return makeError(ErrorCode::InvalidArgument,
                       "block is " + std::to_string(h[i].rows()) + "x" + std::to_string(h[i].cols()) + ", expected " +
                           std::to_string(lineCount()) + "x" + std::to_string(responseCount()),
                       ref);
    }
    for (Eigen::Index o = 0; o < h[i].cols(); ++o) {
      for (Eigen::Index k = 0; k < h[i].rows(); ++k) {
        if (!std::isfinite(h[i](k, o).real()) || !std::isfinite(h[i](k, o).imag())) {
          return makeError(
              ErrorCode::InvalidArgument, "FRF value is not finite",
              ref + ", response " + formatDof(responses[static_cast<std::size_t>(o)]) + ", line " + std::to_string(k));
        }
      }
    }
    if (!coherence.empty()) {
      if (coherence[i].rows() != lineCount() || coherence[i].cols() != responseCount()) {
        return makeError(ErrorCode::InvalidArgument, "coherence block has the wrong shape", ref);
      }
      for (Eigen::Index o = 0; o < coherence[i].cols(); ++o) {
        for (Eigen::Index k = 0; k < coherence[i].rows(); ++k) {
          const double g = coherence[i](k, o);
          if (!(g >= 0.0 && g <= 1.0)) {
            return makeError(ErrorCode::InvalidArgument, "coherence outside [0, 1]",
                             ref + ", response " + formatDof(responses[static_cast<std::size_t>(o)]) + ", line " +
                                 std::to_string(k));
          }
        }
      }
    }
  }
  return {};
}

Result<FrfMatrix> FrfMatrix::convertedTo(FrfType target) const {
  MOZZI_TRY(validate());
  FrfMatrix out = *this;
  out.type = target;
  if (target == type) return out;
  const bool divides = frfTypeOrder(target) < frfTypeOrder(type);
  for (Eigen::Index k = 0; k < lineCount(); ++k) {
    if (divides && frequencyHz[k] == 0.0) {
      return makeError(ErrorCode::InvalidArgument,
                       std::string("cannot convert the 0 Hz line from ") + frfTypeName(type) + " to " +
                           frfTypeName(target) + " (division by omega); drop the DC line first",
                       "FRF matrix, line " + std::to_string(k));
    }
    const Complex factor = frfConversionFactor(type, target, 2.0 * M_PI * frequencyHz[k]);
    for (auto& block : out.h) block.row(k) *= factor;
  }
  return out;
}

}  // namespace mozzi::core
