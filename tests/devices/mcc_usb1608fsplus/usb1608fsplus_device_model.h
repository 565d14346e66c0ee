#pragma once
// The USB-1608FS-Plus behind umockdev's in-process ioctl handler, shared by
// the driver's umockdev test and the campaign engine's: a device model that
// produces its samples from a simulated clock (sample k of channel c is
// DeviceModel::code(k, c), emitted as the host asks for data, never by
// sleeping), with fault switches (overrun, unplug, silent pacer) and a
// replug, and the testbed that attaches it at /dev/bus/usb/001/002.
// Run under umockdev-wrapper (tests/CMakeLists.txt).
#include <linux/usbdevice_fs.h>
#include <sys/ioctl.h>
#include <umockdev.h>

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <functional>
#include <mutex>
#include <vector>

#include "devices/mcc_usb1608fsplus/usb1608fsplus_protocol.h"
#include "devices/usbfs_emulation.h"

namespace mozzi::devices::mcc::emulation {

// Sample k of channel c as the model's ADC produces it.
inline std::uint16_t modelCode(std::int64_t k, int c) {
  return static_cast<std::uint16_t>((k * 37 + c * 8191 + 1234) & 0xFFFF);
}

inline CalibrationTable modelCalibration() {
  CalibrationTable t{};
  for (int r = 0; r < kRangeCount; ++r)
    for (int c = 0; c < kChannelCount; ++c)
      t[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] =
          DeviceCalibration{1.0 + 0.0001 * (r + 1) * (c + 1), -1.5 * c + 0.25 * r};
  return t;
}

class DeviceModel {
 public:
  DeviceModel() {
    cal_ = encodeCalibrationTable(modelCalibration());
    cal_.resize(kCalMemoryBytes, 0xFF);
  }
  ~DeviceModel() {
    for (auto* d : pending_) umockdev_ioctl_data_unref(d);
    for (auto* d : completed_) umockdev_ioctl_data_unref(d);
  }

  // Sample k of channel c (the model's ADC); tests may plant their own signal.
  std::function<std::uint16_t(std::int64_t, int)> code = modelCode;

  // Plugs the device back in after an unplug: the host can open it again and
  // the simulated clock goes on where it was.
  void replug() {
    std::lock_guard<std::mutex> l(mu_);
    for (auto* d : pending_) umockdev_ioctl_data_unref(d);
    for (auto* d : completed_) umockdev_ioctl_data_unref(d);
    pending_.clear();
    completed_.clear();
    fifo_.clear();
    unplugged_ = halted_ = overrun_ = scanning_ = false;
    unplugAfterScans = -1;
  }
  bool unplugged() {
    std::lock_guard<std::mutex> l(mu_);
    return unplugged_;
  }

  // Fault switches (set before the scan).
  std::int64_t overrunAtScan = -1;     // stall the URB that would carry this scan
  std::int64_t skipOnOverrun = 7000;   // scans lost in the cleared FIFO
  std::int64_t unplugAfterScans = -1;  // unplug once this many scans were sent
  std::int64_t unplugAtScan = -1;      // unplug when the simulated clock reaches this scan
  bool silent = false;                 // the pacer never runs: no bulk data

  // What the host did, for the assertions.
  struct Log {
    int calReads = 0, statusReads = 0, clearHalts = 0, clearFifos = 0, scanStarts = 0, scanStops = 0, discards = 0;
    std::vector<ScanRequest> starts;
    std::int64_t scansSent = 0;  // over the whole session
    std::int64_t scansBeforeOverrun = -1;
    std::int64_t restartScan = -1;        // first scan index after the overrun
    std::int64_t scansBeforeUnplug = -1;  // in URBs completed before the unplug
    std::array<std::uint8_t, 8> ranges{};
  };
  Log log() {
    std::lock_guard<std::mutex> l(mu_);
    return log_;
  }

