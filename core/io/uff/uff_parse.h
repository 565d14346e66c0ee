#pragma once
// Internals of the streaming UFF reader, shared by its files (not part of the
// public API, core/io/uff/uff.h): the buffered byte source and the dataset
// context (uff_reader.cpp reads the file with them), the number readers, and
// one parser per dataset family:
//   uff_parse_records.cpp   151 header, 164 units, 55 data at nodes, skipped types
//   uff_parse_geometry.cpp  15 / 2411 nodes, 18 / 2420 coordinate systems, 82 trace lines
//   uff_parse_58.cpp        58 and 58b functions
// The record layouts are listed at the top of uff_reader.cpp.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/uff/uff.h"
#include "core/io/uff/uff_text.h"

namespace mozzi::core::io::uff::parsing {

using detail::field;
using detail::isBlank;
using detail::isDelimiter;
using detail::NumberStatus;
using detail::parseInt;
using detail::scanNumbers;
using detail::trim;
using detail::trimRight;

// Read buffer, grows only for a longer line. 64 kB, not more: a 58b block is
// copied from it to its destination and read past it straight from the file
// (Source::readRaw), so a larger read-ahead only copied most of every block
// twice (1 MB: 4% of `mozzi-cli frf`; ASCII reading as fast, issue 19).
constexpr std::size_t kBufferBytes = std::size_t{64} << 10;
constexpr std::size_t kMaxLineBytes = std::size_t{64} << 20;  // a longer "line" is not a universal file

inline bool hostIsLittleEndian() {
  const std::uint16_t probe = 1;
  unsigned char first = 0;
  std::memcpy(&first, &probe, 1);
  return first == 1;
}

// Buffered byte source over a FILE* or a copy of memory: lines (LF, CR/LF or
// lone CR) and raw byte blocks (58b).
class Source {
 public:
  enum class Status { Ok, End, TooLong, IoFailure };

  Source(std::FILE* file, std::uint64_t size) : file_(file), total_(size) { buf_.resize(kBufferBytes); }
  explicit Source(std::string_view bytes)
      : buf_(bytes.begin(), bytes.end()), end_(buf_.size()), total_(bytes.size()), eof_(true) {}
  Source(const Source&) = delete;
  Source& operator=(const Source&) = delete;
  ~Source() {
    if (file_) std::fclose(file_);
  }

  Status nextLine(std::string_view& line) {
    for (;;) {
      const char* base = buf_.data();
      const std::size_t from = std::max(pos_, scanned_);
      const char* nl = from < end_ ? static_cast<const char*>(std::memchr(base + from, '\n', end_ - from)) : nullptr;
      const std::size_t stop = nl ? static_cast<std::size_t>(nl - base) : end_;
      const char* cr = stop > pos_ ? static_cast<const char*>(std::memchr(base + pos_, '\r', stop - pos_)) : nullptr;
      std::size_t lineEnd = 0;
      std::size_t next = 0;
      if (cr && (static_cast<std::size_t>(cr - base) + 1 < end_ || eof_)) {
        lineEnd = static_cast<std::size_t>(cr - base);
        if (nl && lineEnd + 1 == stop) {
          crlf_ = true;
          next = stop + 1;
        } else {
          loneCr_ = true;
          next = lineEnd + 1;
        }
      } else if (nl) {
        lineEnd = stop;
        next = stop + 1;
      } else {
        scanned_ = end_;
        if (!eof_) {
          const Status s = refill();
          if (s != Status::Ok) return s;
          continue;
        }
        if (pos_ >= end_) return Status::End;
        lineEnd = end_;
        next = end_;
      }
      line = std::string_view(base + pos_, lineEnd - pos_);
      pos_ = next;
      ++lineNumber_;
      return Status::Ok;
    }
  }

  // Copies up to n raw bytes to dst; returns the count copied (short at EOF).
  std::size_t readRaw(char* dst, std::size_t n) {
    std::size_t done = 0;
    const std::size_t inBuffer = std::min(n, end_ - pos_);
    std::memcpy(dst, buf_.data() + pos_, inBuffer);
    pos_ += inBuffer;
    done += inBuffer;
    if (done < n && file_ && !eof_) {
      const std::size_t got = std::fread(dst + done, 1, n - done, file_);
      consumedBefore_ += got;
      done += got;
      if (done < n) eof_ = true;
    }
    return done;
  }

