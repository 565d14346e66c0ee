#include "core/report/report_template.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/io/project_meta.h"

namespace mozzi::core::report {

std::string templateToJson(const ReportTemplate& t) {
  nlohmann::json j = {{"sections", t.sections},
                      {"specimen", t.specimen},
                      {"language", languageCode(t.language)},
                      {"pdf", t.pdf},
                      {"html", t.html}};
  return j.dump();
}

Result<ReportTemplate> templateFromJson(const std::string& text) {
  const std::string where = "report template";
  const auto j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object()) return makeError(ErrorCode::ParseError, "the report template is not a JSON object", where);
  ReportTemplate t;
  if (j.contains("sections")) {
    if (!j["sections"].is_array())
      return makeError(ErrorCode::ParseError, "\"sections\" is not a list of section keys", where);
    const auto& keys = reportSectionKeys();
    for (std::size_t i = 0; i < j["sections"].size(); ++i) {
      const auto& k = j["sections"][i];
      if (!k.is_string())
        return makeError(ErrorCode::ParseError, "sections[" + std::to_string(i) + "] is not text", where);
      const auto key = k.get<std::string>();
      if (std::find(keys.begin(), keys.end(), key) == keys.end())
        return makeError(ErrorCode::InvalidArgument,
                         "unknown report section '" + key + "' in sections[" + std::to_string(i) + "]", where);
      t.sections.push_back(key);
    }
  }
  if (j.contains("specimen")) {
    if (!j["specimen"].is_string()) return makeError(ErrorCode::ParseError, "\"specimen\" is not text", where);
    t.specimen = j["specimen"].get<std::string>();
  }
  if (j.contains("language")) {
    if (!j["language"].is_string()) return makeError(ErrorCode::ParseError, "\"language\" is not text", where);
    MOZZI_TRY_ASSIGN(t.language, parseLanguage(j["language"].get<std::string>()));
  }
  for (const char* flag : {"pdf", "html"}) {
    if (!j.contains(flag)) continue;
    if (!j[flag].is_boolean())
      return makeError(ErrorCode::ParseError, std::string("\"") + flag + "\" is not true or false", where);
    (std::string(flag) == "pdf" ? t.pdf : t.html) = j[flag].get<bool>();
  }
  return t;
}

Result<std::optional<ReportTemplate>> loadReportTemplate(const io::ProjectStore& store) {
  MOZZI_TRY_ASSIGN(auto value, io::metaValue(store, kReportTemplateKey));
  if (!value) return std::optional<ReportTemplate>();
  auto t = templateFromJson(*value);
  if (!t) {
    Error e = t.error();
    e.where = store.path() + ", " + e.where;
    return e;
  }
  return std::optional<ReportTemplate>(std::move(*t));
}

Result<void> saveReportTemplate(io::ProjectStore& store, const ReportTemplate& t) {
  return io::setMetaValue(store, kReportTemplateKey, templateToJson(t));
}

}  // namespace mozzi::core::report