  gboolean handle(UMockdevIoctlClient* client) {
    std::lock_guard<std::mutex> l(mu_);
    const gulong req = umockdev_ioctl_client_get_request(client);
    UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
    // After an unplug usbfs still lets the host reap finished URBs, then
    // answers ENODEV; every other request fails with ENODEV at once.
    if (unplugged_ && req != USBDEVFS_REAPURB && req != USBDEVFS_REAPURBNDELAY) return finish(client, -1, ENODEV);
    GError* err = nullptr;
    switch (req) {
      case USBDEVFS_SUBMITURB: {
        UMockdevIoctlData* urbd = umockdev_ioctl_data_resolve(arg, 0, sizeof(usbdevfs_urb), &err);
        if (!urbd) return finish(client, -1, EFAULT);
        auto* urb = reinterpret_cast<usbdevfs_urb*>(urbd->data);
        UMockdevIoctlData* buf = urb->buffer_length > 0
                                     ? umockdev_ioctl_data_resolve(urbd, offsetof(usbdevfs_urb, buffer),
                                                                   static_cast<gsize>(urb->buffer_length), &err)
                                     : nullptr;
        umockdev_ioctl_data_ref(urbd);
        if (urb->type == USBDEVFS_URB_TYPE_CONTROL) {
          control(urbd, buf);
          completed_.push_back(urbd);
        } else if (urb->endpoint == kBulkInEndpoint) {
          if (halted_) {
            setUrb(urbd, -EPIPE, 0);
            completed_.push_back(urbd);
          } else {
            pending_.push_back(urbd);
            pump();
          }
        } else {
          setUrb(urbd, -EPIPE, 0);
          completed_.push_back(urbd);
        }
        return finish(client, 0, 0);
      }
      case USBDEVFS_REAPURB:
      case USBDEVFS_REAPURBNDELAY: {
        if (completed_.empty()) return finish(client, -1, unplugged_ ? ENODEV : EAGAIN);
        UMockdevIoctlData* p = umockdev_ioctl_data_resolve(arg, 0, sizeof(void*), &err);
        UMockdevIoctlData* urbd = completed_.front();
        completed_.pop_front();
        umockdev_ioctl_data_set_ptr(p, 0, urbd);
        umockdev_ioctl_data_unref(urbd);
        return finish(client, 0, 0);
      }
      case USBDEVFS_DISCARDURB: {
        const unsigned long addr = *reinterpret_cast<unsigned long*>(arg->data);
        for (auto it = pending_.begin(); it != pending_.end(); ++it)
          if ((*it)->client_addr == addr) {
            UMockdevIoctlData* urbd = *it;
            pending_.erase(it);
            setUrb(urbd, -ENOENT, 0);  // usbfs reports an unlinked URB with -ENOENT
            completed_.push_back(urbd);
            ++log_.discards;
            return finish(client, 0, 0);
          }
        return finish(client, -1, EINVAL);
      }
      case USBDEVFS_CLEAR_HALT:
        halted_ = false;
        ++log_.clearHalts;
        return finish(client, 0, 0);
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
  static gboolean finish(UMockdevIoctlClient* client, long result, int err) {
    return devices::testing::finishIoctl(client, result, err);
  }

  static void setUrb(UMockdevIoctlData* urbd, int status, int actual) {
    devices::testing::setUrbResult(urbd, status, actual);
  }

  static UMockdevIoctlData* bufferOf(UMockdevIoctlData* urbd) {
    GError* err = nullptr;
    auto* urb = reinterpret_cast<usbdevfs_urb*>(urbd->data);
    return umockdev_ioctl_data_resolve(urbd, offsetof(usbdevfs_urb, buffer), static_cast<gsize>(urb->buffer_length),
                                       &err);
  }

  void control(UMockdevIoctlData* urbd, UMockdevIoctlData* buf) {
    const std::uint8_t* s = buf->data;
    const std::uint8_t type = s[0], request = s[1];
    const std::uint16_t value = static_cast<std::uint16_t>(s[2] | s[3] << 8);
    const std::uint16_t length = static_cast<std::uint16_t>(s[6] | s[7] << 8);
    std::vector<std::uint8_t> in;
    bool ok = true;
    if (type == 0x80 && request == 6 && (value >> 8) == 3) {  // GET_DESCRIPTOR string
      if ((value & 0xFF) == 0)
        in = {4, 3, 0x09, 0x04};
      else {
        const std::string serial = "01ABCDEF";
        in = {static_cast<std::uint8_t>(2 + 2 * serial.size()), 3};
        for (char ch : serial) in.insert(in.end(), {static_cast<std::uint8_t>(ch), 0});
      }
    } else if (type == 0xC0 && request == kCalMemory) {
      ++log_.calReads;
      if (value + length > kCalMemoryBytes)
        ok = false;
      else
        in.assign(cal_.begin() + value, cal_.begin() + value + length);
    } else if (type == 0xC0 && request == kStatus) {
      ++log_.statusReads;
      const std::uint16_t st =
          static_cast<std::uint16_t>((scanning_ ? kStatusScanRunning : 0) | (overrun_ ? kStatusScanOverrun : 0));
      in = {static_cast<std::uint8_t>(st & 0xFF), static_cast<std::uint8_t>(st >> 8)};
    } else if (type == 0x40 && request == kAInConfig && length == 8) {
      std::copy(s + 8, s + 16, log_.ranges.begin());
    } else if (type == 0x40 && request == kAInScanStop) {
      ++log_.scanStops;
      scanning_ = false;
    } else if (type == 0x40 && request == kAInClearFifo) {
      ++log_.clearFifos;
      fifo_.clear();
      overrun_ = false;
    } else if (type == 0x40 && request == kAInScanStart && length == 10) {
      auto r = decodeScanStart(std::vector<std::uint8_t>(s + 8, s + 18));
      ++log_.scanStarts;
      log_.starts.push_back(*r);
      scan_ = *r;
      channels_.clear();
      for (int c = 0; c < 8; ++c)
        if (scan_.channelMask & (1u << c)) channels_.push_back(c);
      scanning_ = true;
      scansThisRun_ = 0;
      if (log_.scansBeforeOverrun >= 0 && log_.restartScan < 0) {
        nextScan_ += skipOnOverrun;  // the FIFO content lost in the overrun
        log_.restartScan = nextScan_;
      }
    } else {
      ok = false;
    }
    if (!ok) {
      setUrb(urbd, -EPIPE, 0);
      return;
    }
    if (!in.empty()) {
      in.resize(std::min<std::size_t>(in.size(), length));
      umockdev_ioctl_data_update(buf, 8, in.data(), static_cast<gint>(in.size()));
    }
    setUrb(urbd, 0, (type & 0x80) ? static_cast<int>(in.size()) : length);
    if (request == kAInScanStart) pump();
  }

  // Serves pending bulk URBs from the simulated clock.
  void pump() {
    while (scanning_ && !silent && !pending_.empty() && !unplugged_) {
      UMockdevIoctlData* urbd = pending_.front();
      auto* urb = reinterpret_cast<usbdevfs_urb*>(urbd->data);
      const std::size_t want = static_cast<std::size_t>(urb->buffer_length);
      const std::size_t scanBytes = 2 * channels_.size();
      // Produce scans into the FIFO until the URB can be filled or the
      // requested count is reached.
      while (fifo_.size() < want &&
             (scan_.scanCount == 0 || scansThisRun_ < static_cast<std::int64_t>(scan_.scanCount))) {
        if (overrunAtScan >= 0 && nextScan_ == overrunAtScan && log_.scansBeforeOverrun < 0) {
          // FIFO overrun: the device stalls the bulk endpoint; every queued
          // URB fails with -EPIPE until the host clears the halt.
          log_.scansBeforeOverrun = log_.scansSent;
          overrun_ = true;
          halted_ = true;
          scanning_ = false;
          for (auto* d : pending_) {
            setUrb(d, -EPIPE, 0);
            completed_.push_back(d);
          }
          pending_.clear();
          return;
        }
        if (unplugAtScan >= 0 && nextScan_ >= unplugAtScan) {
          // The cable is pulled: the URB being filled and every queued one
          // are lost with the device (-ESHUTDOWN), as usbfs reports it.
          for (auto* d : pending_) {
            setUrb(d, -ESHUTDOWN, 0);
            completed_.push_back(d);
          }
          pending_.clear();
          fifo_.clear();
          unplugged_ = true;
          unplugAtScan = -1;
          return;
        }
        for (int c : channels_) {
          const std::uint16_t code = this->code(nextScan_, c);
          fifo_.push_back(static_cast<std::uint8_t>(code & 0xFF));
          fifo_.push_back(static_cast<std::uint8_t>(code >> 8));
        }
        ++nextScan_;
        ++scansThisRun_;
      }
      const bool done = scan_.scanCount != 0 && scansThisRun_ >= static_cast<std::int64_t>(scan_.scanCount);
      if (fifo_.size() < want && !done) return;
      const std::size_t n = std::min(want, fifo_.size());
      std::vector<std::uint8_t> out(fifo_.begin(), fifo_.begin() + static_cast<std::ptrdiff_t>(n));
      fifo_.erase(fifo_.begin(), fifo_.begin() + static_cast<std::ptrdiff_t>(n));
      if (n > 0) umockdev_ioctl_data_update(bufferOf(urbd), 0, out.data(), static_cast<gint>(n));
      setUrb(urbd, 0, static_cast<int>(n));
      pending_.pop_front();
      completed_.push_back(urbd);
      log_.scansSent += static_cast<std::int64_t>(n / scanBytes);
      if (done && fifo_.empty()) scanning_ = false;
      if (unplugAfterScans >= 0 && log_.scansSent >= unplugAfterScans) {
        // The URB just filled is lost with the device, and so is every
        // queued one: usbfs completes them with -ESHUTDOWN.
        setUrb(urbd, -ESHUTDOWN, 0);
        log_.scansBeforeUnplug = log_.scansSent - static_cast<std::int64_t>(n / scanBytes);
        for (auto* d : pending_) {
          setUrb(d, -ESHUTDOWN, 0);
          completed_.push_back(d);
        }
        pending_.clear();
        unplugged_ = true;
        return;
      }
      if (n == 0) return;
    }
  }

  std::mutex mu_;
  std::vector<std::uint8_t> cal_;
  std::deque<UMockdevIoctlData*> pending_, completed_;
  std::deque<std::uint8_t> fifo_;
  ScanRequest scan_;
  std::vector<int> channels_;
  bool scanning_ = false, halted_ = false, overrun_ = false, unplugged_ = false;
  std::int64_t nextScan_ = 0, scansThisRun_ = 0;
  Log log_;
};

inline gboolean onIoctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer self) {
  return static_cast<DeviceModel*>(self)->handle(client);
}

// The umockdev testbed with the model attached (setUp / tearDown of a fixture).
class Usb1608Testbed {
 public:
  DeviceModel model_;
  void setUp() {
    const char* preload = std::getenv("LD_PRELOAD");
    ASSERT_TRUE(preload && std::strstr(preload, "umockdev")) << "run under umockdev-wrapper";
    testbed_ = umockdev_testbed_new();
    // Device descriptor: USB 2.0, max packet 64 on EP0, VID 09DB PID 00EA,
    // iSerialNumber 3; one configuration, interface 0 with bulk IN 0x81 (64 bytes).
    const std::uint8_t desc[] = {18, 1, 0x00, 0x02, 0, 0,  0, 64, 0xDB, 0x09, 0xEA, 0x00, 0x00, 0x01, 1,
                                 2,  3, 1,    9,    2, 25, 0, 1,  1,    0,    0x80, 50,   9,    4,    0,
                                 0,  1, 0xFF, 0,    0, 0,  7, 5,  0x81, 2,    64,   0,    0};
    const gchar* attrs[] = {"busnum", "1", "devnum", "2", "speed", "12", "dev", "189:1", nullptr};
    const gchar* props[] = {"DEVTYPE", "usb_device", "DEVNAME", "/dev/bus/usb/001/002", "BUSNUM", "001",
                            "DEVNUM",  "002",        nullptr};
    sysPath_ = umockdev_testbed_add_devicev(testbed_, "usb", "usb1608fsplus", nullptr, const_cast<gchar**>(attrs),
                                            const_cast<gchar**>(props));
    umockdev_testbed_set_attribute_binary(testbed_, sysPath_, "descriptors", const_cast<guint8*>(desc), sizeof desc);
    // add_devicev creates no device node; libusb needs /dev/bus/usb/001/002 to exist.
    gchar* root = umockdev_testbed_get_root_dir(testbed_);
    const std::string dir = std::string(root) + "/dev/bus/usb/001";
    g_free(root);
    ASSERT_EQ(g_mkdir_with_parents(dir.c_str(), 0755), 0);
    std::ofstream(dir + "/002").put('\0');
    handler_ = umockdev_ioctl_base_new();
    g_signal_connect(handler_, "handle-ioctl", G_CALLBACK(onIoctl), &model_);
    GError* err = nullptr;
    ASSERT_TRUE(umockdev_testbed_attach_ioctl(testbed_, "/dev/bus/usb/001/002", handler_, &err))
        << (err ? err->message : "");
  }
  void tearDown() {
    if (testbed_) {
      GError* err = nullptr;
      umockdev_testbed_detach_ioctl(testbed_, "/dev/bus/usb/001/002", &err);
      g_object_unref(handler_);
      g_object_unref(testbed_);
    }
    g_free(sysPath_);
  }

  UMockdevTestbed* testbed_ = nullptr;
  UMockdevIoctlBase* handler_ = nullptr;
  gchar* sysPath_ = nullptr;
};

}  // namespace mozzi::devices::mcc::emulation
