// UFF dataset 58 (functions, ASCII) and 58b (the same records, then the raw
// values); see uff_parse.h and the layouts at the top of uff_reader.cpp.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include <Eigen/Geometry>

#include "core/io/uff/uff_parse.h"

namespace mozzi::core::io::uff::parsing {

namespace {
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
    detail::Words words(line);
    for (std::string_view w; words.next(w);) tok.push_back(w);
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
  MOZZI_TRY(checkFitsInt(ctx, "record 6", v));
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
// Value k of an unevenly spaced record's data block: every perPoint-th value
// is an abscissa, the ordPerPoint values after it the ordinate (Re, Im).
inline void storeUneven(double* xs, double* ord, std::uint64_t perPoint, std::uint64_t ordPerPoint, std::uint64_t k,
                        double v) {
  const std::uint64_t point = k / perPoint;
  const std::uint64_t comp = k % perPoint;
  if (comp == 0) {
    xs[point] = v;
  } else {
    ord[point * ordPerPoint + comp - 1] = v;
  }
}

}  // namespace

Result<DatasetData> parse58(DatasetContext& ctx, const Binary58& bin) {
  Function58 f;
  f.binary = bin.binary;
  f.byteOrder = bin.order;
  for (auto& id : f.idLines) {
    if (textLine(ctx, id) != Line::Ok) return ctx.endedBefore("the five ID lines (records 1-5)");
  }
  std::string_view line;
  if (ctx.nextNonBlank(line) != Line::Ok) return ctx.endedBefore("record 6 (function and DOF identification)");
  MOZZI_TRY(parseRecord6(ctx, line, f));

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

  MOZZI_TRY(parseAxis(ctx, f.abscissaAxis, 8));
  MOZZI_TRY(parseAxis(ctx, f.ordinateNumerator, 9));
  MOZZI_TRY(parseAxis(ctx, f.ordinateDenominator, 10));
  MOZZI_TRY(parseAxis(ctx, f.zAxis, 11));

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
            storeUneven(xs, ord, perPoint, ordPerPoint, k, v);
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
        storeUneven(xs, ord, perPoint, ordPerPoint, k++, v);
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

}  // namespace mozzi::core::io::uff::parsing
