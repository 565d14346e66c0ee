#include "devices/campaign/station.h"

namespace mozzi::devices::campaign {
namespace {

class DriverStation final : public Station {
 public:
  DriverStation(const DriverRegistry& registry, std::string driver, std::string serial)
      : registry_(registry), driver_(std::move(driver)), serial_(std::move(serial)) {}
  ~DriverStation() override { disconnect(); }

  std::string label() const override { return serial_.empty() ? driver_ : driver_ + " serial " + serial_; }

  core::Result<Device*> connect() override {
    if (device_) return device_.get();
    Driver* d = registry_.find(driver_);
    if (!d) return core::makeError(core::ErrorCode::NotFound, "no driver named '" + driver_ + "'", "station");
    auto found = d->scan();
    if (!found) return found.error();
    const DeviceDescriptor* pick = nullptr;
    for (const auto& desc : *found)
      if (serial_.empty() || desc.serial == serial_) {
        pick = &desc;
        break;
      }
    if (!pick)
      return core::makeError(core::ErrorCode::NotFound,
                             serial_.empty() ? "no device found" : "device with serial " + serial_ + " not found",
                             label());
    auto dev = d->create(*pick);
    if (!dev) return dev.error();
    if (auto o = (*dev)->open(); !o) return o.error();
    device_ = std::move(*dev);
    return device_.get();
  }

  void disconnect() override {
    if (!device_) return;
    device_->stop();
    device_->close();
    device_.reset();
  }

 private:
  const DriverRegistry& registry_;
  std::string driver_, serial_;
  std::unique_ptr<Device> device_;
};

}  // namespace

std::unique_ptr<Station> makeDriverStation(const DriverRegistry& registry, std::string driver, std::string serial) {
  return std::make_unique<DriverStation>(registry, std::move(driver), std::move(serial));
}

}  // namespace mozzi::devices::campaign
