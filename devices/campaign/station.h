#pragma once
// The acquisition device of a campaign, found again after an unplug. The
// engine asks for the device when it needs one and drops it when it went
// away (an unplugged USB device must be scanned and opened anew); a real
// DAQ (MCC USB-1608FS-Plus) and a simulated station (sim-hammer) are
// reached the same way, through the driver registry.

#include <memory>
#include <string>

#include "devices/common/driver.h"

namespace mozzi::devices::campaign {

class Station {
 public:
  virtual ~Station() = default;
  virtual std::string label() const = 0;  // "sim-hammer", "mcc-usb1608fsplus serial 01ABCDEF"
  // The open device, connecting first when needed; an error (device absent)
  // leaves the station disconnected.
  virtual core::Result<Device*> connect() = 0;
  // Forgets the device (stopped and closed); the next connect() scans again.
  virtual void disconnect() = 0;
};

// A station over a driver of `registry` (which must outlive it): the device
// with `serial`, or the first one found when serial is empty.
std::unique_ptr<Station> makeDriverStation(const DriverRegistry& registry, std::string driver, std::string serial = {});

}  // namespace mozzi::devices::campaign
