#include "devices/usb/usb_transport.h"

#include <libusb.h>

#include <chrono>
#include <cstdio>

namespace mozzi::devices::usb {

const char* transferStatusName(TransferStatus status) {
  switch (status) {
    case TransferStatus::Completed: return "completed";
    case TransferStatus::TimedOut: return "timed out";
    case TransferStatus::Stall: return "stall";
    case TransferStatus::NoDevice: return "no device";
    case TransferStatus::Overflow: return "overflow";
    case TransferStatus::Cancelled: return "cancelled";
    case TransferStatus::Error: return "error";
  }
  return "unknown";
}

namespace {

constexpr std::uint8_t kVendorIn = LIBUSB_ENDPOINT_IN | LIBUSB_REQUEST_TYPE_VENDOR | LIBUSB_RECIPIENT_DEVICE;    // 0xC0
constexpr std::uint8_t kVendorOut = LIBUSB_ENDPOINT_OUT | LIBUSB_REQUEST_TYPE_VENDOR | LIBUSB_RECIPIENT_DEVICE;  // 0x40

int hotplugCallback(libusb_context*, libusb_device* device, libusb_hotplug_event event, void* self) {
  if (event == LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT)
    static_cast<UsbTransport*>(self)->deviceLeft(libusb_get_bus_number(device), libusb_get_device_address(device));
  return 0;  // stay registered
}

}  // namespace

core::Error libusbError(int code, const std::string& what, const std::string& where) {
  const auto ec = code == LIBUSB_ERROR_ACCESS                                        ? core::ErrorCode::Locked
                  : code == LIBUSB_ERROR_NO_DEVICE || code == LIBUSB_ERROR_NOT_FOUND ? core::ErrorCode::NotFound
                  : code == LIBUSB_ERROR_TIMEOUT                                     ? core::ErrorCode::IoError
                  : code == LIBUSB_ERROR_BUSY                                        ? core::ErrorCode::Locked
                                                                                     : core::ErrorCode::IoError;
  std::string hint;
  if (code == LIBUSB_ERROR_ACCESS)
    hint = " (no permission on the USB device node: see docs/hardware.md for the udev rule)";
  if (code == LIBUSB_ERROR_BUSY) hint = " (another program holds the device)";
  return core::makeError(ec, what + ": " + libusb_error_name(code) + hint, where);
}

std::string readStringDescriptor(libusb_device_handle* h, std::uint8_t index) {
  if (index == 0) return {};
  unsigned char buf[128] = {};
  const int n = libusb_get_string_descriptor_ascii(h, index, buf, sizeof(buf));
  return n > 0 ? std::string(reinterpret_cast<char*>(buf), static_cast<std::size_t>(n)) : std::string();
}

static std::string readSerial(libusb_device_handle* h, const libusb_device_descriptor& d) {
  return readStringDescriptor(h, d.iSerialNumber);
}

core::Error UsbTransport::usbError(int code, const std::string& what) const {
  return libusbError(code, what, info_.busPath());
}

core::Result<std::vector<UsbDeviceInfo>> UsbTransport::enumerate(std::uint16_t vendorId, std::uint16_t productId) {
  libusb_context* ctx = nullptr;
  int r = libusb_init(&ctx);
  if (r != 0) return libusbError(r, "libusb could not be initialised", "usb");
  libusb_device** list = nullptr;
  const ssize_t n = libusb_get_device_list(ctx, &list);
  if (n < 0) {
    libusb_exit(ctx);
    return libusbError(static_cast<int>(n), "the USB device list could not be read", "usb");
  }
  std::vector<UsbDeviceInfo> found;
  for (ssize_t i = 0; i < n; ++i) {
    libusb_device_descriptor d{};
    if (libusb_get_device_descriptor(list[i], &d) != 0) continue;
    if (d.idVendor != vendorId || d.idProduct != productId) continue;
    UsbDeviceInfo info;
    info.vendorId = d.idVendor;
    info.productId = d.idProduct;
    info.bus = libusb_get_bus_number(list[i]);
    info.address = libusb_get_device_address(list[i]);
    libusb_device_handle* h = nullptr;
    if (libusb_open(list[i], &h) == 0) {
      info.serial = readSerial(h, d);
      libusb_close(h);
    }
    found.push_back(info);
  }
  libusb_free_device_list(list, 1);
  libusb_exit(ctx);
  return found;
}

core::Result<std::unique_ptr<UsbTransport>> UsbTransport::open(std::uint16_t vendorId, std::uint16_t productId,
                                                               const std::string& busPath) {
  std::unique_ptr<UsbTransport> t(new UsbTransport());
  int r = libusb_init(&t->context_);
  if (r != 0) return libusbError(r, "libusb could not be initialised", "usb");
  libusb_device** list = nullptr;
  const ssize_t n = libusb_get_device_list(t->context_, &list);
  if (n < 0) return libusbError(static_cast<int>(n), "the USB device list could not be read", "usb");
  libusb_device* chosen = nullptr;
  libusb_device_descriptor desc{};
  for (ssize_t i = 0; i < n && !chosen; ++i) {
    libusb_device_descriptor d{};
    if (libusb_get_device_descriptor(list[i], &d) != 0 || d.idVendor != vendorId || d.idProduct != productId) continue;
    UsbDeviceInfo info{d.idVendor, d.idProduct, libusb_get_bus_number(list[i]), libusb_get_device_address(list[i]), {}};
    if (busPath.empty() || info.busPath() == busPath) {
      chosen = list[i];
      desc = d;
      t->info_ = info;
    }
  }
  if (!chosen) {
    libusb_free_device_list(list, 1);
    char id[16];
    std::snprintf(id, sizeof id, "%04x:%04x", vendorId, productId);
    return core::makeError(core::ErrorCode::NotFound, std::string("no USB device ") + id + " is connected",
                           busPath.empty() ? std::string("usb") : busPath);
  }
  r = libusb_open(chosen, &t->handle_);
  libusb_free_device_list(list, 1);
  if (r != 0) return t->usbError(r, "the device could not be opened");
  t->info_.serial = readSerial(t->handle_, desc);
  libusb_set_auto_detach_kernel_driver(t->handle_, 1);
  r = libusb_claim_interface(t->handle_, 0);
  if (r != 0) return t->usbError(r, "interface 0 could not be claimed");
  if (libusb_has_capability(LIBUSB_CAP_HAS_HOTPLUG)) {
    // Unplug is also seen by the transfers (status NO_DEVICE); the hotplug
    // callback covers the moments when none is in flight.
    const int h = libusb_hotplug_register_callback(
        t->context_, LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT, LIBUSB_HOTPLUG_NO_FLAGS, vendorId, productId,
        LIBUSB_HOTPLUG_MATCH_ANY, &hotplugCallback, t.get(), &t->hotplugHandle_);
    t->hotplugRegistered_ = h == LIBUSB_SUCCESS;
  }
  t->eventThread_ = std::thread([p = t.get()] { p->eventLoop(); });
  return t;
}

void UsbTransport::deviceLeft(std::uint8_t bus, std::uint8_t address) {
  if (bus != info_.bus || address != info_.address) return;
  disconnected_ = true;
  std::lock_guard<std::mutex> l(hotplugMutex_);
  if (onDisconnect_) onDisconnect_();
}

void UsbTransport::setDisconnectCallback(std::function<void()> callback) {
  std::lock_guard<std::mutex> l(hotplugMutex_);
  onDisconnect_ = std::move(callback);
}

UsbTransport::~UsbTransport() {
  setDisconnectCallback(nullptr);
  if (hotplugRegistered_) libusb_hotplug_deregister_callback(context_, hotplugHandle_);
  stopBulkIn();
  if (handle_) {
    libusb_release_interface(handle_, 0);
    libusb_close(handle_);  // wakes the event thread
    handle_ = nullptr;
  }
  quit_ = true;
  if (context_) libusb_interrupt_event_handler(context_);
  if (eventThread_.joinable()) eventThread_.join();
  for (auto* tr : transfers_) libusb_free_transfer(tr);
  if (context_) libusb_exit(context_);
}

void UsbTransport::eventLoop() {
  while (!quit_.load()) {
    timeval tv{0, 100000};  // 100 ms: bounds the latency of quit_
    const int r = libusb_handle_events_timeout_completed(context_, &tv, nullptr);
    if (r == LIBUSB_ERROR_NO_DEVICE) disconnected_ = true;
  }
}

core::Result<std::vector<std::uint8_t>> UsbTransport::controlIn(std::uint8_t request, std::uint16_t value,
                                                                std::uint16_t index, std::uint16_t length,
                                                                unsigned timeoutMs) {
  std::vector<std::uint8_t> data(length);
  const int r = libusb_control_transfer(handle_, kVendorIn, request, value, index, data.data(), length, timeoutMs);
  if (r < 0) {
    if (r == LIBUSB_ERROR_NO_DEVICE) disconnected_ = true;
    char what[64];
    std::snprintf(what, sizeof what, "vendor request 0x%02X (in) failed", request);
    return usbError(r, what);
  }
  data.resize(static_cast<std::size_t>(r));
  return data;
}

core::Result<void> UsbTransport::controlOut(std::uint8_t request, std::uint16_t value, std::uint16_t index,
                                            const std::vector<std::uint8_t>& data, unsigned timeoutMs) {
  std::vector<std::uint8_t> copy = data;
  const int r =
      libusb_control_transfer(handle_, kVendorOut, request, value, index, copy.empty() ? nullptr : copy.data(),
                              static_cast<std::uint16_t>(copy.size()), timeoutMs);
  if (r < 0) {
    if (r == LIBUSB_ERROR_NO_DEVICE) disconnected_ = true;
    char what[64];
    std::snprintf(what, sizeof what, "vendor request 0x%02X (out) failed", request);
    return usbError(r, what);
  }
  return {};
}

core::Result<void> UsbTransport::clearHalt(std::uint8_t endpoint) {
  const int r = libusb_clear_halt(handle_, endpoint);
  if (r != 0) {
    if (r == LIBUSB_ERROR_NO_DEVICE) disconnected_ = true;
    return usbError(r, "clearing the halt of the bulk endpoint failed");
  }
  return {};
}

core::Result<void> UsbTransport::startBulkIn(std::uint8_t endpoint, int transferBytes, int transfers,
                                             unsigned timeoutMs, BulkCallback callback) {
  std::unique_lock<std::mutex> lock(bulkMutex_);
  if (inFlight_ > 0)
    return core::makeError(core::ErrorCode::InvalidArgument, "bulk transfers are already running", info_.busPath());
  if (transferBytes <= 0 || transfers <= 0)
    return core::makeError(core::ErrorCode::InvalidArgument, "transfer size and count must be positive",
                           info_.busPath());
  for (auto* tr : transfers_) libusb_free_transfer(tr);
  transfers_.clear();
  buffers_.assign(static_cast<std::size_t>(transfers),
                  std::vector<std::uint8_t>(static_cast<std::size_t>(transferBytes)));
  callback_ = std::move(callback);
  resubmit_ = true;
  for (int i = 0; i < transfers; ++i) {
    libusb_transfer* tr = libusb_alloc_transfer(0);
    if (!tr) return core::makeError(core::ErrorCode::IoError, "out of memory for USB transfers", info_.busPath());
    libusb_fill_bulk_transfer(tr, handle_, endpoint, buffers_[static_cast<std::size_t>(i)].data(), transferBytes,
                              &transferCallback, this, timeoutMs);
    transfers_.push_back(tr);
  }
  for (auto* tr : transfers_) {
    const int r = libusb_submit_transfer(tr);
    if (r != 0) {
      resubmit_ = false;
      lock.unlock();
      stopBulkIn();
      if (r == LIBUSB_ERROR_NO_DEVICE) disconnected_ = true;
      return usbError(r, "a bulk transfer could not be submitted");
    }
    ++inFlight_;
  }
  return {};
}

void UsbTransport::stopBulkIn() {
  std::unique_lock<std::mutex> lock(bulkMutex_);
  resubmit_ = false;
  for (auto* tr : transfers_) libusb_cancel_transfer(tr);  // LIBUSB_ERROR_NOT_FOUND for finished ones: fine
  // Every submitted transfer comes back (cancelled, completed or failed) through
  // the event thread; wait for all so that no callback runs after this returns.
  bulkCv_.wait(lock, [&] { return inFlight_ == 0; });
}

void UsbTransport::transferCallback(libusb_transfer* transfer) {
  static_cast<UsbTransport*>(transfer->user_data)->onTransfer(transfer);
}

void UsbTransport::onTransfer(libusb_transfer* transfer) {
  TransferStatus status = TransferStatus::Error;
  switch (transfer->status) {
    case LIBUSB_TRANSFER_COMPLETED: status = TransferStatus::Completed; break;
    case LIBUSB_TRANSFER_TIMED_OUT: status = TransferStatus::TimedOut; break;
    case LIBUSB_TRANSFER_STALL: status = TransferStatus::Stall; break;
    case LIBUSB_TRANSFER_NO_DEVICE:
      status = TransferStatus::NoDevice;
      disconnected_ = true;
      break;
    case LIBUSB_TRANSFER_OVERFLOW: status = TransferStatus::Overflow; break;
    case LIBUSB_TRANSFER_CANCELLED: status = TransferStatus::Cancelled; break;
    case LIBUSB_TRANSFER_ERROR: status = TransferStatus::Error; break;
  }
  completed_.fetch_add(1);
  std::unique_lock<std::mutex> lock(bulkMutex_);
  const bool keepGoing = resubmit_ && status == TransferStatus::Completed;
  if (callback_ && !(status == TransferStatus::Cancelled && !resubmit_)) {
    // Deliver outside the lock would allow reordering between transfers; the
    // callback is short (a copy into the driver's queue), so hold it.
    callback_(status, transfer->buffer, transfer->actual_length);
  }
  if (keepGoing) {
    const int r = libusb_submit_transfer(transfer);
    if (r == 0) return;
    if (r == LIBUSB_ERROR_NO_DEVICE) disconnected_ = true;
    if (callback_)
      callback_(r == LIBUSB_ERROR_NO_DEVICE ? TransferStatus::NoDevice : TransferStatus::Error, nullptr, 0);
  }
  if (status != TransferStatus::Completed) resubmit_ = false;
  --inFlight_;
  if (inFlight_ == 0) bulkCv_.notify_all();
}

}  // namespace mozzi::devices::usb
