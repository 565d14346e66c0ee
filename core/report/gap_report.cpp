#include "core/report/gap_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/common/dof.h"
#include "core/common/text.h"
#include "core/gap/diagnosis_json.h"

namespace mozzi::core::report {

BestEffect bestEffect(const gap::Diagnosis& d) {
  BestEffect best;
  // Two effects at once: the verdict names both (not for an ambiguous verdict,
  // whose set lists the effects it cannot tell apart).
  if (d.verdictSet.size() == 2 && d.verdict != gap::Verdict::Ambiguous && d.pairFitted && d.pair.effects.size() == 2)
    best.pair = &d.pair;
  if (!d.verdictSet.empty()) {
    const auto index = static_cast<std::size_t>(d.verdictSet.front());
    if (index < d.ranking.size()) {
      best.single = &d.ranking[index];
      best.inVerdict = true;
    }
  } else if (!d.ranking.empty()) {
    best.single = &d.ranking.front();
  }
  return best;
}

std::string effectAtLocation(const gap::Candidate& c) {
  std::string s = c.effect;
  for (std::size_t k = 0; k < c.location.size(); ++k) s += (k == 0 ? " at " : ", ") + c.location[k];
  return s;
}

std::string locationText(const gap::Candidate& c) {
  if (c.location.empty()) return "(global)";
  std::string s;
  for (const auto& l : c.location) s += (s.empty() ? "" : " - ") + l;
  return s;
}

namespace {

std::string sizesText(const gap::RankedEffect& effect) {
  std::string sizes;
  for (std::size_t p = 0; p < effect.parameters.size(); ++p) {
    const gap::Parameter def =
        p < effect.candidate.parameters.size() ? effect.candidate.parameters[p] : gap::Parameter{};
    std::string text = def.name + " = " + formatNumber(effect.parameters[p]);
    if (p < effect.stdErrors.size()) text += " \u00b1 " + formatNumber(effect.stdErrors[p], 2);
    if (!def.unit.empty()) text += " " + def.unit;
    sizes += (sizes.empty() ? "" : "; ") + text;
  }
  if (!effect.identifiable) sizes += (sizes.empty() ? "" : "; ") + std::string("(not identifiable)");
  return sizes;
}

}  // namespace

Section gapDiagnosisSection(const gap::Diagnosis& d, const std::string& model, const std::string& test,
                            const Texts& tx) {
  Section s;
  s.key = "gap";
  s.heading = tx("Gap diagnoses");
  s.blocks.push_back(Paragraph{tx("Model: %1. Test: %2.", {model, test})});
  std::string verdict = tx("Verdict: %1", {gap::verdictName(d.verdict)});
  const BestEffect best = bestEffect(d);
  if (best.pair) {
    verdict += " " + tx("(%1 and %2), gap %3 before, %4 after both",
                        {best.pair->effects[0].candidate.effect, best.pair->effects[1].candidate.effect,
                         tx.number(d.gapBefore.overall, 3), tx.number(best.pair->gapAfterBoth.overall, 3)});
  } else if (best.single && best.inVerdict) {
    verdict += " " + tx("(%1 at %2), gap %3 before, %4 after",
                        {best.single->candidate.effect, locationText(best.single->candidate),
                         tx.number(d.gapBefore.overall, 3), tx.number(best.single->gapAfter.overall, 3)});
  }
  s.blocks.push_back(Paragraph{verdict + "."});
  if (!d.explanation.empty()) s.blocks.push_back(Paragraph{d.explanation});

  Table where;
  where.caption = tx("Gap before: %1 = %2; where it lies (flagged rows)",
                     {d.gapBefore.residualName, tx.number(d.gapBefore.overall)});
  where.headers = {tx("Kind"), tx("Item"), tx("Gap"), "z"};
  where.units = {"", "", "", ""};
  for (const auto& entry : d.where)
    where.rows.push_back(
        {textCell(entry.kind), textCell(entry.label), tx.numberCell(entry.value, 4), tx.numberCell(entry.z, 3)});
  s.blocks.push_back(where);

  Table ranking;
  ranking.caption = tx("Ranked effects (bold in the workbench: the verdict's)");
  ranking.headers = {
      tx("Effect"),        tx("Location"), tx("Size \u00b1 standard error"), tx("Likelihood ratio"), tx("Threshold"),
      tx("Held-out gain"), tx("Shrink")};
  ranking.units = {"", "", "", "", "", "%", "%"};
  for (const auto& effect : d.ranking) {
    std::string sizes = sizesText(effect);
    if (tx.language() == Language::Italian) std::replace(sizes.begin(), sizes.end(), '.', ',');
    // A family of locations whose effect changes the data alike
    // (core/gap/engine/families.h) is one row: it names the others, as the
    // workbench's ranking does.
    std::string location = locationText(effect.candidate);
    const auto& others = effect.candidate.equivalent;
    if (others.size() == 1) {
      std::string other;
      for (const auto& l : others[0]) other += (other.empty() ? "" : " - ") + l;
      location += " " + tx("(equivalent at %1)", {other});
    } else if (others.size() > 1) {
      location += " " + tx("(and %1 equivalent locations)", {std::to_string(others.size())});
    }
    ranking.rows.push_back({textCell(effect.candidate.effect), textCell(location), textCell(sizes),
                            tx.numberCell(effect.likelihoodRatio, 4), tx.numberCell(d.threshold, 4),
                            tx.numberCell(100.0 * effect.heldOutImprovement, 3), tx.numberCell(effect.shrinkPct, 3)});
  }
  s.blocks.push_back(ranking);
  s.blocks.push_back(Figure{"gap-overlay", "gap-overlay", 0, tx("Measured and model, before and after")});
  return s;
}

std::vector<Block> storedAnalysisBlocks(const io::StoredAnalysis& a, const Texts& tx) {
  std::vector<Block> blocks;
  blocks.push_back(Heading{a.name.empty() ? tx("Analysis %1", {std::to_string(a.id)}) : a.name});
  const auto json = nlohmann::json::parse(a.resultJson, nullptr, false);
  if (json.is_object() && json.contains("verdict") && json["verdict"].is_string()) {
    std::string verdict = tx("Verdict: %1", {json["verdict"].get<std::string>()});
    if (json.contains("best") && json["best"].is_object() && json["best"].contains("effect") &&
        json["best"]["effect"].is_string())
      verdict += " (" + json["best"]["effect"].get<std::string>() + ")";
    blocks.push_back(Paragraph{verdict + "."});
  }
  if (json.is_object() && json.contains("explanation") && json["explanation"].is_string())
    blocks.push_back(Paragraph{json["explanation"].get<std::string>()});
  Table t;
  t.caption = tx("Findings of %1", {a.kind});
  t.headers = {tx("Band"),   tx("Mode"), "DOF",      tx("Condition"),
               tx("Effect"), tx("Size"), tx("Unit"), tx("Remaining gap")};
  t.units = {"Hz", "", "", "", "", "", "", "%"};
  for (const auto& f : a.findings) {
    t.rows.push_back({textCell(tx.number(f.bandLowHz) + "-" + tx.number(f.bandHighHz)),
                      textCell(f.modeIndex ? std::to_string(*f.modeIndex + 1) : "-"),
                      textCell(f.dof ? formatDof(*f.dof) : "-"), textCell(f.condition.empty() ? "-" : f.condition),
                      textCell(f.effect), tx.numberCell(f.size, 4, f.uncertainty), textCell(f.unit),
                      tx.numberCell(100.0 * f.remainingGap, 3)});
  }
  blocks.push_back(t);
  if (json.is_object() && json.contains("overlay") && json["overlay"].is_array() && !json["overlay"].empty())
    blocks.push_back(
        Figure{"gap-overlay-" + std::to_string(a.id), "gap-overlay", a.id,
               tx("Measured and model of %1, before and after the best effect", {a.name.empty() ? a.kind : a.name})});
  return blocks;
}

namespace {

// Every step-th point so that at most maxPoints remain (the last point kept).
nlohmann::json thinned(const std::vector<double>& v, std::size_t step) {
  auto out = nlohmann::json::array();
  for (std::size_t i = 0; i < v.size(); i += step) out.push_back(v[i]);
  if (!v.empty() && (v.size() - 1) % step != 0) out.push_back(v.back());
  return out;
}

}  // namespace

io::StoredAnalysis analysisFromDiagnosis(const gap::GapProblem& problem, const gap::Diagnosis& d,
                                         const std::string& name, int maxCurves, int maxPoints) {
  io::StoredAnalysis a;
  a.kind = "gap-diagnosis";
  a.name = name;
  nlohmann::json json = gap::diagnosisToJson(d);
  json["explanation"] = d.explanation;

  // The overlay as the Model vs Test page draws it: before at the calibrated
  // baseline; after with the verdict's pair, else its (or the top) effect.
  const auto before = problem.overlay({d.calibrated.data(), -1, nullptr});
  std::vector<gap::OverlayCurve> after;
  std::string afterLabel;
  const BestEffect best = bestEffect(d);
  if (best.pair && d.pair.theta.size() == d.calibrated.size()) {
    std::vector<double> phi;
    for (const auto& e : d.pair.effects) phi.insert(phi.end(), e.parameters.begin(), e.parameters.end());
    after = problem.combinedOverlay(d.pair.theta.data(),
                                    {d.pair.effects[0].candidateIndex, d.pair.effects[1].candidateIndex}, phi.data());
    afterLabel = "model + " + effectAtLocation(d.pair.effects[0].candidate) + " + " +
                 effectAtLocation(d.pair.effects[1].candidate);
  } else if (best.single && best.single->candidateIndex >= 0 && best.single->theta.size() == d.calibrated.size()) {
    after = problem.overlay({best.single->theta.data(), best.single->candidateIndex, best.single->parameters.data()});
    afterLabel = "model + " + effectAtLocation(best.single->candidate);
  }
  // The curves with the largest measured level first (the driving point and
  // the strongest transfers; a cross-direction FRF the model leaves at zero
  // shows nothing on a log axis).
  std::vector<std::size_t> order(before.size());
  std::vector<double> level(before.size(), 0.0);
  for (std::size_t i = 0; i < before.size(); ++i) {
    order[i] = i;
    for (double v : before[i].measured) level[i] += std::abs(v);
    if (!before[i].measured.empty()) level[i] /= static_cast<double>(before[i].measured.size());
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return level[x] > level[y]; });
  auto curves = nlohmann::json::array();
  for (std::size_t k = 0; k < order.size() && static_cast<int>(k) < maxCurves; ++k) {
    const std::size_t i = order[k];
    const auto& b = before[i];
    const std::size_t step = std::max<std::size_t>(1, (b.x.size() + maxPoints - 1) / std::max(1, maxPoints));
    nlohmann::json c = {{"label", b.label},
                        {"x_label", b.xLabel},
                        {"y_label", b.yLabel},
                        {"log_y", b.logY},
                        {"x", thinned(b.x, step)},
                        {"measured", thinned(b.measured, step)},
                        {"before", thinned(b.predicted, step)}};
    if (i < after.size() && after[i].predicted.size() == b.x.size()) {
      c["after"] = thinned(after[i].predicted, step);
      c["after_label"] = afterLabel;
    }
    curves.push_back(std::move(c));
  }
  json["overlay"] = std::move(curves);
  a.resultJson = json.dump();

