// The tyre-tester sequences (devices/rigtests/tyre_tests.h) on the simulated
// Mototiremeter: set-points beyond the machine's limits (camber +/-55 deg,
// side-slip +/-10 deg, 50 km/h) or the working limits refused before anything
// is sent, naming the limit; an unplug during the harmonic yaw programme ends
// the test with the finished frequencies stored; what a steady-state test
// stores. The numbers (relaxation length, cornering stiffness against the
// virtual tyre) are checked in tests/validation/rigtests_tyre_test.cpp.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/io/project_store.h"
#include "devices/rigtests/tyre_tests.h"
#include "devices/sim/sim_drivers.h"

namespace mozzi::devices::rigtests {
namespace {

namespace fs = std::filesystem;

class TyreSequence : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = fs::temp_directory_path() / ("rigtests_tyre_" + std::to_string(::getpid()) + "_" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".mozzi");
    fs::remove(path_);
    auto s = core::io::ProjectStore::create(path_.string(), "test");
    ASSERT_TRUE(s.ok()) << s.error().describe();
    store_.emplace(std::move(*s));
    auto id = store_->addSpecimen("Tyre 120/70 R17", "tyre", "test");
    ASSERT_TRUE(id.ok());
    specimen_ = *id;
    auto dev = sim::makeTyreTesterDriver()->create(DeviceDescriptor{"sim-tyre-tester", "", 0, 0, "", "sim:0"});
    ASSERT_TRUE(dev.ok());
    device_ = std::move(*dev);
    auto setup = simulatedTyreSetup("tyre-120-70-r17", 2.0, 3, false);
    ASSERT_TRUE(setup.ok()) << setup.error().describe();
    setup_ = *setup;
  }
  void TearDown() override {
    device_.reset();
    store_.reset();
    fs::remove(path_);
    fs::remove(path_.string() + "-wal");
    fs::remove(path_.string() + "-shm");
  }
  sim::FaultCounters counters() { return dynamic_cast<sim::SimulatedRig&>(*device_).counters(); }
  // Refused, with `words` in the message, and nothing sent to the tester.
  void expectRefusedBeforeAnythingMoves(const core::Result<SteadyStateOutcome>& r, const std::string& words) {
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find(words), std::string::npos) << r.error().describe();
    EXPECT_EQ(device_->state(), DeviceState::Closed);
    EXPECT_EQ(counters().scansGenerated, 0);
  }

  fs::path path_;
  std::optional<core::io::ProjectStore> store_;
  std::int64_t specimen_ = 0;
  std::unique_ptr<Device> device_;
  TyreRigSetup setup_;
};

TEST_F(TyreSequence, SetPointsBeyondTheMachineAreRefusedBeforeAnythingMoves) {
  const StoreTarget target{&*store_, specimen_, ""};
  SteadyStateSettings s;
  s.camberDeg = {0, 30, 56};  // the machine's camber limit is +/-55 deg (appendix 2)
  setup_.camberLimitDeg = 55.0;
  expectRefusedBeforeAnythingMoves(runSteadyStateTest(*device_, setup_, s, target), "camber limit of +/-55 deg");
  s.camberDeg = {0};
  s.slipDeg = {-10.5, 0};  // side-slip +/-10 deg (§1.8)
  setup_.slipLimitDeg = 10.0;
  expectRefusedBeforeAnythingMoves(runSteadyStateTest(*device_, setup_, s, target), "side-slip limit of +/-10 deg");
  s.slipDeg = {0};
  s.speedKmh = 60.0;  // the disk runs up to 50 km/h
  expectRefusedBeforeAnythingMoves(runSteadyStateTest(*device_, setup_, s, target), "50 km/h");
  // Within the machine but beyond the operator's working limits (+/-6, +/-45 deg by default, §1.8).
  setup_.slipLimitDeg = 6.0;
  setup_.camberLimitDeg = 45.0;
  s.speedKmh = 5.0;
  s.slipDeg = {8};
  expectRefusedBeforeAnythingMoves(runSteadyStateTest(*device_, setup_, s, target), "working side-slip limit of +/-6");
  s.slipDeg = {0};
  s.camberDeg = {50};
  expectRefusedBeforeAnythingMoves(runSteadyStateTest(*device_, setup_, s, target), "working camber limit of +/-45");
  RelaxationSettings r;
  r.yawAmplitudeDeg = 11.0;
  auto rel = runRelaxationTest(*device_, setup_, r, target);
  ASSERT_FALSE(rel.ok());
  EXPECT_NE(rel.error().message.find("side-slip limit of +/-10 deg"), std::string::npos) << rel.error().describe();
  EXPECT_EQ(counters().scansGenerated, 0);
  auto tests = store_->tyreTests();
  ASSERT_TRUE(tests.ok());
  EXPECT_TRUE(tests->empty());
}

