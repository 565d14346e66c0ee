#include "core/report/project_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "core/common/frf_type.h"
#include "core/common/text.h"
#include "core/report/gap_report.h"
#include "core/report/stability_report.h"

namespace mozzi::core::report {
namespace {

// The stiffness quantities a dynamic test reports per step (thesis §3: lateral
// and torsional stiffness, twist-axis height and inclination), in table order.
const char* const kStepQuantities[] = {"frequency", "k_lat", "k_tw", "a_tw", "axis_inclination"};

std::string jsonText(const nlohmann::json& j, const char* key) {
  if (j.is_object() && j.contains(key) && j[key].is_string()) return j[key].get<std::string>();
  return {};
}

struct Context {
  const io::ProjectStore& store;
  const ReportOptions& options;
  Texts t;
  std::map<std::int64_t, std::string> specimenNames;  // the specimens reported
  bool wanted(std::int64_t specimenId) const { return specimenNames.count(specimenId) > 0; }
  std::string specimen(std::int64_t id) const {
    auto it = specimenNames.find(id);
    return it == specimenNames.end() ? t("specimen %1", {std::to_string(id)}) : it->second;
  }
};

Table transducerTable(const Texts& t, const std::vector<io::StoredTransducer>& transducers) {
  Table table;
  table.caption = t("Transducers");
  table.headers = {t("Channel"), t("Quantity"), t("Unit"), t("Model"), t("Serial"), t("Sensitivity")};
  table.units = {"", "", "", "", "", t("V per unit")};
  for (const auto& x : transducers)
    table.rows.push_back({textCell(std::to_string(x.channel)), textCell(x.quantity), textCell(x.unit),
                          textCell(x.model), textCell(x.serial.empty() ? "-" : x.serial),
                          t.numberCell(x.sensitivity, 6)});
  return table;
}

// The specimens of the report whose measurement mesh is worth a drawing: those
// with a stored mesh and measured data (campaigns, FRF sets or modes).
Result<std::vector<std::int64_t>> meshSpecimens(const Context& c) {
  std::set<std::int64_t> measured;
  MOZZI_TRY_ASSIGN(const auto sets, c.store.frfSets());
  for (const auto& set : sets) measured.insert(set.specimenId);
  MOZZI_TRY_ASSIGN(const auto modal, c.store.modalResults());
  for (const auto& m : modal) measured.insert(m.specimenId);
  std::vector<std::int64_t> ids;
  for (const auto& [id, name] : c.specimenNames) {
    if (!measured.count(id)) continue;
    auto mesh = c.store.mesh(id);
    if (mesh && !mesh->nodes.empty()) ids.push_back(id);
  }
  return ids;
}

Result<bool> titleSection(const Context& c, Section& s) {
  const Texts& t = c.t;
  MOZZI_TRY_ASSIGN(const auto summary, c.store.summary());
  std::string about = t("Project %1, created %2 by Mozzi %3, schema %4.",
                        {std::filesystem::path(c.store.path()).filename().string(), t.date(summary.createdUtc),
                         summary.mozziVersion, std::to_string(summary.schemaVersion)});
  if (!c.options.generatedUtc.empty()) about += " " + t("Report generated %1.", {t.date(c.options.generatedUtc)});
  s.blocks.push_back(Paragraph{about});
  Table specimens;
  specimens.caption = t("Specimens");
  specimens.headers = {t("Specimen"), t("Kind"), t("Description")};
  specimens.units = {"", "", ""};
  for (const auto& sp : summary.specimens)
    if (c.wanted(sp.id)) specimens.rows.push_back({textCell(sp.name), textCell(sp.kind), textCell(sp.description)});
  s.blocks.push_back(specimens);

  // Campaigns: constraint, operator and transducers from their definition.
  for (const auto& [id, name] : c.specimenNames) {
    MOZZI_TRY_ASSIGN(const auto campaigns, c.store.campaigns(id));
    for (const auto& campaign : campaigns) {
      s.blocks.push_back(Heading{t("Campaign %1 (%2)", {campaign.name, name})});
      const auto settings = nlohmann::json::parse(campaign.settingsJson, nullptr, false);
      std::string text = t("Kind %1, started %2.", {campaign.kind, t.date(campaign.startedUtc)});
      if (settings.is_object() && settings.contains("constraint"))
        if (auto d = jsonText(settings["constraint"], "description"); !d.empty())
          text += " " + t("Constraint: %1.", {d});
      if (auto op = jsonText(settings, "operator"); !op.empty()) text += " " + t("Operator: %1.", {op});
      if (auto e = jsonText(settings, "estimator"); !e.empty()) text += " " + t("FRF estimator %1.", {e});
      if (!campaign.notes.empty()) text += " " + t("Notes: %1", {campaign.notes});
      s.blocks.push_back(Paragraph{text});
      if (campaign.rigSetupId) {
        MOZZI_TRY_ASSIGN(const auto rig, c.store.rigSetup(*campaign.rigSetupId));
        if (!rig.transducers.empty()) s.blocks.push_back(transducerTable(t, rig.transducers));
      } else if (settings.is_object() && settings.contains("channels") && settings["channels"].is_array()) {
        Table table;
        table.caption = t("Transducers of %1", {campaign.name});
        table.headers = {t("Input"),  t("Name"),        t("Quantity"),  t("Model"),
                         t("Serial"), t("Sensitivity"), t("Calibrated")};
        table.units = {"", "", "", "", "", t("mV per unit"), ""};
        for (const auto& ch : settings["channels"]) {
          Cell input = ch.contains("input") && ch["input"].is_number()
                           ? textCell(std::to_string(ch["input"].get<int>()))
                           : textCell("-");
          Cell sens = ch.contains("sensitivity_mv_per_unit") && ch["sensitivity_mv_per_unit"].is_number()
                          ? t.numberCell(ch["sensitivity_mv_per_unit"].get<double>(), 6)
                          : textCell("-");
          std::string quantity = jsonText(ch, "kind");
          if (auto unit = jsonText(ch, "unit"); !unit.empty()) quantity += " [" + unit + "]";
          table.rows.push_back({input, textCell(jsonText(ch, "name")), textCell(quantity),
                                textCell(jsonText(ch, "model")), textCell(jsonText(ch, "serial")), sens,
                                textCell(jsonText(ch, "calibration_date"))});
        }
        s.blocks.push_back(table);
      }
    }
  }

  // Rig set-ups of the stiffness and tyre tests.
  std::set<std::int64_t> rigIds;
  MOZZI_TRY_ASSIGN(const auto rigTests, c.store.rigTests());
  for (const auto& info : rigTests) {
    if (!c.wanted(info.specimenId)) continue;
    MOZZI_TRY_ASSIGN(const auto test, c.store.rigTest(info.id));
    if (test.rigSetupId) rigIds.insert(*test.rigSetupId);
  }
  MOZZI_TRY_ASSIGN(const auto tyreTests, c.store.tyreTests());
  for (const auto& info : tyreTests) {
    if (!c.wanted(info.specimenId)) continue;
    MOZZI_TRY_ASSIGN(const auto test, c.store.tyreTest(info.id));
    if (test.rigSetupId) rigIds.insert(*test.rigSetupId);
  }
  for (const auto id : rigIds) {
    MOZZI_TRY_ASSIGN(const auto rig, c.store.rigSetup(id));
    s.blocks.push_back(Heading{t("Rig %1 (%2)", {rig.name, c.specimen(rig.specimenId)})});
    s.blocks.push_back(Paragraph{t("Rig kind %1, driver %2.", {rig.rigKind, rig.driver})});
    if (!rig.transducers.empty()) s.blocks.push_back(transducerTable(t, rig.transducers));
  }

  // The measurement meshes, drawn by the 3-D scene.
  MOZZI_TRY_ASSIGN(const auto meshes, meshSpecimens(c));
  if (!meshes.empty()) s.blocks.push_back(Heading{t("Measurement meshes")});
  for (const auto id : meshes)
    s.blocks.push_back(Figure{"mesh-" + std::to_string(id), "mesh", id,
                              t("Measurement mesh of %1: nodes, trace lines and faces", {c.specimen(id)})});
  return true;
}

Result<bool> frfSection(const Context& c, Section& s) {
  const Texts& tx = c.t;
  MOZZI_TRY_ASSIGN(const auto sets, c.store.frfSets());
  Table t;
  t.caption = tx("FRF sets");
  t.headers = {tx("Set"),  tx("Specimen"), tx("Source"),    tx("Estimator"),
               tx("Type"), tx("Lines"),    tx("Responses"), tx("References")};
  t.units = {"", "", "", "", "", "", "", ""};
  std::vector<Figure> figures;
  for (const auto& set : sets) {
    if (!c.wanted(set.specimenId)) continue;
    t.rows.push_back({textCell(set.name), textCell(c.specimen(set.specimenId)), textCell(set.source),
                      textCell(set.estimator.empty() ? "-" : set.estimator), textCell(frfTypeName(set.type)),
                      tx.numberCell(static_cast<double>(set.lineCount)), tx.numberCell(set.responseCount),
                      tx.numberCell(set.referenceCount)});
    figures.push_back(Figure{"frf-set-" + std::to_string(set.id), "frf-overlay", set.id,
                             tx("FRF overlay of %1 (%2, magnitude)", {set.name, frfTypeName(set.type)})});
    // The coherence of the estimate, when the set carries one (the FRF
    // view's coherence plot).
    MOZZI_TRY_ASSIGN(const auto frf, c.store.frfSet(set.id));
    if (!frf.coherence.empty())
      figures.push_back(Figure{"frf-coherence-" + std::to_string(set.id), "frf-coherence", set.id,
                               tx("Coherence of %1", {set.name})});
  }
  if (t.rows.empty()) return false;
  s.blocks.push_back(t);
  for (auto& f : figures) s.blocks.push_back(std::move(f));
  return true;
}

Result<bool> modalSection(const Context& c, Section& s) {
  const Texts& tx = c.t;
  MOZZI_TRY_ASSIGN(const auto results, c.store.modalResults());
  for (const auto& info : results) {
    if (!c.wanted(info.specimenId)) continue;
    MOZZI_TRY_ASSIGN(const auto table, c.store.modalResult(info.id));
    s.blocks.push_back(Heading{info.name + " (" + c.specimen(info.specimenId) + ")"});
    std::string about =
        tx("Method %1, band %2 to %3 Hz", {info.method, tx.number(info.bandLowHz), tx.number(info.bandHighHz)});
    if (info.frfSetId) about += tx(", from FRF set %1", {std::to_string(*info.frfSetId)});
    s.blocks.push_back(Paragraph{about + ". " +
                                 tx("Damping as the viscous ratio zeta and the loss factor eta = 2 zeta. The project "
                                    "stores frequency, damping and shape per mode; no standard errors or MPC.")});
    Table t;
    t.caption = tx("Modes of %1", {info.name});
    t.headers = {tx("Mode"), tx("Frequency"), tx("Damping ratio zeta"), tx("Loss factor eta")};
    t.units = {"", "Hz", "%", "%"};
    bool shapes = false;
    for (std::size_t m = 0; m < table.modes.size(); ++m) {
      const auto& mode = table.modes[m];
      t.rows.push_back({textCell(std::to_string(m + 1)), tx.numberCell(mode.frequencyHz, 6),
                        tx.numberCell(100.0 * mode.dampingRatio, 4), tx.numberCell(200.0 * mode.dampingRatio, 4)});
      shapes = shapes || mode.shape.size() > 0;
    }
    s.blocks.push_back(t);
    const std::string id = std::to_string(info.id);
    // The diagram the modes were picked from: identified again from the FRF
    // set over the stored band by the identification page's back end.
    if (info.frfSetId)
      s.blocks.push_back(Figure{"stabilization-" + id, "stabilization", info.id,
                                tx("Stabilization diagram of %1 (%2 to %3 Hz)",
                                   {info.name, tx.number(info.bandLowHz), tx.number(info.bandHighHz)})});
    // One still per mode from the Mode Animation view, at its largest deflection.
    if (shapes && c.store.mesh(info.specimenId).ok())
      for (std::size_t m = 0; m < table.modes.size(); ++m)
        s.blocks.push_back(Figure{"mode-" + id + "-" + std::to_string(m + 1), "mode-shape", info.id,
                                  tx("Mode %1 of %2: %3 Hz, zeta %4 %",
                                     {std::to_string(m + 1), info.name, tx.number(table.modes[m].frequencyHz, 5),
                                      tx.number(100 * table.modes[m].dampingRatio, 3)}),
                                  static_cast<int>(m)});
  }
  return !s.blocks.empty();
}

// Analyses the Lumped Fork page keeps (kind "lumped-fork": the three lumped
// models of thesis §4.2, Table 12; "bicycle-fork": §6.4, §6.5), with the keys
// of `mozzi-cli fork ... --json`. They belong with the stiffness results, not
// with the gap diagnoses; so does the Tyre Relaxation page's prediction.
bool isForkModelAnalysis(const io::StoredAnalysis& a) {
  return a.kind == "lumped-fork" || a.kind == "bicycle-fork";
}
bool isGapAnalysis(const io::StoredAnalysis& a) {
  return !isForkModelAnalysis(a) && a.kind != "relaxation-prediction";
}

Result<void> forkModelBlocks(const Context& c, Section& s) {
  const Texts& tx = c.t;
  MOZZI_TRY_ASSIGN(const auto analyses, c.store.analyses());
  auto number = [](const nlohmann::json& j, const char* key) {
    return j.is_object() && j.contains(key) && j[key].is_number() ? j[key].get<double>() : std::nan("");
  };
  for (const auto& a : analyses) {
    if (!c.wanted(a.specimenId) || !isForkModelAnalysis(a)) continue;
    const auto json = nlohmann::json::parse(a.resultJson, nullptr, false);
    s.blocks.push_back(Heading{a.name.empty() ? tx("Analysis %1", {std::to_string(a.id)}) : a.name});
    Table t;
    if (a.kind == "lumped-fork") {
      t.caption = tx("Lumped fork models (thesis §4.2, Table 12)");
      t.headers = {tx("Model"), "k", "L", "J", tx("Pure moment"), "f_n", "c", "zeta"};
      t.units = {"", "N m/rad", "m", "kg m^2", "kg m^2", "Hz", "N m s/rad", ""};
      const auto models = json.is_object() ? json.value("models", nlohmann::json::object()) : nlohmann::json();
      for (int i = 1; i <= 3; ++i) {
        const auto m =
            models.is_object() ? models.value("model" + std::to_string(i), nlohmann::json()) : nlohmann::json();
        t.rows.push_back({textCell(std::to_string(i)), tx.numberCell(number(m, "stiffness_Nm_per_rad")),
                          tx.numberCell(number(m, "arm_m")), tx.numberCell(number(m, "inertia_kgm2")),
                          tx.numberCell(number(m, "pure_moment_kgm2")), tx.numberCell(number(m, "frequency_Hz")),
                          tx.numberCell(number(m, "damping_Nms_per_rad")), tx.numberCell(number(m, "zeta"))});
      }
    } else {
      t.caption = tx("Bicycle fork stiffness and damping (thesis §6.4, §6.5)");
      t.headers = {tx("Quantity"), tx("Value"), tx("Unit")};
      t.units = {"", "", ""};
      const auto tors = json.is_object() ? json.value("torsion", nlohmann::json()) : nlohmann::json();
      const auto bend = json.is_object() ? json.value("bending", nlohmann::json()) : nlohmann::json();
      const struct {
        const char* name;
        double value;
        const char* unit;
      } rows[] = {{"torsion stiffness with wheel", number(tors, "stiffness_with_wheel_Nm_per_rad"), "N m/rad"},
                  {"torsion stiffness, fork alone", number(tors, "stiffness_alone_Nm_per_rad"), "N m/rad"},
                  {"torsion damping", number(tors, "damping_Nms_per_rad"), "N m s/rad"},
                  {"bending arm h_W", number(bend, "bend_arm_hW_m"), "m"},
                  {"bending stiffness", number(bend, "stiffness_Nm_per_rad"), "N m/rad"},
                  {"bending damping", number(bend, "damping_Nms_per_rad"), "N m s/rad"}};
      for (const auto& r : rows) t.rows.push_back({textCell(tx(r.name)), tx.numberCell(r.value), textCell(r.unit)});
    }
    s.blocks.push_back(t);
  }
  return {};
}

// The per-step table of a dynamic test: one row per step, the quantities of
// kStepQuantities that the test has as columns.
void stepTable(const Context& c, const io::StoredRigTest& test, Section& s) {
  const Texts& tx = c.t;
  std::map<int, std::map<std::string, const io::StoredRigTest::Result*>> steps;
  std::set<std::string> present;
  for (const auto& r : test.results) {
    if (!r.step) continue;
    steps[*r.step][r.quantity] = &r;
    present.insert(r.quantity);
  }
  std::vector<std::string> columns;
  for (const char* q : kStepQuantities)
    if (present.count(q)) columns.push_back(q);
  if (steps.empty() || columns.empty()) return;
  Table t;
  t.caption = tx("Per step of %1 (one standard deviation)", {test.name});
  t.headers = {tx("Step")};
  t.units = {""};
  for (const auto& q : columns) {
    t.headers.push_back(q == "frequency" ? tx("frequency") : q);
    std::string unit;
    for (const auto& [step, byName] : steps)
      if (auto it = byName.find(q); it != byName.end()) unit = it->second->unit;
    t.units.push_back(unit);
  }
  for (const auto& [step, byName] : steps) {
    std::vector<Cell> row{textCell(std::to_string(step))};
    for (const auto& q : columns) {
      auto it = byName.find(q);
      row.push_back(it == byName.end() ? textCell("-") : tx.numberCell(it->second->value, 6, it->second->uncertainty));
    }
    t.rows.push_back(std::move(row));
  }
  s.blocks.push_back(t);
}

Result<bool> stiffnessSection(const Context& c, Section& s) {
  const Texts& tx = c.t;
  MOZZI_TRY_ASSIGN(const auto tests, c.store.rigTests());
  for (const auto& info : tests) {
    if (!c.wanted(info.specimenId)) continue;
    MOZZI_TRY_ASSIGN(const auto test, c.store.rigTest(info.id));
    const bool isStatic = test.kind == io::StoredRigTest::Kind::Static;
    s.blocks.push_back(Heading{info.specimenName + " / " + test.name + " (" +
                               (isStatic ? tx("static") : tx("dynamic")) + ", " + tx(io::testStatusName(test.status)) +
                               ")"});
    if (!test.statusNote.empty()) s.blocks.push_back(Paragraph{test.statusNote});
    Table whole;
    whole.caption = tx("Results of %1 (one standard deviation)", {test.name});
    whole.headers = {tx("Quantity"), tx("Value"), tx("Unit")};
    whole.units = {"", "", ""};
    bool axis = false;
    for (const auto& r : test.results) {
      if (r.step) continue;
      whole.rows.push_back({textCell(r.quantity), tx.numberCell(r.value, 6, r.uncertainty), textCell(r.unit)});
      axis = axis || r.quantity == "a_tw";
    }
    if (!whole.rows.empty()) s.blocks.push_back(whole);
    stepTable(c, test, s);
    // The twist axis over the specimen's silhouette, as the Twist Axes page draws it.
    if (axis || !isStatic)
      s.blocks.push_back(Figure{"twist-axes-" + std::to_string(info.id), "twist-axes", info.id,
                                tx("Twist axis of %1 over %2 (plate plane)", {test.name, info.specimenName})});
  }
  MOZZI_TRY(forkModelBlocks(c, s));
  return !s.blocks.empty();
}

Result<bool> tyreSection(const Context& c, Section& s) {
  const Texts& tx = c.t;
  MOZZI_TRY_ASSIGN(const auto tests, c.store.tyreTests());
  std::set<std::int64_t> relaxationSpecimens;
  for (const auto& info : tests) {
    if (!c.wanted(info.specimenId)) continue;
    MOZZI_TRY_ASSIGN(const auto test, c.store.tyreTest(info.id));
    s.blocks.push_back(Heading{info.specimenName + " / " + test.name + " (" + test.kind + ", " +
                               tx(io::testStatusName(test.status)) + ")"});
    std::string about = tx("Inflation pressure %1 Pa, vertical load %2 N, speed %3 m/s, %4 measured points.",
                           {tx.number(test.inflationPressurePa), tx.number(test.verticalLoadN),
                            tx.number(test.speedMps), std::to_string(test.points.size())});
    s.blocks.push_back(Paragraph{about + (test.statusNote.empty() ? "" : " " + test.statusNote)});
    Table params, mf;
    params.caption = tx("Results of %1 (one standard deviation)", {test.name});
    mf.caption = tx("Magic Formula coefficients of %1", {test.name});
    params.headers = mf.headers = {tx("Parameter"), tx("Value"), tx("Unit")};
    params.units = mf.units = {"", "", ""};
    for (const auto& p : test.parameters) {
      if (p.step) continue;
      std::vector<Cell> row{textCell(p.name), tx.numberCell(p.value, 6, p.uncertainty),
                            textCell(p.unit.empty() ? "-" : p.unit)};
      (p.name.rfind("mf_", 0) == 0 ? mf : params).rows.push_back(std::move(row));
    }
    if (!params.rows.empty()) s.blocks.push_back(params);
    if (!mf.rows.empty()) s.blocks.push_back(mf);
    if (test.kind == "relaxation") relaxationSpecimens.insert(info.specimenId);
    if (!test.points.empty())
      s.blocks.push_back(Figure{"tyre-steady-" + std::to_string(info.id), "tyre-steady-state", info.id,
                                tx("Lateral force and aligning moment of %1 against slip angle", {test.name})});
  }
  // The Tyre Relaxation page's charts, one pair per tyre with relaxation tests.
  for (const auto id : relaxationSpecimens)
    s.blocks.push_back(Figure{"tyre-relaxation-" + std::to_string(id), "tyre-relaxation", id,
                              tx("Relaxation length of %1 against frequency and pressure, with the eq. 48 "
                                 "prediction",
                                 {c.specimen(id)})});
  return !s.blocks.empty();
}

Result<bool> gapSection(const Context& c, Section& s) {
  MOZZI_TRY_ASSIGN(const auto analyses, c.store.analyses());
  for (const auto& a : analyses) {
    if (!c.wanted(a.specimenId) || !isGapAnalysis(a) || hasOwnStabilitySection(a.kind)) continue;
    for (auto& block : storedAnalysisBlocks(a, c.t)) s.blocks.push_back(std::move(block));
  }
  return !s.blocks.empty();
}

// The sections in report order. A section is a key, its heading (an English
// source of the catalogue) and its builder (false: the project has nothing
// for it). Add a section by adding a row.
struct SectionEntry {
  const char* key;
  const char* heading;
  Result<bool> (*build)(const Context&, Section&);
};

const std::vector<SectionEntry>& sectionTable() {
  static const std::vector<SectionEntry> table = {
      {"title", "Project and specimens", titleSection},
      {"frf", "Frequency response functions", frfSection},
      {"modal", "Modal parameters", modalSection},
      {"stiffness", "Stiffness tests", stiffnessSection},
      {"tyre", "Tyre tests", tyreSection},
      {"gap", "Gap diagnoses", gapSection},
      // core/report/stability_report.cpp
      {"stability", "Stability against speed",
       [](const Context& c, Section& s) { return stabilitySection(c.store, c.specimenNames, s); }},
      {"wheelchair", "Wheelchair manoeuvres",
       [](const Context& c, Section& s) { return wheelchairSection(c.store, c.specimenNames, s); }},
  };
  return table;
}

}  // namespace

const std::vector<std::string>& reportSectionKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const auto& e : sectionTable()) k.push_back(e.key);
    return k;
  }();
  return keys;
}

