// mozzi-cli report: the project's report as PDF and/or an HTML folder
// (issue 23, docs/cli/report.md). This command checks everything that can be
// checked without drawing (command line, project, sections, specimen,
// outputs), then runs the renderer mozzi-report (app/report), which draws the
// figures and the PDF with the views on Qt's offscreen platform: mozzi-cli
// links no Qt, so its start-up stays that of a core program.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <string>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "app/cli/output.h"
#include "core/io/project_store.h"
#include "core/report/project_report.h"
#include "core/report/report_template.h"

extern char** environ;

namespace mozzi::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSynopsis =
    "PROJECT.mozzi [--out REPORT.pdf] [--html DIR] [--sections LIST] [--specimen NAME] [--lang en|it]";

const OptionSpec kSpec{{"--out", "--html", "--sections", "--specimen", "--lang"}, {}, {}, {"--out"}};

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
  fs::path folder = fs::path(file).parent_path();
  if (folder.empty()) folder = ".";
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return "cannot write " + file + ": folder " + folder.string() + " does not exist";
  if (::access(folder.c_str(), W_OK) != 0)
    return "cannot write " + file + ": folder " + folder.string() + " is not writable";
  return {};
}

// mozzi-report beside this executable (build tree and installation alike),
// else where the build put it.
std::string rendererPath() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path beside = self.parent_path() / "mozzi-report";
    if (::access(beside.c_str(), X_OK) == 0) return beside.string();
  }
#ifdef MOZZI_REPORT_RENDERER
  if (::access(MOZZI_REPORT_RENDERER, X_OK) == 0) return MOZZI_REPORT_RENDERER;
#endif
  return {};
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
  if (!fs::exists(project)) return fail(err, "no project file " + project);

  core::report::ReportOptions options;
  std::string sections = "-";
  if (auto list = parsed->value("--sections")) {
    std::stringstream s(*list);
    std::string key;
    while (std::getline(s, key, ','))
      if (!key.empty()) options.sections.push_back(key);
    if (options.sections.empty()) return usage(err, "--sections needs a comma-separated list");
    sections = *list;
  }
  if (auto specimen = parsed->value("--specimen")) options.specimen = *specimen;
  if (auto lang = parsed->value("--lang")) {
    auto language = core::report::parseLanguage(*lang);
    if (!language) return usage(err, language.error().message);
    options.language = *language;
  }

  // The project is never an output: compared as files (device and inode), so
  // a link or another spelling of its path is refused too.
  const std::vector<std::string> htmlDir = html ? std::vector<std::string>{*html} : std::vector<std::string>{};
  if (int rc = refuseOutputsOntoInputs(*parsed, kSpec, {project}, "report", err, htmlDir); rc != kExitOk) return rc;
  if (pdf)
    if (auto problem = folderProblem(*pdf); !problem.empty()) return fail(err, problem);
  if (html && fs::exists(*html) && !fs::is_directory(*html))
    return fail(err, "--html " + *html + " exists and is not a folder");

  // The content is built here too (cheap, no drawing), so an unknown section
  // or specimen or an unreadable project is said before the renderer starts.
  auto store = core::io::ProjectStore::open(project, core::io::ProjectStore::OpenMode::ReadOnly);
  if (!store) return fail(err, store.error().describe());
  // The project's report template fills what the command line leaves out:
  // the sections (without --sections), the specimen (without --specimen) and
  // the language (without --lang).
  auto saved = core::report::loadReportTemplate(*store);
  if (!saved) return fail(err, saved.error().describe());
  if (*saved) {
    if (!parsed->value("--sections") && !(*saved)->sections.empty()) {
      options.sections = (*saved)->sections;
      sections.clear();
      for (const auto& key : options.sections) sections += (sections.empty() ? "" : ",") + key;
    }
    if (!parsed->value("--specimen")) options.specimen = (*saved)->specimen;
    if (!parsed->value("--lang")) options.language = (*saved)->language;
  }
  auto report = core::report::buildProjectReport(*store, options);
  if (!report) return fail(err, report.error().describe());

  const std::string renderer = rendererPath();
  if (renderer.empty())
    return fail(err, "the report renderer mozzi-report is not beside mozzi-cli (a build without the GUI layer?)");
  std::vector<std::string> childArgs{renderer,
                                     project,
                                     pdf ? *pdf : "-",
                                     html ? *html : "-",
                                     sections,
                                     options.specimen.empty() ? "-" : options.specimen,
                                     core::report::languageCode(options.language)};
  std::vector<char*> argv;
  for (auto& a : childArgs) argv.push_back(a.data());
  argv.push_back(nullptr);
  out.flush();
  err.flush();
  pid_t pid = 0;
  if (const int rc = ::posix_spawn(&pid, renderer.c_str(), nullptr, nullptr, argv.data(), environ); rc != 0)
    return fail(err, "cannot run " + renderer + ": " + std::strerror(rc));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return fail(err, "lost the report renderer: " + std::string(std::strerror(errno)));
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return fail(err, "the report renderer " + renderer + " stopped with signal " + std::to_string(WTERMSIG(status)));
}

const CommandRegistrar kRegistrar({"report", kSynopsis,
                                   "The project's report (title block, FRFs, modes, stiffness, tyres, gap) as PDF "
                                   "and/or HTML, in English or Italian, by the project's report template",
                                   reportCommand, &kSpec});

}  // namespace
}  // namespace mozzi::cli
