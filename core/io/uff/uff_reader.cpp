// Streaming UFF reader. Record layouts follow the universal file format
// description (SDRC I-DEAS, now Siemens; the same layouts pyuff documents):
//   151  7 x (80A1)
//   164  (I10,20A1,I10) (3D25.17) (1D25.17)
//   15   (4I10,1P3E13.5) per node
//   2411 (4I10) (1P3D25.16) per node
//   18   (5I10) (20A2) (1P6E13.5) (1P3E13.5) per coordinate system
//   2420 (1I10) (40A2), then per system (3I10) (40A2) 4 x (1P3D25.16)
//   82   (3I10) (80A1) (8I10)...
//   55   5 x (80A1) (6I10) (8I10) (6E13.5) then per node (I10) (6E13.5)...
//   58   5 x (80A1) (2(I5,I10),2(1X,10A1,I10,I4)) (3I10,3E13.5)
//        4 x (I10,3I5,2(1X,20A1)) then data (6E13.5 / 4E20.12 / mixed)
//   58b  header (I6,1A1,I6,I6,I12,I12,I6,I6,I12,I12), the same 11 ASCII
//        records, then the raw values.
// Vendors bend the widths, so numbers are read blank-separated (with the
// run-together-sign rule of detail::scanNumbers); only records holding text
// fields (58 records 6 and 8-11, 164 record 1) are cut by columns.

#include <sys/stat.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "core/io/uff/uff.h"
#include "core/io/uff/uff_text.h"

