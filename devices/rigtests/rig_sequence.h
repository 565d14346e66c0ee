#pragma once
// What every rig test sequence shares (stiffness rig, tyre tester; thesis
// §1.1 to §1.3, §1.8, §1.9): results with their uncertainties, the callbacks a
// front end (mozzi-cli, a workbench page) follows a test with, cancel, the
// outcome, and where the test is stored.
//
// Threading. A sequence's run function blocks the thread that calls it (the
// CLI's main thread, a worker thread of the GUI's job runner) until the test
// has ended and its status is stored. Every callback is called on that same
// thread, never on a device's acquisition thread: the sequence queues the
// devices' stream events and handles them itself. `live` is called once per
// data block; the sequences ask for blocks of 25 ms of data, so 40 times a
// second when the rig runs in real time (a simulated rig with sim.realtime off
// delivers faster: a front end that draws should throttle). Callbacks must
// return quickly and must not call into the sequence. CancelFlag::cancel()
// may be called from any thread: the sequence stops the devices within one
// block, keeps what it committed and ends with status Interrupted.

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/io/project_records.h"

namespace mozzi::core::io {
class ProjectStore;
}

namespace mozzi::devices::rigtests {

using core::io::TestStatus;

// One result with its uncertainty. Values are SI (angles in rad); `key` is
// stable (mozzi-cli's JSON key, the project's result name), e.g. "k_lat",
// "axis_inclination" (JSON: "axis_inclination_deg"), "relaxation_length_m".
struct Quantity {
  std::string key;
  std::string label;  // English words for tables ("lateral stiffness"); views translate
  double value = 0.0;
  std::string unit;          // "N/m", "N m/rad", "m", "rad", "Hz", "N", "" ...
  double uncertainty = 0.0;  // one standard deviation, same unit; 0 when unknown
};

// The latest block of data while a step runs, for live readouts and plots.
struct LiveReadout {
  int step = 0;                       // index of the step being acquired
  std::string stepLabel;              // "5 Hz", "slip +2 deg", "ramp"
  double time = 0.0;                  // [s] of the block's last scan since the step started
  double sampleRateHz = 0.0;          // per channel
  std::vector<std::string> channels;  // names of the block's columns
  std::vector<std::string> units;     // their units
  core::Matrix block;                 // scans x channels [units above]
  // Per scan of the block, when the sequence derives one quantity the plot
  // needs (stiffness rig: the load-point displacement from the plane through
  // the lasers, for the force-displacement plot); empty otherwise.
  core::Vector derived;
  std::string derivedLabel;  // "load-point displacement [m]"
};

struct Progress {
  int step = 0;           // current step (0-based)
  int steps = 0;          // planned steps
  double fraction = 0.0;  // of the whole test, [0, 1]
  std::string message;    // "5 Hz: settling", "5 Hz: recording"
};

// A step's outcome, once its record and results are committed.
struct StepReport {
  int step = 0;
  std::string label;  // "5 Hz", "slip +2 deg"
  bool ok = true;     // false: its record is kept but gave no result (note says why)
  std::string note;
  std::vector<Quantity> results;
};

struct Callbacks {
  std::function<void(const LiveReadout&)> live;
  std::function<void(const Progress&)> progress;
  std::function<void(const StepReport&)> step;
  std::function<void(const std::string&)> log;  // one line, for a log view
};

class CancelFlag {
 public:
  void cancel() { flag_.store(true); }
  bool cancelled() const { return flag_.load(); }

 private:
  std::atomic<bool> flag_{false};
};

// Where a test goes: the project (null = not stored, e.g. a dry run in a
// test), the specimen it is tied to, and its name (unique per specimen; empty:
// a name from the test kind and the time).
struct StoreTarget {
  core::io::ProjectStore* store = nullptr;
  std::int64_t specimenId = 0;
  std::string testName;
};

struct Outcome {
  TestStatus status = TestStatus::Complete;
  std::string note;                        // why it stopped and which steps are missing; empty when complete
  std::optional<std::int64_t> testId;      // rig_test.id (stiffness) or tyre_test.id (tyre)
  std::optional<std::int64_t> rigSetupId;  // the stored set-up (devices, channels, geometry)
  std::string testName;
  std::vector<Quantity> results;  // whole-test results
  std::vector<StepReport> steps;  // in order, the ones that ran
};

// A quantity by key; nullptr when absent.
const Quantity* findQuantity(const std::vector<Quantity>& quantities, const std::string& key);

// "interrupted: the device was unplugged during step 3 (10 Hz); steps 3 to 4
// (10 Hz, 15 Hz) are missing" and the like.
std::string missingStepsNote(const std::string& cause, int failedStep, const std::vector<std::string>& labels);

// The note a Running test carries in the project after `committed` steps, so
// that a test cut short by a crash or a power cut says what is missing.
std::string cutShortNote(int committed, const std::vector<std::string>& labels);

}  // namespace mozzi::devices::rigtests
