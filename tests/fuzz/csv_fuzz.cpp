// Fuzz target: the CSV readers (time records, FRFs, modal tables). Whatever a
// reader accepts must also be writable and read back; nothing may crash.

#include <cstdint>
#include <sstream>
#include <string_view>

#include "core/io/csv/csv_exchange.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace mozzi::core::io::csv;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (auto t = readTimeCsv(text, "fuzz.csv")) {
    std::ostringstream out;
    if (writeTimeCsv(*t, out)) (void)readTimeCsv(out.str(), "again.csv");
  }
  if (auto f = readFrfCsv(text, "fuzz.csv")) {
    std::ostringstream out;
    if (writeFrfCsv(*f, out)) (void)readFrfCsv(out.str(), "again.csv");
  }
  if (auto m = readModalCsv(text, "fuzz.csv")) {
    std::ostringstream out;
    if (writeModalCsv(*m, out)) (void)readModalCsv(out.str(), "again.csv");
  }
  return 0;
}