namespace mozzi::core::io::uff {

std::string Warning::describe() const {
  return "dataset " + std::to_string(datasetType) + ", line " + std::to_string(line) + ": " + message;
}

const char* functionTypeName(FunctionType type) {
  switch (type) {
    case FunctionType::General: return "general";
    case FunctionType::TimeResponse: return "time response";
    case FunctionType::AutoSpectrum: return "auto spectrum";
    case FunctionType::CrossSpectrum: return "cross spectrum";
    case FunctionType::Frf: return "FRF";
    case FunctionType::Transmissibility: return "transmissibility";
    case FunctionType::Coherence: return "coherence";
    case FunctionType::AutoCorrelation: return "auto correlation";
    case FunctionType::CrossCorrelation: return "cross correlation";
    case FunctionType::Psd: return "PSD";
    case FunctionType::Esd: return "ESD";
    case FunctionType::ProbabilityDensity: return "probability density";
    case FunctionType::Spectrum: return "spectrum";
    case FunctionType::CumulativeFrequency: return "cumulative frequency distribution";
    case FunctionType::PeaksValley: return "peaks valley";
    case FunctionType::StressCycles: return "stress/cycles";
    case FunctionType::StrainCycles: return "strain/cycles";
    case FunctionType::Orbit: return "orbit";
    case FunctionType::ModeIndicator: return "mode indicator function";
    case FunctionType::ForcePattern: return "force pattern";
    case FunctionType::PartialPower: return "partial power";
    case FunctionType::PartialCoherence: return "partial coherence";
    case FunctionType::Eigenvalue: return "eigenvalue";
    case FunctionType::Eigenvector: return "eigenvector";
    case FunctionType::ShockResponseSpectrum: return "shock response spectrum";
    case FunctionType::FirFilter: return "finite impulse response filter";
    case FunctionType::MultipleCoherence: return "multiple coherence";
    case FunctionType::OrderFunction: return "order function";
    case FunctionType::PhaseCompensation: return "phase compensation";
  }
  return "unknown";
}

Vector Function58::abscissaValues() const {
  if (!evenSpacing) return abscissa;
  const Eigen::Index n = pointCount();
  Vector x(n);
  for (Eigen::Index k = 0; k < n; ++k) x[k] = abscissaMin + static_cast<double>(k) * abscissaIncrement;
  return x;
}

namespace {

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

bool hostIsLittleEndian() {
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

std::string textField(std::string_view s) {
  return std::string(trimRight(s));
}

// Exactly `count` numbers from one or more lines (values of one record may
// wrap, e.g. 6 per line). `what` names the record in errors.
Result<void> readNumbers(DatasetContext& ctx, std::size_t count, double* out, const std::string& what,
                         std::string_view* firstLine = nullptr) {
  std::size_t have = 0;
  bool first = true;
  while (have < count) {
    std::string_view line;
    if (first && firstLine) {
      line = *firstLine;
    } else {
      const Line l = ctx.next(line);
      if (l != Line::Ok) {
        return ctx.endedBefore(what + " (" + std::to_string(have) + " of " + std::to_string(count) + " values read)");
      }
    }
    first = false;
    const auto r = scanNumbers(line, [&](double v) {
      if (have >= count) return false;
      out[have++] = v;
      return true;
    });
    if (r.stopped) {
      return ctx.error(what + ": more values on the line than the " + std::to_string(count) + " expected near '" +
                       detail::excerpt(line, r.column) + "'");
    }
    if (r.status == NumberStatus::NonFinite) {
      return ctx.error(what + ": '" + detail::excerpt(line, r.column) + "' is not a finite number (column " +
                       std::to_string(r.column + 1) + ")");
    }
    if (r.status != NumberStatus::Ok) {
      return ctx.error(what + ": malformed number '" + detail::excerpt(line, r.column) + "' at column " +
                       std::to_string(r.column + 1));
    }
  }
  return {};
}

// Integers of one record (blank separated) from the next non-blank line.
Result<std::vector<long long>> readIntLine(DatasetContext& ctx, std::size_t minCount, std::size_t maxCount,
                                           const std::string& what, std::string_view* lineOut = nullptr) {
  std::string_view line;
  const Line l = ctx.nextNonBlank(line);
  if (l != Line::Ok) return ctx.endedBefore(what);
  if (lineOut) *lineOut = line;
  std::vector<long long> values;
  std::string_view rest = line;
  while (true) {
    rest = trim(rest);
    if (rest.empty()) break;
    std::size_t n = 0;
    while (n < rest.size() && !detail::isBlankChar(rest[n])) ++n;
    long long v = 0;
    if (!parseInt(rest.substr(0, n), v)) {
      return ctx.error(what + ": '" + detail::excerpt(rest.substr(0, n)) + "' is not an integer (column " +
                       std::to_string(rest.data() - line.data() + 1) + ")");
    }
    if (values.size() == maxCount) {
      return ctx.error(what + ": more than " + std::to_string(maxCount) + " integers on the line");
    }
    values.push_back(v);
    rest.remove_prefix(n);
  }
  if (values.size() < minCount) {
    return ctx.error(what + ": expected " + std::to_string(minCount) + " integers, found " +
                     std::to_string(values.size()) + " in '" + detail::excerpt(line) + "'");
  }
  return values;
}

bool fitsInt(long long v) {
  return v >= std::numeric_limits<int>::min() && v <= std::numeric_limits<int>::max();
}

// Reads text lines of a fixed-count block of records, allowing an early end.
Line textLine(DatasetContext& ctx, std::string& out) {
  std::string_view line;
  const Line l = ctx.next(line);
  if (l == Line::Ok) out = textField(line);
  return l;
}

// --- 151 -------------------------------------------------------------------
Result<DatasetData> parse151(DatasetContext& ctx) {
  Header151 h;
  std::string* records[] = {&h.modelName, &h.description, &h.dbProgram, &h.dbCreated,
                            &h.dbSaved,   &h.uffProgram,  &h.uffWritten};
  int got = 0;
  for (std::string* r : records) {
    if (textLine(ctx, *r) != Line::Ok) break;
    ++got;
  }
  if (got < 7) {
    if (ctx.atEof() && got == 0) return ctx.endedBefore("the header records");
    ctx.warn("header has " + std::to_string(got) + " of its 7 records; the rest are left empty");
  }
  return DatasetData{std::move(h)};
}

// --- 164 -------------------------------------------------------------------
Result<DatasetData> parse164(DatasetContext& ctx) {
  Units164 u;
  std::string_view line;
  if (ctx.nextNonBlank(line) != Line::Ok) return ctx.endedBefore("record 1 (units code)");
  long long code = 0;
  long long mode = 0;
  // (I10,20A1,I10)
  if (!parseInt(field(line, 0, 10), code)) {
    return ctx.error("record 1: units code '" + detail::excerpt(field(line, 0, 10)) + "' is not an integer");
  }
  u.unitsCode = static_cast<int>(std::clamp<long long>(code, -1000000, 1000000));
  u.description = std::string(trim(field(line, 10, 20)));
  if (parseInt(field(line, 30, 10), mode)) {
    u.temperatureMode = static_cast<int>(std::clamp<long long>(mode, -1000000, 1000000));
  } else {
    ctx.warn("record 1: temperature mode column missing; relative (2) assumed");
  }
  double factors[3] = {1.0, 1.0, 1.0};
  if (auto r = readNumbers(ctx, 3, factors, "record 2 (unit factors)"); !r) return r.error();
  u.lengthFactor = factors[0];
  u.forceFactor = factors[1];
  u.temperatureFactor = factors[2];
  for (double f : factors) {
    if (f == 0.0) return ctx.error("record 2: a unit factor is zero (SI = value / factor would divide by zero)");
  }
  double offset = 273.15;
  const auto off = readNumbers(ctx, 1, &offset, "record 3 (temperature offset)");
  if (!off) {
    if (!ctx.closed()) return off.error();
    ctx.warn("record 3 (temperature offset) missing; 273.15 assumed");
  }
  u.temperatureOffset = offset;
  return DatasetData{std::move(u)};
}

// --- 15 / 2411 ------------------------------------------------------------
Result<DatasetData> parseNodes(DatasetContext& ctx, int type) {
  NodeSet set;
  set.datasetType = type;
  for (;;) {
    std::string_view line;
    const Line l = ctx.nextNonBlank(line);
    if (l == Line::Delimiter) break;
    if (l == Line::Eof) return ctx.endedBefore("the closing -1 of the node list");
    Node n;
    if (type == 15) {
      // (4I10,1P3E13.5) on one line
      double v[7];
      std::size_t have = 0;
      const auto r = scanNumbers(line, [&](double x) {
        if (have >= 7) return false;
        v[have++] = x;
        return true;
      });
      if (r.status != NumberStatus::Ok || r.stopped || have != 7) {
        return ctx.error("node record: expected 4 integers and 3 coordinates, found '" + detail::excerpt(line) + "'");
      }
      for (int i = 0; i < 4; ++i) {
        if (v[i] != std::floor(v[i]) || std::abs(v[i]) > 2147483647.0) {
          return ctx.error("node record: '" + detail::excerpt(line) + "' has a non-integer label or system");
        }
      }
      n.label = static_cast<int>(v[0]);
      n.definitionCs = static_cast<int>(v[1]);
      n.displacementCs = static_cast<int>(v[2]);
      n.color = static_cast<int>(v[3]);
      n.xyz = Vector3(v[4], v[5], v[6]);
    } else {
      // (4I10) then (1P3D25.16)
      std::vector<long long> ints;
      std::string_view rest = trim(line);
      while (!rest.empty()) {
        std::size_t k = 0;
        while (k < rest.size() && !detail::isBlankChar(rest[k])) ++k;
        long long x = 0;
        if (!parseInt(rest.substr(0, k), x) || !fitsInt(x) || ints.size() == 4) {
          return ctx.error("record 1 of a node: expected 4 integers, found '" + detail::excerpt(line) + "'");
        }
        ints.push_back(x);
        rest = trim(rest.substr(k));
      }
      if (ints.size() < 4) {
        if (ints.size() < 1) return ctx.error("record 1 of a node: no node label");
        ctx.warn("record 1 of node " + std::to_string(ints[0]) + ": " + std::to_string(ints.size()) +
                 " of 4 columns; the missing ones are 0");
        ints.resize(4, 0);
      }
      n.label = static_cast<int>(ints[0]);
      n.definitionCs = static_cast<int>(ints[1]);
      n.displacementCs = static_cast<int>(ints[2]);
      n.color = static_cast<int>(ints[3]);
      double xyz[3];
      if (auto r = readNumbers(ctx, 3, xyz, "record 2 (coordinates) of node " + std::to_string(n.label)); !r) {
        return r.error();
      }
      n.xyz = Vector3(xyz[0], xyz[1], xyz[2]);
    }
    set.nodes.push_back(n);
  }
  return DatasetData{std::move(set)};
}

// --- 18 / 2420 --------------------------------------------------------------
// Unit axes from origin, a point on +x and a point in the +xz plane:
// x = (P_x - O)/|P_x - O|, y = ((P_xz - O) x x)/|...|, z = x x y.
bool axesFromPoints(CoordinateSystem& cs) {
  const Vector3 ex = cs.xPoint - cs.origin;
  const Vector3 exz = cs.xzPoint - cs.origin;
  const Vector3 ey = exz.cross(ex);
  if (ex.norm() == 0.0 || ey.norm() <= 1e-12 * ex.norm() * exz.norm()) return false;
  const Vector3 x = ex.normalized();
  const Vector3 y = ey.normalized();
  cs.axes.row(0) = x.transpose();
  cs.axes.row(1) = y.transpose();
  cs.axes.row(2) = x.cross(y).transpose();
  return true;
}

Result<DatasetData> parse18(DatasetContext& ctx) {
  CoordinateSystemSet set;
  set.datasetType = 18;
  for (;;) {
    std::string_view line;
    const Line l = ctx.nextNonBlank(line);
    if (l == Line::Delimiter) break;
    if (l == Line::Eof) return ctx.endedBefore("the closing -1 of the coordinate systems");
    CoordinateSystem cs;
    const auto head = [&]() -> Result<std::vector<long long>> {
      std::vector<long long> v;
      const auto r = scanNumbers(line, [&](double x) {
        if (v.size() >= 5 || x != std::floor(x) || std::abs(x) > 2147483647.0) return false;
        v.push_back(static_cast<long long>(x));
        return true;
      });
      if (r.status != NumberStatus::Ok || r.stopped || v.empty()) {
        return ctx.error("record 1: expected 5 integers (label, type, reference, color, method), found '" +
                         detail::excerpt(line) + "'");
      }
      return v;
    }();
    if (!head) return head.error();
    std::vector<long long> h = *head;
    if (h.size() < 5) {
      ctx.warn("record 1 of coordinate system " + std::to_string(h[0]) + ": " + std::to_string(h.size()) +
               " of 5 columns; the missing ones are 0");
      h.resize(5, 0);
    }
    cs.label = static_cast<int>(h[0]);
    cs.type = static_cast<int>(h[1]);
    cs.referenceCs = static_cast<int>(h[2]);
    cs.color = static_cast<int>(h[3]);
    cs.definitionMethod = static_cast<int>(h[4]);
    std::string_view name;
    if (ctx.next(name) != Line::Ok)
      return ctx.endedBefore("record 2 (name) of coordinate system " + std::to_string(cs.label));
    cs.name = textField(name);
    double p[9];
    if (auto r = readNumbers(ctx, 9, p, "records 3-4 (points) of coordinate system " + std::to_string(cs.label)); !r) {
      return r.error();
    }
    cs.origin = Vector3(p[0], p[1], p[2]);
    cs.xPoint = Vector3(p[3], p[4], p[5]);
    cs.xzPoint = Vector3(p[6], p[7], p[8]);
    if (!axesFromPoints(cs)) {
      ctx.warn("coordinate system " + std::to_string(cs.label) +
               ": origin, +x point and +xz point are collinear; axes left as identity");
      cs.axes = Matrix3::Identity();
    }
    set.systems.push_back(std::move(cs));
  }
  return DatasetData{std::move(set)};
}

Result<DatasetData> parse2420(DatasetContext& ctx) {
  CoordinateSystemSet set;
  set.datasetType = 2420;
  auto uid = readIntLine(ctx, 1, 1, "record 1 (part UID)");
  if (!uid) return uid.error();
  set.partUid = static_cast<int>(std::clamp<long long>((*uid)[0], -2147483647, 2147483647));
  std::string_view partName;
  if (ctx.next(partName) != Line::Ok) return ctx.endedBefore("record 2 (part name)");
  set.partName = textField(partName);
  for (;;) {
    std::string_view line;
    const Line l = ctx.nextNonBlank(line);
    if (l == Line::Delimiter) break;
    if (l == Line::Eof) return ctx.endedBefore("the closing -1 of the coordinate systems");
    std::vector<long long> h;
    const auto r = scanNumbers(line, [&](double x) {
      if (h.size() >= 3 || x != std::floor(x) || std::abs(x) > 2147483647.0) return false;
      h.push_back(static_cast<long long>(x));
      return true;
    });
    if (r.status != NumberStatus::Ok || r.stopped || h.size() != 3) {
      return ctx.error("record 3: expected 3 integers (label, type, color), found '" + detail::excerpt(line) + "'");
    }
    CoordinateSystem cs;
    cs.label = static_cast<int>(h[0]);
    cs.type = static_cast<int>(h[1]);
    cs.color = static_cast<int>(h[2]);
    std::string_view name;
    if (ctx.next(name) != Line::Ok)
      return ctx.endedBefore("record 4 (name) of coordinate system " + std::to_string(cs.label));
    cs.name = textField(name);
    double m[12];
    if (auto rr =
            readNumbers(ctx, 12, m, "records 5-8 (transformation) of coordinate system " + std::to_string(cs.label));
        !rr) {
      return rr.error();
    }
    for (int i = 0; i < 3; ++i) cs.axes.row(i) = Eigen::RowVector3d(m[3 * i], m[3 * i + 1], m[3 * i + 2]);
    cs.origin = Vector3(m[9], m[10], m[11]);
    cs.xPoint = cs.origin + cs.axes.row(0).transpose();
    cs.xzPoint = cs.origin + cs.axes.row(2).transpose();
    set.systems.push_back(std::move(cs));
  }
  return DatasetData{std::move(set)};
}

// --- 82 ----------------------------------------------------------------------
Result<DatasetData> parse82(DatasetContext& ctx) {
  TraceLine82 t;
  auto head = readIntLine(ctx, 2, 3, "record 1 (trace number, node count, color)");
  if (!head) return head.error();
  const std::vector<long long>& h = *head;
  if (h.size() < 3) ctx.warn("record 1: color column missing; 0 assumed");
  if (!fitsInt(h[0])) return ctx.error("record 1: trace number out of range");
  t.traceNumber = static_cast<int>(h[0]);
  t.color = h.size() > 2 && fitsInt(h[2]) ? static_cast<int>(h[2]) : 0;
  // The format caps a trace line at 250 nodes; more than a million is not a
  // trace line but a corrupt count.
  if (h[1] < 0 || h[1] > 1000000) {
    return ctx.error("record 1: node count " + std::to_string(h[1]) + " is not between 0 and 1000000");
  }
  const std::size_t count = static_cast<std::size_t>(h[1]);
  std::string desc;
  if (textLine(ctx, desc) != Line::Ok) return ctx.endedBefore("record 2 (description)");
  t.description = desc;
  t.nodes.reserve(count);
  std::size_t padding = 0;
  std::size_t extra = 0;
  for (;;) {
    std::string_view line;
    const Line l = ctx.next(line);
    if (l == Line::Delimiter) break;
    if (l == Line::Eof) {
      if (t.nodes.size() < count) return ctx.endedBefore("all " + std::to_string(count) + " trace nodes");
      ctx.warn("file ends without the closing -1");
      break;
    }
    std::string_view rest = trim(line);
    while (!rest.empty()) {
      std::size_t k = 0;
      while (k < rest.size() && !detail::isBlankChar(rest[k])) ++k;
      long long v = 0;
      if (!parseInt(rest.substr(0, k), v) || !fitsInt(v)) {
        return ctx.error("record 3: '" + detail::excerpt(rest.substr(0, k)) + "' is not a node number");
      }
      if (t.nodes.size() < count) {
        t.nodes.push_back(static_cast<int>(v));
      } else if (v == 0) {
        ++padding;  // TestLab pads the node list with zeros to a multiple of 8
      } else {
        ++extra;
      }
      rest = trim(rest.substr(k));
    }
  }
  if (extra > 0)
    ctx.warn(std::to_string(extra) + " node numbers after the " + std::to_string(count) + " declared were ignored");
  if (t.nodes.size() < count) {
    ctx.warn("record 1 declares " + std::to_string(count) + " nodes, the list holds " + std::to_string(t.nodes.size()));
  }
  return DatasetData{std::move(t)};
}

// --- 55 ----------------------------------------------------------------------
Result<DatasetData> parse55(DatasetContext& ctx) {
  ModalData55 m;
  for (auto& id : m.idLines) {
    if (textLine(ctx, id) != Line::Ok) return ctx.endedBefore("the five ID lines (records 1-5)");
  }
  auto r6 = readIntLine(ctx, 6, 6,
                        "record 6 (model type, analysis type, data characteristic, specific type, "
                        "data type, values per node)");
  if (!r6) return r6.error();
  const std::vector<long long>& h = *r6;
  for (long long v : h)
    if (!fitsInt(v)) return ctx.error("record 6: value " + std::to_string(v) + " out of range");
  m.modelType = static_cast<int>(h[0]);
  m.analysisType = static_cast<AnalysisType>(h[1]);
  m.dataCharacteristic = static_cast<int>(h[2]);
  m.specificDataType = static_cast<int>(h[3]);
  if (h[4] == 2 || h[4] == 4) {
    m.complexData = false;
  } else if (h[4] == 5 || h[4] == 6) {
    m.complexData = true;
  } else {
    return ctx.error("record 6: data type " + std::to_string(h[4]) + " is neither real (2) nor complex (5)");
  }
  // NDV: 1 scalar, 3 or 6 vector, 6 or 9 tensor. More than 1000 values per node is corrupt.
  if (h[5] < 1 || h[5] > 1000) {
    return ctx.error("record 6: values per node " + std::to_string(h[5]) + " is not between 1 and 1000");
  }
  m.valuesPerNode = static_cast<int>(h[5]);

  // Record 7: NINT, NRVAL, then NINT integers (8 per line, may wrap).
  std::string_view r7line;
  auto r7 = readIntLine(ctx, 2, 8, "record 7 (integer count, real count, ...)", &r7line);
  if (!r7) return r7.error();
  const long long nint = (*r7)[0];
  const long long nrval = (*r7)[1];
  if (nint < 0 || nint > 1000 || nrval < 0 || nrval > 1000) {
    return ctx.error("record 7: counts " + std::to_string(nint) + ", " + std::to_string(nrval) +
                     " are not between 0 and 1000");
  }
  std::vector<long long> ints(r7->begin() + 2, r7->end());
  while (static_cast<long long>(ints.size()) < nint) {
    auto more = readIntLine(ctx, 1, 8, "record 7 (continued)");
    if (!more) return more.error();
    ints.insert(ints.end(), more->begin(), more->end());
  }
  if (static_cast<long long>(ints.size()) > nint) {
    return ctx.error("record 7: " + std::to_string(ints.size()) + " integers where " + std::to_string(nint) +
                     " were declared");
  }
  for (long long v : ints) {
    if (!fitsInt(v)) return ctx.error("record 7: value " + std::to_string(v) + " out of range");
    m.integerValues.push_back(static_cast<int>(v));
  }
  m.realValues.resize(static_cast<std::size_t>(nrval));
  if (nrval > 0) {
    if (auto r = readNumbers(ctx, static_cast<std::size_t>(nrval), m.realValues.data(), "record 8 (real values)"); !r) {
      return r.error();
    }
  }
  const std::size_t perNode = static_cast<std::size_t>(m.valuesPerNode) * (m.complexData ? 2 : 1);
  std::vector<double> values(perNode);
  for (;;) {
    std::string_view line;
    const Line l = ctx.nextNonBlank(line);
    if (l == Line::Delimiter) break;
    if (l == Line::Eof) return ctx.endedBefore("the closing -1 after the node data");
    long long node = 0;
    if (!parseInt(line, node) || !fitsInt(node)) {
      return ctx.error("record 9: expected a node number alone on the line, found '" + detail::excerpt(line) + "'");
    }
    if (auto r = readNumbers(ctx, perNode, values.data(), "record 10 (data) of node " + std::to_string(node)); !r) {
      return r.error();
    }
    NodeValues55 nv;
    nv.node = static_cast<int>(node);
    nv.values.resize(m.valuesPerNode);
    for (int i = 0; i < m.valuesPerNode; ++i) {
      nv.values[i] = m.complexData ? Complex(values[2 * i], values[2 * i + 1]) : Complex(values[i], 0.0);
    }
    m.nodes.push_back(std::move(nv));
  }
  return DatasetData{std::move(m)};
}

// --- 58 / 58b ------------------------------------------------------------------
struct Binary58 {
  bool binary = false;
  ByteOrder order = ByteOrder::LittleEndian;
  int floatFormat = 2;
  long long asciiLines = 11;
  long long byteCount = 0;
};

// Record 6: (2(I5,I10),2(1X,10A1,I10,I4)).
Result<void> parseRecord6(DatasetContext& ctx, std::string_view line, Function58& f) {
  long long v[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  struct Col {
    std::size_t start, width;
  };
  static constexpr Col kCols[8] = {{0, 5}, {5, 10}, {15, 5}, {20, 10}, {41, 10}, {51, 4}, {66, 10}, {76, 4}};
  bool fixedOk = true;
  int missing = 0;
  for (int i = 0; i < 8; ++i) {
    const std::string_view s = field(line, kCols[i].start, kCols[i].width);
    if (isBlank(s)) {
      ++missing;
      v[i] = 0;
    } else if (!parseInt(s, v[i])) {
      fixedOk = false;
      break;
    }
  }
  if (fixedOk && missing > 0 && isBlank(field(line, 0, 5))) fixedOk = false;
  if (fixedOk) {
    f.response.entityName = std::string(trim(field(line, 31, 10)));
    f.reference.entityName = std::string(trim(field(line, 56, 10)));
    if (missing > 0) {
      ctx.warn("record 6: " + std::to_string(missing) + " numeric columns missing (short line); read as 0");
    }
  } else {
    // Columns shifted: blank-separated tokens, names being whatever lies
    // between the 4 leading integers and the node/direction pairs.
    std::vector<std::string_view> tok;
    std::string_view rest = trim(line);
    while (!rest.empty()) {
      std::size_t k = 0;
      while (k < rest.size() && !detail::isBlankChar(rest[k])) ++k;
      tok.push_back(rest.substr(0, k));
      rest = trim(rest.substr(k));
    }
    long long x = 0;
    bool ok = tok.size() >= 8;
    for (std::size_t i = 0; ok && i < 4; ++i) ok = parseInt(tok[i], v[i]);
    std::size_t pair = 0;
    if (ok) {
      ok = parseInt(tok[tok.size() - 2], v[6]) && parseInt(tok[tok.size() - 1], v[7]);
      for (pair = 4; ok && pair + 3 < tok.size(); ++pair) {
        if (parseInt(tok[pair], x) && parseInt(tok[pair + 1], x)) break;
      }
      ok = ok && pair + 3 < tok.size() && parseInt(tok[pair], v[4]) && parseInt(tok[pair + 1], v[5]);
    }
    if (!ok) {
      return ctx.error(
          "record 6: expected function type, ID, version, load case, response name/node/direction, "
          "reference name/node/direction in columns (2(I5,I10),2(1X,10A1,I10,I4)), found '" +
          detail::excerpt(line) + "'");
    }
    auto join = [&](std::size_t a, std::size_t b) {
      std::string s;
      for (std::size_t i = a; i < b; ++i) s += (s.empty() ? "" : " ") + std::string(tok[i]);
      return s;
    };
    f.response.entityName = join(4, pair);
    f.reference.entityName = join(pair + 2, tok.size() - 2);
    ctx.warn("record 6: fields not in their columns; read blank-separated");
  }
  for (long long x : v)
    if (!fitsInt(x)) return ctx.error("record 6: value " + std::to_string(x) + " out of range");
  f.functionType = static_cast<FunctionType>(v[0]);
  f.functionId = static_cast<int>(v[1]);
  f.versionNumber = static_cast<int>(v[2]);
  f.loadCase = static_cast<int>(v[3]);
  f.response.node = static_cast<int>(v[4]);
  f.response.direction = static_cast<int>(v[5]);
  f.reference.node = static_cast<int>(v[6]);
  f.reference.direction = static_cast<int>(v[7]);
  if (std::abs(v[5]) > 6 || std::abs(v[7]) > 6) {
    ctx.warn("record 6: direction code outside -6..6 (response " + std::to_string(v[5]) + ", reference " +
             std::to_string(v[7]) + ")");
  }
  return {};
}

// Records 8-11: (I10,3I5,2(1X,20A1)).
Result<void> parseAxis(DatasetContext& ctx, AxisInfo& a, int record) {
  std::string_view line;
  if (ctx.next(line) != Line::Ok) return ctx.endedBefore("record " + std::to_string(record) + " (axis data)");
  long long v[4] = {0, 0, 0, 0};
  static constexpr std::size_t kStart[4] = {0, 10, 15, 20};
  static constexpr std::size_t kWidth[4] = {10, 5, 5, 5};
  int missing = 0;
  bool fixedOk = true;
  for (int i = 0; i < 4; ++i) {
    const std::string_view s = field(line, kStart[i], kWidth[i]);
    if (isBlank(s)) {
      ++missing;
    } else if (!parseInt(s, v[i]) || !fitsInt(v[i])) {
      fixedOk = false;
    }
  }
  if (!fixedOk) {
    return ctx.error("record " + std::to_string(record) +
                     ": expected data type and three unit exponents in columns (I10,3I5), found '" +
                     detail::excerpt(line) + "'");
  }
  if (missing > 0 || line.size() < 27) {
    ctx.warn("record " + std::to_string(record) + ": short line, missing columns read as 0 / NONE");
  }
  a.specificDataType = static_cast<int>(v[0]);
  a.lengthExponent = static_cast<int>(v[1]);
  a.forceExponent = static_cast<int>(v[2]);
  a.temperatureExponent = static_cast<int>(v[3]);
  a.label = std::string(trim(field(line, 26, 20)));
  a.unitsLabel = std::string(trim(field(line, 47, 32)));
  if (a.label.empty()) a.label = "NONE";
  if (a.unitsLabel.empty()) a.unitsLabel = "NONE";
  return {};
}

// Little helpers for 58b.
template <class T>
T loadValue(const unsigned char* p, bool swap) {
  unsigned char b[sizeof(T)];
  if (swap) {
    for (std::size_t i = 0; i < sizeof(T); ++i) b[i] = p[sizeof(T) - 1 - i];
  } else {
    std::memcpy(b, p, sizeof(T));
  }
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}

Result<DatasetData> parse58(DatasetContext& ctx, const Binary58& bin) {
  Function58 f;
  f.binary = bin.binary;
  f.byteOrder = bin.order;
  for (auto& id : f.idLines) {
    if (textLine(ctx, id) != Line::Ok) return ctx.endedBefore("the five ID lines (records 1-5)");
  }
  std::string_view line;
  if (ctx.nextNonBlank(line) != Line::Ok) return ctx.endedBefore("record 6 (function and DOF identification)");
  if (auto r = parseRecord6(ctx, line, f); !r) return r.error();

  // Record 7: (3I10,3E13.5): ordinate type, points, spacing, min, increment, z.
  if (ctx.nextNonBlank(line) != Line::Ok) return ctx.endedBefore("record 7 (data form)");
  const std::int64_t record7Line = ctx.line();
  double r7[6] = {0, 0, 0, 0, 0, 0};
  std::size_t have = 0;
  const auto s7 = scanNumbers(line, [&](double x) {
    if (have >= 6) return false;
    r7[have++] = x;
    return true;
  });
  if (s7.status != NumberStatus::Ok || s7.stopped || have < 5) {
    return ctx.error(
        "record 7: expected ordinate type, point count, spacing, abscissa minimum, increment and "
        "z value, found '" +
        detail::excerpt(line) + "'");
  }
  if (have == 5) ctx.warn("record 7: z-axis value missing; 0 assumed");
  for (int i = 0; i < 3; ++i) {
    if (r7[i] != std::floor(r7[i]))
      return ctx.error("record 7: column " + std::to_string(i + 1) + " is not an integer");
  }
  const int ordType = static_cast<int>(std::clamp(r7[0], -1e6, 1e6));
  if (ordType != 2 && ordType != 4 && ordType != 5 && ordType != 6) {
    return ctx.error("record 7: ordinate data type " + std::to_string(ordType) +
                         " is not 2 (real single), 4 (real double), 5 (complex single) or 6 (complex double)",
                     ErrorCode::Unsupported);
  }
  f.ordinateType = static_cast<OrdinateType>(ordType);
  if (r7[1] < 0) return ctx.error("record 7: negative point count");
  if (r7[2] != 0 && r7[2] != 1) return ctx.error("record 7: abscissa spacing must be 0 (uneven) or 1 (even)");
  f.evenSpacing = r7[2] == 1;
  f.abscissaMin = r7[3];
  f.abscissaIncrement = r7[4];
  f.zAxisValue = r7[5];

  if (auto r = parseAxis(ctx, f.abscissaAxis, 8); !r) return r.error();
  if (auto r = parseAxis(ctx, f.ordinateNumerator, 9); !r) return r.error();
  if (auto r = parseAxis(ctx, f.ordinateDenominator, 10); !r) return r.error();
  if (auto r = parseAxis(ctx, f.zAxis, 11); !r) return r.error();

  const bool cplx = isComplex(f.ordinateType);
  const std::size_t valueBytes = isDouble(f.ordinateType) ? 8 : 4;
  const std::size_t perPoint = (cplx ? 2 : 1) + (f.evenSpacing ? 0 : 1);
  const double declaredD = r7[1];
  // Memory the declared points would take as doubles (abscissa included).
  const double memory = declaredD * static_cast<double>(perPoint) * 8.0;
  if (memory > static_cast<double>(ctx.options().maxDatasetBytes)) {
    return ctx.errorAt(record7Line,
                       "record 7 declares " + std::to_string(static_cast<long long>(std::min(declaredD, 9e18))) +
                           " points (" + std::to_string(memory / 1e9) + " GB in memory), more than the limit of " +
                           std::to_string(static_cast<double>(ctx.options().maxDatasetBytes) / 1e9) + " GB",
                       ErrorCode::Corrupt);
  }
  const std::uint64_t declared = static_cast<std::uint64_t>(declaredD);
  Source& src = ctx.source();
  if (ctx.options().skip58Data) {
    // Headers only: skip the data (binary block or ASCII lines) unread.
    f.declaredPoints = static_cast<std::int64_t>(declared);
    if (bin.binary) {
      std::uint64_t skip = static_cast<std::uint64_t>(bin.byteCount);
      if (skip > src.remaining()) {
        return ctx.error("file truncated: the 58b header declares " + std::to_string(skip) +
                         " bytes of binary data, only " + std::to_string(src.remaining()) + " remain");
      }
      std::vector<char> sink(static_cast<std::size_t>(std::min<std::uint64_t>(skip, 1 << 16)));
      while (skip > 0) {
        const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(skip, sink.size()));
        if (src.readRaw(sink.data(), n) != n) return ctx.error("file truncated inside the binary data");
        skip -= n;
      }
    } else {
      while (ctx.next(line) == DatasetContext::Line::Ok) {
      }
    }
    return DatasetData{std::move(f)};
  }

  // Storage: the ordinates as doubles, interleaved (re, im) for complex.
  auto allocate = [&](std::uint64_t points) {
    if (cplx) {
      f.complex.resize(static_cast<Eigen::Index>(points));
    } else {
      f.real.resize(static_cast<Eigen::Index>(points));
    }
    if (!f.evenSpacing) f.abscissa.resize(static_cast<Eigen::Index>(points));
  };
  // Ordinates go to the caller's sink when it gives room (ReadOptions::ordinateSink).
  double* external = nullptr;
  auto place = [&](std::uint64_t points) {
    if (ctx.options().ordinateSink) external = ctx.options().ordinateSink(f, points);
    if (external) {
      if (!f.evenSpacing) f.abscissa.resize(static_cast<Eigen::Index>(points));
    } else {
      allocate(points);
    }
  };
  auto ordinates = [&]() -> double* {
    if (external) return external;
    return cplx ? reinterpret_cast<double*>(f.complex.data()) : f.real.data();
  };
  auto shrink = [&](std::uint64_t points) {
    const Eigen::Index n = static_cast<Eigen::Index>(points);
    if (external) {
      f.sinkPoints = points;
      if (!f.evenSpacing) f.abscissa.conservativeResize(n);
      return;
    }
    if (cplx) {
      f.complex.conservativeResize(n);
    } else {
      f.real.conservativeResize(n);
    }
    if (!f.evenSpacing) f.abscissa.conservativeResize(n);
  };

  if (bin.binary) {
    const std::uint64_t needed = declared * perPoint * valueBytes;
    const std::uint64_t byteCount = static_cast<std::uint64_t>(bin.byteCount);
    if (byteCount > src.remaining()) {
      return ctx.error("file truncated: the 58b header declares " + std::to_string(byteCount) +
                       " bytes of binary data, only " + std::to_string(src.remaining()) + " remain");
    }
    std::uint64_t points = declared;
    if (byteCount < needed) {
      points = byteCount / (perPoint * valueBytes);
      ctx.warnAt(record7Line, "record 7 declares " + std::to_string(declared) + " points, the binary block holds " +
                                  std::to_string(points));
    } else if (byteCount > needed) {
      ctx.warnAt(record7Line, "the binary block has " + std::to_string(byteCount - needed) +
                                  " bytes after the declared points; ignored");
    }
    place(points);
    const bool swap = (bin.order == ByteOrder::LittleEndian) != hostIsLittleEndian();
    const std::uint64_t totalValues = points * perPoint;
    double* ord = ordinates();
    double* xs = f.evenSpacing ? nullptr : f.abscissa.data();
    const std::size_t ordPerPoint = cplx ? 2 : 1;
    if (!swap && valueBytes == 8 && f.evenSpacing) {
      // Fast path: the file's doubles are the vector's memory layout.
      const std::size_t bytes = static_cast<std::size_t>(totalValues * 8);
      if (src.readRaw(reinterpret_cast<char*>(ord), bytes) != bytes) {
        return ctx.error("file truncated inside the binary data");
      }
    } else {
      constexpr std::size_t kChunkValues = 1 << 16;
      std::vector<unsigned char> chunk(kChunkValues * valueBytes);
      std::uint64_t done = 0;
      while (done < totalValues) {
        const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(kChunkValues, totalValues - done));
        if (src.readRaw(reinterpret_cast<char*>(chunk.data()), n * valueBytes) != n * valueBytes) {
          return ctx.error("file truncated inside the binary data");
        }
        for (std::size_t i = 0; i < n; ++i) {
          const unsigned char* p = chunk.data() + i * valueBytes;
          const double v =
              valueBytes == 8 ? loadValue<double>(p, swap) : static_cast<double>(loadValue<float>(p, swap));
          const std::uint64_t k = done + i;
          if (xs) {
            const std::uint64_t point = k / perPoint;
            const std::uint64_t comp = k % perPoint;
            if (comp == 0) {
              xs[point] = v;
            } else {
              ord[point * ordPerPoint + comp - 1] = v;
            }
          } else {
            ord[k] = v;
          }
        }
        done += n;
      }
    }
    // Skip any bytes after the declared points.
    std::uint64_t skip = byteCount > points * perPoint * valueBytes ? byteCount - points * perPoint * valueBytes : 0;
    std::vector<char> sink(std::min<std::uint64_t>(skip, 1 << 16));
    while (skip > 0) {
      const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(skip, sink.size()));
      if (src.readRaw(sink.data(), n) != n) return ctx.error("file truncated inside the binary data");
      skip -= n;
    }
    // Non-finite values in the block (NaN, inf) make the record unusable.
    // x * 0 is 0 for a finite x and NaN otherwise, so the (vectorised) sum of
    // the products is NaN exactly when a value is not finite: one fast pass,
    // the scalar search for the value only then (the scalar check alone was
    // 3% of `mozzi-cli frf`, issue 19).
    const Eigen::Index total = static_cast<Eigen::Index>(points * ordPerPoint);
    const bool allFinite = std::isfinite((Eigen::Map<const Vector>(ord, total).array() * 0.0).sum());
    for (Eigen::Index i = 0; !allFinite && i < total; ++i) {
      if (!std::isfinite(ord[i])) {
        return ctx.error("binary data value " + std::to_string(i / static_cast<Eigen::Index>(ordPerPoint)) +
                         " of the ordinate is not a finite number");
      }
    }
    if (xs) {
      for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(points); ++i) {
        if (!std::isfinite(xs[i])) return ctx.error("binary abscissa value " + std::to_string(i) + " is not finite");
      }
    }
    if (external) f.sinkPoints = points;
    return DatasetData{std::move(f)};
  }

