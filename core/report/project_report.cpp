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
  std::map<std::int64_t, std::string> specimenNames;  // the specimens reported
  bool wanted(std::int64_t specimenId) const { return specimenNames.count(specimenId) > 0; }
  std::string specimen(std::int64_t id) const {
    auto it = specimenNames.find(id);
    return it == specimenNames.end() ? "specimen " + std::to_string(id) : it->second;
  }
};

Table transducerTable(const std::vector<io::StoredTransducer>& transducers) {
  Table t;
  t.caption = "Transducers";
  t.headers = {"Channel", "Quantity", "Unit", "Model", "Serial", "Sensitivity"};
  t.units = {"", "", "", "", "", "V per unit"};
  for (const auto& x : transducers)
    t.rows.push_back({textCell(std::to_string(x.channel)), textCell(x.quantity), textCell(x.unit), textCell(x.model),
                      textCell(x.serial.empty() ? "-" : x.serial), numberCell(x.sensitivity, 6)});
  return t;
}

Result<void> titleSection(const Context& c, const ReportOptions& options, Section& s) {
  auto summary = c.store.summary();
  if (!summary) return summary.error();
  std::string about = "Project " + std::filesystem::path(c.store.path()).filename().string() + ", created " +
                      summary->createdUtc + " by Mozzi " + summary->mozziVersion + ", schema " +
                      std::to_string(summary->schemaVersion) + ".";
  if (!options.generatedUtc.empty()) about += " Report generated " + options.generatedUtc + ".";
  s.blocks.push_back(Paragraph{about});
  Table specimens;
  specimens.caption = "Specimens";
  specimens.headers = {"Specimen", "Kind", "Description"};
  specimens.units = {"", "", ""};
  for (const auto& sp : summary->specimens)
    if (c.wanted(sp.id)) specimens.rows.push_back({textCell(sp.name), textCell(sp.kind), textCell(sp.description)});
  s.blocks.push_back(specimens);

  // Campaigns: constraint, operator and transducers from their definition.
  for (const auto& [id, name] : c.specimenNames) {
    auto campaigns = c.store.campaigns(id);
    if (!campaigns) return campaigns.error();
    for (const auto& campaign : *campaigns) {
      s.blocks.push_back(Heading{"Campaign " + campaign.name + " (" + name + ")"});
      const auto settings = nlohmann::json::parse(campaign.settingsJson, nullptr, false);
      std::string text = "Kind " + campaign.kind + ", started " + campaign.startedUtc + ".";
      if (settings.is_object() && settings.contains("constraint"))
        if (auto d = jsonText(settings["constraint"], "description"); !d.empty()) text += " Constraint: " + d + ".";
      if (auto op = jsonText(settings, "operator"); !op.empty()) text += " Operator: " + op + ".";
      if (auto e = jsonText(settings, "estimator"); !e.empty()) text += " FRF estimator " + e + ".";
      if (!campaign.notes.empty()) text += " Notes: " + campaign.notes;
      s.blocks.push_back(Paragraph{text});
      if (campaign.rigSetupId) {
        auto rig = c.store.rigSetup(*campaign.rigSetupId);
        if (!rig) return rig.error();
        if (!rig->transducers.empty()) s.blocks.push_back(transducerTable(rig->transducers));
      } else if (settings.is_object() && settings.contains("channels") && settings["channels"].is_array()) {
        Table t;
        t.caption = "Transducers of " + campaign.name;
        t.headers = {"Input", "Name", "Quantity", "Model", "Serial", "Sensitivity", "Calibrated"};
        t.units = {"", "", "", "", "", "mV per unit", ""};
        for (const auto& ch : settings["channels"]) {
          Cell input = ch.contains("input") && ch["input"].is_number()
                           ? textCell(std::to_string(ch["input"].get<int>()))
                           : textCell("-");
          Cell sens = ch.contains("sensitivity_mv_per_unit") && ch["sensitivity_mv_per_unit"].is_number()
                          ? numberCell(ch["sensitivity_mv_per_unit"].get<double>(), 6)
                          : textCell("-");
          std::string quantity = jsonText(ch, "kind");
          if (auto unit = jsonText(ch, "unit"); !unit.empty()) quantity += " [" + unit + "]";
          t.rows.push_back({input, textCell(jsonText(ch, "name")), textCell(quantity), textCell(jsonText(ch, "model")),
                            textCell(jsonText(ch, "serial")), sens, textCell(jsonText(ch, "calibration_date"))});
        }
        s.blocks.push_back(t);
      }
    }
  }

  // Rig set-ups of the stiffness and tyre tests.
  std::set<std::int64_t> rigIds;
  auto rigTests = c.store.rigTests();
  if (!rigTests) return rigTests.error();
  for (const auto& info : *rigTests) {
    if (!c.wanted(info.specimenId)) continue;
    auto test = c.store.rigTest(info.id);
    if (!test) return test.error();
    if (test->rigSetupId) rigIds.insert(*test->rigSetupId);
  }
  auto tyreTests = c.store.tyreTests();
  if (!tyreTests) return tyreTests.error();
  for (const auto& info : *tyreTests) {
    if (!c.wanted(info.specimenId)) continue;
    auto test = c.store.tyreTest(info.id);
    if (!test) return test.error();
    if (test->rigSetupId) rigIds.insert(*test->rigSetupId);
  }
  for (const auto id : rigIds) {
    auto rig = c.store.rigSetup(id);
    if (!rig) return rig.error();
    s.blocks.push_back(Heading{"Rig " + rig->name + " (" + c.specimen(rig->specimenId) + ")"});
    s.blocks.push_back(Paragraph{"Rig kind " + rig->rigKind + ", driver " + rig->driver + "."});
    if (!rig->transducers.empty()) s.blocks.push_back(transducerTable(rig->transducers));
  }
  return {};
}

