// mozzi-cli wheelchair: the five-DOF wheelchair model of thesis §7.2 in
// steady turning and slalom, and the stiffness studies of §7.3/§7.4.
// Options and output: docs/cli/tire.md.
#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <utility>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "app/cli/output.h"
#include "core/io/output_file.h"
#include "core/io/project_store.h"
#include "core/stability/stability_record.h"
#include "core/stability/wheelchair_model.h"
#include "core/stability/wheelchair_record.h"

namespace mozzi::cli {
namespace {

namespace st = core::stability;
using Json = nlohmann::json;
constexpr double kDeg = 3.14159265358979323846 / 180.0;

const char* kUsage =
    "Usage: mozzi-cli wheelchair steady [--speed M/S] [--torque NM | --yaw-rate RAD/S] [chair options] [--json]\n"
    "       mozzi-cli wheelchair slalom [--speed M/S] [--torque NM] [--frequency HZ] [--duration S]\n"
    "                                   [--out HISTORY.csv] [chair options] [--json]\n"
    "                                   [--project P.mozzi [--store NAME] [--specimen NAME]]\n"
    "       mozzi-cli wheelchair sensitivity --stiffness cornering|aligning|tyre [--speed] [--torque]\n"
    "                                   [--slalom-torque NM] [--frequency HZ] [--duration S] [--json]\n"
    "chair options: --mass KG --yaw-inertia KGM2 --rear-axle-behind M --caster-ahead M --half-track M\n"
    "               --cornering-stiffness N/RAD --aligning-stiffness NM/RAD (per rear tyre)\n";

int usage(std::ostream& err, const std::string& msg) {
  err << "mozzi-cli wheelchair: " << msg << "\n" << kUsage;
  return kExitUsage;
}

// The option table: ranges a wheelchair can have (thesis ch. 7 values are
// well inside); the frequency bound is the model's (kMaxSlalomFrequencyHz).
const OptionSpec kSpec{{"--out", "--stiffness", "--project", "--store", "--specimen"},
                       {"--json"},
                       {{"--speed", aboveTo(0, 10, "m/s"), "forward speed"},
                        {"--torque", closed(-1000, 1000, "N m"), "differential torque T_R - T_L (slalom amplitude)"},
                        {"--yaw-rate", closed(-20, 20, "rad/s"), "prescribed yaw rate"},
                        {"--frequency", aboveTo(0, st::kMaxSlalomFrequencyHz, "Hz"), "slalom frequency"},
                        {"--duration", aboveTo(0, 3600, "s"), "simulated time"},
                        {"--slalom-torque", closed(-1000, 1000, "N m"), "slalom torque amplitude (sensitivity)"},
                        {"--mass", aboveTo(0, 1000, "kg"), "mass of chair and user"},
                        {"--yaw-inertia", aboveTo(0, 1000, "kg m^2"), "yaw inertia"},
                        {"--rear-axle-behind", closed(0, 2, "m"), "rear axle behind the centre of mass"},
                        {"--caster-ahead", closed(0, 2, "m"), "casters ahead of the centre of mass"},
                        {"--half-track", aboveTo(0, 2, "m"), "rear half-track"},
                        {"--cornering-stiffness", aboveTo(0, 1e6, "N/rad"), "rear tyre cornering stiffness"},
                        {"--aligning-stiffness", closed(0, 1e5, "N m/rad"), "rear tyre aligning stiffness"}},
                       {"--out"}};

Json steadyJson(const st::SteadyTurn& s) {
  return {{"u_m_s", s.u},
          {"v_m_s", s.v},
          {"yaw_rate_rad_s", s.r},
          {"radius_m", s.radius},
          {"slip_right_rad", s.slipRight},
          {"slip_left_rad", s.slipLeft},
          {"caster_right_rad", s.deltaRight},
          {"caster_left_rad", s.deltaLeft},
          {"common_torque_nm", s.commonTorque},
          {"differential_torque_nm", s.differentialTorque}};
}

Json slalomJson(const st::SlalomSummary& s) {
  return {{"lateral_amplitude_m", s.lateralAmplitude},
          {"slip_amplitude_right_rad", s.slipAmplitudeRight},
          {"slip_amplitude_left_rad", s.slipAmplitudeLeft},
          {"slip_mean_right_rad", s.slipMeanRight},
          {"slip_mean_left_rad", s.slipMeanLeft}};
}

// Keeps the slalom as an analysis of kind "wheelchair" (wheelchair_record.h).
core::Result<std::pair<std::int64_t, std::string>> storeSlalom(const std::string& path, const std::string& name,
                                                               const std::optional<std::string>& specimen,
                                                               const st::WheelchairRecord& record) {
  auto store = core::io::ProjectStore::open(path);
  if (!store) return store.error();
  auto id = specimen ? st::specimenNamed(*store, *specimen) : st::defaultWheelchairSpecimen(*store);
  if (!id) return id.error();
  auto row = st::wheelchairAnalysis(*store, *id, name, record);
  if (!row) return row.error();
  auto added = store->addAnalysis(*row);
  if (!added) return added.error();
  return std::make_pair(*added, row->name);
}

int wheelchairCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto a = ParsedArgs::parse(args, kSpec);
  if (!a) {
    if (exitCodeFor(a.error()) == kExitUsage) return usage(err, a.error().describe());
    err << "mozzi-cli wheelchair: " << a.error().describe() << "\n";
    return kExitFailure;
  }
  if (a->positional().size() != 1) return usage(err, "expected one subcommand");
  st::WheelchairParameters p;
  double speed = 4.0 / 3.6, torque = 6.0, frequency = 0.25, duration = 20.0, slalomTorque = 10.0;
  const std::vector<std::pair<const char*, double*>> numbers = {{"--speed", &speed},
                                                                {"--torque", &torque},
                                                                {"--frequency", &frequency},
                                                                {"--duration", &duration},
                                                                {"--slalom-torque", &slalomTorque},
                                                                {"--mass", &p.mass},
                                                                {"--yaw-inertia", &p.yawInertia},
                                                                {"--rear-axle-behind", &p.rearAxleBehindCoM},
                                                                {"--caster-ahead", &p.casterAheadOfCoM},
                                                                {"--half-track", &p.rearHalfTrack},
                                                                {"--cornering-stiffness", &p.rearCorneringStiffness},
                                                                {"--aligning-stiffness", &p.rearAligningStiffness}};
  for (const auto& [name, target] : numbers) {
    if (auto v = a->number(name); v && *v) *target = **v;  // range-checked by parse()
  }
  if (a->value("--out") && a->positional()[0] != "slalom") return usage(err, "--out is for the slalom");
  if (a->value("--project") && a->positional()[0] != "slalom") return usage(err, "--project is for the slalom");
  if (!a->value("--project") && (a->value("--store") || a->value("--specimen")))
    return usage(err, "--store and --specimen need --project P.mozzi");
  if (int rc = refuseOutputsOntoInputs(*a, kSpec, {}, "wheelchair", err); rc != kExitOk) return rc;
  const std::string& sub = a->positional()[0];
  const bool json = a->flag("--json");
  if (sub == "steady") {
    // --yaw-rate prescribes the path (u, r) and returns the torque it needs.
    auto yawRate = a->number("--yaw-rate");
    if (*yawRate && a->value("--torque")) return usage(err, "give --torque or --yaw-rate, not both");
    auto s = *yawRate ? st::steadyTurnAtYawRate(p, speed, **yawRate) : st::steadyTurn(p, speed, torque);
    if (!s) {
      err << "mozzi-cli wheelchair steady: " << s.error().describe() << "\n";
      return kExitFailure;
    }
    if (json) {
      out << steadyJson(*s).dump(2) << "\n";
    } else {
      char line[240];
      std::snprintf(line, sizeof line,
                    "steady turn at u = %.3f m/s, T_R - T_L = %.2f Nm: radius %.3f m, yaw rate %.4f rad/s\n"
                    "  rear slip angles: right %.4f deg, left %.4f deg; caster angles: right %.2f deg, left %.2f deg\n",
                    s->u, s->differentialTorque, s->radius, s->r, s->slipRight / kDeg, s->slipLeft / kDeg,
                    s->deltaRight / kDeg, s->deltaLeft / kDeg);
      out << line;
    }
    return kExitOk;
  }
  if (sub == "slalom") {
    if (!a->value("--torque")) torque = slalomTorque;  // slalom default 10 Nm
    auto run = st::runSlalom(p, speed, torque, frequency, duration);
    if (!run) {
      err << "mozzi-cli wheelchair slalom: " << run.error().describe() << "\n";
      return kExitFailure;
    }
    const auto* h = &run->history;
    const auto* s = &run->summary;
    if (auto file = a->value("--out")) {
      // Temporary file renamed into place after a checked flush, fsync and
      // close (core/io/output_file.h): a full disk fails the command.
      auto written = core::io::writeOutputFile(*file, [&](std::ostream& f) -> core::Result<void> {
        f << std::setprecision(12);
        f << "t_s,x_m,y_m,psi_rad,u_m_s,v_m_s,r_rad_s,caster_right_rad,caster_left_rad,slip_right_rad,"
             "slip_left_rad,torque_right_nm,torque_left_nm\n";
        for (const auto& x : *h)
          f << x.t << "," << x.x << "," << x.y << "," << x.psi << "," << x.u << "," << x.v << "," << x.r << ","
            << x.deltaRight << "," << x.deltaLeft << "," << x.slipRight << "," << x.slipLeft << "," << x.torqueRight
            << "," << x.torqueLeft << "\n";
        return {};
      });
      if (!written) {
        err << "mozzi-cli wheelchair slalom: " << written.error().describe() << "\n";
        return kExitFailure;
      }
    }
    std::optional<std::pair<std::int64_t, std::string>> stored;
    if (auto project = a->value("--project")) {
      st::WheelchairRecord record;
      record.study.manoeuvre = "slalom";
      record.study.speed = speed;
      record.study.torque = torque;
      record.study.frequency = frequency;
      record.study.duration = duration;
      record.study.chair = p;
      record.runs.push_back({1.0, *h});
      auto kept = storeSlalom(*project, a->value("--store").value_or("slalom"), a->value("--specimen"), record);
      if (!kept) {
        err << "mozzi-cli wheelchair slalom: " << kept.error().describe() << "\n";
        return kExitFailure;
      }
      stored = *kept;
    }
    if (json) {
      Json j = slalomJson(*s);
      if (stored) j["stored_analysis"] = {{"id", stored->first}, {"name", stored->second}};
      out << j.dump(2) << "\n";
    } else {
      char line[240];
      std::snprintf(line, sizeof line,
                    "slalom at u = %.3f m/s, T_R - T_L = %.2f cos(2 pi %.2f t) Nm: lateral amplitude %.3f m\n"
                    "  rear slip amplitude: right %.4f deg, left %.4f deg\n",
                    speed, torque, frequency, s->lateralAmplitude, s->slipAmplitudeRight / kDeg,
                    s->slipAmplitudeLeft / kDeg);
      out << line;
      if (stored)
        out << "stored in " << *a->value("--project") << " as analysis " << stored->first << " '" << stored->second
            << "'\n";
    }
    return kExitOk;
  }
  if (sub == "sensitivity") {
    const auto which = a->value("--stiffness");
    if (!which || (*which != "cornering" && *which != "aligning" && *which != "tyre"))
      return usage(err, "sensitivity needs --stiffness cornering|aligning|tyre");
    // cornering, aligning: the thesis's studies (§7.3, §7.4), one stiffness
    // scaled, the other held; tyre: both together (pneumatic trail held).
    const auto kind = *which == "cornering"  ? st::WheelchairStiffness::Cornering
                      : *which == "aligning" ? st::WheelchairStiffness::Aligning
                                             : st::WheelchairStiffness::Tyre;
    auto cases = st::stiffnessSensitivity(p, kind, {0.5, 1.0, 2.0}, speed, torque, slalomTorque, frequency, duration);
    if (!cases) {
      err << "mozzi-cli wheelchair sensitivity: " << cases.error().describe() << "\n";
      return kExitFailure;
    }
    Json j = Json::array();
    if (!json)
      out << *which << " stiffness x   radius [m]  slip R [deg]  slip L [deg]  slalom y [m]  slalom slip R [deg]\n";
    for (const auto& c : *cases) {
      j.push_back({{"factor", c.factor}, {"steady", steadyJson(c.steady)}, {"slalom", slalomJson(c.slalom)}});
      char line[200];
      std::snprintf(line, sizeof line, "  %4.1f           %8.3f     %8.4f      %8.4f      %8.4f      %8.4f\n", c.factor,
                    c.steady.radius, c.steady.slipRight / kDeg, c.steady.slipLeft / kDeg, c.slalom.lateralAmplitude,
                    c.slalom.slipAmplitudeRight / kDeg);
      if (!json) out << line;
    }
    if (json) out << j.dump(2) << "\n";
    return kExitOk;
  }
  return usage(err, "unknown subcommand '" + sub + "'");
}

const CommandRegistrar kRegistrar({"wheelchair",
                                   "steady|slalom|sensitivity [options] [--json]; slalom [--project P.mozzi "
                                   "[--store NAME] [--specimen NAME]]",
                                   "Wheelchair manoeuvres with measured tyre stiffnesses (thesis §7.2-§7.4)",
                                   wheelchairCommand, &kSpec});

}  // namespace
}  // namespace mozzi::cli
