#pragma once
// Size caps of the text readers (parameter files, plate and tyre CSV, model
// JSON, SignalCalc ASCII): a text input larger than its cap is refused with an
// error naming the file, after reading at most cap + 1 bytes, so a huge file
// or an endless device such as /dev/zero cannot exhaust memory. The UFF
// readers have their own 64 MiB line cap (core/io/uff/uff.h).

#include <cstdint>
#include <string>

#include "core/common/result.h"

namespace mozzi::core::io {

inline constexpr std::uint64_t kMaxTextFileBytes = std::uint64_t{256} << 20;     // 256 MiB: tables, JSON models
inline constexpr std::uint64_t kMaxParameterFileBytes = std::uint64_t{1} << 20;  // 1 MiB: name,value files

// The whole file as bytes. `what` names the kind of file in the error
// ("tyre test", "model"); errors: cannot open, larger than maxBytes, read error.
Result<std::string> readTextFile(const std::string& path, const std::string& what,
                                 std::uint64_t maxBytes = kMaxTextFileBytes);

}  // namespace mozzi::core::io
