#pragma once
// A result the project keeps as an analysis row whose result_json one record
// type writes and reads (stability sweeps in stability_record.h, wheelchair
// manoeuvres in wheelchair_record.h): its row under a free name, the default
// specimen, and reading the rows back, written once for every kind.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/common/result.h"
#include "core/io/project_records.h"
#include "core/io/project_store.h"

namespace mozzi::core::stability {

template <class Record>
struct StoredResult {
  std::int64_t analysisId = 0;
  std::int64_t specimenId = 0;
  std::string name;
  Record record;
};

// `base`, or "base (2)", "base (3)", ... : the first name the specimen has no
// analysis of (analysis names are unique per specimen).
Result<std::string> freeAnalysisName(const io::ProjectStore& store, std::int64_t specimenId, const std::string& base);

// The analysis row of `kind` holding `resultJson` under the first free name
// from `name`; an empty name is an error at `nameWhere` ("stability result name").
Result<io::StoredAnalysis> resultAnalysis(const io::ProjectStore& store, std::int64_t specimenId,
                                          const std::string& name, const char* kind, const char* nameWhere,
                                          std::string resultJson);

// The specimen a result is kept under when none is chosen: the first specimen
// of kind `specimenKind`, else the project's first. NotFound when the project
// has no specimen.
Result<std::int64_t> defaultSpecimenOfKind(const io::ProjectStore& store, const std::string& specimenKind);

// Every analysis of `kind` that `fromJson` (std::string -> Result<Record>)
// reads, in id order; the ids it cannot read in `unreadable` when given.
template <class Record, class FromJson>
Result<std::vector<StoredResult<Record>>> storedResults(const io::ProjectStore& store, const char* kind,
                                                        FromJson fromJson, std::vector<std::int64_t>* unreadable) {
  MOZZI_TRY_ASSIGN(const auto analyses, store.analyses());
  std::vector<StoredResult<Record>> out;
  for (const auto& a : analyses) {
    if (a.kind != kind) continue;
    auto r = fromJson(a.resultJson);
    if (!r) {
      if (unreadable) unreadable->push_back(a.id);
      continue;
    }
    out.push_back({a.id, a.specimenId, a.name, std::move(*r)});
  }
  return out;
}

// One analysis by id; NotFound when it is not of `kind` ("... not a <noun>"),
// a reading error with the analysis named in its `where`.
template <class Record, class FromJson>
Result<StoredResult<Record>> storedResult(const io::ProjectStore& store, std::int64_t analysisId, const char* kind,
                                          const char* noun, FromJson fromJson) {
  MOZZI_TRY_ASSIGN(const io::StoredAnalysis a, store.analysis(analysisId));
  const std::string where = "analysis " + std::to_string(analysisId);
  if (a.kind != kind) {
    return makeError(ErrorCode::NotFound, "is of kind '" + a.kind + "', not a " + noun, where);
  }
  auto r = fromJson(a.resultJson);
  if (!r) return Error{r.error().code, r.error().message, where + ": " + r.error().where};
  return StoredResult<Record>{a.id, a.specimenId, a.name, std::move(*r)};
}

}  // namespace mozzi::core::stability
