#pragma once
// A USBTMC/USB488 instrument emulated behind umockdev's in-process usbfs ioctl
// handler (UMockdevIoctlBase), so that tests run the real libusb code path:
// the device side of the USBTMC 1.0 / USB488 1.0 protocol (Bulk-OUT headers,
// REQUEST_DEV_DEP_MSG_IN answered with DEV_DEP_MSG_IN, class requests, the
// status byte on Interrupt-IN) in front of the SCPI generator model. Bulk-IN
// data is only sent when the host has asked for it and the instrument has an
// answer, as a real one NAKs until then; nothing sleeps.
// Faults: holdBulkOut (the device stops taking Bulk-OUT data: libusb times the
// transfer out), unplugOn (after this message the device leaves while the host
// waits on Bulk-IN for the answer: pending URBs end with -ESHUTDOWN, every
// later ioctl with ENODEV, as usbfs does).
// Run under umockdev-wrapper (tests/CMakeLists.txt).
#include <linux/usbdevice_fs.h>
#include <sys/ioctl.h>
#include <umockdev.h>

#include <gtest/gtest.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "devices/usbfs_emulation.h"
#include "scpi_generator_model.h"

namespace mozzi::devices::testing {

using Bytes = std::vector<std::uint8_t>;

constexpr std::uint8_t kModelBulkOut = 0x02;
constexpr std::uint8_t kModelBulkIn = 0x81;
constexpr std::uint8_t kModelInterruptIn = 0x83;

class UsbtmcDeviceModel {
 public:
  ~UsbtmcDeviceModel() {
    for (auto* d : pendingIn_) umockdev_ioctl_data_unref(d);
    for (auto* d : pendingInterrupt_) umockdev_ioctl_data_unref(d);
    for (auto* d : heldOut_) umockdev_ioctl_data_unref(d);
    for (auto& [client, queue] : completed_)
      for (auto* d : queue) umockdev_ioctl_data_unref(d);
  }

  struct Log {
    std::vector<Bytes> bulkOut;                      // every Bulk-OUT transfer the device took, as sent
    std::vector<std::string> messages;               // complete messages (EOM), as the instrument saw them
    std::vector<std::pair<int, int>> classRequests;  // bRequest, wValue
    std::vector<unsigned> clearHalts;                // endpoints
    int discards = 0;                                // URBs the host cancelled (its timeouts)
    int protocolErrors = 0;                          // malformed Bulk-OUT headers
  };
  Log log() {
    std::lock_guard<std::mutex> l(mu_);
    return log_;
  }
  // Runs `f` on the model under its lock (faults, instrument state).
  template <class F>
  void with(F f) {
    std::lock_guard<std::mutex> l(mu_);
    f(*this);
  }

  ScpiGeneratorModel instrument;
  bool holdBulkOut = false;
  std::string unplugOn;