  std::int64_t lineNumber() const { return lineNumber_; }
  std::uint64_t consumed() const { return consumedBefore_ + pos_; }
  std::uint64_t remaining() const {
    const std::uint64_t c = consumed();
    return total_ > c ? total_ - c : 0;
  }
  // Nothing left to read (the last line has been handed out).
  bool exhausted() const { return eof_ && pos_ >= end_; }
  // One past the last byte held (a line ending here had no terminator).
  const char* lastByteEnd() const { return buf_.data() + end_; }
  bool sawCrLf() const { return crlf_; }
  bool sawLoneCr() const { return loneCr_; }
  bool ioFailed() const { return file_ && std::ferror(file_); }

 private:
  Status refill() {
    if (pos_ > 0) {
      std::memmove(buf_.data(), buf_.data() + pos_, end_ - pos_);
      consumedBefore_ += pos_;
      end_ -= pos_;
      scanned_ = scanned_ > pos_ ? scanned_ - pos_ : 0;
      pos_ = 0;
    } else if (end_ == buf_.size()) {
      if (buf_.size() >= kMaxLineBytes) return Status::TooLong;
      buf_.resize(buf_.size() * 2);
    }
    const std::size_t got = std::fread(buf_.data() + end_, 1, buf_.size() - end_, file_);
    end_ += got;
    if (got == 0) {
      eof_ = true;
      if (std::ferror(file_)) return Status::IoFailure;
    }
    return Status::Ok;
  }

  std::FILE* file_ = nullptr;
  std::vector<char> buf_;
  std::size_t pos_ = 0;
  std::size_t end_ = 0;
  std::size_t scanned_ = 0;           // no '\n' in [pos_, scanned_)
  std::uint64_t consumedBefore_ = 0;  // bytes dropped from the buffer or read around it
  std::uint64_t total_ = 0;
  bool eof_ = false;
  std::int64_t lineNumber_ = 0;
  bool crlf_ = false;
  bool loneCr_ = false;
};

// One dataset being parsed: line access that stops at the closing delimiter,
// and error/warning helpers that name the dataset and line.
class DatasetContext {
 public:
  enum class Line { Ok, Delimiter, Eof };

  DatasetContext(Source& src, int type, std::int64_t startLine, std::string_view where, std::vector<Warning>& warnings,
                 const ReadOptions& options)
      : src_(src), type_(type), startLine_(startLine), where_(where), warnings_(warnings), options_(options) {}

  // Next record line (blank lines included). Delimiter/Eof end the dataset.
  Line next(std::string_view& line) {
    if (closed_) return Line::Delimiter;
    if (eof_) return Line::Eof;
    const Source::Status s = src_.nextLine(line);
    if (s == Source::Status::Ok) {
      if (isDelimiter(line)) {
        closed_ = true;
        return Line::Delimiter;
      }
      return Line::Ok;
    }
    if (s == Source::Status::TooLong) tooLong_ = true;
    if (s == Source::Status::IoFailure) ioFailure_ = true;
    eof_ = true;
    return Line::Eof;
  }

  // Next line that is not blank (for records that cannot be empty).
  Line nextNonBlank(std::string_view& line) {
    for (;;) {
      const Line l = next(line);
      if (l != Line::Ok || !isBlank(line)) return l;
    }
  }

  std::int64_t line() const { return src_.lineNumber(); }
  int type() const { return type_; }
  bool closed() const { return closed_; }
  bool atEof() const { return eof_; }
  Source& source() { return src_; }
  const ReadOptions& options() const { return options_; }

