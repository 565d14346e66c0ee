#include "devices/common/driver.h"

#include <cstdio>

namespace mozzi::devices {

std::string DeviceDescriptor::label() const {
  std::string s = model.empty() ? driver : model;
  std::string extra;
  if (!serial.empty()) extra = "serial " + serial;
  if (!busPath.empty()) extra += (extra.empty() ? "" : ", ") + busPath;
  if (!extra.empty()) s += " (" + extra + ")";
  return s;
}

core::Result<void> DriverRegistry::add(std::unique_ptr<Driver> driver) {
  if (!driver) return core::makeError(core::ErrorCode::InvalidArgument, "no driver given", "driver registry");
  if (find(driver->name()))
    return core::makeError(core::ErrorCode::InvalidArgument, "a driver with this name is already registered",
                           "driver " + driver->name());
  drivers_.push_back(std::move(driver));
  return {};
}

Driver* DriverRegistry::find(const std::string& name) const {
  for (const auto& d : drivers_)
    if (d->name() == name) return d.get();
  return nullptr;
}

std::vector<Driver*> DriverRegistry::drivers() const {
  std::vector<Driver*> out;
  for (const auto& d : drivers_) out.push_back(d.get());
  return out;
}

std::vector<DeviceDescriptor> DriverRegistry::scanAll(std::vector<std::string>* failures) const {
  std::vector<DeviceDescriptor> all;
  for (const auto& d : drivers_) {
    auto found = d->scan();
    if (!found) {
      if (failures) failures->push_back(d->name() + ": " + found.error().describe());
      continue;
    }
    all.insert(all.end(), found->begin(), found->end());
  }
  return all;
}

core::Result<std::unique_ptr<Device>> DriverRegistry::create(const DeviceDescriptor& descriptor) const {
  Driver* d = find(descriptor.driver);
  if (!d)
    return core::makeError(core::ErrorCode::NotFound, "no driver with this name is registered",
                           "driver " + descriptor.driver);
  return d->create(descriptor);
}

}  // namespace mozzi::devices
