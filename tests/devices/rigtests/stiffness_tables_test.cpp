// The stiffness tables (devices/rigtests/stiffness_tables.h) over a project
// holding a static ramp of every virtual specimen with a static test in the
// thesis, run by the stiffness-rig sequence on the simulated rig: one column
// per test in specimen order; the measured cells are the stored whole-test
// results (equal to the bit, read here straight from the store); the thesis's
// values are the printed ones typed here from reference/thesis.md (Tables 3,
// 4, 5, 7, 9, 10, 13; Table 9's "N/m" is kN/m, Table 13's "22 kNm 7 rad" is
// 22 kNm/rad), with no arm for frame C (Table 5 prints none); the constraint
// of each column; the deviation.
#include "devices/rigtests/stiffness_tables.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <map>

#include "core/io/project_store.h"
#include "devices/rigtests/stiffness_tests.h"
#include "devices/rigtests/virtual_rigs.h"
#include "devices/sim/sim_drivers.h"
#include "devices/sim/specimen_catalogue.h"

namespace mozzi::devices::rigtests {
namespace {

namespace fs = std::filesystem;
constexpr double kDeg = 3.14159265358979323846 / 180.0;

struct Printed {
  const char* key;
  const char* constraint;
  std::map<std::string, double> values;  // SI, as printed
};

const Printed kPrinted[] = {
    {"frame-a-front-constrained",
     "front-constrained",
     {{"k_lat", 167e3},
      {"a_tw", 0.551},
      {"k_tw", 50.8e3},
      {"a_bend", 0.556},
      {"k_bend", 52.1e3},
      {"a_tors", 0.032},
      {"k_tors", 22.0e3}}},
    {"frame-a-rear-constrained",
     "rear-constrained",
     {{"k_lat", 253e3},
      {"a_tw", 0.475},
      {"k_tw", 57.0e3},
      {"a_bend", 0.458},
      {"k_bend", 53.5e3},
      {"a_tors", 0.026},
      {"k_tors", 19.6e3}}},
    {"frame-b-front-constrained",
     "front-constrained",
     {{"k_lat", 272e3},
      {"a_tw", 0.689},
      {"k_tw", 129e3},
      {"a_bend", 0.553},
      {"k_bend", 138.3e3},
      {"a_tors", 0.298},
      {"k_tors", 60.4e3}}},
    {"frame-b-rear-constrained",
     "rear-constrained",
     {{"k_lat", 238e3},
      {"a_tw", 0.498},
      {"k_tw", 59.1e3},
      {"a_bend", 0.510},
      {"k_bend", 64.3e3},
      {"a_tors", 0.097},
      {"k_tors", 60.2e3}}},
    {"frame-c-without-engine", "", {{"k_lat", 361e3}, {"k_tw", 260.2e3}, {"k_bend", 358.6e3}, {"k_tors", 58.4e3}}},
    {"frame-c-with-engine", "", {{"k_lat", 539e3}, {"k_tw", 414.6e3}, {"k_bend", 522.9e3}, {"k_tors", 104e3}}},
    {"swing-arm-a",
     "",
     {{"k_lat", 623e3},
      {"a_tw", 0.375},
      {"k_tw", 87.6e3},
      {"a_bend", 0.388},
      {"k_bend", 94.2e3},
      {"a_tors", 0.025},
      {"k_tors", 98.8e3}}},
    {"swing-arm-b",
     "",
     {{"k_lat", 1083e3},
      {"a_tw", 0.477},
      {"k_tw", 246.4e3},
      {"a_bend", 0.451},
      {"k_bend", 222.4e3},
      {"a_tors", 0.026},
      {"k_tors", 77.4e3}}},
    {"fork-a-with-wheel",
     "steering head locked",
     {{"k_lat", 56.1e3},
      {"a_tw", 0.517},
      {"k_tw", 15e3},
      {"a_bend", 0.67},
      {"k_bend", 28e3},
      {"a_tors", 0.066},
      {"k_tors", 3e3},
      {"axis_inclination", 45.5 * kDeg}}},
    {"fork-b-with-wheel",
     "steering head locked",
     {{"k_lat", 109.3e3},
      {"a_tw", 0.452},
      {"k_tw", 22e3},
      {"a_bend", 0.528},
      {"k_bend", 35e3},
      {"a_tors", 0.083},
      {"k_tors", 6e3},
      {"axis_inclination", 41.2 * kDeg}}},
};

TEST(StiffnessTables, EveryStaticSpecimenBesideItsPrintedTable) {
  ASSERT_EQ(sim::staticSpecimenKeys().size(), std::size(kPrinted));
  const fs::path path = fs::temp_directory_path() / ("stiffness_tables_" + std::to_string(::getpid()) + ".mozzi");
  fs::remove(path);
  auto store = core::io::ProjectStore::create(path.string(), "test");
  ASSERT_TRUE(store.ok()) << store.error().describe();
  auto dev = sim::makeStiffnessRigDriver()->create(DeviceDescriptor{"sim-stiffness", "", 0, 0, "", "sim:0"});
  ASSERT_TRUE(dev.ok());
  std::map<std::string, std::int64_t> testOf;
  std::uint64_t seed = 40;
  for (const auto& p : kPrinted) {
    auto who = resolveSpecimen(*store, p.key);
    ASSERT_TRUE(who.ok()) << who.error().describe();
    auto setup = simulatedStiffnessSetup(p.key, seed++, false);
    ASSERT_TRUE(setup.ok());
    StaticTestSettings settings;
    settings.peakForceN = sim::findSpecimen(p.key)->statics->testForceN;
    settings.periodS = 4.0;
    auto run = runStaticStiffnessTest(**dev, nullptr, *setup, settings, StoreTarget{&*store, who->specimenId, "ramp"});
    ASSERT_TRUE(run.ok()) << run.error().describe();
    ASSERT_TRUE(run->testId.has_value());
    testOf[p.key] = *run->testId;
  }

  std::vector<std::string> skipped;
  auto columns = stiffnessColumns(*store, &skipped);
  ASSERT_TRUE(columns.ok()) << columns.error().describe();
  EXPECT_TRUE(skipped.empty());
  ASSERT_EQ(columns->size(), std::size(kPrinted));
  for (std::size_t i = 0; i < columns->size(); ++i) {
    const auto& c = (*columns)[i];
    const auto& p = kPrinted[i];  // specimens were added in this order
    SCOPED_TRACE(p.key);
    EXPECT_EQ(c.testId, testOf.at(p.key));
    EXPECT_EQ(c.catalogueKey, p.key);
    EXPECT_EQ(c.constraint, p.constraint);
    EXPECT_EQ(c.testName, "ramp");
    // Measured: the stored whole-test results, every row the sequence wrote.
    auto test = store->rigTest(c.testId);
    ASSERT_TRUE(test.ok());
    std::size_t rowsStored = 0;
    for (const auto& r : test->results) {
      if (r.step) continue;
      const auto it = c.measured.find(r.quantity);
      bool isRow = false;
      for (const auto& row : stiffnessRows()) isRow = isRow || r.quantity == row.key;
      if (!isRow) {
        EXPECT_EQ(it, c.measured.end()) << r.quantity;
        continue;
      }
      ++rowsStored;
      ASSERT_NE(it, c.measured.end()) << r.quantity;
      EXPECT_EQ(it->second.value, r.value) << r.quantity;
      EXPECT_EQ(it->second.uncertainty, r.uncertainty) << r.quantity;
      EXPECT_EQ(it->second.unit, r.unit) << r.quantity;
    }
    EXPECT_EQ(c.measured.size(), rowsStored);
    // Thesis: exactly the printed quantities, with the printed values.
    EXPECT_EQ(c.thesis.size(), p.values.size());
    for (const auto& [key, value] : p.values) {
      const auto it = c.thesis.find(key);
      ASSERT_NE(it, c.thesis.end()) << key;
      EXPECT_NEAR(it->second, value, 1e-9 * std::abs(value)) << key;
      const auto m = c.measured.find(key);
      const auto d = thesisDeviation(c, key);
      ASSERT_EQ(d.has_value(), m != c.measured.end()) << key;
      if (d) {
        EXPECT_NEAR(*d, (m->second.value - value) / value, 1e-12) << key;
      }
    }
    EXPECT_FALSE(c.thesisSource.empty());
  }
  store = core::Error{};
  fs::remove(path);
}

}  // namespace
}  // namespace mozzi::devices::rigtests
