#include "core/io/project_contents.h"

#include <algorithm>

#include "core/io/project_store.h"

namespace mozzi::core::io {

namespace {

SpecimenContents* find(std::vector<SpecimenContents>& all, std::int64_t specimenId) {
  auto it = std::find_if(all.begin(), all.end(), [&](const auto& s) { return s.specimenId == specimenId; });
  return it == all.end() ? nullptr : &*it;
}

}  // namespace

Result<std::vector<SpecimenContents>> projectContents(const ProjectStore& store) {
  auto summary = store.summary();
  if (!summary) return summary.error();
  std::vector<SpecimenContents> all;
  all.reserve(summary->specimens.size());
  for (const auto& sp : summary->specimens) {
    SpecimenContents c;
    c.specimenId = sp.id;
    c.name = sp.name;
    c.kind = sp.kind;
    auto mesh = store.mesh(sp.id);
    if (!mesh) return mesh.error();
    c.meshNodes = static_cast<int>(mesh->nodes.size());
    auto campaigns = store.campaigns(sp.id);
    if (!campaigns) return campaigns.error();
    for (const auto& campaign : *campaigns) c.campaigns.push_back(campaign.id);
    all.push_back(std::move(c));
  }
  auto frfSets = store.frfSets();
  if (!frfSets) return frfSets.error();
  for (const auto& set : *frfSets)
    if (auto* c = find(all, set.specimenId)) c->frfSets.push_back(set.id);
  auto modal = store.modalResults();
  if (!modal) return modal.error();
  for (const auto& result : *modal)
    if (auto* c = find(all, result.specimenId)) c->modalResults.push_back(result.id);
  auto rigTests = store.rigTests();
  if (!rigTests) return rigTests.error();
  for (const auto& test : *rigTests) {
    if (auto* c = find(all, test.specimenId))
      (test.kind == "static" ? c->staticRigTests : c->dynamicRigTests).push_back(test.id);
  }
  auto tyreTests = store.tyreTests();
  if (!tyreTests) return tyreTests.error();
  for (const auto& test : *tyreTests)
    if (auto* c = find(all, test.specimenId)) c->tyreTests.push_back(test.id);
  auto analyses = store.analyses();
  if (!analyses) return analyses.error();
  for (const auto& analysis : *analyses)
    if (auto* c = find(all, analysis.specimenId)) c->analyses.push_back(analysis.id);
  return all;
}

}  // namespace mozzi::core::io
