#pragma once
// The driver model (libsigrok's api/protocol split, STYLE 1): a Driver scans
// for devices and creates them; a Device opens, declares its capabilities as
// data, validates and applies a configuration, and streams typed events to a
// sink between start() and stop(). Real and simulated rigs are registered the
// same way in one DriverRegistry.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "devices/common/acquisition.h"

namespace mozzi::devices {

struct DeviceDescriptor {
  std::string driver;          // registry key, e.g. "mcc-usb1608fsplus", "sim-hammer"
  std::string model;           // "MCC USB-1608FS-Plus"
  std::uint16_t vendorId = 0;  // USB VID:PID (0 for simulated rigs)
  std::uint16_t productId = 0;
  std::string serial;
  std::string busPath;        // "usb:1.2" (bus.address), "sim:0"
  std::string label() const;  // "MCC USB-1608FS-Plus (serial 01ABCDEF, usb:1.2)"
};

enum class DeviceState { Closed, Open, Configured, Running };

class Device {
 public:
  virtual ~Device() = default;
  virtual const DeviceDescriptor& descriptor() const = 0;
  virtual core::Result<void> open() = 0;
  virtual void close() = 0;
  virtual Capabilities capabilities() const = 0;
  // Validates `requested` against the capabilities and returns the
  // configuration actually applied (quantised rate, completed parameters).
  virtual core::Result<AcquisitionConfig> configure(const AcquisitionConfig& requested) = 0;
  // Starts streaming to `sink` on the device's own thread; the stream always
  // ends with one StreamEnd (completed, stopped, disconnected, ...).
  virtual core::Result<void> start(StreamSink sink) = 0;
  // Stops, waits for the acquisition thread and the end event; idempotent.
  virtual void stop() = 0;
  virtual DeviceState state() const = 0;
};

class Driver {
 public:
  virtual ~Driver() = default;
  virtual std::string name() const = 0;         // registry key
  virtual std::string description() const = 0;  // one line
  virtual bool simulated() const = 0;
  virtual core::Result<std::vector<DeviceDescriptor>> scan() = 0;
  virtual core::Result<std::unique_ptr<Device>> create(const DeviceDescriptor& descriptor) = 0;
};

class DriverRegistry {
 public:
  // Adds a driver; an error when one with the same name is present.
  core::Result<void> add(std::unique_ptr<Driver> driver);
  Driver* find(const std::string& name) const;
  std::vector<Driver*> drivers() const;
  // Descriptors from every driver; drivers whose scan fails are reported in
  // `failures` (driver name: message) and do not hide the others.
  std::vector<DeviceDescriptor> scanAll(std::vector<std::string>* failures = nullptr) const;
  core::Result<std::unique_ptr<Device>> create(const DeviceDescriptor& descriptor) const;

 private:
  std::vector<std::unique_ptr<Driver>> drivers_;
};

// Every driver built into mozzi_devices (real hardware and simulated rigs).
DriverRegistry& builtinDrivers();

}  // namespace mozzi::devices
