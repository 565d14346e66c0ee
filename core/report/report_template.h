#pragma once
// The report template a project keeps (issue 23): the sections chosen, the
// specimen filter and the language, saved in the project's `meta` table under
// the key "report_template" as JSON
// {"sections": ["title", ...], "specimen": "", "language": "en",
//  "pdf": true, "html": false}. `mozzi-cli report` uses it when no --sections
// is given; the workbench's Report dialog reads and saves it.

#include <optional>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/io/project_store.h"
#include "core/report/project_report.h"

namespace mozzi::core::report {

inline constexpr const char* kReportTemplateKey = "report_template";

struct ReportTemplate {
  std::vector<std::string> sections;  // empty: every section
  std::string specimen;               // empty: every specimen
  Language language = Language::English;
  bool pdf = true;    // what the workbench writes
  bool html = false;  // (the command line says it with --out and --html)

  bool operator==(const ReportTemplate& o) const {
    return sections == o.sections && specimen == o.specimen && language == o.language && pdf == o.pdf && html == o.html;
  }
};

std::string templateToJson(const ReportTemplate& t);
// ParseError naming the field for a malformed template, InvalidArgument for an
// unknown section key or language.
Result<ReportTemplate> templateFromJson(const std::string& json);

// The project's template; nullopt when it has none.
Result<std::optional<ReportTemplate>> loadReportTemplate(const io::ProjectStore& store);
Result<void> saveReportTemplate(io::ProjectStore& store, const ReportTemplate& t);

}  // namespace mozzi::core::report
