#pragma once
// Pieces every usbfs device model behind umockdev's in-process ioctl handler
// needs (the USB-1608FS-Plus and USBTMC umockdev tests): completing an ioctl,
// writing a URB's status and length back to the client, and opening the one
// device a driver's scan finds.
#include <linux/usbdevice_fs.h>
#include <umockdev.h>

#include <gtest/gtest.h>

#include <cstddef>
#include <cstring>
#include <memory>

#include "devices/common/driver.h"

namespace mozzi::devices::testing {

inline gboolean finishIoctl(UMockdevIoctlClient* client, long result, int err) {
  umockdev_ioctl_client_complete(client, result, err);
  return TRUE;
}

// Reaped URBs carry status and actual length back to libusb.
inline void setUrbResult(UMockdevIoctlData* urbd, int status, int actual) {
  usbdevfs_urb u;
  std::memcpy(&u, urbd->data, sizeof u);
  u.status = status;
  u.actual_length = actual;
  umockdev_ioctl_data_update(urbd, offsetof(usbdevfs_urb, status), reinterpret_cast<guint8*>(&u.status),
                             sizeof u.status);
  umockdev_ioctl_data_update(urbd, offsetof(usbdevfs_urb, actual_length), reinterpret_cast<guint8*>(&u.actual_length),
                             sizeof u.actual_length);
}

// Scans with `driver`, expects exactly one device, creates and opens it into `slot`.
inline Device& openOnlyDevice(Driver& driver, std::unique_ptr<Device>& slot) {
  auto found = driver.scan();
  EXPECT_TRUE(found.ok());
  EXPECT_EQ(found->size(), 1u);
  auto dev = driver.create(found->front());
  EXPECT_TRUE(dev.ok());
  slot = std::move(*dev);
  auto opened = slot->open();
  EXPECT_TRUE(opened.ok()) << opened.error().describe();
  return *slot;
}

}  // namespace mozzi::devices::testing
