#pragma once
// The report of a project (issue 23), built only from what the project stores:
// title block (project, specimens, campaigns with constraint and transducers,
// rig set-ups with transducers, measurement meshes), FRF sets (overlay and
// coherence figures), modal results (stabilization diagram, one mode-shape
// still per mode), stiffness tests (twist-axis figures), tyre tests
// (steady-state and relaxation charts) and stored gap diagnoses (overlay). A
// section is included when the project holds its data; figures name the view
// that renders them (views/report). docs/cli/report.md.

#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/io/project_store.h"
#include "core/report/report.h"
#include "core/report/report_text.h"

namespace mozzi::core::report {

// Section keys in report order: title, frf, modal, stiffness, tyre, gap, stability, wheelchair.
const std::vector<std::string>& reportSectionKeys();
// The heading of a section key ("Project and specimens", ...) in `language`;
// empty for an unknown key.
std::string sectionHeading(const std::string& key, Language language = Language::English);

struct ReportOptions {
  std::vector<std::string> sections;      // keys to include (empty: all)
  std::string specimen;                   // only this specimen's data (empty: every specimen)
  std::string generatedUtc;               // date printed in the title block (empty: none)
  Language language = Language::English;  // headings, captions, sentences, numbers and dates
};

// InvalidArgument for an unknown section key, NotFound for an unknown specimen.
Result<Report> buildProjectReport(const io::ProjectStore& store, const ReportOptions& options);

}  // namespace mozzi::core::report
