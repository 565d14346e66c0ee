// mozzi-cli identify: modal identification of the FRFs in a UFF file or of an
// FRF set of a project (docs/cli/identify.md). pLSCF or LSCE + LSFD + Ceres
// refinement (standard errors), or single-mode peak picking / circle fit over
// the band. With --store the modes become a modal result of the project, the
// same table the workbench's identification page saves (core::modal::modalTableOf).
// A set measured by a campaign with an exponential window has the window's
// decay removed from the identified damping (devices/campaign/frf_set_window.h).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "core/io/project_store.h"
#include "core/io/uff/uff.h"
#include "core/modal/lsce.h"
#include "core/modal/plscf.h"
#include "core/modal/pole_selection.h"
#include "core/modal/refine.h"
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
    "                          [--stabilization OUT.csv] [--modes OUT.uff] [--json]\n"
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

struct Row {
  double f = 0, zeta = 0;
  std::optional<double> fStd, zStd;
  double mpc = 0;
};

int identifyCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  OptionSpec spec;
  spec.valued = {"--band", "--method", "--max-order", "--stabilization", "--modes", "--frf-set"};
  spec.flags = {"--json", "--store"};
  auto parsed = ParsedArgs::parse(args, spec);
  if (!parsed) return usage(err, parsed.error().message);
  if (parsed->positional().size() != 1)
    return usage(err, parsed->value("--frf-set") ? "expected one project file" : "expected one FRF file");
  const std::string& input = parsed->positional()[0];
  const bool isProject = input.size() > 6 && input.compare(input.size() - 6, 6, ".mozzi") == 0;
  if (isProject && !parsed->value("--frf-set"))
    return usage(err, "a project needs --frf-set ID (mozzi-cli project info lists the FRF sets)");
  if (parsed->flag("--store") && !parsed->value("--frf-set"))
    return usage(err, "--store keeps the modes in a project: give PROJECT.mozzi --frf-set ID");
  const auto bandText = parsed->value("--band");
  if (!bandText) return usage(err, "--band LO:HI is required");
  double lo = 0, hi = 0;
  {
    const auto colon = bandText->find(':');
    char* end = nullptr;
    bool ok = colon != std::string::npos;
    if (ok) {
      const std::string a = bandText->substr(0, colon), b = bandText->substr(colon + 1);
      lo = std::strtod(a.c_str(), &end);
      ok = !a.empty() && *end == '\0';
      hi = std::strtod(b.c_str(), &end);
      ok = ok && !b.empty() && *end == '\0' && std::isfinite(lo) && std::isfinite(hi) && lo >= 0 && hi > lo;
    }
    if (!ok) return usage(err, "--band must be LO:HI in Hz with 0 <= LO < HI (got '" + *bandText + "')");
  }
  const std::string method = parsed->value("--method").value_or("plscf");
  if (method != "plscf" && method != "lsce" && method != "circle" && method != "peak") {
    return usage(err, "unknown --method '" + method + "' (available: plscf, lsce, circle, peak)");
  }
  int maxOrder = 60;
  auto mo = parsed->number("--max-order");
  if (!mo) return usage(err, mo.error().message);
  if (mo->has_value()) {
    if (!(**mo >= 8 && **mo <= 400 && std::floor(**mo) == **mo))
      return usage(err, "--max-order must be an integer in 8..400");
    maxOrder = static_cast<int>(**mo);
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
    auto file = uff::readFile(input);
    if (!file) return fail(err, file.error());
    frf = uff::toFrfMatrix(*file);
  }
  if (!frf) return fail(err, frf.error());

  md::ModalModel model;
  std::vector<Row> rows;
  if (method == "plscf" || method == "lsce") {
    md::LsceOptions opt;  // the pLSCF options plus the LSCE window (defaults)
    opt.bandLowHz = lo;
    opt.bandHighHz = hi;
    opt.maxOrder = maxOrder;
    const bool lsce = method == "lsce";
    auto res = lsce ? md::identifyLsce(*frf, opt) : md::identifyPlscf(*frf, opt);
    if (auto csv = parsed->value("--stabilization")) {
      auto diag = res    ? core::Result<md::StabilizationDiagram>(res->diagram)
                  : lsce ? md::lsceStabilization(*frf, opt)
                         : md::plscfStabilization(*frf, opt);
      if (!diag) return fail(err, diag.error());
      if (auto w = md::writeStabilizationCsv(*diag, *csv); !w) return fail(err, w.error());
    }
    if (!res) return fail(err, res.error());
    md::RefineOptions ro;
    ro.bandLowHz = lo;
    ro.bandHighHz = hi;
    auto refined = md::refineModalModel(*frf, res->model, ro);
    if (!refined) return fail(err, refined.error());
    model = refined->model;
    for (std::size_t r = 0; r < model.modes.size(); ++r) {
      rows.push_back(
          {model.modes[r].frequencyHz(), model.modes[r].zeta(), refined->frequencyStdHz[r], refined->zetaStd[r], 0.0});
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
  auto shapes = md::modeShapes(model, 0);
  if (!shapes) return fail(err, shapes.error());
  for (std::size_t r = 0; r < rows.size(); ++r) rows[r].mpc = md::mpc(shapes->shapes.col(static_cast<Eigen::Index>(r)));

  if (auto modesPath = parsed->value("--modes")) {
    uff::ModalData data;
    data.dofs = model.responses;
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
    // The table the identification page saves: f, zeta and the shapes of reference 0.
    auto table = md::modalTableOf(model);
    if (!table) return fail(err, table.error());
    // The printed numbers: the window's decay removed as from the rows above.
    if (auto c = md::removeExponentialWindow(*table, tauS); !c) return fail(err, c.error());
    core::io::ModalResultInfo info;
    info.specimenId = setInfo.specimenId;
    info.frfSetId = setInfo.id;
    info.method = md::storedMethodName(method);
    auto existing = store->modalResults();
    if (!existing) return fail(err, existing.error());
    info.name = md::uniqueModalResultName(*existing, info.specimenId, md::defaultModalResultName(method, lo, hi));
    info.bandLowHz = lo;
    info.bandHighHz = hi;
    auto id = store->addModalResult(info, *table);
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
  if (storedId) out << "stored as modal result " << *storedId << "\n";
  return kExitOk;
}

const CommandRegistrar kRegistrar({"identify",
                                   "FRF.uff|PROJECT.mozzi [--frf-set ID [--store]] --band LO:HI "
                                   "[--method plscf|lsce|circle|peak] [--max-order N] "
                                   "[--stabilization OUT.csv] [--modes OUT.uff] [--json]",
                                   "Modal identification: frequencies, damping (zeta, eta), standard errors, MPC",
                                   identifyCommand});

}  // namespace
}  // namespace mozzi::cli
