// mozzi-cli twist static|dynamic|modal FILE.csv and mozzi-cli mozzi FILE.csv:
// twist and Mozzi axes from plate measurements (thesis §1.2 to §1.5).
// Input formats are documented in docs/cli/stiffness.md.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "core/common/dof.h"
#include "core/io/csv/csv_exchange.h"
#include "core/stiffness/dynamic_twist.h"
#include "core/stiffness/plate_csv.h"
#include "core/stiffness/plate_motion.h"
#include "core/stiffness/screw_axis.h"

namespace mozzi::cli {
namespace {

namespace st = core::stiffness;
using core::Vector2;
constexpr double kDeg = 180.0 / 3.14159265358979323846;

using st::readPlateCsv;  // the plate CSV reader the Twist Axes page shares (core/stiffness/plate_csv.h)

nlohmann::json axisJson(const st::PlateAxis& a) {
  return {{"point_m", {a.point(0), a.point(1)}}, {"direction", {a.direction(0), a.direction(1)}},
          {"beta_deg", a.beta * kDeg},           {"beta_sigma_deg", a.betaSigma * kDeg},
          {"offset_sigma_m", a.offsetSigma},     {"rotation", a.rotation},
          {"rotation_sigma", a.rotationSigma}};
}

void printAxis(std::ostream& out, const st::PlateAxis& a) {
  out << "  axis: point (" << a.point(0) << ", " << a.point(1) << ") m, beta " << a.beta * kDeg << " +- "
      << a.betaSigma * kDeg << " deg, offset sigma " << a.offsetSigma * 1e3 << " mm, rotation " << a.rotation << "\n";
}

int fail(std::ostream& err, const std::string& cmd, const core::Error& e) {
  err << "mozzi-cli " << cmd << ": " << e.describe() << "\n";
  return kExitFailure;
}

int twistStatic(const ParsedArgs& args, const std::string& file, std::ostream& out, std::ostream& err) {
  auto csv = readPlateCsv(file, true);
  if (!csv) return fail(err, "twist static", csv.error());
  auto r = st::staticTwistFromCsv(*csv);
  if (!r) return fail(err, "twist static", r.error());
  const st::StaticTwistResult& res = *r;
  nlohmann::json j;
  if (args.flag("--json")) {
    j = {{"axis", axisJson(res.axis.axis)},
         {"lateral_stiffness_N_per_m", res.lateralStiffness},
         {"lateral_stiffness_se", res.lateralStiffnessSe},
         {"r_squared", res.loadPoint.rSquared},
         {"twist_arm_m", res.twistArm},
         {"twist_arm_sigma_m", res.twistArmSigma},
         {"twist_stiffness_Nm_per_rad", res.twistStiffness},
         {"twist_stiffness_sigma", res.twistStiffnessSigma},
         {"linear", res.linear},
         {"low_confidence", res.lowConfidence},
         {"note", res.note}};
    out << j.dump(2) << "\n";
  } else {
    out << "static twist axis (" << csv->sensors.size() << " lasers, " << csv->rows.size() << " load samples)\n";
    printAxis(out, res.axis.axis);
    out << "  lateral stiffness k_lat = " << res.lateralStiffness << " +- " << res.lateralStiffnessSe << " N/m";
    if (csv->rows.size() > 1) out << " (R^2 " << res.loadPoint.rSquared << ")";
    out << "\n  twist arm a_tw = " << res.twistArm << " +- " << res.twistArmSigma << " m\n";
    out << "  twist stiffness k_tw = " << res.twistStiffness << " +- " << res.twistStiffnessSigma << " Nm/rad\n";
    if (res.lowConfidence) out << "  LOW CONFIDENCE: " << res.note << "\n";
  }
  return kExitOk;
}

int twistDynamic(const ParsedArgs& args, const std::string& file, std::ostream& out, std::ostream& err) {
  auto csv = readPlateCsv(file, true);
  if (!csv) return fail(err, "twist dynamic", csv.error());
  auto sweep = st::sweepFromCsv(*csv);
  if (!sweep) return fail(err, "twist dynamic", sweep.error());
  auto res = st::dynamicTwistSweep(csv->sensors, *sweep, csv->load);
  if (!res) return fail(err, "twist dynamic", res.error());
  nlohmann::json arr = nlohmann::json::array();
  if (!args.flag("--json"))
    out << "freq_Hz  method  beta_deg  beta_sigma_deg  point_u_m  point_v_m  k_lat_N_per_m  k_tw_Nm_per_rad  note\n";
  for (const auto& s : *res) {
    if (!s.axis) {
      if (args.flag("--json")) {
        arr.push_back({{"frequency_Hz", s.frequencyHz}, {"error", s.axis.error().describe()}});
      } else {
        out << s.frequencyHz << "  error: " << s.axis.error().describe() << "\n";
      }
      continue;
    }
    const auto& a = s.axis->axis.axis;
    if (args.flag("--json")) {
      arr.push_back({{"frequency_Hz", s.frequencyHz},
                     {"method", st::phasorAxisCaseName(s.axis->method)},
                     {"axis", axisJson(a)},
                     {"dynamic_lateral_stiffness_N_per_m", s.dynamicLateralStiffness},
                     {"dynamic_twist_stiffness_Nm_per_rad", s.dynamicTwistStiffness},
                     {"low_confidence", s.axis->lowConfidence},
                     {"note", s.axis->note}});
    } else {
      out << s.frequencyHz << "  " << st::phasorAxisCaseName(s.axis->method) << "  " << a.beta * kDeg << "  "
          << a.betaSigma * kDeg << "  " << a.point(0) << "  " << a.point(1) << "  " << s.dynamicLateralStiffness << "  "
          << s.dynamicTwistStiffness << "  " << s.axis->note << "\n";
    }
  }
  if (args.flag("--json")) out << arr.dump(2) << "\n";
  return kExitOk;
}

int printModal(const ParsedArgs& args, const st::ModalAxis& modal, std::ostream& out) {
  const st::ModalAxis* r = &modal;
  if (args.flag("--json")) {
    nlohmann::json rec = nlohmann::json::array();
    for (Eigen::Index i = 0; i < r->receptance.size(); ++i) {
      rec.push_back(
          {{"magnitude_m_per_N", std::abs(r->receptance(i))}, {"phase_deg", std::arg(r->receptance(i)) * kDeg}});
    }
    out << nlohmann::json{{"frequency_Hz", r->frequencyHz},
                          {"method", st::phasorAxisCaseName(r->axis.method)},
                          {"max_phase_deviation_deg", r->axis.maxPhaseDeviation * kDeg},
                          {"axis", axisJson(r->axis.axis.axis)},
                          {"receptance", rec},
                          {"low_confidence", r->axis.lowConfidence},
                          {"note", r->axis.note}}
               .dump(2)
        << "\n";
  } else {
    out << "modal twist axis at " << r->frequencyHz << " Hz: " << st::phasorAxisCaseName(r->axis.method)
        << " case (phases within " << r->axis.maxPhaseDeviation * kDeg << " deg of 0/180)\n";
    printAxis(out, r->axis.axis.axis);
    if (r->axis.lowConfidence) out << "  LOW CONFIDENCE: " << r->axis.note << "\n";
  }
  return kExitOk;
}

int twistModal(const ParsedArgs& args, const std::string& file, std::ostream& out, std::ostream& err) {
  auto freq = args.number("--freq");
  if (!freq) return fail(err, "twist modal", freq.error());
  if (!*freq) {
    err << "mozzi-cli twist modal: --freq HZ is required\n";
    return kExitUsage;
  }
  const auto frfFile = args.value("--frf");
  auto csv = readPlateCsv(file, true, !frfFile);
  if (!csv) return fail(err, "twist modal", csv.error());
  const std::size_t ns = csv->sensors.size();
  if (frfFile) {
    // FRFs in the shared CSV exchange format (core/io/csv); the sensors of FILE
    // are matched to --responses DOFs in order, or to the first responses.
    auto frf = core::io::csv::importFrfCsv(*frfFile);
    if (!frf) return fail(err, "twist modal", frf.error());
    std::vector<int> cols;
    if (const auto list = args.value("--responses")) {
      std::istringstream s(*list);
      std::string item;
      while (std::getline(s, item, ',')) {
        auto dof = core::parseDof(item);
        if (!dof) return fail(err, "twist modal", dof.error());
        const auto it = std::find(frf->responses.begin(), frf->responses.end(), *dof);
        if (it == frf->responses.end()) {
          return fail(
              err, "twist modal",
              core::makeError(core::ErrorCode::NotFound, "response " + item + " is not in the FRF file", *frfFile));
        }
        cols.push_back(static_cast<int>(it - frf->responses.begin()));
      }
    } else {
      for (std::size_t i = 0; i < ns && i < frf->responses.size(); ++i) cols.push_back(static_cast<int>(i));
    }
    st::PhasorAxisOptions o;
    if (auto tol = args.number("--phase-tol-deg"); !tol) {
      return fail(err, "twist modal", tol.error());
    } else if (*tol) {
      o.phaseTolerance = **tol / kDeg;
    }
    auto r = st::modalTwistAxis(*frf, cols, 0, **freq, csv->sensors, csv->hasLoad ? csv->load : Vector2::Zero(), o);
    if (!r) return fail(err, "twist modal", r.error());
    return printModal(args, *r, out);
  }
  core::FrfType frfType = core::FrfType::Accelerance;
  const std::string type = args.value("--type").value_or("accelerance");
  if (type == "accelerance") {
    frfType = core::FrfType::Accelerance;
  } else if (type == "mobility") {
    frfType = core::FrfType::Mobility;
  } else if (type == "receptance") {
    frfType = core::FrfType::Receptance;
  } else {
    err << "mozzi-cli twist modal: --type must be accelerance, mobility or receptance\n";
    return kExitUsage;
  }
  auto frf = st::modalFrfFromCsv(*csv, frfType);
  if (!frf) return fail(err, "twist modal", frf.error());
  std::vector<int> cols;
  for (std::size_t i = 0; i < ns; ++i) cols.push_back(static_cast<int>(i));
  st::PhasorAxisOptions o;
  if (auto tol = args.number("--phase-tol-deg"); !tol) {
    return fail(err, "twist modal", tol.error());
  } else if (*tol) {
    o.phaseTolerance = **tol / kDeg;
  }
  auto r = st::modalTwistAxis(*frf, cols, 0, **freq, csv->sensors, csv->hasLoad ? csv->load : Vector2::Zero(), o);
  if (!r) return fail(err, "twist modal", r.error());
  return printModal(args, *r, out);
}

const char* kTwistUsage =
    "Usage: mozzi-cli twist static|dynamic|modal FILE.csv [--freq HZ] [--type accelerance|mobility|receptance] "
    "[--frf FRF.csv [--responses DOF,DOF,DOF]] [--phase-tol-deg D] [--json]\n";

// The option tables (docs/cli/stiffness.md).
const OptionSpec kTwistSpec{{"--type", "--frf", "--responses"},
                            {"--json"},
                            {{"--freq", aboveTo(0, 1e5, "Hz"), "frequency of the mode"},
                             {"--phase-tol-deg", aboveTo(0, 90, "deg"), "phase tolerance about 0/180"}}};
const OptionSpec kMozziSpec{{}, {"--json", "--planar"}, {{"--sigma", aboveTo(0, 1, "m"), "measurement sigma floor"}}};

int twistCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto parsed = ParsedArgs::parse(args, kTwistSpec);
  if (!parsed && exitCodeFor(parsed.error()) == kExitFailure) return fail(err, "twist", parsed.error());
  if (!parsed || parsed->positional().size() != 2) {
    err << "mozzi-cli twist: " << (parsed ? "expected a mode and a file" : parsed.error().describe()) << "\n"
        << kTwistUsage;
    return kExitUsage;
  }
  const std::string& mode = parsed->positional()[0];
  const std::string& file = parsed->positional()[1];
  if (mode == "static") return twistStatic(*parsed, file, out, err);
  if (mode == "dynamic") return twistDynamic(*parsed, file, out, err);
  if (mode == "modal") return twistModal(*parsed, file, out, err);
  err << "mozzi-cli twist: unknown mode '" << mode << "'\n" << kTwistUsage;
  return kExitUsage;
}

// mozzi FILE.csv: rows x,y,z,dx,dy,dz (3-D screw axis) or, with --planar,
// sensor rows plus one data row of lateral displacements (eq. 16).
int mozziCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto parsed = ParsedArgs::parse(args, kMozziSpec);
  const char* usage = "Usage: mozzi-cli mozzi FILE.csv [--planar] [--sigma M] [--json]\n";
  if (!parsed && exitCodeFor(parsed.error()) == kExitFailure) return fail(err, "mozzi", parsed.error());
  if (!parsed || parsed->positional().size() != 1) {
    err << "mozzi-cli mozzi: " << (parsed ? "expected one file" : parsed.error().describe()) << "\n" << usage;
    return kExitUsage;
  }
  const std::string& file = parsed->positional()[0];
  auto sigma = parsed->number("--sigma");
  if (!sigma) return fail(err, "mozzi", sigma.error());
  if (parsed->flag("--planar")) {
    auto csv = readPlateCsv(file, true);
    if (!csv) return fail(err, "mozzi", csv.error());
    if (csv->rows.size() != 1 || csv->rows[0].size() != csv->sensors.size()) {
      return fail(
          err, "mozzi",
          core::makeError(core::ErrorCode::ParseError, "--planar needs one row of lateral displacements", file));
    }
    st::PlaneFitOptions o;
    if (*sigma) o.sigmaFloor = **sigma;
    auto r = st::planarMozziAxis(csv->sensors, csv->rows[0], csv->hasLoad ? csv->load : Vector2::Zero(), o);
    if (!r) return fail(err, "mozzi", r.error());
    if (parsed->flag("--json")) {
      out << nlohmann::json{{"dx_Q_m", r->dxQ},
                            {"dtheta_y_rad", r->dThetaY},
                            {"dtheta_z_rad", r->dThetaZ},
                            {"axis", axisJson(r->twist.axis)},
                            {"low_confidence", r->twist.lowConfidence},
                            {"note", r->twist.note}}
                 .dump(2)
          << "\n";
    } else {
      out << "planar Mozzi axis (eq. 13, 16): dx_Q = " << r->dxQ << " m, dtheta_y = " << r->dThetaY
          << " rad, dtheta_z = " << r->dThetaZ << " rad\n";
      printAxis(out, r->twist.axis);
      if (r->twist.lowConfidence) out << "  LOW CONFIDENCE: " << r->twist.note << "\n";
    }
    return kExitOk;
  }
  auto csv = readPlateCsv(file, false);
  if (!csv) return fail(err, "mozzi", csv.error());
  if (csv->rows.front().size() != 6) {
    return fail(err, "mozzi", core::makeError(core::ErrorCode::ParseError, "rows need x,y,z,dx,dy,dz", file));
  }
  const auto n = static_cast<Eigen::Index>(csv->rows.size());
  core::Matrix p(n, 3), d(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      p(i, c) = csv->rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)];
      d(i, c) = csv->rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(c + 3)];
    }
  }
  st::ScrewAxisOptions o;
  if (*sigma) o.sigmaFloor = **sigma;
  auto r = st::screwAxis(p, d, o);
  if (!r) return fail(err, "mozzi", r.error());
  if (parsed->flag("--json")) {
    out << nlohmann::json{{"direction", {r->direction(0), r->direction(1), r->direction(2)}},
                          {"point_m", {r->point(0), r->point(1), r->point(2)}},
                          {"pitch_m_per_rad", r->pitch},
                          {"angle_rad", r->angle},
                          {"direction_sigma_rad", r->directionSigma},
                          {"point_sigma_m", r->pointSigma},
                          {"pitch_sigma", r->pitchSigma},
                          {"condition_number", r->conditionNumber},
                          {"low_confidence", r->lowConfidence},
                          {"note", r->note}}
               .dump(2)
        << "\n";
  } else {
    out << "Mozzi (screw) axis from " << n << " points\n  direction (" << r->direction.transpose() << ") +- "
        << r->directionSigma << " rad\n  point nearest origin (" << r->point.transpose() << ") m +- " << r->pointSigma
        << "\n  pitch " << r->pitch << " +- " << r->pitchSigma << " m/rad, rotation " << r->angle << " rad, condition "
        << r->conditionNumber << "\n";
    if (r->lowConfidence) out << "  LOW CONFIDENCE: " << r->note << "\n";
  }
  return kExitOk;
}

const CommandRegistrar kTwist({"twist", "static|dynamic|modal FILE.csv [--freq HZ] [--json]",
                               "Static, dynamic (actuator sweep) or modal twist axis of the reference plate",
                               twistCommand, &kTwistSpec});
const CommandRegistrar kMozzi({"mozzi", "FILE.csv [--planar] [--sigma M] [--json]",
                               "Mozzi (instantaneous screw) axis from point displacements", mozziCommand, &kMozziSpec});

}  // namespace
}  // namespace mozzi::cli