  gboolean handle(UMockdevIoctlClient* client) {
    std::lock_guard<std::mutex> l(mu_);
    const gulong req = umockdev_ioctl_client_get_request(client);
    UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
    if (unplugged_ && req != USBDEVFS_REAPURB && req != USBDEVFS_REAPURBNDELAY) return finish(client, -1, ENODEV);
    GError* err = nullptr;
    switch (req) {
      case USBDEVFS_SUBMITURB: {
        UMockdevIoctlData* urbd = umockdev_ioctl_data_resolve(arg, 0, sizeof(usbdevfs_urb), &err);
        if (!urbd) return finish(client, -1, EFAULT);
        umockdev_ioctl_data_ref(urbd);
        owner_[urbd] = client;
        auto* urb = reinterpret_cast<usbdevfs_urb*>(urbd->data);
        if (urb->type == USBDEVFS_URB_TYPE_CONTROL) {
          control(urbd);
          complete(urbd);
        } else if (urb->endpoint == kModelBulkOut) {
          bulkOut(urbd);
        } else if (urb->endpoint == kModelBulkIn) {
          pendingIn_.push_back(urbd);
          if (unplugArmed_) unplug();  // leaves while the host waits for the answer
          pump();
        } else if (urb->endpoint == kModelInterruptIn) {
          pendingInterrupt_.push_back(urbd);
          pump();
        } else {
          setUrb(urbd, -EPIPE, 0);
          complete(urbd);
        }
        return finish(client, 0, 0);
      }
      case USBDEVFS_REAPURB:
      case USBDEVFS_REAPURBNDELAY: {
        // Each open file has its own URBs, as in usbfs: a second handle on
        // the device (a scan while a session is open) never reaps ours.
        auto& done = completed_[client];
        if (done.empty()) return finish(client, -1, unplugged_ ? ENODEV : EAGAIN);
        UMockdevIoctlData* p = umockdev_ioctl_data_resolve(arg, 0, sizeof(void*), &err);
        UMockdevIoctlData* urbd = done.front();
        done.pop_front();
        owner_.erase(urbd);
        umockdev_ioctl_data_set_ptr(p, 0, urbd);
        umockdev_ioctl_data_unref(urbd);
        return finish(client, 0, 0);
      }
      case USBDEVFS_DISCARDURB: {
        const unsigned long addr = *reinterpret_cast<unsigned long*>(arg->data);
        for (auto* queue : {&pendingIn_, &pendingInterrupt_, &heldOut_})
          for (auto it = queue->begin(); it != queue->end(); ++it)
            if ((*it)->client_addr == addr) {
              UMockdevIoctlData* urbd = *it;
              queue->erase(it);
              setUrb(urbd, -ENOENT, 0);  // usbfs reports an unlinked URB with -ENOENT
              complete(urbd);
              ++log_.discards;
              return finish(client, 0, 0);
            }
        return finish(client, -1, EINVAL);
      }
      case USBDEVFS_CLEAR_HALT: {
        UMockdevIoctlData* ep = umockdev_ioctl_data_resolve(arg, 0, sizeof(unsigned int), &err);
        log_.clearHalts.push_back(ep ? *reinterpret_cast<unsigned int*>(ep->data) : 0u);
        return finish(client, 0, 0);
      }
      case USBDEVFS_GET_CAPABILITIES: {
        UMockdevIoctlData* p = umockdev_ioctl_data_resolve(arg, 0, sizeof(std::uint32_t), &err);
        std::uint32_t caps = USBDEVFS_CAP_BULK_CONTINUATION | USBDEVFS_CAP_NO_PACKET_SIZE_LIM;
        umockdev_ioctl_data_update(p, 0, reinterpret_cast<guint8*>(&caps), sizeof caps);
        return finish(client, 0, 0);
      }
      case USBDEVFS_GETDRIVER:
      case USBDEVFS_IOCTL: return finish(client, -1, ENODATA);  // no kernel driver bound
      default: return finish(client, 0, 0);                     // claim/release interface, set configuration, ...
    }
  }

 private:
  static gboolean finish(UMockdevIoctlClient* client, long result, int err) { return finishIoctl(client, result, err); }

  static void setUrb(UMockdevIoctlData* urbd, int status, int actual) { setUrbResult(urbd, status, actual); }

  static UMockdevIoctlData* bufferOf(UMockdevIoctlData* urbd) {
    GError* err = nullptr;
    auto* urb = reinterpret_cast<usbdevfs_urb*>(urbd->data);
    return umockdev_ioctl_data_resolve(urbd, offsetof(usbdevfs_urb, buffer), static_cast<gsize>(urb->buffer_length),
                                       &err);
  }

  static void reply(UMockdevIoctlData* urbd, const Bytes& data) {
    Bytes copy = data;  // the update takes a non-const buffer
    if (!copy.empty()) umockdev_ioctl_data_update(bufferOf(urbd), 0, copy.data(), static_cast<gint>(copy.size()));
    setUrb(urbd, 0, static_cast<int>(data.size()));
  }

  static std::uint32_t u32(const std::uint8_t* p) {
    return static_cast<std::uint32_t>(p[0] | p[1] << 8 | p[2] << 16 | static_cast<std::uint32_t>(p[3]) << 24);
  }

