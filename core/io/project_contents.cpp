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
  MOZZI_TRY_ASSIGN(const auto summary, store.summary());
  std::vector<SpecimenContents> all;
  all.reserve(summary.specimens.size());
  for (const auto& sp : summary.specimens) {
    SpecimenContents c;
    c.specimenId = sp.id;
    c.name = sp.name;
    c.kind = sp.kind;
    MOZZI_TRY_ASSIGN(const auto mesh, store.mesh(sp.id));
    c.meshNodes = static_cast<int>(mesh.nodes.size());
    MOZZI_TRY_ASSIGN(const auto campaigns, store.campaigns(sp.id));
    for (const auto& campaign : campaigns) c.campaigns.push_back(campaign.id);
    all.push_back(std::move(c));
  }
  // Files each record of `records` under its specimen, in `list`.
  auto file = [&](const auto& records, auto list) {
    for (const auto& record : records)
      if (auto* c = find(all, record.specimenId)) (c->*list).push_back(record.id);
  };
  MOZZI_TRY_ASSIGN(const auto frfSets, store.frfSets());
  file(frfSets, &SpecimenContents::frfSets);
  MOZZI_TRY_ASSIGN(const auto modal, store.modalResults());
  file(modal, &SpecimenContents::modalResults);
  MOZZI_TRY_ASSIGN(const auto rigTests, store.rigTests());
  for (const auto& test : rigTests) {
    if (auto* c = find(all, test.specimenId))
      (test.kind == "static" ? c->staticRigTests : c->dynamicRigTests).push_back(test.id);
  }
  MOZZI_TRY_ASSIGN(const auto tyreTests, store.tyreTests());
  file(tyreTests, &SpecimenContents::tyreTests);
  MOZZI_TRY_ASSIGN(const auto analyses, store.analysisInfos());
  for (const auto& analysis : analyses)
    if (auto* c = find(all, analysis.specimenId)) c->analyses.push_back(analysis);
  return all;
}

}  // namespace mozzi::core::io