  // ASCII data: blank-separated values in any line layout. Capacity is
  // bounded by what the remaining bytes can hold (each value needs at least
  // 2 bytes), so a header claiming 10^12 points does not allocate.
  const std::uint64_t totalDeclared = declared * perPoint;
  const std::uint64_t possible = src.remaining() / 2 + 1;
  const std::uint64_t capacityValues = std::min(totalDeclared, possible);
  place(capacityValues / perPoint);
  double* ord = ordinates();
  double* xs = f.evenSpacing ? nullptr : f.abscissa.data();
  const std::uint64_t capacity = (capacityValues / perPoint) * perPoint;
  std::uint64_t k = 0;
  const std::size_t ordPerPoint = cplx ? 2 : 1;
  bool tooMany = false;
  for (;;) {
    const Line l = ctx.next(line);
    if (l != Line::Ok) break;
    detail::ScanResult r;
    if (xs) {
      r = scanNumbers(line, [&](double v) {
        if (k >= capacity) return false;
        const std::uint64_t point = k / perPoint;
        const std::uint64_t comp = k % perPoint;
        if (comp == 0) {
          xs[point] = v;
        } else {
          ord[point * ordPerPoint + comp - 1] = v;
        }
        ++k;
        return true;
      });
    } else {
      r = scanNumbers(line, [&](double v) {
        if (k >= capacity) return false;
        ord[k++] = v;
        return true;
      });
    }
    if (r.stopped) {
      tooMany = true;
      break;
    }
    if (r.status == NumberStatus::NonFinite) {
      return ctx.error("data value '" + detail::excerpt(line, r.column) + "' is not a finite number (column " +
                       std::to_string(r.column + 1) + ")");
    }
    if (r.status != NumberStatus::Ok) {
      // A number cut off by the end of the file is truncation, not a typo.
      if (src.exhausted() && line.data() + line.size() == src.lastByteEnd()) {
        return ctx.error("file truncated: end of file inside data value '" + detail::excerpt(line, r.column) + "' (" +
                         std::to_string(k / perPoint) + " of " + std::to_string(declared) + " declared points read)");
      }
      return ctx.error("malformed data value '" + detail::excerpt(line, r.column) + "' at column " +
                       std::to_string(r.column + 1));
    }
  }
  if (tooMany) {
    return ctx.error("more data values than the " + std::to_string(declared) + " points record 7 (line " +
                     std::to_string(record7Line) + ") declares");
  }
  if (k % perPoint != 0) {
    if (ctx.atEof()) return ctx.endedBefore("the end of the data values");
    return ctx.error("the data end in the middle of a point (" + std::to_string(k) + " values, " +
                     std::to_string(perPoint) + " per point)");
  }
  const std::uint64_t points = k / perPoint;
  if (points < declared) {
    if (ctx.atEof()) {
      return ctx.endedBefore("all " + std::to_string(declared) + " declared points (" + std::to_string(points) +
                             " read)");
    }
    ctx.warnAt(record7Line, "record 7 declares " + std::to_string(declared) + " points, the data hold " +
                                std::to_string(points) + "; the record is read with " + std::to_string(points));
    shrink(points);
  } else if (external) {
    f.sinkPoints = points;
  }
  return DatasetData{std::move(f)};
}

