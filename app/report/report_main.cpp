// mozzi-report: the renderer behind `mozzi-cli report` (issue 23). mozzi-cli
// checks the command line, the project and the outputs, then runs this
// program, so mozzi-cli itself links no Qt, Qwt or VTK (its start-up stays
// that of a core program, docs/performance/commands.md). Arguments, already
// checked: PROJECT PDF HTMLDIR SECTIONS SPECIMEN [LANG], "-" for an absent one,
// SECTIONS comma-separated keys, LANG "en" or "it" (absent: the project's
// report template, else English). SECTIONS and SPECIMEN "-" with no LANG
// (the workbench before its Report dialog) take the project's template too. Output and exit codes as mozzi-cli report
// (docs/cli/report.md).
#include <QApplication>
#include <chrono>
#include <ctime>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "core/io/project_store.h"
#include "core/report/project_report.h"
#include "core/report/report_template.h"
#include "views/report/report_writer.h"
#include "views/scene/scene_view.h"

namespace {

int fail(const std::string& why) {
  std::cerr << "mozzi-cli report: " << why << "\n";
  return 1;
}

std::string utcNow() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &tm);
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6 && argc != 7) {
    std::cerr << "mozzi-report is run by 'mozzi-cli report' (docs/cli/report.md)\n";
    return 2;
  }
  const std::string project = argv[1], pdf = argv[2], html = argv[3], sections = argv[4], specimen = argv[5];
  mozzi::core::report::ReportOptions options;
  if (sections != "-") {
    std::stringstream s(sections);
    std::string key;
    while (std::getline(s, key, ','))
      if (!key.empty()) options.sections.push_back(key);
  }
  if (specimen != "-") options.specimen = specimen;
  options.generatedUtc = utcNow();

  auto store = mozzi::core::io::ProjectStore::open(project, mozzi::core::io::ProjectStore::OpenMode::ReadOnly);
  if (!store) return fail(store.error().describe());
  if (argc == 7) {
    auto language = mozzi::core::report::parseLanguage(argv[6]);
    if (!language) return fail(language.error().describe());
    options.language = *language;
  } else {
    auto saved = mozzi::core::report::loadReportTemplate(*store);
    if (!saved) return fail(saved.error().describe());
    if (*saved) {
      options.language = (*saved)->language;
      if (sections == "-") options.sections = (*saved)->sections;
      if (specimen == "-") options.specimen = (*saved)->specimen;
    }
  }
  auto report = mozzi::core::report::buildProjectReport(*store, options);
  if (!report) return fail(report.error().describe());

  // Widgets draw the figures: the offscreen platform unless the caller chose
  // one (a report never needs a screen).
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  // The 3-D scene's figures (meshes, mode shapes) need VTK's surface format
  // before the application exists.
  mozzi::views::SceneView::prepareSurfaceFormat();
  int qtArgc = 1;
  QApplication app(qtArgc, argv);
  const std::vector<std::string> inputs{project};
  if (html != "-") {
    const QString error = mozzi::views::writeHtmlReport(*report, *store, QString::fromStdString(html), inputs);
    if (!error.isEmpty()) return fail(error.toStdString());
    std::cout << "wrote HTML report " << html << "/index.html (" << report->sections.size() << " sections)\n";
  }
  if (pdf != "-") {
    int pages = 0;
    const QString error =
        mozzi::views::writePdfReport(*report, *store, QString::fromStdString(pdf), inputs, {}, &pages);
    if (!error.isEmpty()) return fail(error.toStdString());
    std::cout << "wrote PDF report " << pdf << " (" << pages << " pages, " << report->sections.size() << " sections)\n";
  }
  return 0;
}