  // Findings: the verdict's effect(s) over the fitted band, else each flagged band.
  const double lo = before.empty() || before[0].x.empty() ? 0.0 : before[0].x.front();
  const double hi = before.empty() || before[0].x.empty() ? 0.0 : before[0].x.back();
  const double gapBefore = d.gapBefore.overall;
  auto finding = [&](const gap::RankedEffect& e, double gapAfter) {
    io::StoredAnalysis::Finding f;
    f.bandLowHz = lo;
    f.bandHighHz = hi;
    f.effect = gap::label(e.candidate);
    if (!e.parameters.empty()) f.size = e.parameters[0];
    if (!e.stdErrors.empty()) f.uncertainty = e.stdErrors[0];
    if (!e.candidate.parameters.empty()) f.unit = e.candidate.parameters[0].unit;
    f.remainingGap = gapBefore > 0 ? std::clamp(gapAfter / gapBefore, 0.0, 1.0) : 0.0;
    return f;
  };
  if (best.pair) {
    for (const auto& e : best.pair->effects) a.findings.push_back(finding(e, best.pair->gapAfterBoth.overall));
  } else if (best.single && best.inVerdict) {
    a.findings.push_back(finding(*best.single, best.single->gapAfter.overall));
  } else {
    for (const auto& w : d.where) {
      if (!w.flagged || w.kind != "band") continue;
      io::StoredAnalysis::Finding f;
      f.effect = d.verdict == gap::Verdict::Ambiguous ? "cannot tell apart" : gap::verdictName(d.verdict);
      f.condition = w.label;
      f.bandLowHz = lo;
      f.bandHighHz = hi;
      double bl = 0, bh = 0;  // the row's own band, "100-200 Hz"
      if (std::sscanf(w.label.c_str(), "%lf-%lf", &bl, &bh) == 2 && bh > bl) f.bandLowHz = bl, f.bandHighHz = bh;
      f.size = w.value;
      f.remainingGap = 1.0;
      a.findings.push_back(f);
    }
  }
  return a;
}

}  // namespace mozzi::core::report
