#include "core/io/mat/matio_library.h"

#include <dlfcn.h>

#include <string>

#ifndef MOZZI_MATIO_SONAME
#error "MOZZI_MATIO_SONAME (the soname of libmatio) is set by core/CMakeLists.txt"
#endif

namespace mozzi::core::io::mat {

const char* matioSoname() {
  return MOZZI_MATIO_SONAME;
}

Result<const MatioLibrary*> matioLibrary() {
  static const Result<const MatioLibrary*> loaded = []() -> Result<const MatioLibrary*> {
    const std::string where = std::string("MAT file support (") + MOZZI_MATIO_SONAME + ")";
    // RTLD_LOCAL: matio's symbols stay out of the global namespace; never closed.
    void* handle = ::dlopen(MOZZI_MATIO_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = ::dlerror();
      return makeError(ErrorCode::Unsupported,
                       std::string("libmatio cannot be loaded: ") + (why ? why : "unknown reason") +
                           " (install the libmatio package)",
                       where);
    }
    static MatioLibrary lib;
    bool ok = true;
    std::string missing;
    auto bind = [&](auto& fn, const char* name) {
      void* sym = ::dlsym(handle, name);
      if (!sym) {
        ok = false;
        missing += std::string(missing.empty() ? "" : ", ") + name;
        return;
      }
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(sym);
    };
    bind(lib.open, "Mat_Open");
    bind(lib.close, "Mat_Close");
    bind(lib.createVer, "Mat_CreateVer");
    bind(lib.varReadInfo, "Mat_VarReadInfo");
    bind(lib.varReadNextInfo, "Mat_VarReadNextInfo");
    bind(lib.varRead, "Mat_VarRead");
    bind(lib.varFree, "Mat_VarFree");
    bind(lib.varGetStructFieldByName, "Mat_VarGetStructFieldByName");
    bind(lib.getLibraryVersion, "Mat_GetLibraryVersion");
    if (!ok) return makeError(ErrorCode::Unsupported, "libmatio lacks " + missing, where);
    return &lib;
  }();
  return loaded;
}

}  // namespace mozzi::core::io::mat
