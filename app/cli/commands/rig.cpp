// mozzi-cli rig: the acquisition drivers, the devices they find, and what a
// device can do (capabilities and parameter specs, as the GUI forms see them).
#include <cmath>
#include <nlohmann/json.hpp>
#include <ostream>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "core/io/project_store.h"
#include "devices/common/driver.h"
#include "devices/rigtests/sequence_parameters.h"
#include "devices/rigtests/stiffness_tests.h"
#include "devices/rigtests/tyre_tests.h"
#include "devices/rigtests/virtual_rigs.h"
#include "devices/sim/sim_drivers.h"
#include "devices/sim/specimen_catalogue.h"

namespace mozzi::cli {
namespace {

constexpr const char* kUsage =
    "Usage: mozzi-cli rig list [--json]\n"
    "       mozzi-cli rig caps DRIVER [--file RECORDING] [--json]\n"
    "       mozzi-cli rig run PROJECT.mozzi --specimen NAME --rig sim-stiffness --test static|dynamic\n"
    "                     [--force N] [--frequencies LIST] [--actuator SOURCE] [--seed S] [--name TEST] [--json]\n"
    "       mozzi-cli rig run PROJECT.mozzi --specimen NAME --rig sim-tyre-tester --test relaxation|steady-state\n"
    "                     [--speed V] [--pressure BAR] [--frequencies LIST] [--seed S] [--name TEST] [--json]\n"
    "  --file         for sim-replay: the UFF file whose channels to show\n"
    "  --specimen     a virtual specimen key (rig list) or a project specimen's name\n"
    "  --force        static: ramp peak [N] (default the thesis's: 300 N, fork B 500 N); dynamic: sine set-point [N]\n"
    "  --actuator     stiffness rig set-point: sim-stiffness (the rig's own drive, default), sim-funcgen\n"
    "                 (the simulated function generator), usbtmc-funcgen (the first USBTMC generator found)\n"
    "  --frequencies  comma-separated [Hz]: stiffness rig 1..45 (default 1,2,5,10,15); tyre yaw\n"
    "                 (default 0.42,0.84,1.26,1.68,2.1)\n"
    "  --speed        disk speed [m/s] (default 5 km/h = 1.389 m/s; machine limit 50 km/h)\n"
    "  --pressure     tyre inflation [bar] (default 2)\n"
    "  --seed         simulation seed (default 1)\n";

nlohmann::json valueJson(const devices::ParameterValue& v) {
  return std::visit([](const auto& x) { return nlohmann::json(x); }, v);
}

nlohmann::json capsJson(const devices::Capabilities& c) {
  nlohmann::json j;
  j["model"] = c.model;
  j["inputs"] = nlohmann::json::array();
  for (const auto& in : c.inputs) {
    nlohmann::json r = nlohmann::json::array();
    for (const auto& range : in.ranges)
      r.push_back({{"code", range.code}, {"label", range.label}, {"min_v", range.minVolts}, {"max_v", range.maxVolts}});
    nlohmann::json coupling = nlohmann::json::array();
    for (auto k : in.couplings) coupling.push_back(devices::couplingName(k));
    j["inputs"].push_back({{"name", in.name},
                           {"ranges", r},
                           {"coupling", coupling},
                           {"iepe", in.iepeSupply},
                           {"bits", in.resolutionBits}});
  }
  j["outputs"] = nlohmann::json::array();
  for (const auto& o : c.outputs)
    j["outputs"].push_back({{"name", o.name}, {"unit", o.unit}, {"min", o.min}, {"max", o.max}});
  j["rates"] = {{"min_hz", c.rates.minHz},
                {"max_hz", c.rates.maxHz},
                {"max_aggregate_hz", c.rates.maxAggregateHz},
                {"timebase_hz", c.rates.timebaseHz},
                {"simultaneous", c.rates.simultaneous}};
  j["triggers"] = nlohmann::json::array();
  for (auto t : c.triggers) j["triggers"].push_back(devices::triggerKindName(t));
  j["fifo_samples"] = c.fifoSamples;
  j["parameters"] = nlohmann::json::array();
  for (const auto& p : c.parameters) {
    nlohmann::json q = {{"key", p.key},
                        {"label", p.label},
                        {"type", devices::parameterTypeName(p.type)},
                        {"unit", p.unit},
                        {"default", valueJson(p.defaultValue)},
                        {"help", p.help}};
    if (p.min) q["min"] = *p.min;
    if (p.max) q["max"] = *p.max;
    if (!p.choices.empty()) q["choices"] = p.choices;
    j["parameters"].push_back(q);
  }
  return j;
}

// The virtual specimens of the simulated rigs, with the thesis sources of
// their numbers (devices/sim/specimen_catalogue.h).
nlohmann::json specimensJson() {
  nlohmann::json all = nlohmann::json::array();
  for (const auto& e : devices::sim::specimenCatalogue()) {
    nlohmann::json modes = nlohmann::json::array();
    for (std::size_t r = 0; r < e.modes.size(); ++r)
      modes.push_back({{"frequency_hz", e.modes[r].frequencyHz},
                       {"damping", e.modes[r].damping},
                       {"zeta", e.zeta(r)},
                       {"shape", e.modes[r].shape}});
    nlohmann::json s = {{"key", e.key},
                        {"name", e.name},
                        {"kind", e.kind},
                        {"modal_source", e.modalSource},
                        {"damping_measure", devices::sim::dampingMeasureName(e.damping)},
                        {"modes", modes}};
    if (e.statics) {
      const auto& st = *e.statics;
      s["static_source"] = e.staticSource;
      s["static"] = {{"lateral_stiffness_n_per_m", st.lateralStiffness}, {"twist_arm_m", st.twistArm},
                     {"twist_stiffness_nm_per_rad", st.twistStiffness},  {"inclination_deg", st.inclinationDeg},
                     {"inclination_tabulated", st.inclinationTabulated}, {"test_force_n", st.testForceN}};
    }
    all.push_back(s);
  }
  return all;
}

int list(bool json, std::ostream& out) {
  auto& reg = devices::builtinDrivers();
  std::vector<std::string> failures;
  const auto found = reg.scanAll(&failures);
  if (json) {
    nlohmann::json j;
    j["drivers"] = nlohmann::json::array();
    for (auto* d : reg.drivers())
      j["drivers"].push_back({{"name", d->name()}, {"description", d->description()}, {"simulated", d->simulated()}});
    j["devices"] = nlohmann::json::array();
    for (const auto& d : found)
      j["devices"].push_back({{"driver", d.driver},
                              {"model", d.model},
                              {"vid", d.vendorId},
                              {"pid", d.productId},
                              {"serial", d.serial},
                              {"bus", d.busPath}});
    j["scan_failures"] = failures;
    j["specimens"] = specimensJson();
    out << j.dump(2) << "\n";
    return kExitOk;
  }
  out << "Drivers:\n";
  for (auto* d : reg.drivers())
    out << "  " << d->name() << (d->simulated() ? " (simulated)" : "") << ": " << d->description() << "\n";
  out << "Devices found:\n";
  for (const auto& d : found) out << "  " << d.driver << "  " << d.label() << "\n";
  for (const auto& f : failures) out << "  scan failed: " << f << "\n";
  out << "Virtual specimens (simulated rigs):\n";
  for (const auto& e : devices::sim::specimenCatalogue()) {
    out << "  " << e.key << "  " << e.name << ": " << e.modes.size() << " modes (" << e.modalSource << ")";
    if (e.statics) out << "; static " << e.staticSource;
    out << "\n";
  }
  return kExitOk;
}

int caps(const std::string& driver, const std::string& file, bool json, std::ostream& out, std::ostream& err) {
  auto* d = devices::builtinDrivers().find(driver);
  if (!d) {
    err << "mozzi-cli rig caps: no driver named '" << driver << "' (see mozzi-cli rig list)\n";
    return kExitFailure;
  }
  // Capabilities are static data of the driver: no device needs to be present.
  // A replay's channels come from its recording's headers, read by create()
  // without the samples (so a recording of any size is summarised at once).
  if (!file.empty() && driver != "sim-replay") {
    err << "mozzi-cli rig caps: --file is for the sim-replay driver\n";
    return kExitUsage;
  }
  auto dev = d->create(devices::DeviceDescriptor{driver, "", 0, 0, "", file});
  if (!dev) {
    err << "mozzi-cli rig caps: " << dev.error().describe() << "\n";
    return kExitFailure;
  }
  auto capabilities = file.empty() ? core::Result<devices::Capabilities>((*dev)->capabilities())
                                   : devices::sim::replayRecordingCapabilities(file);
  if (!capabilities) {
    err << "mozzi-cli rig caps: " << capabilities.error().describe() << "\n";
    return kExitFailure;
  }
  const auto j = capsJson(*capabilities);
  if (json) {
    out << j.dump(2) << "\n";
    return kExitOk;
  }
  out << j["model"].get<std::string>() << "\n  inputs: " << j["inputs"].size() << ", max "
      << j["rates"]["max_hz"].get<double>() << " Hz per channel, " << j["rates"]["max_aggregate_hz"].get<double>()
      << " S/s aggregate, FIFO " << j["fifo_samples"].get<std::int64_t>() << " samples\n  parameters:\n";
  for (const auto& p : j["parameters"])
    out << "    " << p["key"].get<std::string>() << " (" << p["type"].get<std::string>() << ") "
        << p["help"].get<std::string>() << "\n";
  return kExitOk;
}

// ---------------------------------------------------------------- rig run

constexpr double kPi = 3.14159265358979323846;

// A quantity as JSON: SI value and uncertainty; angles (rad) as "<key>_deg" in degrees.
void putQuantity(nlohmann::json& j, const devices::rigtests::Quantity& q) {
  const bool angle = q.unit == "rad";
  const double k = angle ? 180.0 / kPi : 1.0;
  j[angle ? q.key + "_deg" : q.key] = {
      {"value", q.value * k}, {"uncertainty", q.uncertainty * k}, {"unit", angle ? "deg" : q.unit}, {"label", q.label}};
}

nlohmann::json quantitiesJson(const std::vector<devices::rigtests::Quantity>& qs) {
  nlohmann::json j = nlohmann::json::object();
  nlohmann::json mf = nlohmann::json::object();
  for (const auto& q : qs) {
    if (q.key.rfind("mf_", 0) == 0) {
      nlohmann::json m;
      putQuantity(m, devices::rigtests::Quantity{q.key.substr(3), q.label, q.value, q.unit, q.uncertainty});
      mf.update(m);
    } else {
      putQuantity(j, q);
    }
  }
  if (!mf.empty()) j["magic_formula"] = mf;
  return j;
}

nlohmann::json outcomeJson(const devices::rigtests::Outcome& o, const std::string& rig, const std::string& test,
                           const devices::rigtests::SpecimenChoice& who) {
  nlohmann::json j;
  j["rig"] = rig;
  j["test"] = test;
  j["specimen"] = {
      {"id", who.specimenId}, {"name", who.projectName}, {"key", who.catalogueKey}, {"created", who.created}};
  j["stored_test_id"] = o.testId ? nlohmann::json(*o.testId) : nlohmann::json(nullptr);
  j["stored_in"] = rig == "sim-tyre-tester" ? "tyre_test" : "rig_test";
  j["rig_setup_id"] = o.rigSetupId ? nlohmann::json(*o.rigSetupId) : nlohmann::json(nullptr);
  j["name"] = o.testName;
  j["status"] = core::io::testStatusName(o.status);
  j["status_note"] = o.note;
  j["results"] = quantitiesJson(o.results);
  j["steps"] = nlohmann::json::array();
  for (const auto& s : o.steps) {
    nlohmann::json step = quantitiesJson(s.results);
    step["step"] = s.step;
    step["label"] = s.label;
    step["ok"] = s.ok;
    step["note"] = s.note;
    j["steps"].push_back(step);
  }
  return j;
}

void printQuantities(std::ostream& out, const std::vector<devices::rigtests::Quantity>& qs, const char* indent) {
  for (const auto& q : qs) {
    const bool angle = q.unit == "rad";
    const double k = angle ? 180.0 / kPi : 1.0;
    out << indent << q.label << " (" << (angle ? q.key + "_deg" : q.key) << "): " << q.value * k;
    if (q.uncertainty > 0) out << " +/- " << q.uncertainty * k;
    out << " " << (angle ? "deg" : q.unit) << "\n";
  }
}

int runTest(const ParsedArgs& a, std::ostream& out, std::ostream& err) {
  namespace rt = devices::rigtests;
  const auto& pos = a.positional();
  auto usage = [&](const std::string& what) {
    err << "mozzi-cli rig run: " << what << "\n" << kUsage;
    return kExitUsage;
  };
  if (pos.size() != 2) return usage("one project file is needed");
  const std::string file = pos[1];
  const auto specimen = a.value("--specimen");
  const auto rig = a.value("--rig");
  const auto test = a.value("--test");
  if (!specimen || !rig || !test) return usage("--specimen, --rig and --test are required");
  const bool stiffness = *rig == "sim-stiffness", tyre = *rig == "sim-tyre-tester";
  if (!stiffness && !tyre) return usage("--rig must be sim-stiffness or sim-tyre-tester, not '" + *rig + "'");
  if (stiffness && *test != "static" && *test != "dynamic")
    return usage("--test for sim-stiffness is static or dynamic, not '" + *test + "'");
  if (tyre && *test != "relaxation" && *test != "steady-state")
    return usage("--test for sim-tyre-tester is relaxation or steady-state, not '" + *test + "'");
  if (stiffness && (a.value("--speed") || a.value("--pressure")))
    return usage("--speed and --pressure are options of the tyre tester");
  if (tyre && a.value("--force")) return usage("--force is an option of the stiffness rig");
  if (tyre && a.value("--actuator")) return usage("--actuator is an option of the stiffness rig");
  const std::string actuatorChoice = a.value("--actuator").value_or(rt::kActuatorRigDrive);
  if (actuatorChoice != rt::kActuatorRigDrive && actuatorChoice != rt::kActuatorSimGenerator &&
      actuatorChoice != rt::kActuatorUsbtmcGenerator)
    return usage("--actuator is sim-stiffness, sim-funcgen or usbtmc-funcgen, not '" + actuatorChoice + "'");
  if (tyre && *test == "steady-state" && a.value("--frequencies"))
    return usage("--frequencies is not an option of the steady-state test");
  if (stiffness && *test == "static" && a.value("--frequencies"))
    return usage("--frequencies is not an option of the static test");
  // The numbers are range-checked by the parser (kSpec); the rig's own limits
  // (5000 N, 1..45 Hz, 50 km/h) by the test's settings check below.
  auto number = [&](const char* name) -> std::optional<double> {
    const auto v = a.numbers(name);
    return v.empty() ? std::nullopt : std::optional<double>(v.front());
  };
  const std::optional<double> force = number("--force"), speed = number("--speed"), pressure = number("--pressure");
  const std::uint64_t seed = static_cast<std::uint64_t>(number("--seed").value_or(1.0));
  std::optional<std::vector<double>> frequencies;
  if (a.value("--frequencies")) frequencies = a.numbers("--frequencies");
  const bool json = a.flag("--json");
  const std::string name = a.value("--name").value_or("");

  auto store = core::io::ProjectStore::open(file);
  if (!store) {
    err << "mozzi-cli rig run: " << store.error().describe() << "\n";
    return kExitFailure;
  }
  if (store->isReadOnly()) {
    err << "mozzi-cli rig run: " << file << " is open read-only (" << store->readOnlyReason()
        << "); the test could not be stored\n";
    return kExitFailure;
  }
  auto fail = [&](const core::Error& e) {
    err << "mozzi-cli rig run: " << e.describe() << "\n";
    return kExitFailure;
  };
  // Everything is checked before the project or a device is touched: the
  // specimen's key (a project name is looked up without adding anything), the
  // set-up and the settings.
  std::string key = *specimen;
  if (!devices::sim::findSpecimen(key)) {
    auto who = rt::resolveSpecimen(*store, *specimen);  // a project name: adds nothing
    if (!who) return fail(who.error());
    key = who->catalogueKey;
  }
  const auto* e = devices::sim::findSpecimen(key);
  if (stiffness && !e->statics) {
    std::string keys;
    for (const auto& x : devices::sim::staticSpecimenKeys()) keys += (keys.empty() ? "" : ", ") + x;
    return fail(core::makeError(core::ErrorCode::InvalidArgument,
                                "the thesis has no static test of this specimen; the stiffness rig runs on " + keys,
                                "--specimen " + *specimen));
  }
  if (tyre && e->kind != "tyre")
    return fail(core::makeError(core::ErrorCode::InvalidArgument, "the tyre tester runs on tyres (tyre-...)",
                                "--specimen " + *specimen));
  std::optional<rt::StiffnessRigSetup> stiffSetup;
  std::optional<rt::TyreRigSetup> tyreSetup;
  rt::StaticTestSettings staticSettings;
  rt::DynamicTestSettings dynamicSettings;
  rt::RelaxationSettings relaxationSettings;
  rt::SteadyStateSettings steadySettings;
  if (stiffness) {
    auto setup = rt::simulatedStiffnessSetup(key, seed, false);
    if (!setup) return fail(setup.error());
    stiffSetup = *setup;
    staticSettings.peakForceN = force.value_or(e->statics->testForceN);
    dynamicSettings.amplitudeN = force.value_or(e->statics->testForceN);
    if (frequencies) dynamicSettings.frequenciesHz = *frequencies;
    auto ok = *test == "static" ? rt::checkStaticSettings(*stiffSetup, staticSettings)
                                : rt::checkDynamicSettings(*stiffSetup, dynamicSettings);
    if (!ok) return fail(ok.error());
  } else {
    auto setup = rt::simulatedTyreSetup(key, pressure.value_or(2.0), seed, false);
    if (!setup) return fail(setup.error());
    tyreSetup = *setup;
    if (speed) relaxationSettings.speedKmh = steadySettings.speedKmh = *speed * 3.6;
    if (frequencies) relaxationSettings.frequenciesHz = *frequencies;
    auto ok = *test == "relaxation" ? rt::checkRelaxationSettings(*tyreSetup, relaxationSettings)
                                    : rt::checkSteadyStateSettings(*tyreSetup, steadySettings);
    if (!ok) return fail(ok.error());
  }
  auto who = rt::resolveSpecimen(*store, key == *specimen ? key : *specimen);
  if (!who) return fail(who.error());

  rt::Callbacks cb;
  if (!json) cb.log = [&out](const std::string& line) { out << line << "\n"; };
  const rt::StoreTarget target{&*store, who->specimenId, name};
  const std::string label = *rig + " " + *test;
  auto report = [&](const rt::Outcome& o) {
    if (json) {
      out << outcomeJson(o, *rig, *test, *who).dump(2) << "\n";
    } else {
      out << label << " on " << who->projectName << " (" << who->catalogueKey
          << "): " << core::io::testStatusName(o.status) << (o.note.empty() ? "" : " (" + o.note + ")") << "\n";
      for (const auto& s : o.steps) {
        out << "  step " << s.step << " " << s.label << (s.ok ? "" : " [no result]")
            << (s.note.empty() ? "" : ": " + s.note) << "\n";
        // A step that holds the whole test's results (the static ramp) prints them once, below.
        if (o.steps.size() != 1 || s.results.size() != o.results.size()) printQuantities(out, s.results, "    ");
      }
      out << "  results:\n";
      printQuantities(out, o.results, "    ");
      if (o.testId)
        out << "  stored as " << (tyre ? "tyre" : "rig") << " test " << *o.testId << " '" << o.testName << "'\n";
    }
    return o.status == core::io::TestStatus::Complete ? kExitOk : kExitFailure;
  };

  if (stiffness) {
    auto dev = devices::sim::makeStiffnessRigDriver()->create(
        devices::DeviceDescriptor{"sim-stiffness", "", 0, 0, "", "sim:0"});
    if (!dev) return fail(dev.error());
    // The set-point through a function generator when one is chosen.
    auto actuator = rt::actuatorFor(actuatorChoice, *stiffSetup);
    if (!actuator) return fail(actuator.error());
    if (*test == "static") {
      auto o = rt::runStaticStiffnessTest(**dev, actuator->get(), *stiffSetup, staticSettings, target, cb);
      if (!o) return fail(o.error());
      return report(*o);
    }
    auto o = rt::runDynamicStiffnessTest(**dev, actuator->get(), *stiffSetup, dynamicSettings, target, cb);
    if (!o) return fail(o.error());
    return report(*o);
  }
  auto dev =
      devices::sim::makeTyreTesterDriver()->create(devices::DeviceDescriptor{"sim-tyre-tester", "", 0, 0, "", "sim:0"});
  if (!dev) return fail(dev.error());
  if (*test == "relaxation") {
    auto o = rt::runRelaxationTest(**dev, *tyreSetup, relaxationSettings, target, cb);
    if (!o) return fail(o.error());
    return report(*o);
  }
  auto o = rt::runSteadyStateTest(**dev, *tyreSetup, steadySettings, target, cb);
  if (!o) return fail(o.error());
  return report(*o);
}

// The option table of list, caps and run. The ranges say what a number can
// mean; each rig refuses set-points beyond its own limits (the stiffness
// rig's 5000 N and 1..45 Hz, the tyre tester's 50 km/h), naming the limit.
const OptionSpec kSpec{{"--file", "--specimen", "--rig", "--test", "--name", "--actuator"},
                       {"--json"},
                       {{"--force", aboveTo(0, 1e5, "N"), "stiffness rig force set-point"},
                        {"--frequencies", "test frequencies", {{"f", aboveTo(0, 1000, "Hz")}}, ',', true, 1000},
                        {"--speed", aboveTo(0, 100, "m/s"), "tyre tester disk speed"},
                        {"--pressure", closed(0.5, 4, "bar"), "tyre inflation pressure"},
                        {"--seed", wholeNumber(0, 4294967295.0), "simulation seed"}}};

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto parsed = ParsedArgs::parse(args, kSpec);
  if (!parsed) {
    err << "mozzi-cli rig: " << parsed.error().describe() << "\n";
    if (exitCodeFor(parsed.error()) == kExitUsage) err << kUsage;
    return exitCodeFor(parsed.error());
  }
  const auto& pos = parsed->positional();
  if (!pos.empty() && pos[0] == "run") {
    if (parsed->value("--file")) {
      err << "mozzi-cli rig run: --file is an option of rig caps\n" << kUsage;
      return kExitUsage;
    }
    return runTest(*parsed, out, err);
  }
  for (const char* o : {"--specimen", "--rig", "--test", "--name", "--actuator", "--force", "--frequencies", "--speed",
                        "--pressure", "--seed"}) {
    if (parsed->value(o)) {
      err << "mozzi-cli rig: " << o << " is an option of rig run\n" << kUsage;
      return kExitUsage;
    }
  }
  if (pos.size() == 1 && pos[0] == "list") return list(parsed->flag("--json"), out);
  if (pos.size() == 2 && pos[0] == "caps")
    return caps(pos[1], parsed->value("--file").value_or(""), parsed->flag("--json"), out, err);
  err << kUsage;
  return kExitUsage;
}

const CommandRegistrar kRegistrar(
    {"rig",
     "list | caps DRIVER [--file RECORDING] | run PROJECT.mozzi --specimen NAME --rig sim-stiffness|sim-tyre-tester "
     "--test static|dynamic|relaxation|steady-state [...] [--json]",
     "acquisition drivers, devices found, virtual specimens, capabilities and parameters; run a stiffness-rig or "
     "tyre-tester test into a project",
     &run, &kSpec});

}  // namespace
}  // namespace mozzi::cli
