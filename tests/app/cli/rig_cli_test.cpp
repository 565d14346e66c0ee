// mozzi-cli rig: the driver list and a device's capabilities, checked against
// the registry and against the USB-1608FS-Plus data sheet figures the issue
// quotes (8 simultaneous channels, 100 kS/s per channel, 400 kS/s aggregate).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>
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
  EXPECT_TRUE(listed.count("sim-tyre-tester"));
  EXPECT_TRUE(listed.count("sim-replay"));
  for (const auto& d : j.at("drivers")) {
    const bool simulated = d.at("name").get<std::string>().rfind("sim-", 0) == 0;
    EXPECT_EQ(d.at("simulated").get<bool>(), simulated) << d.dump();
  }
}

// The virtual specimens of issue 9 with the thesis numbers of a few of them
// (Table 3 frame A front-constrained, Table 11 fork A, Table 18 steel bicycle)
// and their sources.
TEST(RigCli, ListShowsTheVirtualSpecimensWithTheirSources) {
  const CliRun r = run({"rig", "list", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::map<std::string, nlohmann::json> byKey;
  std::map<std::string, int> kinds;
  for (const auto& s : j.at("specimens")) {
    byKey[s.at("key").get<std::string>()] = s;
    ++kinds[s.at("kind").get<std::string>()];
  }
  // Frames A, B front/rear and C with/without engine; two swing-arms; forks A
  // and B with and without wheel; six tyres; four bicycles; two bicycle forks
  // with and without wheel.
  EXPECT_EQ(kinds["frame"], 6);
  EXPECT_EQ(kinds["swing-arm"], 2);
  EXPECT_EQ(kinds["fork"], 4);
  EXPECT_EQ(kinds["tyre"], 6);
  EXPECT_EQ(kinds["bicycle"], 4);
  EXPECT_EQ(kinds["bicycle-fork"], 4);
  const auto& frameA = byKey.at("frame-a-front-constrained");
  EXPECT_DOUBLE_EQ(frameA.at("static").at("lateral_stiffness_n_per_m").get<double>(), 167e3);
  EXPECT_DOUBLE_EQ(frameA.at("static").at("twist_arm_m").get<double>(), 0.551);
  EXPECT_EQ(frameA.at("static_source").get<std::string>(), "thesis Tables 3 and 4");
  const auto& forkA = byKey.at("fork-a-without-wheel");
  EXPECT_DOUBLE_EQ(forkA.at("modes").at(0).at("frequency_hz").get<double>(), 38.6);
  EXPECT_NE(forkA.at("modal_source").get<std::string>().find("Table 11"), std::string::npos);
  const auto& steel = byKey.at("bicycle-steel");
  EXPECT_EQ(steel.at("modes").size(), 7u);
  EXPECT_DOUBLE_EQ(steel.at("modes").at(4).at("damping").get<double>(), 0.017);  // eta 1.7%
  EXPECT_DOUBLE_EQ(steel.at("modes").at(4).at("zeta").get<double>(), 0.0085);    // zeta = eta / 2

  const CliRun text = run({"rig", "list"});
  ASSERT_EQ(text.code, kExitOk);
  EXPECT_NE(text.out.find("Virtual specimens"), std::string::npos);
  EXPECT_NE(text.out.find("swing-arm-b"), std::string::npos);
}

TEST(RigCli, TyreTesterCapabilitiesFollowTheMototiremeter) {
  const CliRun r = run({"rig", "caps", "sim-tyre-tester", "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  // §1.8: disk up to 50 km/h, yaw +/-10 deg and camber +/-55 deg servos
  // (appendix 2; §1.8 prints 54) limited to 6 and 45 by default, three load
  // cells and a rate gyro.
  std::map<std::string, nlohmann::json> outputs, params;
  for (const auto& o : j.at("outputs")) outputs[o.at("name").get<std::string>()] = o;
  for (const auto& p : j.at("parameters")) params[p.at("key").get<std::string>()] = p;
  EXPECT_DOUBLE_EQ(outputs.at("disk speed").at("max").get<double>(), 50.0);
  EXPECT_DOUBLE_EQ(outputs.at("yaw servo").at("max").get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(outputs.at("camber servo").at("max").get<double>(), 55.0);
  EXPECT_DOUBLE_EQ(params.at("servo.yaw_limit_deg").at("default").get<double>(), 6.0);
  EXPECT_DOUBLE_EQ(params.at("servo.camber_limit_deg").at("default").get<double>(), 45.0);
  EXPECT_EQ(params.at("tyre").at("choices").size(), 6u);
  EXPECT_EQ(j.at("inputs").size(), 6u);
}

TEST(RigCli, ReplayCapabilitiesComeFromTheRecording) {
  const CliRun bare = run({"rig", "caps", "sim-replay", "--json"});
  ASSERT_EQ(bare.code, kExitOk) << bare.err;
  EXPECT_TRUE(nlohmann::json::parse(bare.out).at("inputs").empty());
  const CliRun missing = run({"rig", "caps", "sim-replay", "--file", "/nonexistent/hits.uff"});
  EXPECT_EQ(missing.code, kExitFailure);
  EXPECT_NE(missing.err.find("hits.uff"), std::string::npos) << missing.err;
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
