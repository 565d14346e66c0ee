// mozzi-cli rig: the driver list and a device's capabilities, checked against
// the registry and against the USB-1608FS-Plus data sheet figures the issue
// quotes (8 simultaneous channels, 100 kS/s per channel, 400 kS/s aggregate).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <set>

#include "cli_run.h"
#include "devices/common/driver.h"

namespace mozzi::cli {
namespace {

TEST(RigCli, ListNamesEveryBuiltInDriver) {
  const CliRun r = run({"rig", "list", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::set<std::string> listed;
  for (const auto& d : j.at("drivers")) listed.insert(d.at("name").get<std::string>());
  std::set<std::string> registered;
  for (auto* d : devices::builtinDrivers().drivers()) registered.insert(d->name());
  EXPECT_EQ(listed, registered);
  EXPECT_TRUE(listed.count("mcc-usb1608fsplus"));
  EXPECT_TRUE(listed.count("sim-hammer"));
  EXPECT_TRUE(listed.count("sim-stiffness"));
  for (const auto& d : j.at("drivers")) {
    const bool simulated = d.at("name").get<std::string>().rfind("sim-", 0) == 0;
    EXPECT_EQ(d.at("simulated").get<bool>(), simulated) << d.dump();
  }
}

TEST(RigCli, Usb1608FsPlusCapabilitiesMatchTheDataSheet) {
  const CliRun r = run({"rig", "caps", "mcc-usb1608fsplus", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("inputs").size(), 8u);
  EXPECT_DOUBLE_EQ(j.at("rates").at("max_hz").get<double>(), 100000.0);
  EXPECT_DOUBLE_EQ(j.at("rates").at("max_aggregate_hz").get<double>(), 400000.0);
  EXPECT_FALSE(j.at("parameters").empty());
}

TEST(RigCli, UnknownDriverAndSubcommandAreReported) {
  const CliRun missing = run({"rig", "caps", "no-such-rig"});
  EXPECT_EQ(missing.code, kExitFailure);
  EXPECT_NE(missing.err.find("no driver named 'no-such-rig'"), std::string::npos) << missing.err;
  EXPECT_EQ(run({"rig", "dance"}).code, kExitUsage);
}

}  // namespace
}  // namespace mozzi::cli