Result<DatasetData> parseSkipped(DatasetContext& ctx) {
  SkippedDataset s;
  const std::int64_t start = ctx.line();
  std::string_view line;
  for (;;) {
    const Line l = ctx.next(line);
    if (l == Line::Delimiter) break;
    if (l == Line::Eof) return ctx.endedBefore("the closing -1");
  }
  s.lineCount = ctx.line() - start - 1;
  ctx.warnAt(start, "dataset type " + std::to_string(ctx.type()) + " is not used by Mozzi; skipped (" +
                        std::to_string(s.lineCount) + " lines)");
  return DatasetData{s};
}

}  // namespace

// ---------------------------------------------------------------------------
struct DatasetReader::Impl {
  Impl(std::unique_ptr<Source> s, std::string w, ReadOptions o) : src(std::move(s)), where(std::move(w)), options(o) {}

  std::unique_ptr<Source> src;
  std::string where;
  ReadOptions options;
  std::vector<Warning> warnings;
  bool done = false;
  bool crlfWarned = false;
  bool loneCrWarned = false;
  int lastType = 0;
  std::int64_t lastEnd = 0;

  Error fail(const std::string& message, std::int64_t line) {
    done = true;
    return makeError(ErrorCode::ParseError, message, where + ":" + std::to_string(line));
  }

