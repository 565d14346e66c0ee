// mozzi-cli report: the project's report as PDF and/or an HTML folder
// (issue 23, docs/cli/report.md). The content is core/report's; the figures
// and the PDF are drawn by views/report on Qt's offscreen platform, so no
// display is needed.
#include <unistd.h>

#include <QApplication>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <memory>
#include <ostream>
#include <sstream>
#include <string>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "app/cli/output.h"
#include "core/io/project_store.h"
#include "core/report/project_report.h"
#include "views/report/report_writer.h"

namespace mozzi::cli {
namespace {

constexpr const char* kSynopsis = "PROJECT.mozzi [--out REPORT.pdf] [--html DIR] [--sections LIST] [--specimen NAME]";

const OptionSpec kSpec{{"--out", "--html", "--sections", "--specimen"}, {}, {}, {"--out"}};

int usage(std::ostream& err, const std::string& why) {
  err << "mozzi-cli report: " << why << "\nUsage: mozzi-cli report " << kSynopsis << "\n";
  return kExitUsage;
}

int fail(std::ostream& err, const std::string& why) {
  err << "mozzi-cli report: " << why << "\n";
  return kExitFailure;
}

// The folder a file will be written in must exist and be writable: said
// before the report is built, not after.
std::string folderProblem(const std::string& file) {
  namespace fs = std::filesystem;
  fs::path folder = fs::path(file).parent_path();
  if (folder.empty()) folder = ".";
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return "cannot write " + file + ": folder " + folder.string() + " does not exist";
  if (::access(folder.c_str(), W_OK) != 0)
    return "cannot write " + file + ": folder " + folder.string() + " is not writable";
  return {};
}

std::string utcNow() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &tm);
  return buf;
}

int reportCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  auto parsed = ParsedArgs::parse(args, kSpec);
  if (!parsed) {
    if (exitCodeFor(parsed.error()) == kExitUsage) return usage(err, parsed.error().message);
    return fail(err, parsed.error().describe());
  }
  if (parsed->positional().size() != 1) return usage(err, "name one project file");
  const std::string project = parsed->positional()[0];
  const auto pdf = parsed->value("--out");
  const auto html = parsed->value("--html");
  if (!pdf && !html) return usage(err, "--out REPORT.pdf or --html DIR is required");
  if (!std::filesystem::exists(project)) return fail(err, "no project file " + project);

  core::report::ReportOptions options;
  if (auto list = parsed->value("--sections")) {
    std::stringstream s(*list);
    std::string key;
    while (std::getline(s, key, ','))
      if (!key.empty()) options.sections.push_back(key);
    if (options.sections.empty()) return usage(err, "--sections needs a comma-separated list");
  }
  if (auto specimen = parsed->value("--specimen")) options.specimen = *specimen;
  options.generatedUtc = utcNow();

  // The project is never an output: compared as files (device and inode), so
  // a link or another spelling of its path is refused too.
  if (int rc = refuseOutputsOntoInputs(*parsed, kSpec, {project}, "report", err,
                                       html ? std::vector<std::string>{*html} : std::vector<std::string>{});
      rc != kExitOk)
    return rc;
  if (pdf)
    if (auto problem = folderProblem(*pdf); !problem.empty()) return fail(err, problem);
  if (html && std::filesystem::exists(*html) && !std::filesystem::is_directory(*html))
    return fail(err, "--html " + *html + " exists and is not a folder");

  auto store = core::io::ProjectStore::open(project, core::io::ProjectStore::OpenMode::ReadOnly);
  if (!store) return fail(err, store.error().describe());
  auto report = core::report::buildProjectReport(*store, options);
  if (!report) return fail(err, report.error().describe());

  // Widgets draw the figures: a QApplication on the offscreen platform unless
  // the caller chose one (a report never needs a screen).
  std::unique_ptr<QApplication> app;
  if (!QCoreApplication::instance()) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char name[] = "mozzi-cli";
    static char* argv[] = {name, nullptr};
    app = std::make_unique<QApplication>(argc, argv);
  }
  const std::vector<std::string> inputs{project};
  if (html) {
    const QString error = views::writeHtmlReport(*report, *store, QString::fromStdString(*html), inputs);
    if (!error.isEmpty()) return fail(err, error.toStdString());
    out << "wrote HTML report " << *html << "/index.html (" << report->sections.size() << " sections)\n";
  }
  if (pdf) {
    int pages = 0;
    const QString error = views::writePdfReport(*report, *store, QString::fromStdString(*pdf), inputs, {}, &pages);
    if (!error.isEmpty()) return fail(err, error.toStdString());
    out << "wrote PDF report " << *pdf << " (" << pages << " pages, " << report->sections.size() << " sections)\n";
  }
  return kExitOk;
}

const CommandRegistrar kRegistrar({"report", kSynopsis,
                                   "The project's report (title block, FRFs, modes, stiffness, tyres, gap) as PDF "
                                   "and/or HTML",
                                   reportCommand, &kSpec});

}  // namespace
}  // namespace mozzi::cli
