#include "core/io/text_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace mozzi::core::io {

Result<std::string> readTextFile(const std::string& path, const std::string& what, std::uint64_t maxBytes) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) {
    return makeError(ErrorCode::IoError, "cannot open the " + what + " file: " + std::string(std::strerror(errno)),
                     path);
  }
  std::string text;
  char buffer[65536];
  for (;;) {
    const std::size_t n = std::fread(buffer, 1, sizeof buffer, f.get());
    if (n > 0) {
      if (text.size() + n > maxBytes) {
        return makeError(ErrorCode::Unsupported,
                         "the " + what + " file is larger than " + std::to_string(maxBytes >> 20) +
                             " MiB, the most this reader accepts",
                         path);
      }
      text.append(buffer, n);
    }
    if (n < sizeof buffer) {
      if (std::ferror(f.get())) {
        return makeError(ErrorCode::IoError, "read error in the " + what + " file: " + std::strerror(errno), path);
      }
      if (std::feof(f.get())) break;
    }
  }
  return text;
}

}  // namespace mozzi::core::io
