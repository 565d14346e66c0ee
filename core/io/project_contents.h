#pragma once
// What a project holds, specimen by specimen: the records of each kind, by id
// in store order. The workbench's Overview page shows it as counts and opens
// pages on the first record of a kind (WORKBENCH.md: the demo project must
// let a newcomer walk the three jobs in five minutes). Read through the
// store's public queries only.

#include <cstdint>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/io/project_records.h"

namespace mozzi::core::io {

class ProjectStore;

struct SpecimenContents {
  std::int64_t specimenId = 0;
  std::string name;
  std::string kind;
  int meshNodes = 0;
  std::vector<std::int64_t> campaigns;
  std::vector<std::int64_t> frfSets;
  std::vector<std::int64_t> modalResults;
  std::vector<std::int64_t> staticRigTests;   // rig tests of kind "static"
  std::vector<std::int64_t> dynamicRigTests;  // every other rig test (sine sweeps)
  std::vector<std::int64_t> tyreTests;
  // Gap diagnoses and other stored analyses, each with its kind and name (the
  // page of its kind opens it), in id order; their results are not read.
  std::vector<AnalysisInfo> analyses;
};

// One entry per specimen, in the summary's order.
Result<std::vector<SpecimenContents>> projectContents(const ProjectStore& store);

}  // namespace mozzi::core::io