Result<bool> frfSection(const Context& c, Section& s) {
  auto sets = c.store.frfSets();
  if (!sets) return sets.error();
  Table t;
  t.caption = "FRF sets";
  t.headers = {"Set", "Specimen", "Source", "Estimator", "Type", "Lines", "Responses", "References"};
  t.units = {"", "", "", "", "", "", "", ""};
  std::vector<Figure> figures;
  for (const auto& set : *sets) {
    if (!c.wanted(set.specimenId)) continue;
    t.rows.push_back({textCell(set.name), textCell(c.specimen(set.specimenId)), textCell(set.source),
                      textCell(set.estimator.empty() ? "-" : set.estimator), textCell(frfTypeName(set.type)),
                      numberCell(static_cast<double>(set.lineCount)), numberCell(set.responseCount),
                      numberCell(set.referenceCount)});
    figures.push_back(Figure{"frf-set-" + std::to_string(set.id), "frf-overlay", set.id,
                             "FRF overlay of " + set.name + " (" + frfTypeName(set.type) + ", magnitude)"});
  }
  if (t.rows.empty()) return false;
  s.blocks.push_back(t);
  for (auto& f : figures) s.blocks.push_back(std::move(f));
  return true;
}

Result<bool> modalSection(const Context& c, Section& s) {
  auto results = c.store.modalResults();
  if (!results) return results.error();
  for (const auto& info : *results) {
    if (!c.wanted(info.specimenId)) continue;
    auto table = c.store.modalResult(info.id);
    if (!table) return table.error();
    s.blocks.push_back(Heading{info.name + " (" + c.specimen(info.specimenId) + ")"});
    s.blocks.push_back(Paragraph{"Method " + info.method + ", band " + formatNumber(info.bandLowHz) + " to " +
                                 formatNumber(info.bandHighHz) + " Hz" +
                                 (info.frfSetId ? ", from FRF set " + std::to_string(*info.frfSetId) : "") +
                                 ". Damping as the viscous ratio zeta and the loss factor eta = 2 zeta. The project "
                                 "stores frequency, damping and shape per mode; no standard errors or MPC."});
    Table t;
    t.caption = "Modes of " + info.name;
    t.headers = {"Mode", "Frequency", "Damping ratio zeta", "Loss factor eta"};
    t.units = {"", "Hz", "%", "%"};
    for (std::size_t m = 0; m < table->modes.size(); ++m) {
      const auto& mode = table->modes[m];
      t.rows.push_back({textCell(std::to_string(m + 1)), numberCell(mode.frequencyHz, 6),
                        numberCell(100.0 * mode.dampingRatio, 4), numberCell(200.0 * mode.dampingRatio, 4)});
    }
    s.blocks.push_back(t);
  }
  return !s.blocks.empty();
}

// Analyses the Lumped Fork page keeps (kind "lumped-fork": the three lumped
// models of thesis §4.2, Table 12; "bicycle-fork": §6.4, §6.5), with the keys
// of `mozzi-cli fork ... --json`. They belong with the stiffness results, not
// with the gap diagnoses.
bool isForkModelAnalysis(const io::StoredAnalysis& a) {
  return a.kind == "lumped-fork" || a.kind == "bicycle-fork";
}