  void control(UMockdevIoctlData* urbd) {
    UMockdevIoctlData* buf = bufferOf(urbd);
    const std::uint8_t* s = buf->data;
    const std::uint8_t type = s[0], request = s[1];
    const std::uint16_t value = static_cast<std::uint16_t>(s[2] | s[3] << 8);
    const std::uint16_t length = static_cast<std::uint16_t>(s[6] | s[7] << 8);
    Bytes in;
    bool ok = true;
    if (type == 0x80 && request == 6 && (value >> 8) == 3) {  // GET_DESCRIPTOR string
      static const char* strings[] = {"", "Keysight Technologies", "33522B Waveform Generator", "MY00000001"};
      const unsigned index = value & 0xFF;
      if (index == 0)
        in = {4, 3, 0x09, 0x04};
      else if (index < 4) {
        const std::string str = strings[index];
        in = {static_cast<std::uint8_t>(2 + 2 * str.size()), 3};
        for (char ch : str) in.insert(in.end(), {static_cast<std::uint8_t>(ch), 0});
      } else {
        ok = false;
      }
    } else if (type == 0xA1 || type == 0xA2) {
      log_.classRequests.emplace_back(request, value);
      ok = classRequest(request, static_cast<std::uint8_t>(value), in);
    } else {
      ok = false;
    }
    if (!ok) {
      setUrb(urbd, -EPIPE, 0);
      return;
    }
    in.resize(std::min<std::size_t>(in.size(), length));
    if (!in.empty()) umockdev_ioctl_data_update(buf, 8, in.data(), static_cast<gint>(in.size()));
    setUrb(urbd, 0, static_cast<int>(in.size()));
    pump();
  }

  bool classRequest(std::uint8_t request, std::uint8_t tag, Bytes& in) {
    constexpr std::uint8_t success = 0x01, pending = 0x02, failed = 0x80;
    switch (request) {
      case 1:  // INITIATE_ABORT_BULK_OUT: the held transfer with this bTag is dropped
        in = {heldOutTag_ == tag ? success : failed, tag};
        if (heldOutTag_ == tag) {
          heldOutTag_ = 0;
          holdBulkOut = false;
          partial_.clear();
        }
        return true;
      case 2:  // CHECK_ABORT_BULK_OUT_STATUS
        in = {success, 0, 0, 0, 0, 0, 0, 0};
        return true;
      case 3:  // INITIATE_ABORT_BULK_IN: only the outstanding request can be aborted
        if (inRequestTag_ == tag) {
          in = {success, tag};
          inRequestTag_ = 0;
          shortPacketDue_ = true;  // the aborted transfer ends with a short packet
        } else {
          in = {failed, tag};
        }
        return true;
      case 4:  // CHECK_ABORT_BULK_IN_STATUS: pending until the short packet was read
        in = {
            shortPacketDue_ ? pending : success, static_cast<std::uint8_t>(shortPacketDue_ ? 1 : 0), 0, 0, 0, 0, 0, 0};
        return true;
      case 5:  // INITIATE_CLEAR: input, output and the outstanding request are dropped
        partial_.clear();
        output_.clear();
        inRequestTag_ = 0;
        in = {success};
        return true;
      case 6:  // CHECK_CLEAR_STATUS
        in = {success, 0};
        return true;
      case 7:  // GET_CAPABILITIES: USBTMC 1.00, USB488 1.00, 488.2 + REN + trigger, SCPI SR1 RL1 DT1
        in = {success, 0, 0x00, 0x01, 0x00, 0x00, 0, 0, 0, 0, 0, 0, 0x00, 0x01, 0x07, 0x0F, 0, 0, 0, 0, 0, 0, 0, 0};
        return true;
      case 128: {  // READ_STATUS_BYTE: answer on Interrupt-IN (the device has that endpoint)
        in = {success, tag, 0};
        // IEEE 488.2 status byte: bit 4 MAV (output queued), bit 2 error queue not empty.
        const std::uint8_t stb =
            static_cast<std::uint8_t>((output_.empty() ? 0 : 0x10) | (instrument.errors.empty() ? 0 : 0x04));
        notifications_.push_back({static_cast<std::uint8_t>(0x80 | tag), stb});
        return true;
      }
      default: return false;
    }
  }

