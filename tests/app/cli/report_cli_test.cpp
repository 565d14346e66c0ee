// mozzi-cli report (issue 23): the demo project's report as PDF and HTML,
// built by the real executable on Qt's offscreen platform. The PDF is read
// back with poppler-utils (page count, every section heading, one page
// rendered to PNG); the HTML has the same headings; the modal and stiffness
// numbers are the project's, read here through the project API. Then the
// error cases: missing project, unknown section or specimen, the project as
// the output, an output folder that does not exist.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "cli_run.h"
#include "core/common/text.h"
#include "core/io/project_store.h"
#include "core/report/project_report.h"
#include "core/report/report_template.h"
#include "devices/sim/virtual_specimens.h"

namespace mozzi::cli {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kHeadings = {
    "Project and specimens", "Frequency response functions", "Modal parameters", "Stiffness tests", "Tyre tests",
    "Gap diagnoses",         "Stability against speed"};

// Modes stored into the demo (it holds none yet): values of our choosing.
const std::vector<std::pair<double, double>> kModes = {{23.4567, 0.0123}, {71.8125, 0.0251}, {203.375, 0.00875}};

struct Shell {
  int code;
  std::string out;
};

Shell shell(const std::string& command) {
  Shell r{-1, {}};
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
  const int status = ::pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// pdftotext keeps the font's ligatures (U+FB00..U+FB04: "Stiﬀness"); a reader
// searching the PDF sees the letters.
std::string withoutLigatures(std::string text) {
  const std::pair<const char*, const char*> ligatures[] = {
      {"\uFB00", "ff"}, {"\uFB01", "fi"}, {"\uFB02", "fl"}, {"\uFB03", "ffi"}, {"\uFB04", "ffl"}};
  for (const auto& [from, to] : ligatures) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at))
      text.replace(at, std::string(from).size(), to);
  }
  return text;
}

std::string quoted(const fs::path& p) {
  return "'" + p.string() + "'";
}

class ReportCliTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("mozzi-report-cli-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    project_ = dir_ / "demo.mozzi";
    auto made = devices::sim::createDemoProject(project_.string(), "test");
    ASSERT_TRUE(made.ok()) << made.error().describe();
    auto store = core::io::ProjectStore::open(project_.string());
    ASSERT_TRUE(store.ok());
    auto summary = store->summary();
    ASSERT_TRUE(summary.ok());
    std::int64_t frame = 0, fork = 0;
    for (const auto& s : summary->specimens) {
      if (s.name == "Frame A") frame = s.id;
      if (s.name == "Fork A (enduro) with wheel") fork = s.id;
    }
    ASSERT_NE(frame, 0);
    core::io::ModalResultInfo info;
    info.specimenId = frame;
    info.name = "report test modes";
    info.method = "LSCE";
    info.bandLowHz = 5;
    info.bandHighHz = 400;
    core::io::ModalTable table;
    for (const auto& [f, zeta] : kModes) table.modes.push_back({f, zeta, {}});
    ASSERT_TRUE(store->addModalResult(info, table).ok());
    core::io::StoredAnalysis analysis;
    analysis.specimenId = fork;
    analysis.name = "report test gap";
    analysis.resultJson = R"({"verdict":"effect","best":{"effect":"mass_loading"}})";
    core::io::StoredAnalysis::Finding finding;
    finding.bandLowHz = 60;
    finding.bandHighHz = 90;
    finding.effect = "mass_loading";
    finding.size = 0.125;
    finding.unit = "kg";
    analysis.findings.push_back(finding);
    ASSERT_TRUE(store->addAnalysis(analysis).ok());
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static fs::path dir_, project_;
};
fs::path ReportCliTest::dir_, ReportCliTest::project_;

