#pragma once
// Measured or synthesised FRFs on a common frequency axis: the one FRF type
// shared by signal processing, file exchange, modal identification and the gap
// diagnosis. H_{o,i}(f_k) = response o / reference i at line k, of one FrfType.

#include <vector>

#include "core/common/dof.h"
#include "core/common/eigen_types.h"
#include "core/common/frf_type.h"
#include "core/common/result.h"

namespace mozzi::core {

struct FrfMatrix {
  Vector frequencyHz;           // nf lines [Hz], strictly ascending, not necessarily even
  std::vector<Dof> responses;   // no output DOFs
  std::vector<Dof> references;  // ni input DOFs
  FrfType type = FrfType::Accelerance;
  // h[i] is nf x no: column o holds H_{o,i} over frequency.
  std::vector<ComplexMatrix> h;
  // Ordinary coherence per h[i] (nf x no, values in [0, 1]); empty when unknown.
  std::vector<Matrix> coherence;

  Eigen::Index lineCount() const { return frequencyHz.size(); }
  Eigen::Index responseCount() const { return static_cast<Eigen::Index>(responses.size()); }
  Eigen::Index referenceCount() const { return static_cast<Eigen::Index>(references.size()); }

  // Shapes agree, frequencies finite and strictly ascending, no NaN in h or
  // coherence, coherence within [0, 1]. The error names the first offender.
  Result<void> validate() const;

  // Same FRFs expressed as another type (multiplying by (i omega)^n); a line at
  // 0 Hz is an error when the conversion divides by omega.
  Result<FrfMatrix> convertedTo(FrfType target) const;

  // The same values with responses and references exchanged, H'_{i,o} = H_{o,i}
  // (coherence too): what a reciprocal structure (Maxwell-Betti) gives when
  // excitation and measurement swap places, and in any case a matrix with the
  // same poles.
  FrfMatrix transposed() const;
};

}  // namespace mozzi::core