  void bulkOut(UMockdevIoctlData* urbd) {
    auto* urb = reinterpret_cast<usbdevfs_urb*>(urbd->data);
    const Bytes data(bufferOf(urbd)->data, bufferOf(urbd)->data + urb->buffer_length);
    if (holdBulkOut) {
      // Busy: the transfer is not taken; the host's timeout and abort follow.
      heldOutTag_ = data.size() >= 2 ? data[1] : 0;
      heldOut_.push_back(urbd);
      return;
    }
    log_.bulkOut.push_back(data);
    setUrb(urbd, 0, urb->buffer_length);
    complete(urbd);
    if (data.size() < 12 || data[2] != static_cast<std::uint8_t>(~data[1]) || data.size() % 4 != 0) {
      ++log_.protocolErrors;
      return;
    }
    const std::uint32_t size = u32(data.data() + 4);
    if (data[0] == 1) {  // DEV_DEP_MSG_OUT
      if (12 + size > data.size()) {
        ++log_.protocolErrors;
        return;
      }
      partial_.append(data.begin() + 12, data.begin() + 12 + size);
      if (data[8] & 1) {
        const std::string message = partial_;
        partial_.clear();
        log_.messages.push_back(message);
        if (auto answer = instrument.handle(message)) output_ += *answer + "\n";
        if (!unplugOn.empty() && message == unplugOn + "\n") unplugArmed_ = true;
      }
    } else if (data[0] == 2) {  // REQUEST_DEV_DEP_MSG_IN
      inRequestTag_ = data[1];
      inRequestMax_ = size;
    } else {
      ++log_.protocolErrors;
    }
    pump();
  }

  // Serves the pending Bulk-IN and Interrupt-IN URBs from what the device has.
  void pump() {
    while (!pendingInterrupt_.empty() && !notifications_.empty()) {
      reply(pendingInterrupt_.front(), notifications_.front());
      complete(pendingInterrupt_.front());
      pendingInterrupt_.pop_front();
      notifications_.pop_front();
    }
    if (pendingIn_.empty() || unplugged_) return;
    UMockdevIoctlData* urbd = pendingIn_.front();
    const std::size_t room = static_cast<std::size_t>(reinterpret_cast<usbdevfs_urb*>(urbd->data)->buffer_length);
    if (shortPacketDue_) {
      reply(urbd, {});
      shortPacketDue_ = false;
    } else if (inRequestTag_ != 0 && !output_.empty() && room >= 16) {
      const std::size_t n = std::min<std::size_t>({output_.size(), inRequestMax_, room - 12 - 3});
      const bool eom = n == output_.size();
      Bytes t = {2,
                 inRequestTag_,
                 static_cast<std::uint8_t>(~inRequestTag_),
                 0,
                 static_cast<std::uint8_t>(n & 0xFF),
                 static_cast<std::uint8_t>(n >> 8),
                 0,
                 0,
                 static_cast<std::uint8_t>(eom ? 1 : 0),
                 0,
                 0,
                 0};
      t.insert(t.end(), output_.begin(), output_.begin() + static_cast<std::ptrdiff_t>(n));
      t.resize((t.size() + 3) / 4 * 4, 0);
      output_.erase(0, n);
      inRequestTag_ = 0;
      reply(urbd, t);
    } else {
      return;  // NAK: the host waits (and times out if nothing comes)
    }
    complete(urbd);
    pendingIn_.pop_front();
  }

  void unplug() {
    unplugged_ = true;
    for (auto* queue : {&pendingIn_, &pendingInterrupt_, &heldOut_}) {
      for (auto* d : *queue) {
        setUrb(d, -ESHUTDOWN, 0);
        complete(d);
      }
      queue->clear();
    }
  }

  std::mutex mu_;
  Log log_;
  void complete(UMockdevIoctlData* urbd) { completed_[owner_[urbd]].push_back(urbd); }

  std::deque<UMockdevIoctlData*> pendingIn_, pendingInterrupt_, heldOut_;
  std::map<UMockdevIoctlClient*, std::deque<UMockdevIoctlData*>> completed_;
  std::map<UMockdevIoctlData*, UMockdevIoctlClient*> owner_;
  std::deque<Bytes> notifications_;
  std::string partial_, output_;
  std::uint8_t inRequestTag_ = 0, heldOutTag_ = 0;
  std::uint32_t inRequestMax_ = 0;
  bool shortPacketDue_ = false, unplugged_ = false, unplugArmed_ = false;
};

inline gboolean onUsbtmcIoctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer self) {
  return static_cast<UsbtmcDeviceModel*>(self)->handle(client);
}

// A umockdev testbed with the emulated instrument at usb:1.5 and, beside it, a
// vendor-class device at usb:1.2 (no USBTMC interface: scans must skip it).
class UsbtmcTestbed : public ::testing::Test {
 protected:
  static constexpr const char* kNode = "/dev/bus/usb/001/005";

