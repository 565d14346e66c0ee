#include "core/stability/kept_forks.h"

#include <nlohmann/json.hpp>

#include "core/io/project_store.h"

namespace mozzi::core::stability {

namespace {

Result<double> number(const nlohmann::json& j, const char* object, const char* key) {
  if (!j.contains(object) || !j.at(object).is_object() || !j.at(object).contains(key) ||
      !j.at(object).at(key).is_number())
    return makeError(ErrorCode::InvalidArgument, std::string("no number '") + object + "." + key + "'", "kept fork");
  return j.at(object).at(key).get<double>();
}

}  // namespace

Result<KeptFork> keptForkFromJson(const std::string& text, const std::string& kind) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object())
    return makeError(ErrorCode::InvalidArgument, "the result is not a JSON object", "kept fork");
  KeptFork f;
  if (kind == "lumped-fork") {
    f.motorcycle = true;
    MOZZI_TRY_ASSIGN(const double mass, number(j, "inputs", "vibrating_mass_kg"));
    MOZZI_TRY_ASSIGN(const double wheelCentre, number(j, "inputs", "wheel_centre_height_m"));
    if (!j.contains("models")) return makeError(ErrorCode::InvalidArgument, "no 'models'", "kept fork");
    for (int i = 0; i < 3; ++i) {
      const std::string key = "model" + std::to_string(i + 1);
      const nlohmann::json& models = j.at("models");
      auto k = number(models, key.c_str(), "stiffness_Nm_per_rad");
      auto c = number(models, key.c_str(), "damping_Nms_per_rad");
      auto J = number(models, key.c_str(), "inertia_kgm2");
      auto L = number(models, key.c_str(), "arm_m");
      if (!k || !c || !J || !L) continue;  // a model the page could not compute
      f.lumped[static_cast<std::size_t>(i)] =
          LumpedForkModel{"kept " + key, *k, *c, *J, mass, *L - wheelCentre, *L};  // arm below the axis
    }
    if (!f.lumped[0] && !f.lumped[1] && !f.lumped[2])
      return makeError(ErrorCode::InvalidArgument, "no complete lumped model", "kept fork");
    return f;
  }
  if (kind == "bicycle-fork") {
    auto kb = number(j, "bending", "stiffness_Nm_per_rad");
    auto cb = number(j, "bending", "damping_Nms_per_rad");
    auto hW = number(j, "bending", "bend_arm_hW_m");
    auto kt = number(j, "torsion", "stiffness_alone_Nm_per_rad");
    auto ct = number(j, "torsion", "damping_Nms_per_rad");
    if (kb && cb && hW) f.bending = ForkBending{*kb, *cb, *hW};
    if (kt && ct) f.torsion = ForkTorsion{*kt, *ct, 0.0};
    if (!f.bending && !f.torsion)
      return makeError(ErrorCode::InvalidArgument, "neither bending nor torsion stiffness", "kept fork");
    return f;
  }
  return makeError(ErrorCode::InvalidArgument, "'" + kind + "' is not a kept fork", "kept fork");
}

Result<std::vector<KeptFork>> keptForks(const io::ProjectStore& store, std::vector<std::int64_t>* unreadable) {
  MOZZI_TRY_ASSIGN(auto analyses, store.analyses());
  std::vector<KeptFork> out;
  for (const auto& a : analyses) {
    if (a.kind != "lumped-fork" && a.kind != "bicycle-fork") continue;
    auto f = keptForkFromJson(a.resultJson, a.kind);
    if (!f) {
      if (unreadable) unreadable->push_back(a.id);
      continue;
    }
    f->analysisId = a.id;
    f->name = a.name;
    f->specimenId = a.specimenId;
    out.push_back(std::move(*f));
  }
  return out;
}

}  // namespace mozzi::core::stability
