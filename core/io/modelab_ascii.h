#pragma once
// Reader for the SignalCalc ASCII FRF export used by the ModeLAB example data
// (github.com/alxhslm/ModeLAB, Example/SignalCalc; copy in
// shared/data/modelab-beam): a 9-line header (units line may hold non-ASCII
// bytes), then tab-separated rows "frequency real imaginary", CRLF line ends.

#include <string>
#include <vector>

#include "core/common/dof.h"
#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/result.h"

namespace mozzi::core::io {

struct SignalCalcFrf {
  Vector frequencyHz;
  ComplexVector h;
  std::string unitsLine;  // the header's units text as found (bytes kept)
};

// One exported FRF. Parse errors name the file and the line.
Result<SignalCalcFrf> readSignalCalcAscii(const std::string& path);

// Roving-hammer set: files[i] is the FRF for hammer position i (reference
// DOF refs[i]) to the fixed response DOF `response`. The result is a one-row
// FRF matrix stored by reciprocity as one reference (`response`) and the
// hammer DOFs as responses (H_{response, ref_i} = H_{ref_i, response}), of the
// given type. All files must share the frequency axis.
Result<FrfMatrix> readSignalCalcRovingHammer(const std::vector<std::string>& files, const std::vector<Dof>& hammerDofs,
                                             const Dof& response, FrfType type);

}  // namespace mozzi::core::io
