#pragma once
// The one way Mozzi writes a file the user names (exports, --out, --modes,
// --stabilization, ...); no Qt, so the GUI uses it too. docs/cli.md, "Output files".
//
// Rules:
// - The target is refused when it is the same file as one of the inputs
//   (same device and inode after following symbolic links, so a symlink or a
//   hard link of the input is caught), and when it exists but is not writable.
// - A regular file (or a name that does not exist yet) is written to a
//   temporary file in the target's own folder (".NAME.part-PID-XXXX"); after
//   the last byte the file is flushed, fsync'd and closed, every step checked,
//   and only then renamed over the target (a symbolic link is followed: the
//   file it points to is replaced, the link stays). A failed write (disk full,
//   read-only folder, I/O error) removes the temporary file and leaves any
//   earlier file under the target's name untouched.
// - A special file (character device such as /dev/null or /dev/full, a pipe,
//   a socket) and the names /dev/stdout, /dev/stderr, /dev/fd/N and
//   /proc/self/fd/N are written directly, every write checked; there is no
//   temporary file and no rename (a pipe cannot be replaced), so such a write
//   is not atomic.

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/result.h"

namespace mozzi::core::io {

// Error when `target` is the same file as one of `inputs` (inputs that do not
// exist are skipped). Call it before any work so nothing is computed for a
// write that will be refused.
Result<void> refuseInputAsOutput(const std::string& target, const std::vector<std::string>& inputs);

class OutputFile {
 public:
  // Checks the target (and the inputs, see refuseInputAsOutput) and opens the
  // temporary file (or the special file) for writing.
  static Result<OutputFile> open(const std::string& target, const std::vector<std::string>& inputs = {});

  OutputFile(OutputFile&&) noexcept;
  OutputFile& operator=(OutputFile&&) noexcept;
  ~OutputFile();  // without commit(): the temporary file is removed

  // The stream to write to; a failed write sets its badbit and is reported by commit().
  std::ostream& stream();
  // Flush, fsync, close, rename into place: the target holds the new content
  // only when this returns success. Call at most once.
  Result<void> commit();

  const std::string& target() const;
  bool writesDirectly() const;  // special file: no temporary, no rename

 private:
  struct State;
  explicit OutputFile(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

// Whole-file conveniences over OutputFile.
Result<void> writeOutputFile(const std::string& target, std::string_view bytes,
                             const std::vector<std::string>& inputs = {});
Result<void> writeOutputFile(const std::string& target, const std::function<Result<void>(std::ostream&)>& write,
                             const std::vector<std::string>& inputs = {});

}  // namespace mozzi::core::io
