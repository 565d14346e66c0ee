// libFuzzer target for the UFF reader: any byte string must give datasets or
// an Error, never a crash, a hang or a huge allocation. Whatever is read is
// written back and read again (the writer must accept what the reader gives,
// except skipped datasets), in both 58 encodings.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/io/uff/uff.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace mozzi::core::io::uff;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  ReadOptions options;
  options.maxDatasetBytes = std::uint64_t{64} << 20;  // keep the fuzzer within its RSS limit
  auto file = readBytes(bytes, options);
  if (!file.ok()) return 0;
  for (Encoding58 encoding : {Encoding58::Ascii, Encoding58::Binary}) {
    WriteOptions w;
    w.encoding = encoding;
    auto text = writeBytes(*file, w);
    if (!text.ok()) continue;
    auto again = readBytes(*text, options);
    (void)again;
  }
  (void)toFrfMatrix(*file);
  (void)toModalData(*file);
  return 0;
}
