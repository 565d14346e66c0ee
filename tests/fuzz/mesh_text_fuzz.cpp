// Fuzz target: the mesh readers of the mesh editor, i.e. the mesh CSV
// (core/io/csv) and the editor's cell texts (node DOFs "+X +Z", slave rules
// "5:+Z = 0.5 4:+Z"). Whatever a reader accepts and validates must be
// writable and read back to the same document; nothing may crash.

#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string_view>

#include "core/geometry/mesh_edit.h"
#include "core/io/csv/csv_exchange.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace mozzi::core;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (auto doc = io::csv::readMeshCsv(text, "fuzz.csv")) {
    if (geometry::validate(*doc)) {
      std::ostringstream out;
      if (io::csv::writeMeshCsv(*doc, out)) {
        auto again = io::csv::readMeshCsv(out.str(), "again.csv");
        if (!again || !io::sameDocument(*again, *doc)) std::abort();  // a round trip must be exact
      }
    }
  }
  if (auto rule = geometry::parseSlaveRule(text)) {
    auto again = geometry::parseSlaveRule(geometry::formatSlaveRule(*rule));
    if (!again) std::abort();
  }
  (void)geometry::parseNodeDofs(7, text);
  return 0;
}
