// mozzi-cli fork lumped|bicycle: lumped 1-DOF fork models (thesis §4.2,
// Table 12) and bicycle-fork torsion/bending stiffness and damping (§6.4, §6.5).
#include <nlohmann/json.hpp>
#include <ostream>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "core/stiffness/fork_models.h"
#include "devices/rigtests/fork_model_inputs.h"

namespace mozzi::cli {
namespace {

namespace st = core::stiffness;

const char* kUsage =
    "Usage: mozzi-cli fork lumped --k NM_PER_RAD --l1 M --l2 M --wheel-centre M --mass KG --wheel-inertia KGM2\n"
    "                             --freq HZ --zeta RATIO [--json]\n"
    "       mozzi-cli fork bicycle --fork-mass KG --wheel-mass KG --wheel-radius M --hub-mass KG --hub-radius M\n"
    "                             --hub-length M --tip-distance M [--max-bend-arm M]\n"
    "                             --f-tors-wheel HZ --eta-tors-wheel ETA --f-tors-alone HZ [--f-tors-alone2 HZ]\n"
    "                             --f-bend-wheel HZ --eta-bend-wheel ETA --f-bend-alone HZ [--json]\n";

// The option table: a motorcycle or bicycle fork (thesis §4.2 Table 12,
// §6.4-§6.5 Tables 19-21 are well inside).
const OptionSpec kSpec{{},
                       {"--json"},
                       {{"--k", aboveTo(0, 1e9, "N m/rad"), "static bending stiffness"},
                        {"--l1", closed(-10, 10, "m"), "static axis arm L1"},
                        {"--l2", closed(-10, 10, "m"), "dynamic axis arm L2"},
                        {"--wheel-centre", closed(-10, 10, "m"), "wheel centre height h_c"},
                        {"--mass", aboveTo(0, 1000, "kg"), "vibrating mass M"},
                        {"--wheel-inertia", closed(0, 100, "kg m^2"), "wheel inertia"},
                        {"--freq", aboveTo(0, 1e4, "Hz"), "measured natural frequency"},
                        {"--zeta", closed(0, 1, ""), "viscous damping ratio"},
                        {"--fork-mass", aboveTo(0, 100, "kg"), "fork mass"},
                        {"--wheel-mass", aboveTo(0, 100, "kg"), "wheel mass"},
                        {"--wheel-radius", aboveTo(0, 2, "m"), "wheel radius"},
                        {"--hub-mass", aboveTo(0, 100, "kg"), "hub mass"},
                        {"--hub-radius", aboveTo(0, 1, "m"), "hub radius"},
                        {"--hub-length", aboveTo(0, 1, "m"), "hub length"},
                        {"--tip-distance", aboveTo(0, 5, "m"), "fork tip distance"},
                        {"--max-bend-arm", aboveTo(0, 5, "m"), "largest bend arm (fixing point)"},
                        {"--f-tors-wheel", aboveTo(0, 1e4, "Hz"), "torsion frequency with wheel"},
                        {"--eta-tors-wheel", closed(0, 2, ""), "torsion loss factor with wheel"},
                        {"--f-tors-alone", aboveTo(0, 1e4, "Hz"), "torsion frequency, fork alone"},
                        {"--f-tors-alone2", aboveTo(0, 1e4, "Hz"), "second torsion frequency, fork alone"},
                        {"--f-bend-wheel", aboveTo(0, 1e4, "Hz"), "bending frequency with wheel"},
                        {"--eta-bend-wheel", closed(0, 2, ""), "bending loss factor with wheel"},
                        {"--f-bend-alone", aboveTo(0, 1e4, "Hz"), "bending frequency, fork alone"}}};

int forkCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto parsed = ParsedArgs::parse(args, kSpec);
  if (!parsed && exitCodeFor(parsed.error()) == kExitFailure) {
    err << "mozzi-cli fork: " << parsed.error().describe() << "\n";
    return kExitFailure;
  }
  if (!parsed || parsed->positional().size() != 1) {
    err << "mozzi-cli fork: " << (parsed ? "expected 'lumped' or 'bicycle'" : parsed.error().describe()) << "\n"
        << kUsage;
    return kExitUsage;
  }
  bool usageError = false;
  auto get = [&](const char* name, double& v, bool required = true) {
    auto n = parsed->number(name);
    if (!n) {
      err << "mozzi-cli fork: " << n.error().describe() << "\n";
      usageError = true;
    } else if (*n) {
      v = **n;
    } else if (required) {
      err << "mozzi-cli fork: " << name << " is required\n";
      usageError = true;
    }
  };
  const std::string& sub = parsed->positional()[0];
  const bool json = parsed->flag("--json");
  if (sub == "lumped") {
    st::ForkLumpedInput in;
    get("--k", in.staticBendStiffness);
    get("--l1", in.staticAxisArm);
    get("--l2", in.dynamicAxisArm);
    get("--wheel-centre", in.wheelCentreHeight);
    get("--mass", in.vibratingMass);
    get("--wheel-inertia", in.wheelInertia);
    get("--freq", in.measuredFrequencyHz);
    get("--zeta", in.zeta);
    if (usageError) {
      err << kUsage;
      return kExitUsage;
    }
    auto r = st::forkLumpedModels(in);
    if (!r) {
      err << "mozzi-cli fork lumped: " << r.error().describe() << "\n";
      return kExitFailure;
    }
    if (json) {
      out << devices::rigtests::lumpedModelsJson(*r).dump(2) << "\n";
    } else {
      out << "model  k_Nm_per_rad  L_m  J_kgm2  pure_moment_kgm2  f_n_Hz  c_Nms_per_rad  zeta\n";
      int i = 1;
      for (const auto* m : {&r->model1, &r->model2, &r->model3}) {
        out << i++ << "  " << m->stiffness << "  " << m->arm << "  " << m->inertia << "  " << m->pureMoment << "  "
            << m->frequencyHz << "  " << m->damping << "  " << m->zeta << "\n";
      }
    }
    return kExitOk;
  }
  if (sub == "bicycle") {
    st::BicycleForkParameters p;
    double ftw = 0, etw = 0, fta = 0, fta2 = 0, fbw = 0, ebw = 0, fba = 0;
    get("--fork-mass", p.forkMass);
    get("--wheel-mass", p.wheelMass);
    get("--wheel-radius", p.wheelRadius);
    get("--hub-mass", p.hubMass);
    get("--hub-radius", p.hubRadius);
    get("--hub-length", p.hubLength);
    get("--tip-distance", p.tipDistance);
    get("--max-bend-arm", p.maxBendArm, false);
    get("--f-tors-wheel", ftw);
    get("--eta-tors-wheel", etw);
    get("--f-tors-alone", fta);
    get("--f-tors-alone2", fta2, false);
    get("--f-bend-wheel", fbw);
    get("--eta-bend-wheel", ebw);
    get("--f-bend-alone", fba);
    if (usageError) {
      err << kUsage;
      return kExitUsage;
    }
    auto t = st::bicycleForkTorsion(p, ftw, etw, fta, fta2);
    if (!t) {
      err << "mozzi-cli fork bicycle: " << t.error().describe() << "\n";
      return kExitFailure;
    }
    auto b = st::bicycleForkBending(p, fbw, ebw, fba);
    if (!b) {
      err << "mozzi-cli fork bicycle: " << b.error().describe() << "\n";
      return kExitFailure;
    }
    if (json) {
      out << nlohmann::json{{"torsion",
                             {{"inertia_with_wheel_kgm2", t->inertiaWithWheel},
                              {"inertia_alone_kgm2", t->inertiaAlone},
                              {"stiffness_with_wheel_Nm_per_rad", t->stiffnessWithWheel},
                              {"stiffness_alone_Nm_per_rad", t->stiffnessAlone},
                              {"damping_Nms_per_rad", t->damping}}},
                            {"bending",
                             {{"bend_arm_hW_m", b->bendArm},
                              {"stiffness_Nm_per_rad", b->stiffness},
                              {"inertia_with_wheel_kgm2", b->inertiaWithWheel},
                              {"damping_Nms_per_rad", b->damping}}}}
                 .dump(2)
          << "\n";
    } else {
      out << "torsion: k (with wheel) = " << t->stiffnessWithWheel << " Nm/rad, k (fork alone) = " << t->stiffnessAlone
          << " Nm/rad, c = " << t->damping << " Nms/rad\n"
          << "bending: h_W = " << b->bendArm << " m, k = " << b->stiffness << " Nm/rad, c = " << b->damping
          << " Nms/rad\n";
    }
    return kExitOk;
  }
  err << "mozzi-cli fork: unknown subcommand '" << sub << "'\n" << kUsage;
  return kExitUsage;
}

const CommandRegistrar kRegistrar({"fork", "lumped|bicycle --OPTION VALUE ... [--json]",
                                   "Lumped fork models (Table 12) and bicycle-fork stiffness and damping (§6.4, §6.5)",
                                   forkCommand, &kSpec});

}  // namespace
}  // namespace mozzi::cli
