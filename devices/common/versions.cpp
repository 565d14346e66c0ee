#include "devices/common/versions.h"

#include <libusb.h>

#include <string>

namespace mozzi::devices {

core::LibraryVersions deviceLibraryVersions() {
  const libusb_version* v = libusb_get_version();
  return {{"libusb", std::to_string(v->major) + "." + std::to_string(v->minor) + "." + std::to_string(v->micro)}};
}

}  // namespace mozzi::devices