Result<void> forkModelBlocks(const Context& c, Section& s) {
  auto analyses = c.store.analyses();
  if (!analyses) return analyses.error();
  auto number = [](const nlohmann::json& j, const char* key) {
    return j.is_object() && j.contains(key) && j[key].is_number() ? j[key].get<double>() : std::nan("");
  };
  for (const auto& a : *analyses) {
    if (!c.wanted(a.specimenId) || !isForkModelAnalysis(a)) continue;
    const auto json = nlohmann::json::parse(a.resultJson, nullptr, false);
    s.blocks.push_back(Heading{a.name.empty() ? "Analysis " + std::to_string(a.id) : a.name});
    Table t;
    if (a.kind == "lumped-fork") {
      t.caption = "Lumped fork models (thesis §4.2, Table 12)";
      t.headers = {"Model", "k", "L", "J", "Pure moment", "f_n", "c", "zeta"};
      t.units = {"", "N m/rad", "m", "kg m^2", "kg m^2", "Hz", "N m s/rad", ""};
      const auto models = json.is_object() ? json.value("models", nlohmann::json::object()) : nlohmann::json();
      for (int i = 1; i <= 3; ++i) {
        const auto m =
            models.is_object() ? models.value("model" + std::to_string(i), nlohmann::json()) : nlohmann::json();
        t.rows.push_back({textCell(std::to_string(i)), numberCell(number(m, "stiffness_Nm_per_rad")),
                          numberCell(number(m, "arm_m")), numberCell(number(m, "inertia_kgm2")),
                          numberCell(number(m, "pure_moment_kgm2")), numberCell(number(m, "frequency_Hz")),
                          numberCell(number(m, "damping_Nms_per_rad")), numberCell(number(m, "zeta"))});
      }
    } else {
      t.caption = "Bicycle fork stiffness and damping (thesis §6.4, §6.5)";
      t.headers = {"Quantity", "Value", "Unit"};
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
      for (const auto& r : rows) t.rows.push_back({textCell(r.name), numberCell(r.value), textCell(r.unit)});
    }
    s.blocks.push_back(t);
  }
  return {};
}

Result<bool> stiffnessSection(const Context& c, Section& s) {
  auto tests = c.store.rigTests();
  if (!tests) return tests.error();
  for (const auto& info : *tests) {
    if (!c.wanted(info.specimenId)) continue;
    auto test = c.store.rigTest(info.id);
    if (!test) return test.error();
    s.blocks.push_back(Heading{info.specimenName + " / " + test->name + " (" +
                               (test->kind == io::StoredRigTest::Kind::Static ? "static" : "dynamic") + ", " +
                               io::testStatusName(test->status) + ")"});
    if (!test->statusNote.empty()) s.blocks.push_back(Paragraph{test->statusNote});
    Table whole;
    whole.caption = "Results of " + test->name + " (one standard deviation)";
    whole.headers = {"Quantity", "Value", "Unit"};
    whole.units = {"", "", ""};
    std::map<int, std::map<std::string, const io::StoredRigTest::Result*>> steps;
    std::set<std::string> present;
    for (const auto& r : test->results) {
      if (r.step) {
        steps[*r.step][r.quantity] = &r;
        present.insert(r.quantity);
      } else {
        whole.rows.push_back({textCell(r.quantity), numberCell(r.value, 6, r.uncertainty), textCell(r.unit)});
      }
    }
    if (!whole.rows.empty()) s.blocks.push_back(whole);
    std::vector<std::string> columns;
    for (const char* q : kStepQuantities)
      if (present.count(q)) columns.push_back(q);
    if (!steps.empty() && !columns.empty()) {
      Table t;
      t.caption = "Per step of " + test->name + " (one standard deviation)";
      t.headers = {"Step"};
      t.units = {""};
      for (const auto& q : columns) {
        t.headers.push_back(q);
        std::string unit;
        for (const auto& [step, byName] : steps)
          if (auto it = byName.find(q); it != byName.end()) unit = it->second->unit;
        t.units.push_back(unit);
      }
      for (const auto& [step, byName] : steps) {
        std::vector<Cell> row{textCell(std::to_string(step))};
        for (const auto& q : columns) {
          auto it = byName.find(q);
          row.push_back(it == byName.end() ? textCell("-") : numberCell(it->second->value, 6, it->second->uncertainty));
        }
        t.rows.push_back(std::move(row));
      }
      s.blocks.push_back(t);
    }
  }
  if (auto r = forkModelBlocks(c, s); !r) return r.error();
  return !s.blocks.empty();
}

