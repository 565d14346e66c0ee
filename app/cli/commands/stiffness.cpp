// mozzi-cli stiffness decompose: bending and torsion stiffness from the twist
// stiffness and the axes (thesis §1.7 eq. 24, 27; fork variant §4 eq. 35, 36).
#include <nlohmann/json.hpp>
#include <ostream>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "core/stiffness/decomposition.h"

namespace mozzi::cli {
namespace {

namespace st = core::stiffness;
constexpr double kRad = 3.14159265358979323846 / 180.0;

const char* kUsage =
    "Usage: mozzi-cli stiffness decompose --k-twist NM_PER_RAD --a-twist M --a-bend M --a-tors M\n"
    "         (--fork --alpha-deg DEG | --beta-twist-deg DEG --beta-bend-deg DEG --beta-tors-deg DEG) [--json]\n";

// The option table: stiffness of a frame or fork (thesis Tables 1-11 are
// 1e3..1e6 Nm/rad), axis arms within a few metres of the reference, angles
// within a turn.
const OptionSpec kSpec{{},
                       {"--json", "--fork"},
                       {{"--k-twist", aboveTo(0, 1e12, "N m/rad"), "twist stiffness k_tw"},
                        {"--a-twist", closed(-100, 100, "m"), "twist axis arm a_tw"},
                        {"--a-bend", closed(-100, 100, "m"), "bending axis arm a_bend"},
                        {"--a-tors", closed(-100, 100, "m"), "torsion axis arm a_tors"},
                        {"--alpha-deg", closed(-360, 360, "deg"), "fork axis angle alpha"},
                        {"--beta-twist-deg", closed(-360, 360, "deg"), "twist axis inclination"},
                        {"--beta-bend-deg", closed(-360, 360, "deg"), "bending axis inclination"},
                        {"--beta-tors-deg", closed(-360, 360, "deg"), "torsion axis inclination"}}};

int stiffnessCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto parsed = ParsedArgs::parse(args, kSpec);
  if (!parsed && exitCodeFor(parsed.error()) == kExitFailure) {
    err << "mozzi-cli stiffness: " << parsed.error().describe() << "\n";
    return kExitFailure;
  }
  if (!parsed || parsed->positional().size() != 1 || parsed->positional()[0] != "decompose") {
    err << "mozzi-cli stiffness: " << (parsed ? "expected the subcommand 'decompose'" : parsed.error().describe())
        << "\n"
        << kUsage;
    return kExitUsage;
  }
  auto get = [&](const char* name, double& v) -> bool {
    auto n = parsed->number(name);
    if (!n || !*n) {
      err << "mozzi-cli stiffness decompose: " << (n ? std::string(name) + " is required" : n.error().describe())
          << "\n"
          << kUsage;
      return false;
    }
    v = **n;
    return true;
  };
  double kTw = 0, aTw = 0, aB = 0, aT = 0;
  if (!get("--k-twist", kTw) || !get("--a-twist", aTw) || !get("--a-bend", aB) || !get("--a-tors", aT)) {
    return kExitUsage;
  }
  core::Result<st::Decomposition> r = core::Error{};
  if (parsed->flag("--fork")) {
    double alpha = 0;
    if (!get("--alpha-deg", alpha)) return kExitUsage;
    r = st::decomposeForkStiffness({kTw, aTw, aB, aT, alpha * kRad});
  } else {
    double b = 0, bb = 0, bt = 0;
    if (!get("--beta-twist-deg", b) || !get("--beta-bend-deg", bb) || !get("--beta-tors-deg", bt)) return kExitUsage;
    r = st::decomposeStiffness(st::DecompositionInput{kTw, aTw, b * kRad, aB, bb * kRad, aT, bt * kRad});
  }
  if (!r) {
    err << "mozzi-cli stiffness decompose: " << r.error().describe() << "\n";
    return kExitFailure;
  }
  if (parsed->flag("--json")) {
    out << nlohmann::json{{"bending_stiffness_Nm_per_rad", r->bendStiffness},
                          {"torsion_stiffness_Nm_per_rad", r->torsStiffness},
                          {"eq24_residual", r->balanceResidual},
                          {"rotation_residual", r->rotationResidual},
                          {"low_confidence", r->lowConfidence},
                          {"note", r->note}}
               .dump(2)
        << "\n";
  } else {
    out << "bending stiffness k_bend = " << r->bendStiffness << " Nm/rad\n"
        << "torsion stiffness k_tors = " << r->torsStiffness << " Nm/rad\n"
        << "rotation-magnitude residual (eq. 25/26) " << r->rotationResidual << "\n";
    if (r->lowConfidence) out << "LOW CONFIDENCE: " << r->note << "\n";
  }
  return kExitOk;
}

const CommandRegistrar kRegistrar({"stiffness", "decompose --k-twist K --a-twist A --a-bend A --a-tors A ... [--json]",
                                   "Decompose the twist stiffness into bending and torsion (eq. 24, 27, 35, 36)",
                                   stiffnessCommand, &kSpec});

}  // namespace
}  // namespace mozzi::cli
