#pragma once
// USBTMC/USB488 transport over libusb 1.0 (STYLE 4): finds instruments by
// their interface class (0xFE/0x03), claims that interface (detaching the
// kernel's usbtmc driver), and exchanges whole messages with synchronous bulk
// transfers. Every libusb outcome is mapped on purpose:
//   timeout on Bulk-OUT -> INITIATE_ABORT_BULK_OUT, CHECK_ABORT_BULK_OUT_STATUS
//     until done, CLEAR_FEATURE(HALT) on Bulk-OUT; the error names the timeout;
//   timeout on Bulk-IN -> INITIATE_ABORT_BULK_IN, read Bulk-IN until the short
//     packet, CHECK_ABORT_BULK_IN_STATUS until done;
//   an abort that fails -> device clear (INITIATE_CLEAR, CHECK_CLEAR_STATUS,
//     CLEAR_FEATURE(HALT) on Bulk-OUT), so the next command starts clean;
//   stall -> clear the halt, report; no device (a transfer's status, or the
//     hotplug monitor on the transport's event thread) -> "unplugged", every
//     later call fails at once with the same clear error, nothing hangs.
// Codec (headers, tags, class requests): usbtmc_protocol.h.

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "devices/usb/usb_transport.h"
#include "devices/usbtmc/scpi.h"
#include "devices/usbtmc/usbtmc_protocol.h"

struct libusb_context;
struct libusb_device_handle;

namespace mozzi::devices::usbtmc {

struct UsbtmcDeviceInfo {
  usb::UsbDeviceInfo usb;    // VID:PID, bus path, serial
  std::string manufacturer;  // USB string descriptors (empty when not readable)
  std::string product;
  std::uint8_t interfaceNumber = 0;
  std::uint8_t protocol = kProtocolUsb488;                // 0 plain USBTMC, 1 USB488
  std::uint8_t bulkOut = 0, bulkIn = 0, interruptIn = 0;  // endpoint addresses (interruptIn 0: none)
  std::uint16_t bulkInMaxPacket = 64;
};

struct UsbtmcOptions {
  // Data bytes per Bulk-OUT transfer and asked for per REQUEST_DEV_DEP_MSG_IN;
  // longer messages take several transfers.
  std::uint32_t maxTransferData = 4096 - kHeaderBytes;
  std::size_t maxResponseBytes = std::size_t{1} << 20;
  bool clearOnOpen = true;  // device clear on open: stale output of a previous program is dropped
  unsigned controlTimeoutMs = 1000;
  int abortPolls = 50;  // CHECK_* polls before giving up (10 ms apart)
};

class UsbtmcTransport final : public MessageChannel {
 public:
  // USBTMC interfaces on the system (any VID:PID).
  static core::Result<std::vector<UsbtmcDeviceInfo>> enumerate();
  // Opens the instrument at `busPath` ("usb:B.A"), or the first one found when
  // empty, and claims its USBTMC interface.
  static core::Result<std::unique_ptr<UsbtmcTransport>> open(const std::string& busPath, UsbtmcOptions options = {});
  ~UsbtmcTransport() override;
  UsbtmcTransport(const UsbtmcTransport&) = delete;
  UsbtmcTransport& operator=(const UsbtmcTransport&) = delete;

  const UsbtmcDeviceInfo& info() const { return info_; }
  const Capabilities& capabilities() const { return caps_; }
  bool disconnected() const { return disconnected_.load(); }
  // Called on the transport's event thread when libusb's hotplug monitor sees
  // the instrument leave (where the platform has hotplug): an idle session
  // learns of an unplug without waiting for its next transfer. Keep it short
  // and do no I/O on this transport in it.
  void setDisconnectCallback(std::function<void()> callback);
  // Entry point of libusb's hotplug callback (event thread).
  void deviceLeft(std::uint8_t bus, std::uint8_t address);

  core::Result<void> write(const std::string& message, unsigned timeoutMs) override;
  core::Result<std::string> read(unsigned timeoutMs) override;
  core::Result<void> clear() override;
  std::string where() const override { return "usbtmc " + info_.usb.busPath(); }

  // USB488 READ_STATUS_BYTE (the IEEE 488.2 status byte without a bus poll).
  core::Result<std::uint8_t> readStatusByte();
  // Abort recovery, public for the tests: abort the transfer with `tag`.
  core::Result<void> abortBulkOut(std::uint8_t tag);
  core::Result<void> abortBulkIn(std::uint8_t tag);
  std::uint8_t lastTag() const { return tag_; }

 private:
  UsbtmcTransport() = default;
  core::Result<std::vector<std::uint8_t>> control(const ControlSetup& setup);
  // One bulk transfer; `transferred` is set even on timeout.
  int bulk(std::uint8_t endpoint, std::uint8_t* data, int length, int* transferred, unsigned timeoutMs);
  core::Error fail(int code, const std::string& what);
  core::Error gone() const;
  core::Result<void> discardBulkIn();
  // Repeats a CHECK_* request while it answers PENDING (reading Bulk-IN out
  // when the device says its FIFO holds data); on success clears the Bulk-OUT
  // halt when asked.
  core::Result<void> pollUntilDone(const ControlSetup& check, bool clearOutHalt);
  core::Result<void> recover(core::Result<void> abort);
  core::Error timedOut(const std::string& what, unsigned timeoutMs, const core::Result<void>& recovery) const;

  libusb_context* context_ = nullptr;
  libusb_device_handle* handle_ = nullptr;
  UsbtmcDeviceInfo info_;
  UsbtmcOptions options_;
  Capabilities caps_;
  std::uint8_t tag_ = 0;
  std::uint8_t statusTag_ = 1;
  bool claimed_ = false;
  std::atomic<bool> disconnected_{false};
  std::thread eventThread_;
  std::atomic<bool> quit_{false};
  std::mutex callbackMutex_;
  std::function<void()> onDisconnect_;
  int hotplugHandle_ = 0;
  bool hotplugRegistered_ = false;
};

}  // namespace mozzi::devices::usbtmc
