// UFF datasets 151 (header), 164 (units), 55 (data at nodes) and the types
// Mozzi skips; see uff_parse.h and the layouts at the top of uff_reader.cpp.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include <Eigen/Geometry>

#include "core/io/uff/uff_parse.h"

namespace mozzi::core::io::uff::parsing {

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
  MOZZI_TRY(readNumbers(ctx, 3, factors, "record 2 (unit factors)"));
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

// --- 55 ----------------------------------------------------------------------
Result<DatasetData> parse55(DatasetContext& ctx) {
  ModalData55 m;
  for (auto& id : m.idLines) {
    if (textLine(ctx, id) != Line::Ok) return ctx.endedBefore("the five ID lines (records 1-5)");
  }
  MOZZI_TRY_ASSIGN(const std::vector<long long> h,
                   readIntLine(ctx, 6, 6,
                               "record 6 (model type, analysis type, data characteristic, specific type, "
                               "data type, values per node)"));
  MOZZI_TRY(checkFitsInt(ctx, "record 6", h));
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
  MOZZI_TRY_ASSIGN(auto r7, readIntLine(ctx, 2, 8, "record 7 (integer count, real count, ...)", &r7line));
  const long long nint = r7[0];
  const long long nrval = r7[1];
  if (nint < 0 || nint > 1000 || nrval < 0 || nrval > 1000) {
    return ctx.error("record 7: counts " + std::to_string(nint) + ", " + std::to_string(nrval) +
                     " are not between 0 and 1000");
  }
  std::vector<long long> ints(r7.begin() + 2, r7.end());
  while (static_cast<long long>(ints.size()) < nint) {
    MOZZI_TRY_ASSIGN(auto more, readIntLine(ctx, 1, 8, "record 7 (continued)"));
    ints.insert(ints.end(), more.begin(), more.end());
  }
  if (static_cast<long long>(ints.size()) > nint) {
    return ctx.error("record 7: " + std::to_string(ints.size()) + " integers where " + std::to_string(nint) +
                     " were declared");
  }
  MOZZI_TRY(checkFitsInt(ctx, "record 7", ints));
  for (long long v : ints) m.integerValues.push_back(static_cast<int>(v));
  m.realValues.resize(static_cast<std::size_t>(nrval));
  if (nrval > 0) {
    MOZZI_TRY(readNumbers(ctx, static_cast<std::size_t>(nrval), m.realValues.data(), "record 8 (real values)"));
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
    MOZZI_TRY(readNumbers(ctx, perNode, values.data(), "record 10 (data) of node " + std::to_string(node)));
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

}  // namespace mozzi::core::io::uff::parsing
