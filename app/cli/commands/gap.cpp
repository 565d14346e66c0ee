// mozzi-cli gap: sim-to-real gap diagnosis of a model against a test
// (docs/cli/gap.md, shared/GAP.md): where the gap lies, which catalogue effect
// explains it, and how far it shrinks.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <ostream>
#include <set>
#include <sstream>
#include <string>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "core/common/text.h"
#include "core/gap/diagnosis.h"
#include "core/gap/diagnosis_json.h"
#include "core/gap/problem_loader.h"
#include "core/report/gap_report.h"

namespace mozzi::cli {
namespace {

namespace gap = core::gap;

constexpr const char* kSynopsis =
    "--model MODEL --measured TEST [--band LO:HI] [--bands A:B,C:D...] [--effects a,b,...] [--json] "
    "[--bootstrap N] [--seed S] [--multistarts N] [--noise auto|estimated|coherence|stated] [--noise-floor REL] "
    "[--averages N] [--pairs auto|always|never]";

int usage(std::ostream& err, const std::string& why) {
  err << "mozzi-cli gap: " << why << "\nUsage: mozzi-cli gap " << kSynopsis << "\n";
  return kExitUsage;
}

int fail(std::ostream& err, const core::Error& e) {
  err << "mozzi-cli gap: " << e.describe() << "\n";
  return kExitFailure;
}

// "LO:HI" with 0 <= LO < HI, finite.
bool parseRange(const std::string& text, double& lo, double& hi) {
  const auto colon = text.find(':');
  if (colon == std::string::npos) return false;
  const std::string a = text.substr(0, colon), b = text.substr(colon + 1);
  char* end = nullptr;
  lo = std::strtod(a.c_str(), &end);
  if (a.empty() || *end != '\0') return false;
  hi = std::strtod(b.c_str(), &end);
  if (b.empty() || *end != '\0') return false;
  return std::isfinite(lo) && std::isfinite(hi) && lo >= 0 && hi > lo;
}

std::vector<std::string> splitComma(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

std::string detailText(const gap::GapEntry& e, const char* name, int digits = 4) {
  for (const auto& d : e.details)
    if (d.first == name) return std::isfinite(d.second) ? core::formatNumber(d.second, digits) : "-";
  return "-";
}

using core::report::locationText;

void printMetrics(std::ostream& out, const gap::GapMetrics& m) {
  char buf[256];
  out << "Gap before (" << m.residualName << " " << core::formatNumber(m.overall, 3) << ")\n";
  // Structural kinds first, then whatever else the problem reports (tyre
  // conditions, stability predictions...) in the order it gives them.
  std::vector<std::string> kinds = {"band", "dof", "mode"};
  for (const auto& e : m.entries) {
    if (std::find(kinds.begin(), kinds.end(), e.kind) == kinds.end()) kinds.push_back(e.kind);
  }
  for (const auto& kind : kinds) {
    bool header = false;
    for (const auto& e : m.entries) {
      if (e.kind != kind) continue;
      if (!header) {
        if (kind == "mode") {
          out << "  mode                       value     z        f_err%    zeta_err%  MAC     flag\n";
        } else {
          std::snprintf(buf, sizeof buf, "  %-26s value     z        flag\n", kind.c_str());
          out << buf;
        }
        header = true;
      }
      if (kind == "mode") {
        std::snprintf(buf, sizeof buf, "  %-26s %-9s %-8s %-9s %-10s %-7s %s\n", e.label.c_str(),
                      core::formatNumber(e.value, 3).c_str(), core::formatNumber(e.z, 3).c_str(),
                      detailText(e, "frequency_error_pct", 3).c_str(), detailText(e, "zeta_error_pct", 3).c_str(),
                      detailText(e, "mac", 3).c_str(), e.flagged ? "*" : "");
      } else {
        std::snprintf(buf, sizeof buf, "  %-26s %-9s %-8s %-4s", e.label.c_str(),
                      core::formatNumber(e.value, 3).c_str(), core::formatNumber(e.z, 3).c_str(), e.flagged ? "*" : "");
        out << buf;
        // Outside the structural tables the details (measured, predicted...) are the point.
        if (kind != "band" && kind != "dof") {
          for (const auto& d : e.details) out << " " << d.first << " " << core::formatNumber(d.second, 4);
        }
        buf[0] = '\n';
        buf[1] = '\0';
      }
      out << buf;
    }
  }
}

void printNoise(std::ostream& out, const gap::NoiseModel& n) {
  if (n.description.empty() && n.entries.empty()) return;
  out << "\nNoise model: " << n.source << "\n  " << n.description << "\n";
  if (n.entries.empty()) return;
  char buf[256];
  std::snprintf(buf, sizeof buf, "  %-24s %-18s %-10s %-12s %s\n", "applies to", "band", "relative", "floor", "lines");
  out << buf;
  for (const auto& e : n.entries) {
    const std::string floor = core::formatNumber(e.floor, 3) + (e.unit.empty() ? "" : " " + e.unit);
    std::snprintf(buf, sizeof buf, "  %-24s %-18s %-10s %-12s %s\n", e.label.c_str(),
                  e.band.empty() ? "(all)" : e.band.c_str(), core::formatNumber(e.relative, 3).c_str(), floor.c_str(),
                  e.lines > 0 ? std::to_string(e.lines).c_str() : "-");
    out << buf;
  }
}

void printPair(std::ostream& out, const gap::Diagnosis& d) {
  if (!d.pairFitted || d.pair.effects.size() != 2) return;
  const auto& p = d.pair;
  out << "\nTwo effects at once (best of " << p.pairsFitted << " pairs" << (p.significant ? "" : ", not significant")
      << ")\n";
  for (std::size_t m = 0; m < 2; ++m) {
    const auto& e = p.effects[m];
    std::string sizes;
    for (std::size_t q = 0; q < e.candidate.parameters.size() && q < e.parameters.size(); ++q) {
      const auto& def = e.candidate.parameters[q];
      sizes += (sizes.empty() ? "" : ", ") + def.name + " " + core::formatNumber(e.parameters[q], 3);
      if (q < e.stdErrors.size()) sizes += " +/- " + core::formatNumber(e.stdErrors[q], 2);
      if (!def.unit.empty()) sizes += " " + def.unit;
    }
    out << "  " << gap::familyLabel(e.candidate) << ": " << sizes << " (LR given the other "
        << core::formatNumber(p.eachRatio[m], 3) << ")\n";
  }
  out << "  gap " << core::formatNumber(d.gapBefore.overall, 3) << " before, "
      << core::formatNumber(p.gapAfterOne.overall, 3) << " after one, " << core::formatNumber(p.gapAfterBoth.overall, 3)
      << " after both (shrink " << core::formatNumber(p.shrinkBothPct, 3)
      << "%), fit p = " << core::formatNumber(p.fitPValue, 2) << "\n";
}

void printRanking(std::ostream& out, const gap::Diagnosis& d) {
  out << "\nRanking (likelihood-ratio threshold " << core::formatNumber(d.threshold, 3) << ", bootstrap "
      << d.bootstrapSamples << ")\n";
  out << "  #  effect               location         size +/- SE                          LR        shrink%\n";
  char buf[512];
  for (std::size_t i = 0; i < d.ranking.size(); ++i) {
    const auto& e = d.ranking[i];
    std::string sizes;
    for (std::size_t p = 0; p < e.candidate.parameters.size() && p < e.parameters.size(); ++p) {
      const auto& def = e.candidate.parameters[p];
      sizes += (sizes.empty() ? "" : ", ") + def.name + " " + core::formatNumber(e.parameters[p], 3);
      if (p < e.stdErrors.size()) sizes += " +/- " + core::formatNumber(e.stdErrors[p], 2);
      if (!def.unit.empty()) sizes += " " + def.unit;
    }
    if (!e.fitted) sizes = e.identifiable ? "(fit failed)" : "(not identifiable)";
    const bool reported = !(e.gapAfter.entries.empty() && e.gapAfter.overall == 0.0);
    std::snprintf(buf, sizeof buf, "  %-2zu %-20s %-16s %-36s %-9s %s\n", i + 1, e.candidate.effect.c_str(),
                  locationText(e.candidate).c_str(), sizes.c_str(), core::formatNumber(e.likelihoodRatio, 3).c_str(),
                  reported ? core::formatNumber(e.shrinkPct, 3).c_str() : "-");
    out << buf;
  }
  // A row may stand for a family of candidates that change the data alike
  // (core/gap/engine/families.h): fitted once, named here.
  for (std::size_t i = 0; i < d.ranking.size(); ++i) {
    const auto& c = d.ranking[i].candidate;
    if (c.equivalent.empty()) continue;
    std::string others;
    for (const auto& l : c.equivalent) {
      std::string at;
      for (const auto& part : l) at += (at.empty() ? "" : "-") + part;
      others += (others.empty() ? "" : ", ") + at;
    }
    out << "  " << i + 1 << ": " << gap::familyLabel(c) << ", equivalent at " << others << "\n";
  }
}

// The option table (docs/cli/gap.md).
const OptionSpec kSpec{
    {"--model", "--measured", "--bands", "--effects", "--noise", "--pairs"},
    {"--json"},
    {{"--band", "analysis band in Hz, LO < HI", {{"LO", closed(0, 1e6, "Hz")}, {"HI", aboveTo(0, 1e6, "Hz")}}, ':'},
     {"--bootstrap", wholeNumber(0, 100000), "bootstrap samples"},
     {"--seed", wholeNumber(0, 2147483647), "random seed"},
     {"--multistarts", wholeNumber(1, 100), "fit start points per effect"},
     {"--noise-floor", NumberRange(0, 1, true, true), "relative noise floor sigma"},
     {"--averages", wholeNumber(1, 100000), "averages behind the measured FRFs"}}};

int gapCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  auto parsed = ParsedArgs::parse(args, kSpec);
  if (!parsed) {
    if (exitCodeFor(parsed.error()) == kExitUsage) return usage(err, parsed.error().message);
    return fail(err, parsed.error());
  }
  if (!parsed->positional().empty()) return usage(err, "unexpected argument '" + parsed->positional()[0] + "'");
  const auto model = parsed->value("--model"), measured = parsed->value("--measured");
  if (!model || !measured) return usage(err, "--model and --measured are required");

  gap::LoadOptions load;
  if (parsed->value("--band")) {
    const auto band = parsed->numbers("--band");
    if (!(band.at(1) > band.at(0))) {
      err << "mozzi-cli gap: option --band needs LO < HI (got '" << *parsed->value("--band") << "')\n";
      return kExitFailure;
    }
    load.bandLowHz = band[0];
    load.bandHighHz = band[1];
  }
  if (auto bands = parsed->value("--bands")) {
    for (const auto& b : splitComma(*bands)) {
      double lo = 0, hi = 0;
      if (!parseRange(b, lo, hi) || hi > 1e6) {
        err << "mozzi-cli gap: option --bands must be LO:HI,LO:HI,... in Hz with 0 <= LO < HI <= 1e6 (got '"
            << b.substr(0, 40) << "')\n";
        return kExitFailure;
      }
      load.reportBands.emplace_back(lo, hi);
    }
  }
  gap::DiagnosisOptions options;
  int seed = 1;
  // Range-checked by parse().
  auto integer = [&](const char* name, int& value) {
    if (auto n = parsed->number(name); n && n->has_value()) value = static_cast<int>(**n);
  };
  integer("--bootstrap", options.bootstrapSamples);
  integer("--seed", seed);
  integer("--multistarts", options.multistarts);
  integer("--averages", load.averages);
  options.seed = static_cast<unsigned long long>(seed);
  if (auto nf = parsed->number("--noise-floor"); nf && nf->has_value()) {
    load.relativeFloor = **nf;
    load.noise = "stated";  // a stated relative sigma replaces the estimate
  }
  if (auto noise = parsed->value("--noise")) {
    if (*noise != "auto" && *noise != "estimated" && *noise != "coherence" && *noise != "stated") {
      return usage(err, "--noise must be auto, estimated, coherence or stated (got '" + *noise + "')");
    }
    load.noise = *noise;
  }
  if (auto pairs = parsed->value("--pairs")) {
    if (*pairs == "auto") {
      options.pairs = gap::DiagnosisOptions::PairMode::Auto;
    } else if (*pairs == "always") {
      options.pairs = gap::DiagnosisOptions::PairMode::Always;
    } else if (*pairs == "never") {
      options.pairs = gap::DiagnosisOptions::PairMode::Never;
    } else {
      return usage(err, "--pairs must be auto, always or never (got '" + *pairs + "')");
    }
  }

  auto problem = gap::loadGapProblem(*model, *measured, load);
  if (!problem) return fail(err, problem.error());
  if (auto effects = parsed->value("--effects")) {
    std::set<std::string> known;
    for (const auto& c : (*problem)->candidates()) known.insert(c.effect);
    for (const auto& e : splitComma(*effects)) {
      if (known.count(e) == 0) {
        std::string list;
        for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
        return usage(err, "unknown effect '" + e + "' for this model and test (available: " + list + ")");
      }
      options.effects.push_back(e);
    }
  }
  auto diagnosis = gap::diagnose(**problem, options);
  if (!diagnosis) return fail(err, diagnosis.error());

  if (parsed->flag("--json")) {
    out << gap::diagnosisToJson(*diagnosis).dump(2) << "\n";
    return kExitOk;
  }
  printMetrics(out, diagnosis->gapBefore);
  printNoise(out, diagnosis->noise);
  printRanking(out, *diagnosis);
  printPair(out, *diagnosis);
  out << "\nVerdict: " << gap::verdictName(diagnosis->verdict);
  // The effect(s) the verdict puts forward: one rule for the CLI, the
  // workbench and the report (core/report/gap_report.h).
  const auto best = core::report::bestEffect(*diagnosis);
  if (best.pair) {
    const auto& p = *best.pair;
    out << " - " << gap::familyLabel(p.effects[0].candidate) << " and " << gap::familyLabel(p.effects[1].candidate)
        << ", gap " << core::formatNumber(diagnosis->gapBefore.overall, 3) << " -> "
        << core::formatNumber(p.gapAfterOne.overall, 3) << " -> " << core::formatNumber(p.gapAfterBoth.overall, 3)
        << " (shrink " << core::formatNumber(p.shrinkBothPct, 3) << "%)";
  } else if (best.single && best.inVerdict) {
    out << " - " << gap::familyLabel(best.single->candidate) << ", gap "
        << core::formatNumber(diagnosis->gapBefore.overall, 3) << " -> "
        << core::formatNumber(best.single->gapAfter.overall, 3) << " (shrink "
        << core::formatNumber(best.single->shrinkPct, 3) << "%)";
  }
  out << "\n" << diagnosis->explanation << "\n";
  return kExitOk;
}

const CommandRegistrar kRegistrar(
    {"gap", kSynopsis, "Sim-to-real gap: where model and test disagree, which effect explains it, the shrink",
     gapCommand, &kSpec});

}  // namespace
}  // namespace mozzi::cli
