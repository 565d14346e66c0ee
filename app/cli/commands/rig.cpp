// mozzi-cli rig: the acquisition drivers, the devices they find, and what a
// device can do (capabilities and parameter specs, as the GUI forms see them).
#include <nlohmann/json.hpp>
#include <ostream>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "devices/common/driver.h"
#include "devices/sim/sim_drivers.h"
#include "devices/sim/specimen_catalogue.h"

namespace mozzi::cli {
namespace {

constexpr const char* kUsage =
    "Usage: mozzi-cli rig list [--json]\n"
    "       mozzi-cli rig caps DRIVER [--file RECORDING] [--json]\n"
    "  --file  for sim-replay: the UFF file whose channels to show\n";

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

const OptionSpec kSpec{{"--file"}, {"--json"}};

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto parsed = ParsedArgs::parse(args, kSpec);
  if (!parsed) {
    err << parsed.error().describe() << "\n" << kUsage;
    return kExitUsage;
  }
  const auto& pos = parsed->positional();
  if (pos.size() == 1 && pos[0] == "list") return list(parsed->flag("--json"), out);
  if (pos.size() == 2 && pos[0] == "caps")
    return caps(pos[1], parsed->value("--file").value_or(""), parsed->flag("--json"), out, err);
  err << kUsage;
  return kExitUsage;
}

const CommandRegistrar kRegistrar(
    {"rig", "list | caps DRIVER [--file RECORDING] [--json]",
     "acquisition drivers, devices found, virtual specimens, and capabilities and parameters", &run, &kSpec});

}  // namespace
}  // namespace mozzi::cli
