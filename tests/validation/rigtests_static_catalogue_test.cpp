// Validation of the static stiffness-rig sequence (devices/rigtests, issue 20):
// the whole path a technician uses (sequence -> simulated Motostiffmeter with
// its load-cell noise, 4 um lasers and 16-bit DAQ -> core/stiffness -> the
// project file) on every virtual specimen with a static test in the thesis,
// against the printed tables: k_lat and k_tw within 1% (plus the rounding of
// the two-digit k_tw of Tables 10 and 13), the twist-axis inclination within
// 0.5 deg of Tables 10 and 13 for the forks and of the virtual specimen's
// assumed 30 deg elsewhere (the thesis prints no inclination for frames and
// swing-arms). The numbers read back from the project are the ones checked.
// Prints the table.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/io/project_store.h"
#include "devices/rigtests/stiffness_tests.h"
#include "devices/sim/sim_drivers.h"
#include "devices/sim/specimen_catalogue.h"
#include "devices/sim/specimen_models.h"

namespace mozzi::devices::rigtests {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;

struct Row {
  const char* key;
  const char* table;
  double kLat;            // [N/m] as printed
  double kTw;             // [Nm/rad] as printed
  double inclinationDeg;  // printed (forks) or the catalogue's assumed 30 deg
  bool printedInclination;
  double kBend, kTors;  // printed (0: not printed); compared loosely, see below
};

// Tables 3, 5, 7, 9, 10, 13 (Table 9's 1083 N/m is kN/m, reference/notes.md).
const Row kRows[] = {
    {"frame-a-front-constrained", "Table 3", 167e3, 50.8e3, 30.0, false, 52.1e3, 22.0e3},
    {"frame-b-front-constrained", "Table 3", 272e3, 129e3, 30.0, false, 138.3e3, 60.4e3},
    {"frame-a-rear-constrained", "Table 3", 253e3, 57.0e3, 30.0, false, 53.5e3, 19.6e3},
    {"frame-b-rear-constrained", "Table 3", 238e3, 59.1e3, 30.0, false, 64.3e3, 60.2e3},
    {"frame-c-without-engine", "Table 5", 361e3, 260.2e3, 30.0, false, 0, 0},
    {"frame-c-with-engine", "Table 5", 539e3, 414.6e3, 30.0, false, 0, 0},
    {"swing-arm-a", "Table 7", 623e3, 87.6e3, 30.0, false, 94.2e3, 98.8e3},
    {"swing-arm-b", "Table 9", 1083e3, 246.4e3, 30.0, false, 222.4e3, 77.4e3},
    {"fork-a-with-wheel", "Table 10", 56.1e3, 15e3, 45.5, true, 28e3, 3e3},
    {"fork-b-with-wheel", "Table 13", 109.3e3, 22e3, 41.2, true, 35e3, 6e3},
};

TEST(RigTestsStaticValidation, EveryVirtualSpecimenGivesBackItsTable) {
  // Every catalogue specimen with static data is in the table above.
  EXPECT_EQ(sim::staticSpecimenKeys().size(), std::size(kRows));
  const fs::path path =
      fs::temp_directory_path() / ("rigtests_static_validation_" + std::to_string(::getpid()) + ".mozzi");
  fs::remove(path);
  auto store = core::io::ProjectStore::create(path.string(), "test");
  ASSERT_TRUE(store.ok());
  std::printf("%-26s %-9s %10s %10s %7s %10s %10s %7s %8s %8s %7s\n", "specimen", "table", "k_lat", "printed", "dev%",
              "k_tw", "printed", "dev%", "incl", "expected", "dev");
  for (const auto& row : kRows) {
    auto specimen = store->addSpecimen(row.key, "test", "");
    ASSERT_TRUE(specimen.ok());
    auto setup = simulatedStiffnessSetup(row.key, 5, false);
    ASSERT_TRUE(setup.ok()) << row.key;
    auto dev = sim::makeStiffnessRigDriver()->create(DeviceDescriptor{"sim-stiffness", "", 0, 0, "", "sim:0"});
    ASSERT_TRUE(dev.ok());
    StaticTestSettings st;
    st.peakForceN = sim::findSpecimen(row.key)->statics->testForceN;  // ±300 N; fork B ±500 N; swing-arms 1000 N
    st.periodS = 20.0;
    // 200 Hz x 20 s: 4000 scans per specimen keeps the suite fast; the
    // regression over them averages the 4 um quantisation far below 1%.
    setup->sampleRateHz = 200.0;
    auto out = runStaticStiffnessTest(**dev, nullptr, *setup, st, StoreTarget{&*store, *specimen, "validation"});
    ASSERT_TRUE(out.ok()) << row.key << ": " << out.error().describe();
    ASSERT_EQ(out->status, TestStatus::Complete) << row.key << ": " << out->note;
    // What is checked is what the project holds.
    auto stored = store->rigTest(*out->testId);
    ASSERT_TRUE(stored.ok());
    auto value = [&](const char* key) {
      for (const auto& r : stored->results)
        if (r.quantity == key) return r.value;
      ADD_FAILURE() << row.key << ": no stored " << key;
      return 0.0;
    };
    const double kLat = value("k_lat"), kTw = value("k_tw");
    const double beta = std::abs(value("axis_inclination")) * 180 / kPi;
    const double incl = beta > 90 ? 180 - beta : beta;
    std::printf("%-26s %-9s %10.0f %10.0f %+7.2f %10.0f %10.0f %+7.2f %8.2f %8.2f %+7.2f\n", row.key, row.table, kLat,
                row.kLat, 100 * (kLat / row.kLat - 1), kTw, row.kTw, 100 * (kTw / row.kTw - 1), incl,
                row.inclinationDeg, incl - row.inclinationDeg);
    EXPECT_NEAR(kLat / row.kLat, 1.0, 0.01) << row.key;
    // k_tw: 1%, plus half a unit of the last printed digit where the table
    // prints two digits (15 and 22 kNm/rad: 3.3% and 2.3%).
    const double rounding = row.kTw < 30e3 ? 0.5e3 / row.kTw : 0.0;
    EXPECT_NEAR(kTw / row.kTw, 1.0, 0.01 + rounding) << row.key;
    EXPECT_NEAR(incl, row.inclinationDeg, 0.5) << row.key << (row.printedInclination ? " (printed)" : " (assumed)");
    // Bending and torsion stiffness where the specimen has the axes: the
    // decomposition returns the virtual specimen's own (its plate model, see
    // specimen_models.h) within 2%; against the printed values, which do not
    // close eq. 24 exactly, it is printed for reference.
    const auto spec = sim::staticSpecimen(row.key).value();
    if (spec.hasAxes()) {
      const double kb = value("k_bend"), kt = value("k_tors");
      std::printf("  k_bend %.1f kNm/rad (model %.1f, printed %.1f), k_tors %.1f kNm/rad (model %.1f, printed %.1f)\n",
                  kb / 1e3, spec.modes[0].stiffness() / 1e3, row.kBend / 1e3, kt / 1e3, spec.modes[1].stiffness() / 1e3,
                  row.kTors / 1e3);
      EXPECT_NEAR(kb / spec.modes[0].stiffness(), 1.0, 0.02) << row.key;
      EXPECT_NEAR(kt / spec.modes[1].stiffness(), 1.0, 0.02) << row.key;
      // Against the tables: the model keeps the printed torsion arm and
      // stiffness and closes eq. 22 with the bending arm, so k_bend differs
      // from the print by what eq. 24 misses with the printed numbers (fork A:
      // 0.67 m printed, 0.684 m needed, +2.1%); 2.5% covers it.
      EXPECT_NEAR(kb / row.kBend, 1.0, 0.025) << row.key;
      EXPECT_NEAR(kt / row.kTors, 1.0, 0.025) << row.key;
    }
  }
  store = core::Result<core::io::ProjectStore>(core::makeError(core::ErrorCode::NotFound, "closed", ""));
  fs::remove(path);
  fs::remove(path.string() + "-wal");
  fs::remove(path.string() + "-shm");
}

}  // namespace
}  // namespace mozzi::devices::rigtests
