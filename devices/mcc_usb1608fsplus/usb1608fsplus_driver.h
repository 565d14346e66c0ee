#pragma once
// MCC USB-1608FS-Plus driver (STYLE 1: libsigrok's api.c): discovery, the
// capabilities of the device as data, configuration, and a streaming session
// over UsbTransport with every transfer status handled on purpose (STYLE 4):
//   completed -> data; stall -> overrun: read status, stop, clear halt and
//   FIFO, report, then restart or end (parameter "overrun.policy");
//   no device -> end "device disconnected" after handing on the data so far;
//   timed out -> end "transfer timeout"; anything else -> end "error".

#include <memory>

#include "devices/common/driver.h"

namespace mozzi::devices::mcc {

std::unique_ptr<Driver> makeUsb1608FsPlusDriver();

}  // namespace mozzi::devices::mcc
