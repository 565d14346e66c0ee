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

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "core/io/uff/uff.h"
#include "core/io/uff/uff_parse.h"

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

namespace parsing {

std::string textField(std::string_view s) {
  return std::string(trimRight(s));
}

// Exactly `count` numbers from one or more lines (values of one record may
// wrap, e.g. 6 per line). `what` names the record in errors.
Result<void> readNumbers(DatasetContext& ctx, std::size_t count, double* out, const std::string& what,
                         std::string_view* firstLine) {
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
                                           const std::string& what, std::string_view* lineOut) {
  std::string_view line;
  const Line l = ctx.nextNonBlank(line);
  if (l != Line::Ok) return ctx.endedBefore(what);
  if (lineOut) *lineOut = line;
  std::vector<long long> values;
  detail::Words words(line);
  for (std::string_view word; words.next(word);) {
    long long v = 0;
    if (!parseInt(word, v)) {
      return ctx.error(what + ": '" + detail::excerpt(word) + "' is not an integer (column " +
                       std::to_string(word.data() - line.data() + 1) + ")");
    }
    if (values.size() == maxCount) {
      return ctx.error(what + ": more than " + std::to_string(maxCount) + " integers on the line");
    }
    values.push_back(v);
  }
  if (values.size() < minCount) {
    return ctx.error(what + ": expected " + std::to_string(minCount) + " integers, found " +
                     std::to_string(values.size()) + " in '" + detail::excerpt(line) + "'");
  }
  return values;
}

// Reads text lines of a fixed-count block of records, allowing an early end.
Line textLine(DatasetContext& ctx, std::string& out) {
  std::string_view line;
  const Line l = ctx.next(line);
  if (l == Line::Ok) out = textField(line);
  return l;
}

}  // namespace parsing

namespace {
using detail::isBlank;
using detail::isDelimiter;
using detail::parseInt;
using detail::trim;
using parsing::Binary58;
using parsing::DatasetContext;
using parsing::fitsInt;
using parsing::Line;
using parsing::Source;
}  // namespace

// ---------------------------------------------------------------------------
struct DatasetReader::Impl {
  Impl(std::unique_ptr<Source> s, std::string w, ReadOptions o)
      : src(std::move(s)), where(std::move(w)), options(std::move(o)) {}

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
      detail::Words words(line);
      for (std::string_view w; words.next(w);) tok.push_back(w);
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
        case 151: return parsing::parse151(ctx);
        case 164: return parsing::parse164(ctx);
        case 15: return parsing::parseNodes(ctx, 15);
        case 2411: return parsing::parseNodes(ctx, 2411);
        case 18: return parsing::parse18(ctx);
        case 2420: return parsing::parse2420(ctx);
        case 82: return parsing::parse82(ctx);
        case 55: return parsing::parse55(ctx);
        case 58: return parsing::parse58(ctx, bin);
        default: return parsing::parseSkipped(ctx);
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
  return DatasetReader(std::make_unique<Impl>(std::make_unique<Source>(f, size), path, std::move(options)));
}

DatasetReader DatasetReader::fromBytes(std::string_view bytes, ReadOptions options) {
  return DatasetReader(std::make_unique<Impl>(std::make_unique<Source>(bytes), "<memory>", std::move(options)));
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
    MOZZI_TRY_ASSIGN(std::optional<Dataset> d, reader.next());
    if (!d) break;
    file.datasets.push_back(std::move(*d));
  }
  file.warnings = reader.warnings();
  return file;
}
}  // namespace

Result<UffFile> readFile(const std::string& path, ReadOptions options) {
  MOZZI_TRY_ASSIGN(auto reader, DatasetReader::open(path, std::move(options)));
  return readAll(reader);
}

Result<UffFile> readBytes(std::string_view bytes, ReadOptions options) {
  DatasetReader reader = DatasetReader::fromBytes(bytes, std::move(options));
  return readAll(reader);
}

}  // namespace mozzi::core::io::uff