  Result<std::optional<Dataset>> next() {
    if (done) return std::optional<Dataset>{};
    std::string_view line;
    // Opening delimiter.
    for (;;) {
      const Source::Status s = src->nextLine(line);
      if (s == Source::Status::End) {
        done = true;
        return std::optional<Dataset>{};
      }
      if (s != Source::Status::Ok) return fail("read failed or a line longer than 64 MiB", src->lineNumber());
      if (isBlank(line)) continue;
      if (isDelimiter(line)) break;
      std::string context =
          lastType ? " after dataset " + std::to_string(lastType) + " (ended at line " + std::to_string(lastEnd) + ")"
                   : " (a universal file starts with '    -1')";
      return fail("line " + std::to_string(src->lineNumber()) + ": expected the dataset delimiter '    -1'" + context +
                      ", found '" + detail::excerpt(line) + "'",
                  src->lineNumber());
    }
    // Dataset number (and for 58b the binary description).
    for (;;) {
      const Source::Status s = src->nextLine(line);
      if (s == Source::Status::End) {
        warnings.push_back({lastType, src->lineNumber(), "file ends with an unpaired delimiter '-1'"});
        done = true;
        return std::optional<Dataset>{};
      }
      if (s != Source::Status::Ok) return fail("read failed or a line longer than 64 MiB", src->lineNumber());
      if (isBlank(line)) continue;
      if (isDelimiter(line)) {
        warnings.push_back({lastType, src->lineNumber(), "empty dataset (two delimiters in a row) ignored"});
        continue;
      }
      break;
    }
    const std::int64_t startLine = src->lineNumber();
    std::vector<std::string_view> tok;
    {
      std::string_view rest = trim(line);
      while (!rest.empty()) {
        std::size_t k = 0;
        while (k < rest.size() && !detail::isBlankChar(rest[k])) ++k;
        tok.push_back(rest.substr(0, k));
        rest = trim(rest.substr(k));
      }
    }
    Binary58 bin;
    std::string_view number = tok.front();
    if (!number.empty() && (number.back() == 'b' || number.back() == 'B')) {
      bin.binary = true;
      number.remove_suffix(1);
    }
    long long type = 0;
    if (!parseInt(number, type) || type <= 0 || !fitsInt(type)) {
      return fail("line " + std::to_string(startLine) + ": expected a dataset number after '-1', found '" +
                      detail::excerpt(line) + "'",
                  startLine);
    }
    Dataset ds;
    ds.type = static_cast<int>(type);
    ds.line = startLine;
    DatasetContext ctx(*src, ds.type, startLine, where, warnings, options);
    if (bin.binary) {
      long long f[4] = {0, 0, 0, 0};
      bool ok = tok.size() >= 5;
      for (std::size_t i = 0; ok && i < 4; ++i) ok = parseInt(tok[i + 1], f[i]);
      if (!ok) {
        done = true;
        return ctx.error(
            "binary header: expected byte order, floating-point format, ASCII line count and byte "
            "count after '" +
            std::to_string(type) + "b', found '" + detail::excerpt(line) + "'");
      }
      if (type != 58) {
        done = true;
        return ctx.error("binary form 'b' is only defined for dataset 58", ErrorCode::Unsupported);
      }
      if (f[0] != 1 && f[0] != 2) {
        done = true;
        return ctx.error("binary header: byte order " + std::to_string(f[0]) +
                         " is neither 1 (little endian) nor 2 "
                         "(big endian)");
      }
      if (f[1] != 2) {
        done = true;
        return ctx.error("binary header: floating-point format " + std::to_string(f[1]) +
                             " is not IEEE 754 (2); VAX (1) and IBM (3) are not supported",
                         ErrorCode::Unsupported);
      }
      if (f[2] != 11) {
        done = true;
        return ctx.error("binary header: " + std::to_string(f[2]) + " ASCII lines declared, dataset 58 has 11");
      }
      if (f[3] < 0) {
        done = true;
        return ctx.error("binary header: negative byte count");
      }
      if (static_cast<std::uint64_t>(f[3]) > options.maxDatasetBytes) {
        done = true;
        return ctx.error("binary header declares " + std::to_string(f[3]) + " bytes, more than the limit of " +
                             std::to_string(options.maxDatasetBytes),
                         ErrorCode::Corrupt);
      }
      bin.order = f[0] == 1 ? ByteOrder::LittleEndian : ByteOrder::BigEndian;
      bin.floatFormat = static_cast<int>(f[1]);
      bin.asciiLines = f[2];
      bin.byteCount = f[3];
    }

    Result<DatasetData> parsed = [&]() -> Result<DatasetData> {
      switch (ds.type) {
        case 151: return parse151(ctx);
        case 164: return parse164(ctx);
        case 15: return parseNodes(ctx, 15);
        case 2411: return parseNodes(ctx, 2411);
        case 18: return parse18(ctx);
        case 2420: return parse2420(ctx);
        case 82: return parse82(ctx);
        case 55: return parse55(ctx);
        case 58: return parse58(ctx, bin);
        default: return parseSkipped(ctx);
      }
    }();
    if (!parsed) {
      done = true;
      return parsed.error();
    }
    // Whatever the parser left before the closing delimiter.
    std::int64_t extra = 0;
    const std::int64_t extraStart = src->lineNumber() + 1;
    while (!ctx.closed() && !ctx.atEof()) {
      std::string_view rest;
      if (ctx.next(rest) == Line::Ok && !isBlank(rest)) ++extra;
    }
    if (extra > 0) ctx.warnAt(extraStart, std::to_string(extra) + " unexpected lines before the closing -1 ignored");
    if (!ctx.closed()) {
      if (src->ioFailed()) return fail("read failed: " + std::string(std::strerror(errno)), src->lineNumber());
      ctx.warn("file ends without the closing -1 of the dataset");
      done = true;
    }
    if (src->sawCrLf() && !crlfWarned) {
      crlfWarned = true;
      ctx.warnAt(startLine, "CR/LF line ends (read as LF)");
    }
    if (src->sawLoneCr() && !loneCrWarned) {
      loneCrWarned = true;
      ctx.warnAt(startLine, "lone CR line ends (read as LF)");
    }
    ds.data = std::move(*parsed);
    lastType = ds.type;
    lastEnd = src->lineNumber();
    return std::optional<Dataset>{std::move(ds)};
  }
};

