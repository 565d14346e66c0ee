#pragma once
// Running the sequences on the simulated rigs: which virtual specimen a
// `--specimen` text means, and the demo project's rig and tyre tests.

#include <cstdint>
#include <string>

#include "core/common/result.h"

namespace mozzi::core::io {
class ProjectStore;
}
namespace mozzi::devices::sim {
struct SpecimenEntry;
}

namespace mozzi::devices::rigtests {

struct SpecimenChoice {
  std::string catalogueKey;  // devices/sim/specimen_catalogue.h key, e.g. "fork-a-with-wheel"
  std::int64_t specimenId = 0;
  std::string projectName;  // the project specimen's name
  bool created = false;     // the specimen was added to the project for this test
};

// `text` is a catalogue key (mozzi-cli rig list, e.g. "frame-a-front-constrained")
// or the name of a project specimen that stands for a catalogue entry (its name
// is the entry's name, or starts the entry's name before a comma, as the demo's
// "Frame A" does for "Frame A, front-constrained", or holds a tyre's size).
// A key with no specimen in the project adds one (the catalogue's name, kind
// and sources) unless `store` is read-only. Errors name the text and list
// where the keys are.
core::Result<SpecimenChoice> resolveSpecimen(core::io::ProjectStore& store, const std::string& text);

// The virtual specimen a project specimen's name stands for, by the rule
// above (the entry's name, the part before its comma, a tyre's size);
// nullptr when none.
const sim::SpecimenEntry* catalogueEntryForName(const std::string& specimenName);

// The demo project's rig and tyre tests (issue 20): a static and a dynamic
// test of fork A with wheel and of frame A (front-constrained) on the
// simulated Motostiffmeter, a relaxation and a steady-state test of the
// 120/70 R17 tyre on the simulated Mototiremeter; fixed seeds, sim.realtime off.
core::Result<void> addDemoRigTests(core::io::ProjectStore& store);

}  // namespace mozzi::devices::rigtests
