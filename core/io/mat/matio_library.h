#pragma once
// libmatio, opened with dlopen the first time a MAT file is read, not linked:
// libmatio pulls in HDF5 and through it curl, gnutls, krb5 and ldap, about
// 20 ms of start-up for every mozzi-cli command that never reads a MAT file
// (issue 19). Only the functions mat_import.cpp calls are resolved.

#include <matio.h>

#include "core/common/result.h"

namespace mozzi::core::io::mat {

struct MatioLibrary {
  decltype(&::Mat_Open) open = nullptr;
  decltype(&::Mat_Close) close = nullptr;
  decltype(&::Mat_CreateVer) createVer = nullptr;
  decltype(&::Mat_VarReadInfo) varReadInfo = nullptr;
  decltype(&::Mat_VarReadNextInfo) varReadNextInfo = nullptr;
  decltype(&::Mat_VarRead) varRead = nullptr;
  decltype(&::Mat_VarFree) varFree = nullptr;
  decltype(&::Mat_VarGetStructFieldByName) varGetStructFieldByName = nullptr;
  decltype(&::Mat_GetLibraryVersion) getLibraryVersion = nullptr;
};

// The library, loaded on the first call (thread-safe). Error (Unsupported)
// naming the library and dlerror() when it cannot be opened or lacks a symbol.
Result<const MatioLibrary*> matioLibrary();

// The soname opened (e.g. "libmatio.so.11"), fixed at build time.
const char* matioSoname();

}  // namespace mozzi::core::io::mat
