#include "core/io/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <random>
#include <streambuf>

namespace mozzi::core::io {
namespace {

namespace fs = std::filesystem;

std::string errnoText(int e) {
  return std::strerror(e);
}

// write() until every byte is out, retrying on EINTR and short writes.
int writeAll(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (n == 0) return EIO;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return 0;
}

// A streambuf over a file descriptor that remembers the first write error
// (errno), so commit() can name it; 64 KiB buffer.
class FdBuf : public std::streambuf {
 public:
  explicit FdBuf(int fd) : fd_(fd) { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
  int error() const { return error_; }
  int drain() {
    if (error_ != 0) return error_;
    const std::size_t n = static_cast<std::size_t>(pptr() - pbase());
    if (n > 0) error_ = writeAll(fd_, pbase(), n);
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return error_;
  }

 protected:
  int_type overflow(int_type ch) override {
    if (drain() != 0) return traits_type::eof();
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }
  int sync() override { return drain() == 0 ? 0 : -1; }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (error_ != 0) return 0;
    const auto room = epptr() - pptr();
    if (n <= room) {
      std::memcpy(pptr(), s, static_cast<std::size_t>(n));
      pbump(static_cast<int>(n));
      return n;
    }
    if (drain() != 0) return 0;
    if (n >= static_cast<std::streamsize>(buffer_.size())) {
      error_ = writeAll(fd_, s, static_cast<std::size_t>(n));
      return error_ == 0 ? n : 0;
    }
    std::memcpy(pptr(), s, static_cast<std::size_t>(n));
    pbump(static_cast<int>(n));
    return n;
  }

 private:
  int fd_;
  int error_ = 0;
  std::array<char, 65536> buffer_{};
};

// Names that stand for an already open descriptor: never replaced by a rename.
bool isStreamAlias(const std::string& path) {
  return path == "/dev/stdout" || path == "/dev/stderr" || path.rfind("/dev/fd/", 0) == 0 ||
         path.rfind("/proc/self/fd/", 0) == 0;
}

std::string hexToken() {
  static std::mt19937_64 rng{std::random_device{}() ^ static_cast<std::uint64_t>(::getpid())};
  char buf[20];
  std::snprintf(buf, sizeof buf, "%08llx", static_cast<unsigned long long>(rng() & 0xffffffffULL));
  return buf;
}

void fsyncFolder(const fs::path& folder) {
  const int dfd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd < 0) return;
  ::fsync(dfd);  // best effort: some file systems refuse fsync on a folder
  ::close(dfd);
}

}  // namespace

Result<void> refuseInputAsOutput(const std::string& target, const std::vector<std::string>& inputs) {
  struct stat out {};
  if (::stat(target.c_str(), &out) != 0) return {};  // does not exist (yet): cannot be an input
  for (const auto& input : inputs) {
    if (input.empty()) continue;
    struct stat in {};
    if (::stat(input.c_str(), &in) != 0) continue;
    if (in.st_dev == out.st_dev && in.st_ino == out.st_ino) {
      return makeError(ErrorCode::InvalidArgument,
                       "refusing to write the output onto the input '" + input +
                           "' (the same file, possibly through a link): the input would be destroyed",
                       target);
    }
  }
  return {};
}

struct OutputFile::State {
  std::string target;  // as the user named it (for messages)
  fs::path finalPath;  // where the rename lands (links followed)
  fs::path tempPath;   // empty when writing directly
  int fd = -1;
  bool direct = false;
  bool committed = false;
  std::unique_ptr<FdBuf> buf;
  std::unique_ptr<std::ostream> stream;

  ~State() {
    if (fd >= 0) ::close(fd);
    if (!committed && !tempPath.empty()) ::unlink(tempPath.c_str());
  }
};

OutputFile::OutputFile(std::unique_ptr<State> state) : state_(std::move(state)) {}
OutputFile::OutputFile(OutputFile&&) noexcept = default;
OutputFile& OutputFile::operator=(OutputFile&&) noexcept = default;
OutputFile::~OutputFile() = default;

std::ostream& OutputFile::stream() {
  return *state_->stream;
}
const std::string& OutputFile::target() const {
  return state_->target;
}
bool OutputFile::writesDirectly() const {
  return state_->direct;
}

