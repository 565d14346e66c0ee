#include "core/report/gap_report.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/common/dof.h"
#include "core/common/text.h"

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

Section gapDiagnosisSection(const gap::Diagnosis& d, const std::string& model, const std::string& test) {
  Section s;
  s.key = "gap";
  s.heading = "Gap diagnoses";
  s.blocks.push_back(Paragraph{"Model: " + model + ". Test: " + test + "."});
  std::string verdict = std::string("Verdict: ") + gap::verdictName(d.verdict);
  const BestEffect best = bestEffect(d);
  if (best.pair) {
    verdict += " (" + best.pair->effects[0].candidate.effect + " and " + best.pair->effects[1].candidate.effect +
               "), gap " + formatNumber(d.gapBefore.overall, 3) + " before, " +
               formatNumber(best.pair->gapAfterBoth.overall, 3) + " after both";
  } else if (best.single && best.inVerdict) {
    verdict += " (" + best.single->candidate.effect + " at " + locationText(best.single->candidate) + "), gap " +
               formatNumber(d.gapBefore.overall, 3) + " before, " + formatNumber(best.single->gapAfter.overall, 3) +
               " after";
  }
  s.blocks.push_back(Paragraph{verdict + "."});
  if (!d.explanation.empty()) s.blocks.push_back(Paragraph{d.explanation});

  Table where;
  where.caption = "Gap before: " + d.gapBefore.residualName + " = " + formatNumber(d.gapBefore.overall) +
                  "; where it lies (flagged rows)";
  where.headers = {"Kind", "Item", "Gap", "z"};
  where.units = {"", "", "", ""};
  for (const auto& entry : d.where)
    where.rows.push_back(
        {textCell(entry.kind), textCell(entry.label), numberCell(entry.value, 4), numberCell(entry.z, 3)});
  s.blocks.push_back(where);

  Table ranking;
  ranking.caption = "Ranked effects (bold in the workbench: the verdict's)";
  ranking.headers = {"Effect",        "Location", "Size \u00b1 standard error", "Likelihood ratio", "Threshold",
                     "Held-out gain", "Shrink"};
  ranking.units = {"", "", "", "", "", "%", "%"};
  for (const auto& effect : d.ranking) {
    ranking.rows.push_back({textCell(effect.candidate.effect), textCell(locationText(effect.candidate)),
                            textCell(sizesText(effect)), numberCell(effect.likelihoodRatio, 4),
                            numberCell(d.threshold, 4), numberCell(100.0 * effect.heldOutImprovement, 3),
                            numberCell(effect.shrinkPct, 3)});
  }
  s.blocks.push_back(ranking);
  s.blocks.push_back(Figure{"gap-overlay", "gap-overlay", 0, "Measured and model, before and after"});
  return s;
}

std::vector<Block> storedAnalysisBlocks(const io::StoredAnalysis& a) {
  std::vector<Block> blocks;
  blocks.push_back(Heading{a.name.empty() ? "Analysis " + std::to_string(a.id) : a.name});
  const auto json = nlohmann::json::parse(a.resultJson, nullptr, false);
  if (json.is_object() && json.contains("verdict") && json["verdict"].is_string()) {
    std::string verdict = "Verdict: " + json["verdict"].get<std::string>();
    if (json.contains("best") && json["best"].is_object() && json["best"].contains("effect") &&
        json["best"]["effect"].is_string())
      verdict += " (" + json["best"]["effect"].get<std::string>() + ")";
    blocks.push_back(Paragraph{verdict + "."});
  }
  Table t;
  t.caption = "Findings of " + a.kind;
  t.headers = {"Band", "Mode", "DOF", "Condition", "Effect", "Size", "Unit", "Remaining gap"};
  t.units = {"Hz", "", "", "", "", "", "", "%"};
  for (const auto& f : a.findings) {
    t.rows.push_back({textCell(formatNumber(f.bandLowHz) + "-" + formatNumber(f.bandHighHz)),
                      textCell(f.modeIndex ? std::to_string(*f.modeIndex + 1) : "-"),
                      textCell(f.dof ? formatDof(*f.dof) : "-"), textCell(f.condition.empty() ? "-" : f.condition),
                      textCell(f.effect), numberCell(f.size, 4, f.uncertainty), textCell(f.unit),
                      numberCell(100.0 * f.remainingGap, 3)});
  }
  blocks.push_back(t);
  return blocks;
}

}  // namespace mozzi::core::report