TEST_F(ReportCliTest, DemoReportAsPdfAndHtml) {
  const fs::path pdf = dir_ / "report.pdf", html = dir_ / "html";
  // The real executable, no display: the offscreen platform.
  const auto made = shell("env -u DISPLAY QT_QPA_PLATFORM=offscreen " + std::string(MOZZI_CLI_PATH) + " report " +
                          quoted(project_) + " --out " + quoted(pdf) + " --html " + quoted(html));
  ASSERT_EQ(made.code, 0) << made.out;
  EXPECT_NE(made.out.find("wrote PDF report"), std::string::npos) << made.out;

  const auto info = shell(std::string(MOZZI_PDFINFO) + " " + quoted(pdf));
  ASSERT_EQ(info.code, 0) << info.out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(info.out, m, std::regex("Pages:\\s+(\\d+)"))) << info.out;
  // The demo's content: title block with two meshes, two FRF sets (overlay
  // and coherence each), three modal results, four stiffness tests, the tyre
  // tests and two gap diagnoses fill well over ten A4 pages; fewer means a
  // section or its figures went missing.
  EXPECT_GE(std::stoi(m[1]), 12) << info.out;

  auto text = shell(std::string(MOZZI_PDFTOTEXT) + " -layout " + quoted(pdf) + " -");
  ASSERT_EQ(text.code, 0);
  text.out = withoutLigatures(text.out);
  std::ifstream in(html / "index.html");
  ASSERT_TRUE(in.good());
  std::stringstream page;
  page << in.rdbuf();
  const std::string index = page.str();
  for (const auto& heading : kHeadings) {
    EXPECT_NE(text.out.find(heading), std::string::npos) << "PDF lacks " << heading;
    EXPECT_NE(index.find("<h2>" + heading + "</h2>"), std::string::npos) << "HTML lacks " << heading;
  }
  // Same sections in both: every <h2> of the HTML is one of the headings.
  std::regex h2("<h2>([^<]*)</h2>");
  int sections = 0;
  for (auto it = std::sregex_iterator(index.begin(), index.end(), h2); it != std::sregex_iterator(); ++it, ++sections)
    EXPECT_NE(std::find(kHeadings.begin(), kHeadings.end(), (*it)[1].str()), kHeadings.end()) << (*it)[1].str();
  EXPECT_EQ(sections, static_cast<int>(kHeadings.size()));
  // The demo's kept stability sweeps (devices/sim/demo_stability.cpp): the
  // benchmark bicycle's weave speed as the CLI prints it (Meijaard et al.
  // 2007: 4.29238253634110 m/s) and the Stability page's plots as figures.
  EXPECT_NE(text.out.find("4.292383"), std::string::npos);
  EXPECT_NE(index.find("src=\"stability-"), std::string::npos);
  // The FRF overlays, vector and raster; the other figures of the views.
  EXPECT_TRUE(fs::file_size(html / "frf-set-1.svg") > 1000);
  EXPECT_TRUE(fs::file_size(html / "frf-set-1.png") > 1000);
  EXPECT_NE(index.find("src=\"frf-set-1.svg\""), std::string::npos);
  for (const char* figure :
       {"frf-coherence-1.svg", "stabilization-1.svg", "stabilization-2.svg", "twist-axes-1.svg", "tyre-steady-2.svg"}) {
    EXPECT_TRUE(fs::exists(html / figure) && fs::file_size(html / figure) > 1000) << figure;
    EXPECT_NE(index.find(std::string("src=\"") + figure + "\""), std::string::npos) << figure;
  }
  // The demo's stored gap diagnosis (demo step 6) with its overlay.
  EXPECT_NE(index.find("Fork A design model against campaign"), std::string::npos);
  EXPECT_NE(index.find("src=\"gap-overlay-"), std::string::npos);

  // One page to PNG (poppler's renderer reads what we wrote).
  const auto png =
      shell(std::string(MOZZI_PDFTOPPM) + " -r 50 -f 1 -l 1 -png " + quoted(pdf) + " " + quoted(dir_ / "page"));
  ASSERT_EQ(png.code, 0) << png.out;
  EXPECT_TRUE(fs::exists(dir_ / "page-01.png") || fs::exists(dir_ / "page-1.png"));

  // Numbers: the stored ones, read here through the project API.
  auto store = core::io::ProjectStore::open(project_.string(), core::io::ProjectStore::OpenMode::ReadOnly);
  ASSERT_TRUE(store.ok());
  for (const auto& [f, zeta] : kModes) {
    EXPECT_NE(text.out.find(core::formatNumber(f, 6)), std::string::npos) << f;
    EXPECT_NE(text.out.find(core::formatNumber(100 * zeta, 4)), std::string::npos) << zeta;
  }
  auto tests = store->rigTests();
  ASSERT_TRUE(tests.ok());
  int checked = 0;
  for (const auto& t : *tests) {
    auto test = store->rigTest(t.id);
    ASSERT_TRUE(test.ok());
    for (const auto& r : test->results) {
      if (r.step ||
          (r.quantity != "k_lat" && r.quantity != "k_tw" && r.quantity != "a_tw" && r.quantity != "axis_inclination"))
        continue;
      const std::string shown = core::formatNumber(r.value, 6) + " \u00b1 " + core::formatNumber(r.uncertainty, 2);
      EXPECT_NE(text.out.find(shown), std::string::npos) << r.quantity << " " << shown;
      EXPECT_NE(index.find(shown), std::string::npos) << r.quantity << " " << shown;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 8);  // two static tests, four quantities each

  // The content model's cells hold the stored values exactly, per step too.
  auto report = core::report::buildProjectReport(*store, {});
  ASSERT_TRUE(report.ok());
  // One table per stored modal result (the demo's identified campaigns and
  // the one added here), each holding its result's values exactly.
  const auto* modal = report->section("modal");
  ASSERT_NE(modal, nullptr);
  std::vector<const core::report::Table*> tables;
  for (const auto& b : modal->blocks)
    if (auto* t = std::get_if<core::report::Table>(&b)) tables.push_back(t);
  auto stored = store->modalResults();
  ASSERT_TRUE(stored.ok());
  ASSERT_EQ(tables.size(), stored->size());
  bool added = false;
  for (std::size_t r = 0; r < stored->size(); ++r) {
    const auto& info = (*stored)[r];
    EXPECT_EQ(tables[r]->caption, "Modes of " + info.name);
    auto storedModes = store->modalResult(info.id);
    ASSERT_TRUE(storedModes.ok());
    ASSERT_EQ(tables[r]->rows.size(), storedModes->modes.size());
    for (std::size_t i = 0; i < storedModes->modes.size(); ++i) {
      EXPECT_EQ(*tables[r]->rows[i][1].value, storedModes->modes[i].frequencyHz);
      EXPECT_EQ(*tables[r]->rows[i][2].value, 100 * storedModes->modes[i].dampingRatio);
    }
    if (info.name == "report test modes") {
      added = true;
      ASSERT_EQ(storedModes->modes.size(), kModes.size());
      for (std::size_t i = 0; i < kModes.size(); ++i) EXPECT_EQ(storedModes->modes[i].frequencyHz, kModes[i].first);
    }
  }
  EXPECT_TRUE(added);
  int stepCells = 0;
  for (const auto& t : *tests) {
    auto test = store->rigTest(t.id);
    for (const auto& r : test->results) {
      if (!r.step || r.quantity != "k_tw") continue;
      bool found = false;
      for (const auto& b : report->section("stiffness")->blocks)
        if (auto* table = std::get_if<core::report::Table>(&b))
          for (const auto& row : table->rows)
            for (const auto& cell : row)
              if (cell.value && *cell.value == r.value && cell.uncertainty && *cell.uncertainty == r.uncertainty)
                found = true;
      EXPECT_TRUE(found) << "k_tw of step " << *r.step << " of " << test->name;
      ++stepCells;
    }
  }
  EXPECT_GT(stepCells, 0);
}

