#pragma once
// Forks the project keeps: the Lumped Fork page stores its results as analyses
// of kind "lumped-fork" (the motorcycle fork's lumped models 1 to 3, thesis
// §4.2, Table 12, with the keys of `mozzi-cli fork lumped --json` and the
// inputs) and "bicycle-fork" (the bicycle fork's torsion and bending stiffness
// and damping and the bending arm h_W, §6.4, §6.5). Read here into the
// stability models' fork parameters, so the Stability page can sweep the
// vehicle with the project's identified fork instead of the thesis's.
//
// Motorcycle (motorcycle.h LumpedForkModel): k_i, c_i, J_i and L_i as kept;
// the vibrating mass M = the input's vibrating mass; its arm below the bending
// axis = L_i - the wheel-centre height (Table 12: 0.670 - 0.265 = 0.405 m).
// Bicycle (compliant_fork_bicycle.h): bending k_beta, c_beta, h_W as kept;
// torsion k_gamma of the fork alone and c_gamma (as thesisSteelForkTorsion,
// §6.4: eq. 54, 55), the axis on the steer axis.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/stability/compliant_fork_bicycle.h"
#include "core/stability/motorcycle.h"

namespace mozzi::core::io {
class ProjectStore;
}

namespace mozzi::core::stability {

struct KeptFork {
  std::int64_t analysisId = 0;
  std::string name;  // the analysis's name, e.g. "Lumped fork models 1 to 3"
  std::int64_t specimenId = 0;
  bool motorcycle = false;
  std::array<std::optional<LumpedForkModel>, 3> lumped;  // models 1 to 3 (motorcycle)
  std::optional<ForkBending> bending;                    // bicycle
  std::optional<ForkTorsion> torsion;                    // bicycle
};

// One kept analysis's result_json. Errors name the missing key.
Result<KeptFork> keptForkFromJson(const std::string& json, const std::string& kind);

// Every readable kept fork of the project, in analysis order; analyses whose
// JSON cannot be read are left out (their ids in `unreadable` when given).
Result<std::vector<KeptFork>> keptForks(const io::ProjectStore& store, std::vector<std::int64_t>* unreadable = nullptr);

}  // namespace mozzi::core::stability
