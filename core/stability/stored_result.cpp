#include "core/stability/stored_result.h"

namespace mozzi::core::stability {

Result<std::string> freeAnalysisName(const io::ProjectStore& store, std::int64_t specimenId, const std::string& base) {
  MOZZI_TRY_ASSIGN(const auto analyses, store.analyses());
  auto taken = [&](const std::string& name) {
    for (const auto& a : analyses)
      if (a.specimenId == specimenId && a.name == name) return true;
    return false;
  };
  if (!taken(base)) return base;
  for (int k = 2;; ++k) {
    const std::string name = base + " (" + std::to_string(k) + ")";
    if (!taken(name)) return name;
  }
}

Result<io::StoredAnalysis> resultAnalysis(const io::ProjectStore& store, std::int64_t specimenId,
                                          const std::string& name, const char* kind, const char* nameWhere,
                                          std::string resultJson) {
  if (name.empty()) return makeError(ErrorCode::InvalidArgument, "the name is empty", nameWhere);
  MOZZI_TRY_ASSIGN(std::string free, freeAnalysisName(store, specimenId, name));
  io::StoredAnalysis a;
  a.specimenId = specimenId;
  a.kind = kind;
  a.name = std::move(free);
  a.resultJson = std::move(resultJson);
  return a;
}

Result<std::int64_t> defaultSpecimenOfKind(const io::ProjectStore& store, const std::string& specimenKind) {
  MOZZI_TRY_ASSIGN(const auto summary, store.summary());
  if (summary.specimens.empty())
    return makeError(ErrorCode::NotFound, "the project has no specimen to keep the result under", store.path());
  for (const auto& s : summary.specimens)
    if (s.kind == specimenKind) return s.id;
  return summary.specimens.front().id;
}

}  // namespace mozzi::core::stability
