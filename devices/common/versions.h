#pragma once
// Versions of the libraries the devices layer is linked with (libusb, read at run time).

#include "core/common/versions.h"

namespace mozzi::devices {

core::LibraryVersions deviceLibraryVersions();

}  // namespace mozzi::devices
