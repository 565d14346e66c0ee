#pragma once
// The project report's "stability" and "wheelchair" sections (issues 22, 23),
// built from the stored analyses of kinds "stability" and "wheelchair"
// (core/stability/stability_record.h, wheelchair_record.h): for each, what was
// computed, its figures (rendered by views/report/stability_figures.cpp with
// the pages' own plots) and the critical speeds with the digits `mozzi-cli
// stability` prints, or the manoeuvre's summary per run.

#include <cstdint>
#include <map>
#include <string>

#include "core/common/result.h"
#include "core/io/project_store.h"
#include "core/report/report.h"

namespace mozzi::core::report {

// Analyses of these kinds ("stability", "wheelchair") have their own sections,
// not the gap section's.
bool hasOwnStabilitySection(const std::string& analysisKind);

// `specimens`: the specimens reported (id to name). True when blocks were added.
Result<bool> stabilitySection(const io::ProjectStore& store, const std::map<std::int64_t, std::string>& specimens,
                              Section& section);
Result<bool> wheelchairSection(const io::ProjectStore& store, const std::map<std::int64_t, std::string>& specimens,
                               Section& section);

}  // namespace mozzi::core::report