  Error error(const std::string& what, ErrorCode code = ErrorCode::ParseError) const {
    return errorAt(line(), what, code);
  }
  Error errorAt(std::int64_t atLine, const std::string& what, ErrorCode code = ErrorCode::ParseError) const {
    if (tooLong_) {
      return makeError(ErrorCode::ParseError,
                       "dataset " + std::to_string(type_) + " starting at line " + std::to_string(startLine_) +
                           ": a line after line " + std::to_string(atLine) + " is longer than 64 MiB",
                       location(atLine));
    }
    if (ioFailure_) {
      return makeError(ErrorCode::IoError,
                       "dataset " + std::to_string(type_) + ": read failed after line " + std::to_string(atLine) +
                           ": " + std::strerror(errno),
                       location(atLine));
    }
    return makeError(code, "dataset " + std::to_string(type_) + " at line " + std::to_string(atLine) + ": " + what,
                     location(atLine));
  }
  // The dataset ended (delimiter or end of file) before `what`.
  Error endedBefore(const std::string& what) const {
    if (eof_ && !tooLong_ && !ioFailure_) {
      return errorAt(line(), "file truncated: end of file before " + what + " (dataset starts at line " +
                                 std::to_string(startLine_) + ")");
    }
    return errorAt(line(),
                   "dataset ends before " + what + " (dataset starts at line " + std::to_string(startLine_) + ")");
  }
  void warn(const std::string& what) { warnAt(line(), what); }
  void warnAt(std::int64_t atLine, const std::string& what) { warnings_.push_back({type_, atLine, what}); }

  std::string location(std::int64_t atLine) const {
    return std::string(where_) + ":" + std::to_string(atLine) + " (dataset " + std::to_string(type_) + ")";
  }

 private:
  Source& src_;
  int type_;
  std::int64_t startLine_;
  std::string_view where_;
  std::vector<Warning>& warnings_;
  const ReadOptions& options_;
  bool closed_ = false;
  bool eof_ = false;
  bool tooLong_ = false;
  bool ioFailure_ = false;
};

using Line = DatasetContext::Line;

std::string textField(std::string_view s);

// Exactly `count` numbers from one or more lines (values of one record may
// wrap, e.g. 6 per line). `what` names the record in errors.
Result<void> readNumbers(DatasetContext& ctx, std::size_t count, double* out, const std::string& what,
                         std::string_view* firstLine = nullptr);

// Integers of one record (blank separated) from the next non-blank line.
Result<std::vector<long long>> readIntLine(DatasetContext& ctx, std::size_t minCount, std::size_t maxCount,
                                           const std::string& what, std::string_view* lineOut = nullptr);

inline bool fitsInt(long long v) {
  return v >= std::numeric_limits<int>::min() && v <= std::numeric_limits<int>::max();
}

// The error "<record>: value V out of range" at the first value that does not
// fit an int.
template <class Values>
Result<void> checkFitsInt(const DatasetContext& ctx, const char* record, const Values& values) {
  for (long long v : values)
    if (!fitsInt(v)) return ctx.error(std::string(record) + ": value " + std::to_string(v) + " out of range");
  return {};
}

// Reads text lines of a fixed-count block of records, allowing an early end.
Line textLine(DatasetContext& ctx, std::string& out);

// The 58b header's fields (record 1 of a binary 58).
struct Binary58 {
  bool binary = false;
  ByteOrder order = ByteOrder::LittleEndian;
  int floatFormat = 2;
  long long asciiLines = 11;
  long long byteCount = 0;
};

// One parser per dataset type; each reads up to and including the closing -1.
Result<DatasetData> parse151(DatasetContext& ctx);
Result<DatasetData> parse164(DatasetContext& ctx);
Result<DatasetData> parseNodes(DatasetContext& ctx, int type);  // 15 or 2411
Result<DatasetData> parse18(DatasetContext& ctx);
Result<DatasetData> parse2420(DatasetContext& ctx);
Result<DatasetData> parse82(DatasetContext& ctx);
Result<DatasetData> parse55(DatasetContext& ctx);
Result<DatasetData> parse58(DatasetContext& ctx, const Binary58& bin);
Result<DatasetData> parseSkipped(DatasetContext& ctx);  // types Mozzi does not use

}  // namespace mozzi::core::io::uff::parsing