Result<OutputFile> OutputFile::open(const std::string& target, const std::vector<std::string>& inputs) {
  if (target.empty()) return makeError(ErrorCode::InvalidArgument, "the output file name is empty", target);
  if (auto r = refuseInputAsOutput(target, inputs); !r) return r.error();
  auto state = std::make_unique<State>();
  state->target = target;

  struct stat st {};
  const bool exists = ::stat(target.c_str(), &st) == 0;
  if (exists && S_ISDIR(st.st_mode)) {
    return makeError(ErrorCode::InvalidArgument, "the output names a folder, not a file", target);
  }
  if (isStreamAlias(target) || (exists && !S_ISREG(st.st_mode))) {
    // Special file: write in place, each write checked. O_APPEND for a
    // descriptor alias that is a regular file, so what the shell redirected
    // there before is kept.
    int flags = O_WRONLY | O_CLOEXEC;
    if (exists && S_ISREG(st.st_mode)) flags |= O_APPEND;
    state->fd = ::open(target.c_str(), flags);
    if (state->fd < 0) return makeError(ErrorCode::IoError, "cannot open for writing: " + errnoText(errno), target);
    state->direct = true;
  } else {
    if (exists && ::access(target.c_str(), W_OK) != 0) {
      return makeError(ErrorCode::IoError, "the existing file is not writable: " + errnoText(errno), target);
    }
    std::error_code ec;
    // A symbolic link is followed: the file it points to is replaced.
    state->finalPath = exists ? fs::canonical(target, ec) : fs::path(target);
    if (ec) return makeError(ErrorCode::IoError, "cannot resolve the output path: " + ec.message(), target);
    const fs::path folder = state->finalPath.parent_path();
    struct stat dst {};
    if (::stat(folder.empty() ? "." : folder.c_str(), &dst) != 0 || !S_ISDIR(dst.st_mode)) {
      return makeError(ErrorCode::NotFound, "the folder of the output file does not exist", target);
    }
    const std::string base = "." + state->finalPath.filename().string() + ".part-" + std::to_string(::getpid()) + "-";
    for (int attempt = 0; attempt < 100 && state->fd < 0; ++attempt) {
      state->tempPath = folder / (base + hexToken());
      // 0666 less the umask, as a plain create would give.
      state->fd = ::open(state->tempPath.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (state->fd < 0 && errno != EEXIST) {
        const int e = errno;
        state->tempPath.clear();
        return makeError(ErrorCode::IoError,
                         "cannot create a temporary file in the output's folder '" +
                             (folder.empty() ? std::string(".") : folder.string()) + "': " + errnoText(e),
                         target);
      }
    }
    if (state->fd < 0) {
      state->tempPath.clear();
      return makeError(ErrorCode::IoError, "cannot find a free temporary name beside the output", target);
    }
    if (exists) ::fchmod(state->fd, st.st_mode & 07777);  // keep the replaced file's permissions
  }
  state->buf = std::make_unique<FdBuf>(state->fd);
  state->stream = std::make_unique<std::ostream>(state->buf.get());
  return OutputFile(std::move(state));
}

Result<void> OutputFile::commit() {
  State& s = *state_;
  if (s.committed || s.fd < 0) return makeError(ErrorCode::InvalidArgument, "output already committed", s.target);
  const bool streamOk = static_cast<bool>(*s.stream);
  const int writeError = s.buf->drain();
  if (writeError != 0 || !streamOk) {
    return makeError(ErrorCode::IoError,
                     "write failed: " + (writeError != 0 ? errnoText(writeError) : std::string("stream error")) +
                         (s.direct ? "" : "; the earlier file (if any) is untouched"),
                     s.target);
  }
  if (!s.direct && ::fsync(s.fd) != 0) {
    return makeError(ErrorCode::IoError,
                     "write failed (fsync): " + errnoText(errno) + "; the earlier file (if any) is untouched",
                     s.target);
  }
  const int fd = s.fd;
  s.fd = -1;
  if (::close(fd) != 0) {
    return makeError(
        ErrorCode::IoError,
        "write failed (close): " + errnoText(errno) + (s.direct ? "" : "; the earlier file (if any) is untouched"),
        s.target);
  }
  if (!s.direct) {
    if (::rename(s.tempPath.c_str(), s.finalPath.c_str()) != 0) {
      return makeError(
          ErrorCode::IoError,
          "cannot move the written file into place: " + errnoText(errno) + "; the earlier file (if any) is untouched",
          s.target);
    }
    fsyncFolder(s.finalPath.parent_path());
  }
  s.committed = true;
  return {};
}

Result<void> writeOutputFile(const std::string& target, std::string_view bytes,
                             const std::vector<std::string>& inputs) {
  return writeOutputFile(
      target,
      [&](std::ostream& out) -> Result<void> {
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        return {};
      },
      inputs);
}

Result<void> writeOutputFile(const std::string& target, const std::function<Result<void>(std::ostream&)>& write,
                             const std::vector<std::string>& inputs) {
  auto file = OutputFile::open(target, inputs);
  if (!file) return file.error();
  auto r = write(file->stream());
  // A failed write is reported by commit(), which names the file and the
  // system's reason, rather than by the writer's own message.
  if (!file->stream()) return file->commit();
  if (!r) return r;
  return file->commit();
}

}  // namespace mozzi::core::io