  void SetUp() override {
    const char* preload = std::getenv("LD_PRELOAD");
    ASSERT_TRUE(preload && std::strstr(preload, "umockdev")) << "run under umockdev-wrapper";
    testbed_ = umockdev_testbed_new();
    // Device descriptor: USB 2.0, EP0 64 bytes, VID 0957 (Agilent/Keysight),
    // PID 2C07 (picked for the test: the driver matches on the interface
    // class), strings 1..3. Configuration 1: interface 0, class FE/03/01
    // (USB488), Bulk-OUT 0x02, Bulk-IN 0x81 (64 bytes), Interrupt-IN 0x83 (2 bytes).
    const std::uint8_t tmc[] = {18,   1, 0x00, 0x02, 0,    0,  0, 64,   0x57, 0x09, 0x07, 0x2C, 0x00, 0x01, 1,
                                2,    3, 1,    9,    2,    39, 0, 1,    1,    0,    0x80, 50,   9,    4,    0,
                                0,    3, 0xFE, 0x03, 0x01, 0,  7, 5,    0x02, 2,    64,   0,    0,    7,    5,
                                0x81, 2, 64,   0,    0,    7,  5, 0x83, 3,    2,    0,    1};
    sysPath_ = addDevice("usbtmc", "1", "5", tmc, sizeof tmc);
    const std::uint8_t vendor[] = {18, 1, 0x00, 0x02, 0, 0,  0, 64, 0xDB, 0x09, 0xEA, 0x00, 0x00, 0x01, 0,
                                   0,  0, 1,    9,    2, 25, 0, 1,  1,    0,    0x80, 50,   9,    4,    0,
                                   0,  1, 0xFF, 0,    0, 0,  7, 5,  0x81, 2,    64,   0,    0};
    otherPath_ = addDevice("daq", "1", "2", vendor, sizeof vendor);
    handler_ = umockdev_ioctl_base_new();
    g_signal_connect(handler_, "handle-ioctl", G_CALLBACK(onUsbtmcIoctl), &model_);
    GError* err = nullptr;
    ASSERT_TRUE(umockdev_testbed_attach_ioctl(testbed_, kNode, handler_, &err)) << (err ? err->message : "");
  }

  void TearDown() override {
    if (testbed_) {
      GError* err = nullptr;
      umockdev_testbed_detach_ioctl(testbed_, kNode, &err);
      g_object_unref(handler_);
      g_object_unref(testbed_);
    }
    g_free(sysPath_);
    g_free(otherPath_);
  }

  gchar* addDevice(const char* name, const char* bus, const char* dev, const std::uint8_t* desc, std::size_t size) {
    const std::string busnum = std::string("00") + bus, devnum = std::string("00") + dev;
    const std::string devname = "/dev/bus/usb/" + busnum + "/" + devnum;
    const std::string major = "189:" + std::to_string(std::atoi(dev) - 1);
    const gchar* attrs[] = {
        "busnum", bus, "devnum", dev, "speed", "480", "dev", major.c_str(), "bConfigurationValue", "1", nullptr};
    const gchar* props[] = {"DEVTYPE",      "usb_device", "DEVNAME",      devname.c_str(), "BUSNUM",
                            busnum.c_str(), "DEVNUM",     devnum.c_str(), nullptr};
    gchar* path = umockdev_testbed_add_devicev(testbed_, "usb", name, nullptr, const_cast<gchar**>(attrs),
                                               const_cast<gchar**>(props));
    umockdev_testbed_set_attribute_binary(testbed_, path, "descriptors", const_cast<guint8*>(desc), size);
    // add_devicev creates no device node; libusb needs it to exist.
    gchar* root = umockdev_testbed_get_root_dir(testbed_);
    const std::string dir = std::string(root) + "/dev/bus/usb/" + busnum;
    g_free(root);
    g_mkdir_with_parents(dir.c_str(), 0755);
    std::ofstream(dir + "/" + devnum).put('\0');
    return path;
  }

  UMockdevTestbed* testbed_ = nullptr;
  UMockdevIoctlBase* handler_ = nullptr;
  gchar* sysPath_ = nullptr;
  gchar* otherPath_ = nullptr;
  UsbtmcDeviceModel model_;
};

}  // namespace mozzi::devices::testing