TEST_F(TyreSequence, AnUnplugDuringTheYawProgrammeKeepsTheFinishedFrequencies) {
  // 10 cycles at 2.1 Hz (4.76 s), then 10 at 1.05 Hz (9.52 s): unplugged 8 s in.
  setup_.daqParameters["fault.disconnect_after_s"] = 8.0;
  RelaxationSettings r;
  r.frequenciesHz = {2.1, 1.05};
  auto out = runRelaxationTest(*device_, setup_, r, StoreTarget{&*store_, specimen_, "unplugged"});
  ASSERT_TRUE(out.ok()) << out.error().describe();
  EXPECT_EQ(out->status, TestStatus::Interrupted);
  EXPECT_NE(out->note.find("unplugged"), std::string::npos) << out->note;
  EXPECT_NE(out->note.find("step 1 is missing (1.05 Hz)"), std::string::npos) << out->note;
  ASSERT_EQ(out->steps.size(), 1u);
  EXPECT_TRUE(out->steps[0].ok) << out->steps[0].note;
  EXPECT_NE(findQuantity(out->steps[0].results, "relaxation_length_m"), nullptr);
  EXPECT_EQ(counters().disconnects, 1);
  auto t = store_->tyreTest(*out->testId);
  ASSERT_TRUE(t.ok());
  EXPECT_EQ(t->status, core::io::TestStatus::Interrupted);
  EXPECT_EQ(t->kind, "relaxation");
  EXPECT_TRUE(store_->tyreTestRecord(*out->testId, 0).ok());
  auto partial = store_->tyreTestRecord(*out->testId, 1);
  ASSERT_TRUE(partial.ok());  // the unfinished frequency's data, without a result
  EXPECT_EQ(partial->cols(), 6);
  bool sigma0 = false, sigma1 = false;
  for (const auto& p : t->parameters) {
    sigma0 |= p.step == 0 && p.name == "relaxation_length_m";
    sigma1 |= p.step == 1 && p.name == "relaxation_length_m";
  }
  EXPECT_TRUE(sigma0);
  EXPECT_FALSE(sigma1);
}

TEST_F(TyreSequence, SteadyStateStoresOnePointPerSetPoint) {
  SteadyStateSettings s;
  s.slipDeg = {-3, -2, -1, 0, 1, 2, 3};
  s.camberDeg = {-20, -10, 0, 10, 20};
  s.settleS = 1.0;
  s.holdS = 1.0;
  int steps = 0;
  Callbacks cb;
  cb.step = [&](const StepReport& r) {
    EXPECT_TRUE(r.ok) << r.label << ": " << r.note;
    ++steps;
  };
  auto out = runSteadyStateTest(*device_, setup_, s, StoreTarget{&*store_, specimen_, "sweeps"}, cb);
  ASSERT_TRUE(out.ok()) << out.error().describe();
  EXPECT_EQ(steps, 12);
  EXPECT_EQ(out->points.size(), 12u);
  ASSERT_NE(findQuantity(out->results, "cornering_stiffness"), nullptr) << out->note;
  ASSERT_NE(findQuantity(out->results, "camber_stiffness"), nullptr) << out->note;
  auto t = store_->tyreTest(*out->testId);
  ASSERT_TRUE(t.ok());
  EXPECT_EQ(t->kind, "steady-state");
  EXPECT_EQ(t->points.size(), 12u);
  EXPECT_NEAR(t->points[7].camberRad, -20 * 3.14159265358979323846 / 180, 1e-12);
  EXPECT_NEAR(t->verticalLoadN, 1500.0, 1e-9);
  for (int k = 0; k < 12; ++k) EXPECT_TRUE(store_->tyreTestRecord(*out->testId, k).ok()) << k;
}

}  // namespace
}  // namespace mozzi::devices::rigtests
