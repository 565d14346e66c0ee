#include "core/report/stability_report.h"

#include <cmath>

#include "core/common/text.h"
#include "core/stability/stability_record.h"
#include "core/stability/wheelchair_record.h"

namespace mozzi::core::report {
namespace {

namespace st = stability;
constexpr double kDeg = 3.14159265358979323846 / 180.0;

std::string specimenOf(const std::map<std::int64_t, std::string>& specimens, std::int64_t id) {
  auto it = specimens.find(id);
  return it == specimens.end() ? "specimen " + std::to_string(id) : it->second;
}

// The crossings of one sweep (thesis §4.2 Figure 33, §6.6; Meijaard et al.
// 2007 §6): the speed with `mozzi-cli stability`'s digits.
Table criticalSpeedTable(const st::StabilitySweep& sweep, const std::string& caption) {
  Table t;
  t.caption = caption;
  t.headers = {"Mode", "Real part", "Speed", "Im λ at the crossing"};
  t.units = {"", "", "m/s", "rad/s"};
  for (const auto& e : sweep.events) {
    if (e.kind != "stabilises" && e.kind != "destabilises") continue;
    Cell v{st::criticalSpeedText(e.v), e.v, std::nullopt};
    Cell im{st::crossingFrequencyText(e.frequency), e.frequency, std::nullopt};
    t.rows.push_back({textCell(e.mode), textCell(e.kind), v, im});
  }
  return t;
}

}  // namespace

bool hasOwnStabilitySection(const std::string& analysisKind) {
  return analysisKind == st::kStabilityAnalysisKind || analysisKind == st::kWheelchairAnalysisKind;
}

Result<bool> stabilitySection(const io::ProjectStore& store, const std::map<std::int64_t, std::string>& specimens,
                              Section& s) {
  std::vector<std::int64_t> unreadable;
  MOZZI_TRY_ASSIGN(auto records, st::storedStabilityRecords(store, &unreadable));
  for (const auto& r : records) {
    if (!specimens.count(r.specimenId)) continue;
    const st::StabilityRecord& rec = r.record;
    s.blocks.push_back(Heading{r.name + " (" + specimenOf(specimens, r.specimenId) + ")"});
    std::string text = rec.model + ". Fork: " + (rec.fork.empty() ? "rigid" : rec.fork);
    if (!rec.forkSource.empty()) text += " (" + rec.forkSource + ")";
    text += ". Speeds " + formatNumber(rec.sweep.points.front().v, 6) + " to " +
            formatNumber(rec.sweep.points.back().v, 6) + " m/s, " + std::to_string(rec.sweep.points.size()) +
            " speeds; modes tracked by eigenvector continuity, critical speeds refined by Brent's method.";
    if (!rec.parametersFile.empty()) text += " Parameters: " + rec.parametersFile + ".";
    s.blocks.push_back(Paragraph{text});
    const std::string stem = "stability-" + std::to_string(r.analysisId);
    const std::string compared = rec.rigidSweep ? "; the rigid fork with open symbols, dotted lines" : "";
    s.blocks.push_back(Figure{stem + "-real", "stability-real", r.analysisId,
                              "Real parts of the eigenvalues against speed, critical speeds dashed" + compared});
    s.blocks.push_back(Figure{stem + "-imaginary", "stability-imaginary", r.analysisId,
                              "Imaginary parts of the oscillating modes against speed" + compared});
    Table t = criticalSpeedTable(rec.sweep, "Critical speeds (a real part crossing zero)");
    if (t.rows.empty())
      s.blocks.push_back(Paragraph{"No real part crosses zero in this speed range."});
    else
      s.blocks.push_back(std::move(t));
    if (rec.rigidSweep) {
      Table rigid = criticalSpeedTable(*rec.rigidSweep, "Critical speeds with the rigid fork");
      if (rigid.rows.empty())
        s.blocks.push_back(Paragraph{"Rigid fork: no real part crosses zero in this speed range."});
      else
        s.blocks.push_back(std::move(rigid));
    }
  }
  if (!unreadable.empty())
    s.blocks.push_back(Paragraph{std::to_string(unreadable.size()) + " stored stability result(s) could not be read."});
  return !s.blocks.empty();
}

Result<bool> wheelchairSection(const io::ProjectStore& store, const std::map<std::int64_t, std::string>& specimens,
                               Section& s) {
  MOZZI_TRY_ASSIGN(auto records, st::storedWheelchairRecords(store));
  for (const auto& r : records) {
    if (!specimens.count(r.specimenId)) continue;
    const st::WheelchairStudy& study = r.record.study;
    const bool slalom = study.manoeuvre == "slalom";
    s.blocks.push_back(Heading{r.name + " (" + specimenOf(specimens, r.specimenId) + ")"});
    std::string text = std::string(slalom ? "Slalom" : "Steady turning") + " at " + formatNumber(study.speed, 4) +
                       " m/s, differential torque " + formatNumber(study.torque, 4) + " N m" +
                       (slalom ? " at " + formatNumber(study.frequency, 3) + " Hz" : "") + ", " +
                       formatNumber(study.duration, 4) + " s simulated (thesis §7.2 five-DOF model)";
    if (study.study != "none") text += "; rear " + study.study + " at 0.5, 1 and 2 times its value (§7.3, §7.4)";
    s.blocks.push_back(Paragraph{text + "."});
    s.blocks.push_back(Figure{"wheelchair-" + std::to_string(r.analysisId), "wheelchair-trajectory", r.analysisId,
                              "Trajectory of the centre of mass (thesis Figures 57 to 60)"});
    Table t;
    t.caption = slalom ? "Slalom after two cycles of start transient" : "Steady turn at the end of the run";
    if (slalom) {
      t.headers = {"Stiffness factor", "Lateral amplitude", "Rear slip amplitude right", "Rear slip amplitude left"};
      t.units = {"", "m", "deg", "deg"};
    } else {
      t.headers = {"Stiffness factor", "Radius", "Rear slip right", "Rear slip left"};
      t.units = {"", "m", "deg", "deg"};
    }
    for (const auto& run : r.record.runs) {
      if (run.history.empty()) continue;
      if (slalom) {
        auto sum = st::summariseSlalom(run.history, 2.0 / study.frequency, study.frequency);
        if (!sum) continue;
        t.rows.push_back({numberCell(run.factor, 3), numberCell(sum->lateralAmplitude, 4),
                          numberCell(sum->slipAmplitudeRight / kDeg, 4), numberCell(sum->slipAmplitudeLeft / kDeg, 4)});
      } else {
        const auto& end = run.history.back();
        const double radius = std::abs(end.r) > 0.0 ? std::hypot(end.u, end.v) / std::abs(end.r) : 0.0;
        t.rows.push_back({numberCell(run.factor, 3), numberCell(radius, 4), numberCell(end.slipRight / kDeg, 4),
                          numberCell(end.slipLeft / kDeg, 4)});
      }
    }
    if (!t.rows.empty()) s.blocks.push_back(std::move(t));
  }
  return !s.blocks.empty();
}

}  // namespace mozzi::core::report