// --lang it: the Italian headings in the PDF and the HTML, numbers with a
// decimal comma (a stored modal frequency written by the catalogue's rule).
TEST_F(ReportCliTest, ItalianReport) {
  const fs::path pdf = dir_ / "it.pdf", html = dir_ / "it-html";
  const auto made = shell("env -u DISPLAY QT_QPA_PLATFORM=offscreen " + std::string(MOZZI_CLI_PATH) + " report " +
                          quoted(project_) + " --out " + quoted(pdf) + " --html " + quoted(html) +
                          " --lang it --sections title,modal,stiffness,tyre,gap");
  ASSERT_EQ(made.code, 0) << made.out;
  auto text = shell(std::string(MOZZI_PDFTOTEXT) + " " + quoted(pdf) + " -");
  ASSERT_EQ(text.code, 0);
  text.out = withoutLigatures(text.out);
  std::ifstream in(html / "index.html");
  std::stringstream page;
  page << in.rdbuf();
  for (const char* heading : {"Progetto e provini", "Parametri modali", "Prove di rigidezza", "Prove sugli pneumatici",
                              "Diagnosi dello scarto modello-prova"}) {
    EXPECT_NE(text.out.find(heading), std::string::npos) << "PDF lacks " << heading;
    EXPECT_NE(page.str().find(std::string("<h2>") + heading + "</h2>"), std::string::npos) << heading;
  }
  EXPECT_EQ(text.out.find("Modal parameters"), std::string::npos);
  EXPECT_NE(page.str().find("lang=\"it\""), std::string::npos);
  std::string frequency = core::formatNumber(kModes[0].first, 6);  // 23.4567 -> 23,4567
  std::replace(frequency.begin(), frequency.end(), '.', ',');
  EXPECT_NE(text.out.find(frequency), std::string::npos) << frequency;
}

