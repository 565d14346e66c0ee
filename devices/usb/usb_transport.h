#pragma once
// USB transport over libusb 1.0 (STYLE 4): one libusb context per transport
// with its own event thread, synchronous control transfers, and a ring of
// asynchronous bulk-IN transfers whose every completion status is mapped on
// purpose. No protocol knowledge here: codecs live beside each driver.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/common/result.h"

struct libusb_context;
struct libusb_device_handle;
struct libusb_transfer;

namespace mozzi::devices::usb {

// Completion of one transfer, as the driver must treat it.
enum class TransferStatus {
  Completed,  // data (possibly a short packet)
  TimedOut,   // no data within the transfer timeout
  Stall,      // endpoint halted (USB-1608FS-Plus: FIFO overrun)
  NoDevice,   // unplugged: end the session cleanly
  Overflow,   // device sent more than asked: a protocol fault
  Cancelled,  // we cancelled it (stop)
  Error,      // any other transport error
};

const char* transferStatusName(TransferStatus status);

// A libusb error code as a core::Error: unplug -> NotFound, permission or busy
// -> Locked (with the udev hint), the rest IoError; the message names `what`.
core::Error libusbError(int code, const std::string& what, const std::string& where);
// String descriptor `index` in ASCII; empty for index 0 or when unreadable.
std::string readStringDescriptor(libusb_device_handle* handle, std::uint8_t index);

struct UsbDeviceInfo {
  std::uint16_t vendorId = 0;
  std::uint16_t productId = 0;
  std::uint8_t bus = 0;
  std::uint8_t address = 0;
  std::string serial;  // empty when the device could not be opened to read it
  std::string busPath() const { return "usb:" + std::to_string(bus) + "." + std::to_string(address); }
};

class UsbTransport {
 public:
  using BulkCallback = std::function<void(TransferStatus status, const std::uint8_t* data, int length)>;

  // Devices with this VID:PID on the system (serials read where permitted).
  static core::Result<std::vector<UsbDeviceInfo>> enumerate(std::uint16_t vendorId, std::uint16_t productId);
  // Opens the device at `busPath` ("usb:B.A"), or the first with VID:PID when
  // busPath is empty, claims interface 0 and starts the event thread.
  static core::Result<std::unique_ptr<UsbTransport>> open(std::uint16_t vendorId, std::uint16_t productId,
                                                          const std::string& busPath);
  ~UsbTransport();
  UsbTransport(const UsbTransport&) = delete;
  UsbTransport& operator=(const UsbTransport&) = delete;

  const UsbDeviceInfo& info() const { return info_; }

  // Vendor requests to the device (bmRequestType 0xC0 in, 0x40 out).
  core::Result<std::vector<std::uint8_t>> controlIn(std::uint8_t request, std::uint16_t value, std::uint16_t index,
                                                    std::uint16_t length, unsigned timeoutMs = 2000);
  core::Result<void> controlOut(std::uint8_t request, std::uint16_t value, std::uint16_t index,
                                const std::vector<std::uint8_t>& data, unsigned timeoutMs = 2000);
  core::Result<void> clearHalt(std::uint8_t endpoint);

  // Submits `transfers` bulk-IN transfers of `transferBytes` each and keeps
  // resubmitting them while they complete normally. Every completion calls
  // `callback` on the event thread (keep it short: copy and return). On any
  // other status the ring stops resubmitting; the caller decides.
  core::Result<void> startBulkIn(std::uint8_t endpoint, int transferBytes, int transfers, unsigned timeoutMs,
                                 BulkCallback callback);
  // Cancels the ring and waits until every transfer has come back; idempotent.
  void stopBulkIn();
  bool disconnected() const { return disconnected_.load(); }
  // Called on the event thread when libusb's hotplug monitor reports that this
  // device left (where the platform supports hotplug); set before streaming.
  void setDisconnectCallback(std::function<void()> callback);
  // Entry point of libusb's hotplug callback (event thread): a device left.
  void deviceLeft(std::uint8_t bus, std::uint8_t address);
  std::int64_t transfersCompleted() const { return completed_.load(); }

 private:
  UsbTransport() = default;
  static void transferCallback(libusb_transfer* transfer);
  void onTransfer(libusb_transfer* transfer);
  void eventLoop();
  core::Error usbError(int code, const std::string& what) const;

  libusb_context* context_ = nullptr;
  libusb_device_handle* handle_ = nullptr;
  UsbDeviceInfo info_;
  std::thread eventThread_;
  std::atomic<bool> quit_{false};
  std::atomic<bool> disconnected_{false};
  std::atomic<std::int64_t> completed_{0};

  std::mutex bulkMutex_;
  std::condition_variable bulkCv_;
  std::vector<libusb_transfer*> transfers_;
  std::vector<std::vector<std::uint8_t>> buffers_;
  int inFlight_ = 0;
  bool resubmit_ = false;
  BulkCallback callback_;
  std::mutex hotplugMutex_;
  std::function<void()> onDisconnect_;
  int hotplugHandle_ = 0;
  bool hotplugRegistered_ = false;
};

}  // namespace mozzi::devices::usb