std::string sectionHeading(const std::string& key, Language language) {
  for (const auto& e : sectionTable())
    if (key == e.key) return Texts(language)(e.heading);
  return {};
}

Result<Report> buildProjectReport(const io::ProjectStore& store, const ReportOptions& options) {
  const auto& keys = reportSectionKeys();
  for (const auto& key : options.sections) {
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
      std::string list;
      for (const auto& k : keys) list += (list.empty() ? "" : ", ") + k;
      return makeError(ErrorCode::InvalidArgument, "unknown report section '" + key + "' (known: " + list + ")",
                       "report of " + store.path());
    }
  }
  MOZZI_TRY_ASSIGN(const auto summary, store.summary());
  Context c{store, options, Texts(options.language), {}};
  for (const auto& sp : summary.specimens)
    if (options.specimen.empty() || sp.name == options.specimen) c.specimenNames[sp.id] = sp.name;
  if (!options.specimen.empty() && c.specimenNames.empty())
    return makeError(ErrorCode::NotFound, "no specimen named '" + options.specimen + "'", store.path());

  Report report;
  report.language = languageCode(options.language);
  report.title = c.t("Mozzi report: %1", {std::filesystem::path(store.path()).stem().string()});
  if (!options.specimen.empty()) report.title += ", " + options.specimen;
  for (const auto& entry : sectionTable()) {
    if (!options.sections.empty() &&
        std::find(options.sections.begin(), options.sections.end(), entry.key) == options.sections.end())
      continue;
    Section s;
    s.key = entry.key;
    s.heading = c.t(entry.heading);
    MOZZI_TRY_ASSIGN(const auto has, entry.build(c, s));
    if (has) report.sections.push_back(std::move(s));
  }
  return report;
}

}  // namespace mozzi::core::report
