// mozzi-cli identify: modal identification of the FRFs in a UFF file or of
// an FRF set of a project (docs/cli/identify.md). pLSCF or LSCE + LSFD +
// refinement by variable projection (standard errors) through
// core::modal::identifyModes, or single-mode peak picking / circle fit over
// the band. With --store the modes become a modal result of the project, the
// same table the workbench's identification page saves (core::modal::modalTableOf).
// A set measured by a campaign with an exponential window has the window's
// decay removed from the identified damping (devices/campaign/frf_set_window.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "app/cli/output.h"
#include "core/io/project_store.h"
#include "core/io/uff/uff.h"
#include "core/modal/identification.h"
#include "core/modal/pole_selection.h"
#include "core/modal/sdof.h"
#include "core/modal/shape_tools.h"
#include "core/signal/window.h"
#include "devices/campaign/frf_set_window.h"

namespace mozzi::cli {
namespace {

namespace md = core::modal;
namespace uff = core::io::uff;

constexpr const char* kUsage =
    "Usage: mozzi-cli identify FRF.uff --band LO:HI [--method plscf|lsce|circle|peak] [--max-order N]\n"
    "                          [--refine-all-lines] [--stabilization OUT.csv] [--modes OUT.uff] [--json]\n"
    "       mozzi-cli identify PROJECT.mozzi --frf-set ID --band LO:HI [--store] [same options]\n";

int usage(std::ostream& err, const std::string& why) {
  err << "mozzi-cli identify: " << why << "\n" << kUsage;
  return kExitUsage;
}

int fail(std::ostream& err, const core::Error& e) {
  err << "mozzi-cli identify: " << e.describe() << "\n";
  return kExitFailure;
}

// FRF set `text` of a project; *info receives its record (specimen, name),
// *tauS the time constant of the exponential window it was measured with (0: none).
core::Result<core::FrfMatrix> projectFrf(const core::io::ProjectStore& store, const std::string& text,
                                         core::io::FrfSetInfo* info, double* tauS) {
  char* end = nullptr;
  const long long id = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || id <= 0)
    return core::makeError(core::ErrorCode::InvalidArgument,
                           "--frf-set takes a positive FRF set id (got '" + text + "')", "--frf-set");
  auto sets = store.frfSets();
  if (!sets) return sets.error();
  bool found = false;
  for (const auto& s : *sets) {
    if (s.id == id) {
      *info = s;
      found = true;
    }
  }
  if (!found)
    return core::makeError(core::ErrorCode::NotFound,
                           "the project has no FRF set " + text + " (mozzi-cli project info lists them)", "--frf-set");
  auto tau = devices::campaign::frfSetExponentialTauS(store, id);
  if (!tau) return tau.error();
  *tauS = *tau;
  return store.frfSet(id);
}

// 9000 -> "9,000".
std::string groupedThousands(Eigen::Index n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

struct Row {
  double f = 0, zeta = 0;
  std::optional<double> fStd, zStd;
  double mpc = 0;
};

// The option table: a band within what a UFF file can sample (1 MHz); the
// model order bounds the pLSCF/LSCE solve size.
const OptionSpec kSpec{
    {"--method", "--stabilization", "--modes", "--frf-set"},
    {"--json", "--store", "--refine-all-lines"},
    {{"--band", "band in Hz, LO < HI", {{"LO", closed(0, 1e6, "Hz")}, {"HI", aboveTo(0, 1e6, "Hz")}}, ':'},
     {"--max-order", wholeNumber(8, 400), "largest model order"}},
    {"--stabilization", "--modes"}};

int identifyCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  auto parsed = ParsedArgs::parse(args, kSpec);
  if (!parsed) {
    if (exitCodeFor(parsed.error()) == kExitUsage) return usage(err, parsed.error().message);
    return fail(err, parsed.error());
  }
  if (parsed->positional().size() != 1)
    return usage(err, parsed->value("--frf-set") ? "expected one project file" : "expected one FRF file");
  if (!parsed->value("--band")) return usage(err, "--band LO:HI is required");
  const auto band = parsed->numbers("--band");
  const double lo = band.at(0), hi = band.at(1);
  if (!(hi > lo)) {
    err << "mozzi-cli identify: option --band needs LO < HI (got '" << *parsed->value("--band") << "')\n";
    return kExitFailure;
  }
  const std::string& input = parsed->positional()[0];
  const bool isProject = input.size() > 6 && input.compare(input.size() - 6, 6, ".mozzi") == 0;
  if (isProject && !parsed->value("--frf-set"))
    return usage(err, "a project needs --frf-set ID (mozzi-cli project info lists the FRF sets)");
  if (parsed->flag("--store") && !parsed->value("--frf-set"))
    return usage(err, "--store keeps the modes in a project: give PROJECT.mozzi --frf-set ID");
  const std::string method = parsed->value("--method").value_or("plscf");
  if (method != "plscf" && method != "lsce" && method != "circle" && method != "peak") {
    return usage(err, "unknown --method '" + method + "' (available: plscf, lsce, circle, peak)");
  }
  int maxOrder = 60;
  bool orderGiven = false;
  if (auto mo = parsed->number("--max-order"); mo && mo->has_value()) {
    maxOrder = static_cast<int>(**mo);
    orderGiven = true;
  }
  if (parsed->value("--stabilization") && method != "plscf" && method != "lsce") {
    return usage(err, "--stabilization needs --method plscf or lsce");
  }
  if (int rc = refuseOutputsOntoInputs(*parsed, kSpec, {parsed->positional()[0]}, "identify", err); rc != kExitOk) {
    return rc;
  }

  std::optional<core::io::ProjectStore> store;
  core::io::FrfSetInfo setInfo;
  double tauS = 0.0;  // exponential window of the measurement, removed from the damping
  core::Result<core::FrfMatrix> frf = core::makeError(core::ErrorCode::NotFound, "no FRFs");
  if (auto set = parsed->value("--frf-set")) {
    // Read-only unless the modes are to be stored.
    auto opened =
        core::io::ProjectStore::open(input, parsed->flag("--store") ? core::io::ProjectStore::OpenMode::ReadWrite
                                                                    : core::io::ProjectStore::OpenMode::ReadOnly);
    if (!opened) return fail(err, opened.error());
    store.emplace(std::move(opened).value());
    frf = projectFrf(*store, *set, &setInfo, &tauS);
  } else {
    frf = uff::readFrfMatrix(input);  // streamed: memory is the FRF matrix
  }
  if (!frf) {
    core::Error e = frf.error();
    e.where = input + (e.where.empty() ? "" : ", " + e.where);  // name the file
    return fail(err, e);
  }

  md::ModalModel model;
  std::vector<Row> rows;
  Eigen::Index fittedLines = 0, bandLines = 0;  // of the refinement (pLSCF, LSCE)
  std::vector<double> frequencyStdHz, zetaStd;  // its standard errors, one per mode
  if (method == "plscf" || method == "lsce") {
    md::IdentificationOptions opt;  // the pLSCF options plus the LSCE window (defaults)
    opt.method = method == "lsce" ? md::IdentificationMethod::Lsce : md::IdentificationMethod::Plscf;
    opt.estimator.bandLowHz = lo;
    opt.estimator.bandHighHz = hi;
    // The default order is capped at what the band's lines support (a narrow
    // band of a short record); an order the user gave is kept, and refused
    // with the line count when too high.
    opt.estimator.maxOrder = orderGiven || opt.method != md::IdentificationMethod::Plscf
                                 ? maxOrder
                                 : std::min(maxOrder, std::max(8, md::plscfOrderLimit(*frf, lo, hi)));
    // The refinement on the lines carrying the modes where the band holds
    // many (the core's default, the workbench's too), or on every line.
    if (parsed->flag("--refine-all-lines")) opt.refineMaxLines = 0;
    auto res = md::identifyModes(*frf, opt);
    if (auto csv = parsed->value("--stabilization")) {
      // the diagram is written even when no mode qualifies
      auto diag = res                                            ? core::Result<md::StabilizationDiagram>(res->diagram)
                  : opt.method == md::IdentificationMethod::Lsce ? md::lsceStabilization(*frf, opt.estimator)
                                                                 : md::plscfStabilization(*frf, opt.estimator);
      if (!diag) return fail(err, diag.error());
      if (auto w = md::writeStabilizationCsv(*diag, *csv); !w) return fail(err, w.error());
    }
    if (!res) return fail(err, res.error());
    model = res->model();
    fittedLines = res->refined->fittedLines;
    bandLines = res->refined->bandLines;
    frequencyStdHz = res->refined->frequencyStdHz;
    zetaStd = res->refined->zetaStd;
    for (std::size_t r = 0; r < model.modes.size(); ++r) {
      rows.push_back({model.modes[r].frequencyHz(), model.modes[r].zeta(), res->refined->frequencyStdHz[r],
                      res->refined->zetaStd[r], 0.0});
    }
  } else {
    if (parsed->value("--stabilization")) return usage(err, "--stabilization needs --method plscf or lsce");
    auto est = method == "peak" ? md::peakPicking(*frf, 0, lo, hi) : md::circleFit(*frf, 0, lo, hi);
    if (!est) return fail(err, est.error());
    model.responses = frf->responses;
    model.references = {frf->references[0]};
    md::Mode mode;
    mode.pole = md::poleFromFrequencyDamping(est->frequencyHz, est->zeta);
    mode.residue = est->residue;
    model.modes.push_back(mode);
    rows.push_back({est->frequencyHz, est->zeta, std::nullopt, std::nullopt, 0.0});
  }
  if (tauS > 0.0) {
    for (auto& r : rows) {
      auto corrected = core::signal::correctExponentialWindowDamping({r.f, r.zeta}, tauS);
      if (!corrected) return fail(err, corrected.error());
      r.f = corrected->naturalFrequencyHz;
      r.zeta = corrected->zeta;
    }
  }
  auto measured = md::measuredShapes(model);  // along the hammer points of a roving-hammer set
  if (!measured) return fail(err, measured.error());
  const md::ShapeSet* shapes = &measured->set;
  for (std::size_t r = 0; r < rows.size(); ++r) rows[r].mpc = md::mpc(shapes->shapes.col(static_cast<Eigen::Index>(r)));

  if (auto modesPath = parsed->value("--modes")) {
    uff::ModalData data;
    data.dofs = measured->dofs;
    const auto nm = static_cast<Eigen::Index>(rows.size());
    data.frequencyHz.resize(nm);
    data.dampingRatio.resize(nm);
    data.modalMass = core::Vector::Zero(nm);
    data.shapes = shapes->shapes;
    data.complexShapes = true;
    for (std::size_t i = 0; i < data.dofs.size(); ++i) {
      if (data.dofs[i].negative) {  // 55 stores +X..+RZ: flip the sign with the direction
        data.dofs[i].negative = false;
        data.shapes.row(static_cast<Eigen::Index>(i)) *= -1.0;
      }
    }
    for (Eigen::Index r = 0; r < nm; ++r) {
      data.frequencyHz[r] = rows[static_cast<std::size_t>(r)].f;
      data.dampingRatio[r] = rows[static_cast<std::size_t>(r)].zeta;
      if (shapes->normalisation == md::Normalisation::UnitModalMass) data.modalMass[r] = 1.0;
    }
    auto records = uff::fromModalData(data);
    if (!records) return fail(err, records.error());
    uff::UffFile outFile;
    for (auto& rec : *records) outFile.datasets.push_back(uff::makeDataset(std::move(rec)));
    if (auto w = uff::writeFile(*modesPath, outFile); !w) return fail(err, w.error());
  }

  std::optional<std::int64_t> storedId;
  if (parsed->flag("--store")) {
    core::io::ModalResultInfo info;
    info.specimenId = setInfo.specimenId;
    info.frfSetId = setInfo.id;
    info.bandLowHz = lo;
    info.bandHighHz = hi;
    // the printed numbers' table, standard errors included
    auto id = md::storeModalResult(*store, model, info, method, tauS, frequencyStdHz, zetaStd);
    if (!id) return fail(err, id.error());
    storedId = *id;
  }

  if (parsed->flag("--json")) {
    nlohmann::json j;
    if (storedId) j["modal_result_id"] = *storedId;
    if (parsed->value("--frf-set")) j["frf_set_id"] = setInfo.id;
    j["method"] = method;
    j["band_hz"] = {lo, hi};
    j["normalisation"] =
        shapes->normalisation == md::Normalisation::UnitModalMass ? "unit modal mass" : "max component";
    if (bandLines > 0) j["refinement"] = {{"fitted_lines", fittedLines}, {"band_lines", bandLines}};
    j["modes"] = nlohmann::json::array();
    for (const auto& r : rows) {
      nlohmann::json m = {{"frequency_hz", r.f}, {"zeta", r.zeta}, {"eta", 2 * r.zeta}, {"mpc", r.mpc}};
      m["frequency_std"] = r.fStd ? nlohmann::json(*r.fStd) : nlohmann::json(nullptr);
      m["zeta_std"] = r.zStd ? nlohmann::json(*r.zStd) : nlohmann::json(nullptr);
      j["modes"].push_back(m);
    }
    out << j.dump(2) << "\n";
    return kExitOk;
  }
  out << "mode  frequency_hz   zeta       eta        frequency_std  zeta_std    mpc\n";
  char buf[256];
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const auto& row = rows[r];
    char fs[32] = "-", zs[32] = "-";
    if (row.fStd) std::snprintf(fs, sizeof fs, "%.3g", *row.fStd);
    if (row.zStd) std::snprintf(zs, sizeof zs, "%.3g", *row.zStd);
    std::snprintf(buf, sizeof buf, "%-5zu %-14.6f %-10.6f %-10.6f %-14s %-11s %.4f\n", r + 1, row.f, row.zeta,
                  2 * row.zeta, fs, zs, row.mpc);
    out << buf;
  }
  if (fittedLines < bandLines) {
    out << "refined on " << groupedThousands(fittedLines) << " of " << groupedThousands(bandLines)
        << " band lines: those carrying the modes (--refine-all-lines fits every line)\n";
  }
  if (storedId) out << "stored as modal result " << *storedId << "\n";
  return kExitOk;
}

const CommandRegistrar kRegistrar({"identify",
                                   "FRF.uff|PROJECT.mozzi [--frf-set ID [--store]] --band LO:HI "
                                   "[--method plscf|lsce|circle|peak] [--max-order N] [--refine-all-lines] "
                                   "[--stabilization OUT.csv] [--modes OUT.uff] [--json]",
                                   "Modal identification: frequencies, damping (zeta, eta), standard errors, MPC",
                                   identifyCommand, &kSpec});

}  // namespace
}  // namespace mozzi::cli
