// Fuzz target: what users type or point the simulated rigs at. The tyre
// tester's yaw-frequency list ("0.42,0.84,...", a configure() parameter) and
// the replay driver's recording (a file named as the bus path, checked at
// open() for load cases, channels and sample spacing). Bad input must give an
// error naming the parameter or file, never a crash.

#include <unistd.h>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include "devices/common/driver.h"
#include "devices/sim/sim_drivers.h"

namespace {

using namespace mozzi::devices;

Device& tyreTester() {
  static std::unique_ptr<Device> device = [] {
    auto d = sim::makeTyreTesterDriver()->create(DeviceDescriptor{"sim-tyre-tester", "", 0, 0, "", "sim:0"}).value();
    (void)d->open();
    return d;
  }();
  return *device;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);

  AcquisitionConfig cfg;
  cfg.sampleRateHz = 100.0;
  ChannelConfig fy;
  fy.input = 1;
  fy.name = "Fy";
  cfg.channels = {fy};
  cfg.parameters["yaw.frequencies_hz"] = text;
  (void)tyreTester().configure(cfg);

  // One file per process: the replay driver reads the recording at open().
  static const std::string path = "/tmp/mozzi_sim_rig_inputs_fuzz_" + std::to_string(::getpid()) + ".uff";
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  }
  auto replay = sim::makeReplayDriver()->create(DeviceDescriptor{"sim-replay", "", 0, 0, "", path});
  if (replay.ok() && (*replay)->open().ok()) {
    AcquisitionConfig all;
    all.sampleRateHz = 1000.0;
    ChannelConfig c;
    c.input = 0;
    all.channels = {c};
    (void)(*replay)->configure(all);
    (*replay)->close();
  }
  return 0;
}
