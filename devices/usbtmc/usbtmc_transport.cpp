#include "devices/usbtmc/usbtmc_transport.h"

#include <libusb.h>

#include <chrono>
#include <thread>

namespace mozzi::devices::usbtmc {

namespace {

using Clock = std::chrono::steady_clock;

// The USBTMC interface of `device`, if it has one: interface number, protocol
// and endpoints from the active configuration.
bool findUsbtmcInterface(libusb_device* device, UsbtmcDeviceInfo& info) {
  libusb_config_descriptor* config = nullptr;
  if (libusb_get_active_config_descriptor(device, &config) != 0 &&
      libusb_get_config_descriptor(device, 0, &config) != 0)
    return false;
  bool found = false;
  for (int i = 0; i < config->bNumInterfaces && !found; ++i) {
    const libusb_interface& itf = config->interface[i];
    for (int a = 0; a < itf.num_altsetting && !found; ++a) {
      const libusb_interface_descriptor& alt = itf.altsetting[a];
      if (alt.bInterfaceClass != kInterfaceClass || alt.bInterfaceSubClass != kInterfaceSubclass) continue;
      UsbtmcDeviceInfo candidate = info;
      candidate.interfaceNumber = alt.bInterfaceNumber;
      candidate.protocol = alt.bInterfaceProtocol;
      for (int e = 0; e < alt.bNumEndpoints; ++e) {
        const libusb_endpoint_descriptor& ep = alt.endpoint[e];
        const int type = ep.bmAttributes & LIBUSB_TRANSFER_TYPE_MASK;
        const bool in = (ep.bEndpointAddress & LIBUSB_ENDPOINT_IN) != 0;
        if (type == LIBUSB_TRANSFER_TYPE_BULK && !in) candidate.bulkOut = ep.bEndpointAddress;
        if (type == LIBUSB_TRANSFER_TYPE_BULK && in) {
          candidate.bulkIn = ep.bEndpointAddress;
          candidate.bulkInMaxPacket = ep.wMaxPacketSize > 0 ? ep.wMaxPacketSize : 64;
        }
        if (type == LIBUSB_TRANSFER_TYPE_INTERRUPT && in) candidate.interruptIn = ep.bEndpointAddress;
      }
      // Both bulk endpoints are mandatory (USBTMC 3); without them it is not usable.
      if (candidate.bulkOut != 0 && candidate.bulkIn != 0) {
        info = candidate;
        found = true;
      }
    }
  }
  libusb_free_config_descriptor(config);
  return found;
}

// Every USBTMC device in `list`, strings read where the device can be opened.
std::vector<std::pair<libusb_device*, UsbtmcDeviceInfo>> usbtmcDevices(libusb_device** list, ssize_t n) {
  std::vector<std::pair<libusb_device*, UsbtmcDeviceInfo>> found;
  for (ssize_t i = 0; i < n; ++i) {
    libusb_device_descriptor d{};
    if (libusb_get_device_descriptor(list[i], &d) != 0) continue;
    UsbtmcDeviceInfo info;
    if (!findUsbtmcInterface(list[i], info)) continue;
    info.usb = usb::UsbDeviceInfo{
        d.idVendor, d.idProduct, libusb_get_bus_number(list[i]), libusb_get_device_address(list[i]), {}};
    libusb_device_handle* h = nullptr;
    if (libusb_open(list[i], &h) == 0) {
      info.usb.serial = usb::readStringDescriptor(h, d.iSerialNumber);
      info.manufacturer = usb::readStringDescriptor(h, d.iManufacturer);
      info.product = usb::readStringDescriptor(h, d.iProduct);
      libusb_close(h);
    }
    found.emplace_back(list[i], info);
  }
  return found;
}

int hotplugCallback(libusb_context*, libusb_device* device, libusb_hotplug_event event, void* self) {
  if (event == LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT)
    static_cast<UsbtmcTransport*>(self)->deviceLeft(libusb_get_bus_number(device), libusb_get_device_address(device));
  return 0;  // stay registered
}

unsigned remainingMs(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  return left > 1 ? static_cast<unsigned>(left) : 1u;  // libusb: 0 would mean "no timeout"
}

}  // namespace

core::Result<std::vector<UsbtmcDeviceInfo>> UsbtmcTransport::enumerate() {
  libusb_context* ctx = nullptr;
  const int r = libusb_init(&ctx);
  if (r != 0) return usb::libusbError(r, "libusb could not be initialised", "usb");
  libusb_device** list = nullptr;
  const ssize_t n = libusb_get_device_list(ctx, &list);
  if (n < 0) {
    libusb_exit(ctx);
    return usb::libusbError(static_cast<int>(n), "the USB device list could not be read", "usb");
  }
  std::vector<UsbtmcDeviceInfo> out;
  for (auto& [device, info] : usbtmcDevices(list, n)) out.push_back(info);
  libusb_free_device_list(list, 1);
  libusb_exit(ctx);
  return out;
}

core::Result<std::unique_ptr<UsbtmcTransport>> UsbtmcTransport::open(const std::string& busPath,
                                                                     UsbtmcOptions options) {
  std::unique_ptr<UsbtmcTransport> t(new UsbtmcTransport());
  t->options_ = options;
  int r = libusb_init(&t->context_);
  if (r != 0) return usb::libusbError(r, "libusb could not be initialised", "usb");
  libusb_device** list = nullptr;
  const ssize_t n = libusb_get_device_list(t->context_, &list);
  if (n < 0) return usb::libusbError(static_cast<int>(n), "the USB device list could not be read", "usb");
  libusb_device* chosen = nullptr;
  for (auto& [device, info] : usbtmcDevices(list, n))
    if (!chosen && (busPath.empty() || info.usb.busPath() == busPath)) {
      chosen = device;
      t->info_ = info;
    }
  if (chosen) r = libusb_open(chosen, &t->handle_);
  libusb_free_device_list(list, 1);
  if (!chosen)
    return core::makeError(core::ErrorCode::NotFound, "no USBTMC instrument (interface class 0xFE/0x03) is connected",
                           busPath.empty() ? std::string("usb") : busPath);
  if (r != 0) return usb::libusbError(r, "the instrument could not be opened", t->info_.usb.busPath());
  // The kernel's usbtmc driver binds every such interface (/dev/usbtmcN); take
  // it over for the session and give it back on close.
  libusb_set_auto_detach_kernel_driver(t->handle_, 1);
  r = libusb_claim_interface(t->handle_, t->info_.interfaceNumber);
  if (r != 0)
    return t->fail(r, "USBTMC interface " + std::to_string(t->info_.interfaceNumber) + " could not be claimed");
  t->claimed_ = true;
  if (libusb_has_capability(LIBUSB_CAP_HAS_HOTPLUG)) {
    const int h = libusb_hotplug_register_callback(
        t->context_, LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT, LIBUSB_HOTPLUG_NO_FLAGS, t->info_.usb.vendorId,
        t->info_.usb.productId, LIBUSB_HOTPLUG_MATCH_ANY, &hotplugCallback, t.get(), &t->hotplugHandle_);
    t->hotplugRegistered_ = h == LIBUSB_SUCCESS;
  }
  // Transfers are synchronous (libusb handles their events in the caller);
  // this thread serves the hotplug monitor between them.
  t->eventThread_ = std::thread([p = t.get()] {
    while (!p->quit_.load()) {
      timeval tv{0, 100000};  // 100 ms: bounds the latency of quit_
      libusb_handle_events_timeout_completed(p->context_, &tv, nullptr);
    }
  });
  auto caps = t->control(getCapabilities(t->info_.interfaceNumber));
  if (!caps) return caps.error();
  auto parsed = parseCapabilities(*caps);
  if (!parsed) return parsed.error();
  t->caps_ = *parsed;
  if (options.clearOnOpen)
    if (auto c = t->clear(); !c) return c.error();
  return t;
}

UsbtmcTransport::~UsbtmcTransport() {
  setDisconnectCallback(nullptr);
  if (hotplugRegistered_) libusb_hotplug_deregister_callback(context_, hotplugHandle_);
  if (handle_) {
    if (claimed_) libusb_release_interface(handle_, info_.interfaceNumber);
    libusb_close(handle_);  // wakes the event thread
  }
  quit_ = true;
  if (context_) libusb_interrupt_event_handler(context_);
  if (eventThread_.joinable()) eventThread_.join();
  if (context_) libusb_exit(context_);
}

void UsbtmcTransport::setDisconnectCallback(std::function<void()> callback) {
  std::lock_guard<std::mutex> l(callbackMutex_);
  onDisconnect_ = std::move(callback);
}

void UsbtmcTransport::deviceLeft(std::uint8_t bus, std::uint8_t address) {
  if (bus != info_.usb.bus || address != info_.usb.address) return;
  disconnected_ = true;
  std::lock_guard<std::mutex> l(callbackMutex_);
  if (onDisconnect_) onDisconnect_();
}

core::Error UsbtmcTransport::gone() const {
  return core::makeError(core::ErrorCode::NotFound, "the instrument was unplugged", where());
}

core::Error UsbtmcTransport::fail(int code, const std::string& what) {
  if (code == LIBUSB_ERROR_NO_DEVICE) {
    disconnected_ = true;
    return core::makeError(core::ErrorCode::NotFound, "the instrument was unplugged (" + what + ")", where());
  }
  return usb::libusbError(code, what, where());
}

int UsbtmcTransport::bulk(std::uint8_t endpoint, std::uint8_t* data, int length, int* transferred, unsigned timeoutMs) {
  *transferred = 0;
  const int r = libusb_bulk_transfer(handle_, endpoint, data, length, transferred, timeoutMs);
  if (r == LIBUSB_ERROR_NO_DEVICE) disconnected_ = true;
  return r;
}

core::Result<std::vector<std::uint8_t>> UsbtmcTransport::control(const ControlSetup& s) {
  if (disconnected_) return gone();
  std::vector<std::uint8_t> answer(s.length);
  const int r = libusb_control_transfer(handle_, s.requestType, s.request, s.value, s.index, answer.data(), s.length,
                                        options_.controlTimeoutMs);
  if (r < 0) return fail(r, classRequestName(s.request) + " failed");
  answer.resize(static_cast<std::size_t>(r));
  return answer;
}

core::Result<void> UsbtmcTransport::write(const std::string& message, unsigned timeoutMs) {
  if (disconnected_) return gone();
  const auto deadline = Clock::now() + std::chrono::milliseconds(timeoutMs);
  for (auto& transfer : encodeMessage(tag_, message, options_.maxTransferData)) {
    int sent = 0;
    const int r = bulk(info_.bulkOut, transfer.data(), static_cast<int>(transfer.size()), &sent, remainingMs(deadline));
    if (r == LIBUSB_ERROR_TIMEOUT) {
      return timedOut("the instrument did not accept the message", timeoutMs, recover(abortBulkOut(tag_)));
    }
    if (r == LIBUSB_ERROR_PIPE) {
      libusb_clear_halt(handle_, info_.bulkOut);
      return core::makeError(core::ErrorCode::IoError, "the instrument stalled the Bulk-OUT endpoint (halt cleared)",
                             where());
    }
    if (r != 0) return fail(r, "Bulk-OUT transfer failed");
    if (sent != static_cast<int>(transfer.size()))
      return core::makeError(
          core::ErrorCode::IoError,
          "Bulk-OUT sent " + std::to_string(sent) + " of " + std::to_string(transfer.size()) + " bytes", where());
  }
  return {};
}

core::Result<std::string> UsbtmcTransport::read(unsigned timeoutMs) {
  if (disconnected_) return gone();
  const auto deadline = Clock::now() + std::chrono::milliseconds(timeoutMs);
  ResponseAssembler assembler(options_.maxResponseBytes);
  // Room for the header, the data and the alignment bytes, in whole packets:
  // the device's transfer always ends inside one read.
  const std::size_t packet = info_.bulkInMaxPacket;
  std::vector<std::uint8_t> buffer((kHeaderBytes + options_.maxTransferData + 3 + packet - 1) / packet * packet);
  for (;;) {
    tag_ = nextTag(tag_);
    auto request = encodeRequestDevDepMsgIn(tag_, options_.maxTransferData);
    int sent = 0;
    int r = bulk(info_.bulkOut, request.data(), static_cast<int>(request.size()), &sent, remainingMs(deadline));
    if (r == LIBUSB_ERROR_TIMEOUT) {
      return timedOut("the instrument did not take the read request", timeoutMs, recover(abortBulkOut(tag_)));
    }
    if (r != 0) return fail(r, "REQUEST_DEV_DEP_MSG_IN failed");
    assembler.expect(tag_, options_.maxTransferData);
    for (;;) {
      int got = 0;
      r = bulk(info_.bulkIn, buffer.data(), static_cast<int>(buffer.size()), &got, remainingMs(deadline));
      if (r == LIBUSB_ERROR_TIMEOUT) {
        return timedOut("no answer", timeoutMs, recover(abortBulkIn(tag_)));
      }
      if (r == LIBUSB_ERROR_PIPE) {
        libusb_clear_halt(handle_, info_.bulkIn);
        return core::makeError(core::ErrorCode::IoError, "the instrument stalled the Bulk-IN endpoint (halt cleared)",
                               where());
      }
      if (r != 0) return fail(r, "Bulk-IN transfer failed");
      auto step = assembler.feed(buffer.data(), static_cast<std::size_t>(got));
      if (!step) {
        // Out of step with the device: a clear brings both sides back to idle.
        (void)clear();
        return core::makeError(step.error().code, step.error().message + " (device cleared)", where());
      }
      if (*step == ResponseAssembler::Step::MessageDone) return assembler.text();
      if (*step == ResponseAssembler::Step::TransferDone) break;
    }
  }
}

core::Result<void> UsbtmcTransport::discardBulkIn() {
  // Reads until a short packet ends the aborted transfer;
  // bounded so a device that keeps talking cannot hold us.
  std::vector<std::uint8_t> buffer(static_cast<std::size_t>(info_.bulkInMaxPacket) * 16);
  for (int i = 0; i < 64; ++i) {
    int got = 0;
    const int r = bulk(info_.bulkIn, buffer.data(), static_cast<int>(buffer.size()), &got, options_.controlTimeoutMs);
    if (r == LIBUSB_ERROR_TIMEOUT) return {};  // nothing (more) queued
    if (r != 0) return fail(r, "reading out the aborted Bulk-IN transfer failed");
    if (got % info_.bulkInMaxPacket != 0 || got == 0) return {};
  }
  return core::makeError(core::ErrorCode::IoError, "the Bulk-IN endpoint kept sending after the abort", where());
}

core::Result<void> UsbtmcTransport::pollUntilDone(const ControlSetup& check, bool clearOutHalt) {
  const std::string name = classRequestName(check.request);
  for (int i = 0; i < options_.abortPolls; ++i) {
    auto c = control(check);
    if (!c) return c.error();
    std::uint8_t status = 0;
    bool fifoHasData = false;
    if (check.request == kCheckClearStatus) {
      auto answer = parseCheckClearAnswer(*c);
      if (!answer) return answer.error();
      status = answer->status;
      fifoHasData = answer->bulkInFifoHasData;
    } else {
      auto answer = parseCheckAbortAnswer(*c);
      if (!answer) return answer.error();
      status = answer->status;
      fifoHasData = answer->bulkInFifoHasData;
    }
    if (status == static_cast<std::uint8_t>(Status::Success)) {
      if (!clearOutHalt) return {};
      const int r = libusb_clear_halt(handle_, info_.bulkOut);
      if (r != 0) return fail(r, "clearing the Bulk-OUT halt after " + name + " failed");
      return {};
    }
    if (status != static_cast<std::uint8_t>(Status::Pending))
      return core::makeError(core::ErrorCode::IoError, name + " answered " + statusName(status), where());
    // Pending: the device may hold Bulk-IN data that must be read out first.
    if (fifoHasData) {
      if (auto d = discardBulkIn(); !d) return d;
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  return core::makeError(core::ErrorCode::IoError, name + " stayed pending", where());
}

core::Result<void> UsbtmcTransport::abortBulkOut(std::uint8_t tag) {
  auto a = control(initiateAbortBulkOut(tag, info_.bulkOut));
  if (!a) return a.error();
  auto answer = parseAbortAnswer(*a);
  if (!answer) return answer.error();
  // FAILED: no transfer in progress and the FIFO is empty: nothing to abort.
  if (answer->status == static_cast<std::uint8_t>(Status::Failed)) return {};
  if (answer->status != static_cast<std::uint8_t>(Status::Success))
    return core::makeError(core::ErrorCode::IoError, "INITIATE_ABORT_BULK_OUT answered " + statusName(answer->status),
                           where());
  // The abort ends with CLEAR_FEATURE(ENDPOINT_HALT) on Bulk-OUT.
  return pollUntilDone(checkAbortBulkOutStatus(info_.bulkOut), true);
}

core::Result<void> UsbtmcTransport::abortBulkIn(std::uint8_t tag) {
  auto a = control(initiateAbortBulkIn(tag, info_.bulkIn));
  if (!a) return a.error();
  auto answer = parseAbortAnswer(*a);
  if (!answer) return answer.error();
  if (answer->status == static_cast<std::uint8_t>(Status::Failed)) return {};  // nothing queued: done
  if (answer->status != static_cast<std::uint8_t>(Status::Success))
    return core::makeError(core::ErrorCode::IoError, "INITIATE_ABORT_BULK_IN answered " + statusName(answer->status),
                           where());
  if (auto d = discardBulkIn(); !d) return d;
  return pollUntilDone(checkAbortBulkInStatus(info_.bulkIn), false);
}

core::Result<void> UsbtmcTransport::clear() {
  auto a = control(initiateClear(info_.interfaceNumber));
  if (!a) return a.error();
  auto answer = parseInitiateClearAnswer(*a);
  if (!answer) return answer.error();
  if (answer->status != static_cast<std::uint8_t>(Status::Success))
    return core::makeError(core::ErrorCode::IoError, "INITIATE_CLEAR answered " + statusName(answer->status), where());
  // The clear, too, ends with CLEAR_FEATURE(ENDPOINT_HALT) on Bulk-OUT.
  return pollUntilDone(checkClearStatus(info_.interfaceNumber), true);
}

core::Error UsbtmcTransport::timedOut(const std::string& what, unsigned timeoutMs,
                                      const core::Result<void>& recovery) const {
  if (disconnected_) return gone();
  return core::makeError(
      core::ErrorCode::IoError,
      what + " within " + std::to_string(timeoutMs) + " ms" +
          (recovery ? " (transfer aborted)" : " (recovery failed: " + recovery.error().message + ")"),
      where());
}

core::Result<void> UsbtmcTransport::recover(core::Result<void> abort) {
  if (abort || disconnected_) return abort;
  // The abort itself failed: a device clear is the stronger reset.
  if (auto c = clear(); !c)
    return core::makeError(c.error().code, abort.error().message + "; then " + c.error().message, where());
  return {};
}

core::Result<std::uint8_t> UsbtmcTransport::readStatusByte() {
  statusTag_ = nextStatusTag(statusTag_);
  auto a = control(usbtmc::readStatusByte(statusTag_, info_.interfaceNumber));
  if (!a) return a.error();
  auto answer = parseStatusByteAnswer(*a, statusTag_);
  if (!answer) return answer.error();
  if (answer->status != static_cast<std::uint8_t>(Status::Success))
    return core::makeError(core::ErrorCode::IoError, "READ_STATUS_BYTE answered " + statusName(answer->status),
                           where());
  if (info_.interruptIn == 0) return answer->statusByte;
  // With an Interrupt-IN endpoint the status byte comes there.
  std::vector<std::uint8_t> note(2);
  int got = 0;
  const int r = libusb_interrupt_transfer(handle_, info_.interruptIn, note.data(), 2, &got, options_.controlTimeoutMs);
  if (r != 0) return fail(r, "reading the status byte on Interrupt-IN failed");
  note.resize(static_cast<std::size_t>(got));
  auto n = parseInterruptNotification(note, statusTag_);
  if (!n) return n.error();
  return n->statusByte;
}

}  // namespace mozzi::devices::usbtmc