// The project's template chooses sections, specimen and language when the
// command line does not; the command line still wins where it speaks.
TEST_F(ReportCliTest, TemplateFromTheProject) {
  const fs::path copy = dir_ / "templated.mozzi";
  fs::copy_file(project_, copy, fs::copy_options::overwrite_existing);
  {
    auto store = core::io::ProjectStore::open(copy.string());
    ASSERT_TRUE(store.ok());
    core::report::ReportTemplate t;
    t.sections = {"title", "tyre"};
    t.specimen = "Tyre 120/70 R17 radial (front)";
    t.language = core::report::Language::Italian;
    ASSERT_TRUE(core::report::saveReportTemplate(*store, t).ok());
  }
  const fs::path html = dir_ / "templated-html";
  auto made = shell("env -u DISPLAY QT_QPA_PLATFORM=offscreen " + std::string(MOZZI_CLI_PATH) + " report " +
                    quoted(copy) + " --html " + quoted(html));
  ASSERT_EQ(made.code, 0) << made.out;
  std::ifstream in(html / "index.html");
  std::stringstream page;
  page << in.rdbuf();
  EXPECT_NE(page.str().find("<h2>Prove sugli pneumatici</h2>"), std::string::npos);
  EXPECT_EQ(page.str().find("<h2>Prove di rigidezza</h2>"), std::string::npos);
  EXPECT_EQ(page.str().find("Frame A"), std::string::npos);  // another specimen
  // --sections and --lang override the template.
  const fs::path html2 = dir_ / "templated-html-2";
  made = shell("env -u DISPLAY QT_QPA_PLATFORM=offscreen " + std::string(MOZZI_CLI_PATH) + " report " + quoted(copy) +
               " --html " + quoted(html2) + " --sections stiffness --lang en --specimen 'Frame A'");
  ASSERT_EQ(made.code, 0) << made.out;
  std::ifstream in2(html2 / "index.html");
  std::stringstream page2;
  page2 << in2.rdbuf();
  EXPECT_NE(page2.str().find("<h2>Stiffness tests</h2>"), std::string::npos);
  EXPECT_EQ(page2.str().find("<h2>Tyre tests</h2>"), std::string::npos);

  auto r = run({"report", copy.string(), "--out", (dir_ / "x.pdf").string(), "--lang", "de"});
  EXPECT_EQ(r.code, kExitUsage);
  EXPECT_NE(r.err.find("unknown report language 'de'"), std::string::npos) << r.err;
}

