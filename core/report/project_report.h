#pragma once
// The report of a project (issue 23), built only from what the project stores:
// title block (project, specimens, campaigns with constraint and transducers,
// rig set-ups with transducers), FRF sets (with their overlay figures), modal
// results, stiffness tests, tyre tests and stored gap diagnoses. A section is
// included when the project holds its data. docs/cli/report.md.

#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/io/project_store.h"
#include "core/report/report.h"

namespace mozzi::core::report {

// Section keys in report order: title, frf, modal, stiffness, tyre, gap, stability, wheelchair.
const std::vector<std::string>& reportSectionKeys();
// The heading of a section key ("Project and specimens", ...); empty for an unknown key.
std::string sectionHeading(const std::string& key);

struct ReportOptions {
  std::vector<std::string> sections;  // keys to include (empty: all)
  std::string specimen;               // only this specimen's data (empty: every specimen)
  std::string generatedUtc;           // date printed in the title block (empty: none)
};

// InvalidArgument for an unknown section key, NotFound for an unknown specimen.
Result<Report> buildProjectReport(const io::ProjectStore& store, const ReportOptions& options);

}  // namespace mozzi::core::report
