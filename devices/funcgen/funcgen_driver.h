#pragma once
// Driver "usbtmc-funcgen": a SCPI function generator on USBTMC giving the
// stiffness rig's actuator controller its set-point (thesis §1.1: static ramp
// up to 5000 N, sine 1 to 45 Hz). Same parameter keys as the simulated rig
// (sim-stiffness) so the GUI form and the CLI options are the same:
//   mode static-ramp | sine, static.max_force [N], static.period_s [s],
//   sine.frequency [Hz], sine.amplitude [N], actuator.newtons_per_volt [N/V],
//   channel.
// Forces become volts through the controller's input scale (N/V); the ramp is
// the generator's RAMP at 50% symmetry (a triangle -F .. +F over the period).
// The device has no inputs: configure() takes no channels and returns the
// setting read back from the instrument; start() switches the output on and
// emits the header, stop() switches it off and emits the end; an unplug while
// the output runs ends the stream at once ("device disconnected", from the
// transport's hotplug monitor). The output is switched off on open and on
// close, so the actuator only moves between start() and stop().

#include <memory>
#include <vector>

#include "devices/common/driver.h"

namespace mozzi::devices::funcgen {

std::unique_ptr<Driver> makeFunctionGeneratorDriver();

// The rig parameters above as the generator declares them, for `channels`
// outputs; the simulated generator (devices/sim "sim-funcgen") declares the same.
std::vector<ParameterSpec> setPointParameters(int channels);

}  // namespace mozzi::devices::funcgen
