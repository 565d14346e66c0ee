#pragma once
// The exponential window an FRF set was measured with, for the identification
// of a stored set (`mozzi-cli identify --frf-set` and the workbench's
// identification page): a campaign's response window adds 1/tau to every
// pole's decay, which the identified damping must lose
// (core::signal::correctExponentialWindowDamping). Both callers use this one
// function so their numbers agree.

#include <cstdint>

#include "core/common/result.h"
#include "core/io/project_store.h"

namespace mozzi::devices::campaign {

// Time constant [s] of the exponential window of the campaign that measured FRF
// set `frfSetId`; 0 when the set was not measured by a campaign, the campaign
// stores no definition, or it used no exponential window. Errors: no such FRF
// set (NotFound, naming the id), a stored definition that does not parse.
core::Result<double> frfSetExponentialTauS(const core::io::ProjectStore& store, std::int64_t frfSetId);

}  // namespace mozzi::devices::campaign