TEST_F(ReportCliTest, SectionsAndSpecimenChooseTheContent) {
  const fs::path pdf = dir_ / "tyre.pdf";
  const auto made =
      shell("env -u DISPLAY QT_QPA_PLATFORM=offscreen " + std::string(MOZZI_CLI_PATH) + " report " + quoted(project_) +
            " --out " + quoted(pdf) + " --sections title,tyre --specimen " + quoted("Tyre 120/70 R17 radial (front)"));
  ASSERT_EQ(made.code, 0) << made.out;
  auto text = shell(std::string(MOZZI_PDFTOTEXT) + " " + quoted(pdf) + " -");
  text.out = withoutLigatures(text.out);
  EXPECT_NE(text.out.find("Tyre tests"), std::string::npos);
  EXPECT_NE(text.out.find("relaxation_length_m"), std::string::npos);
  EXPECT_EQ(text.out.find("Stiffness tests"), std::string::npos);
  EXPECT_EQ(text.out.find("Frame A"), std::string::npos);  // another specimen
}

TEST_F(ReportCliTest, ErrorsAreClear) {
  const std::string out = (dir_ / "e.pdf").string();
  auto r = run({"report", (dir_ / "missing.mozzi").string(), "--out", out});
  EXPECT_EQ(r.code, kExitFailure);
  EXPECT_NE(r.err.find("no project file"), std::string::npos) << r.err;

  r = run({"report", project_.string(), "--out", out, "--sections", "title,stifness"});
  EXPECT_EQ(r.code, kExitFailure);
  EXPECT_NE(r.err.find("unknown report section 'stifness'"), std::string::npos) << r.err;

  r = run({"report", project_.string(), "--out", out, "--specimen", "Frame Z"});
  EXPECT_EQ(r.code, kExitFailure);
  EXPECT_NE(r.err.find("no specimen named 'Frame Z'"), std::string::npos) << r.err;

  r = run({"report", project_.string()});
  EXPECT_EQ(r.code, kExitUsage);

  r = run({"report", project_.string(), "--out", (dir_ / "no-such-folder" / "r.pdf").string()});
  EXPECT_EQ(r.code, kExitFailure);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;

  // The project itself, spelt differently and through a symbolic link: refused,
  // and the project is untouched.
  const auto size = fs::file_size(project_);
  const auto time = fs::last_write_time(project_);
  fs::create_directories(dir_ / "sub");
  r = run({"report", project_.string(), "--out", (dir_ / "sub" / ".." / "demo.mozzi").string()});
  EXPECT_EQ(r.code, kExitFailure);
  EXPECT_NE(r.err.find("demo.mozzi"), std::string::npos) << r.err;
  fs::create_symlink(project_, dir_ / "link.pdf");
  r = run({"report", project_.string(), "--out", (dir_ / "link.pdf").string()});
  EXPECT_EQ(r.code, kExitFailure) << r.out;
  EXPECT_EQ(fs::file_size(project_), size);
  EXPECT_EQ(fs::last_write_time(project_), time);
  auto store = core::io::ProjectStore::open(project_.string(), core::io::ProjectStore::OpenMode::ReadOnly);
  EXPECT_TRUE(store.ok());

  // --html naming an existing file.
  r = run({"report", project_.string(), "--html", project_.string()});
  EXPECT_EQ(r.code, kExitFailure);
}

}  // namespace
}  // namespace mozzi::cli