Result<bool> tyreSection(const Context& c, Section& s) {
  auto tests = c.store.tyreTests();
  if (!tests) return tests.error();
  for (const auto& info : *tests) {
    if (!c.wanted(info.specimenId)) continue;
    auto test = c.store.tyreTest(info.id);
    if (!test) return test.error();
    s.blocks.push_back(Heading{info.specimenName + " / " + test->name + " (" + test->kind + ", " +
                               io::testStatusName(test->status) + ")"});
    s.blocks.push_back(Paragraph{"Inflation pressure " + formatNumber(test->inflationPressurePa) +
                                 " Pa, vertical load " + formatNumber(test->verticalLoadN) + " N, speed " +
                                 formatNumber(test->speedMps) + " m/s, " + std::to_string(test->points.size()) +
                                 " measured points." + (test->statusNote.empty() ? "" : " " + test->statusNote)});
    Table params, mf;
    params.caption = "Results of " + test->name + " (one standard deviation)";
    mf.caption = "Magic Formula coefficients of " + test->name;
    params.headers = mf.headers = {"Parameter", "Value", "Unit"};
    params.units = mf.units = {"", "", ""};
    for (const auto& p : test->parameters) {
      if (p.step) continue;
      std::vector<Cell> row{textCell(p.name), numberCell(p.value, 6, p.uncertainty),
                            textCell(p.unit.empty() ? "-" : p.unit)};
      (p.name.rfind("mf_", 0) == 0 ? mf : params).rows.push_back(std::move(row));
    }
    if (!params.rows.empty()) s.blocks.push_back(params);
    if (!mf.rows.empty()) s.blocks.push_back(mf);
  }
  return !s.blocks.empty();
}

Result<bool> gapSection(const Context& c, Section& s) {
  auto analyses = c.store.analyses();
  if (!analyses) return analyses.error();
  for (const auto& a : *analyses) {
    if (!c.wanted(a.specimenId) || isForkModelAnalysis(a) || hasOwnStabilitySection(a.kind)) continue;
    for (auto& block : storedAnalysisBlocks(a)) s.blocks.push_back(std::move(block));
  }
  return !s.blocks.empty();
}

}  // namespace

const std::vector<std::string>& reportSectionKeys() {
  static const std::vector<std::string> keys = {"title", "frf", "modal",     "stiffness",
                                                "tyre",  "gap", "stability", "wheelchair"};
  return keys;
}

std::string sectionHeading(const std::string& key) {
  if (key == "title") return "Project and specimens";
  if (key == "frf") return "Frequency response functions";
  if (key == "modal") return "Modal parameters";
  if (key == "stiffness") return "Stiffness tests";
  if (key == "tyre") return "Tyre tests";
  if (key == "gap") return "Gap diagnoses";
  if (key == "stability") return "Stability against speed";
  if (key == "wheelchair") return "Wheelchair manoeuvres";
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
  auto summary = store.summary();
  if (!summary) return summary.error();
  Context c{store, {}};
  for (const auto& sp : summary->specimens)
    if (options.specimen.empty() || sp.name == options.specimen) c.specimenNames[sp.id] = sp.name;
  if (!options.specimen.empty() && c.specimenNames.empty())
    return makeError(ErrorCode::NotFound, "no specimen named '" + options.specimen + "'", store.path());

  Report report;
  report.title = "Mozzi report: " + std::filesystem::path(store.path()).stem().string();
  if (!options.specimen.empty()) report.title += ", " + options.specimen;
  for (const auto& key : keys) {
    if (!options.sections.empty() &&
        std::find(options.sections.begin(), options.sections.end(), key) == options.sections.end())
      continue;
    Section s;
    s.key = key;
    s.heading = sectionHeading(key);
    Result<bool> has = true;
    if (key == "title") {
      auto done = titleSection(c, options, s);
      if (!done) return done.error();
    } else if (key == "frf") {
      has = frfSection(c, s);
    } else if (key == "modal") {
      has = modalSection(c, s);
    } else if (key == "stiffness") {
      has = stiffnessSection(c, s);
    } else if (key == "tyre") {
      has = tyreSection(c, s);
    } else if (key == "gap") {
      has = gapSection(c, s);
    } else if (key == "stability" || key == "wheelchair") {  // core/report/stability_report.cpp
      has = key == "stability" ? stabilitySection(store, c.specimenNames, s)
                               : wheelchairSection(store, c.specimenNames, s);
    }
    if (!has) return has.error();
    if (*has) report.sections.push_back(std::move(s));
  }
  return report;
}

}  // namespace mozzi::core::report
