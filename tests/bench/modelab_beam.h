#pragma once
// The ModeLAB beam (shared/data/modelab-beam, SignalCalc ASCII export): nine
// roving-hammer accelerances at X, response 4 +X, 51,200 lines at 0.0195 Hz,
// read once. Shared by modal_plscf_bench and cli_commands_bench.

#include <cstdio>
#include <string>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/io/modelab_ascii.h"

namespace mozzi::core::modal::bench {

inline const FrfMatrix& modelabBeam() {
  static const FrfMatrix frf = [] {
    std::vector<std::string> files;
    std::vector<Dof> hammers;
    for (int i = 1; i <= 9; ++i) {
      char name[160];
      std::snprintf(name, sizeof name, "%s/modelab-beam/SignalCalc/ASCII%05d/Hxysv%05d.txt", MOZZI_SHARED_DATA_DIR, i,
                    i);
      files.emplace_back(name);
      hammers.push_back(Dof{i, Direction::X, false});
    }
    return io::readSignalCalcRovingHammer(files, hammers, Dof{4, Direction::X, true}, FrfType::Accelerance).value();
  }();
  return frf;
}

}  // namespace mozzi::core::modal::bench