DatasetReader::DatasetReader(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
DatasetReader::DatasetReader(DatasetReader&&) noexcept = default;
DatasetReader& DatasetReader::operator=(DatasetReader&&) noexcept = default;
DatasetReader::~DatasetReader() = default;

Result<DatasetReader> DatasetReader::open(const std::string& path, ReadOptions options) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {
    const int e = errno;
    return makeError(e == ENOENT ? ErrorCode::NotFound : ErrorCode::IoError,
                     "cannot open universal file: " + std::string(std::strerror(e)), path);
  }
  struct stat st {};
  std::uint64_t size = std::numeric_limits<std::uint64_t>::max();
  if (::fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode)) size = static_cast<std::uint64_t>(st.st_size);
  if (::fstat(fileno(f), &st) == 0 && S_ISDIR(st.st_mode)) {
    std::fclose(f);
    return makeError(ErrorCode::IoError, "is a directory, not a universal file", path);
  }
  return DatasetReader(std::make_unique<Impl>(std::make_unique<Source>(f, size), path, options));
}

DatasetReader DatasetReader::fromBytes(std::string_view bytes, ReadOptions options) {
  return DatasetReader(std::make_unique<Impl>(std::make_unique<Source>(bytes), "<memory>", options));
}

Result<std::optional<Dataset>> DatasetReader::next() {
  return impl_->next();
}
const std::vector<Warning>& DatasetReader::warnings() const {
  return impl_->warnings;
}
std::uint64_t DatasetReader::bytesRead() const {
  return impl_->src->consumed();
}

namespace {
Result<UffFile> readAll(DatasetReader& reader) {
  UffFile file;
  for (;;) {
    auto d = reader.next();
    if (!d) return d.error();
    if (!d->has_value()) break;
    file.datasets.push_back(std::move(**d));
  }
  file.warnings = reader.warnings();
  return file;
}
}  // namespace

Result<UffFile> readFile(const std::string& path, ReadOptions options) {
  auto reader = DatasetReader::open(path, options);
  if (!reader) return reader.error();
  return readAll(*reader);
}

Result<UffFile> readBytes(std::string_view bytes, ReadOptions options) {
  DatasetReader reader = DatasetReader::fromBytes(bytes, options);
  return readAll(reader);
}

}  // namespace mozzi::core::io::uff
