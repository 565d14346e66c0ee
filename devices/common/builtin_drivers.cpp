#include "devices/common/driver.h"
#include "devices/funcgen/funcgen_driver.h"
#include "devices/mcc_usb1608fsplus/usb1608fsplus_driver.h"
#include "devices/sim/sim_drivers.h"

namespace mozzi::devices {

DriverRegistry& builtinDrivers() {
  // Explicit list rather than static self-registration: objects of a static
  // library that nothing references would be dropped by the linker.
  static DriverRegistry registry = [] {
    DriverRegistry r;
    (void)r.add(mcc::makeUsb1608FsPlusDriver());
    (void)r.add(sim::makeHammerStationDriver());
    (void)r.add(sim::makeStiffnessRigDriver());
    (void)r.add(sim::makeTyreTesterDriver());
    (void)r.add(sim::makeFunctionGeneratorSimDriver());
    (void)r.add(sim::makeReplayDriver());
    (void)r.add(funcgen::makeFunctionGeneratorDriver());
    return r;
  }();
  return registry;
}

}  // namespace mozzi::devices
