#include "core/tire/tire_csv.h"

#include "core/io/text_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

namespace mozzi::core::tire {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

std::string_view trim(std::string_view s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string_view::npos) return {};
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const auto pos = s.find(sep, start);
    out.push_back(trim(s.substr(start, pos == std::string_view::npos ? std::string_view::npos : pos - start)));
    if (pos == std::string_view::npos) return out;
    start = pos + 1;
  }
}

// The whole cell must be a finite number (strtod needs a terminated string).
bool toNumber(std::string_view cell, double& value) {
  if (cell.empty()) return false;
  const std::string s(cell);
  char* end = nullptr;
  value = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(value);
}

std::string at(const std::string& source, int line) {
  return source + ":" + std::to_string(line);
}

// Valid range of each known column (docs/formats/csv.md, tyre tables): a
// tyre on a test rig, with room to spare; any other column: |x| <= 1e12.
struct ColumnRange {
  double min, max;
  const char* unit;
};
ColumnRange columnRange(const std::string& name) {
  static const std::map<std::string, ColumnRange> kRanges = {{"frequency_hz", {0.0, 1e4, "Hz"}},
                                                             {"time_s", {-1e6, 1e6, "s"}},
                                                             {"yaw_rate_rad_s", {-100.0, 100.0, "rad/s"}},
                                                             {"lateral_force_n", {-1e6, 1e6, "N"}},
                                                             {"slip_deg", {-90.0, 90.0, "deg"}},
                                                             {"camber_deg", {-90.0, 90.0, "deg"}},
                                                             {"load_n", {0.0, 1e6, "N"}},
                                                             {"pressure_bar", {0.0, 100.0, "bar"}},
                                                             {"force_n", {-1e6, 1e6, "N"}},
                                                             {"torque_nm", {-1e5, 1e5, "N m"}},
                                                             {"half_length_m", {0.0, 1.0, "m"}}};
  const auto it = kRanges.find(name);
  return it == kRanges.end() ? ColumnRange{-1e12, 1e12, ""} : it->second;
}

// A cell as shown in an error: at most 40 characters of it.
std::string shown(std::string_view cell) {
  return cell.size() <= 40 ? std::string(cell) : std::string(cell.substr(0, 40)) + "...";
}

}  // namespace

int NumericTable::column(const std::string& name) const {
  const auto it = std::find(header.begin(), header.end(), name);
  return it == header.end() ? -1 : static_cast<int>(it - header.begin());
}

Result<NumericTable> parseNumericTable(std::string_view text, const std::string& source,
                                       const std::vector<std::string>& required) {
  NumericTable t;
  int n = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto end = std::min(text.find('\n', start), text.size());
    const std::string_view line = trim(text.substr(start, end - start));
    start = end + 1;
    ++n;
    if (line.empty() || line[0] == '#') continue;
    const auto cells = split(line, ',');
    if (t.header.empty()) {
      for (const auto& c : cells) {
        if (c.empty()) return makeError(ErrorCode::ParseError, "empty column name in the header", at(source, n));
        if (std::find(t.header.begin(), t.header.end(), c) != t.header.end())
          return makeError(ErrorCode::ParseError, "column '" + shown(c) + "' appears twice", at(source, n));
        t.header.emplace_back(c);
      }
      continue;
    }
    if (cells.size() != t.header.size())
      return makeError(
          ErrorCode::ParseError,
          "expected " + std::to_string(t.header.size()) + " columns, found " + std::to_string(cells.size()),
          at(source, n));
    std::vector<double> row(cells.size());
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (!toNumber(cells[i], row[i]))
        return makeError(ErrorCode::ParseError,
                         "column " + shown(t.header[i]) + " is not a finite number: '" + shown(cells[i]) + "'",
                         at(source, n));
      const ColumnRange r = columnRange(t.header[i]);
      if (row[i] < r.min || row[i] > r.max) {
        char range[96];
        std::snprintf(range, sizeof range, "[%g, %g]%s%s", r.min, r.max, *r.unit ? " " : "", r.unit);
        return makeError(ErrorCode::ParseError,
                         "column " + shown(t.header[i]) + " = " + shown(cells[i]) + " is out of range; valid: " + range,
                         at(source, n));
      }
    }
    t.rows.push_back(std::move(row));
    t.lines.push_back(n);
  }
  if (t.header.empty()) return makeError(ErrorCode::ParseError, "no header row", source);
  for (const auto& r : required)
    if (t.column(r) < 0) return makeError(ErrorCode::ParseError, "missing column '" + r + "'", source);
  if (t.rows.empty()) return makeError(ErrorCode::ParseError, "no data rows", source);
  return t;
}

Result<NumericTable> readNumericTable(const std::string& path, const std::vector<std::string>& required) {
  // size cap: core/io/text_file.h
  MOZZI_TRY_ASSIGN(const std::string text, io::readTextFile(path, "tyre test"));
  return parseNumericTable(text, path, required);
}

const std::vector<std::string>& harmonicYawColumns() {
  static const std::vector<std::string> c{"frequency_hz", "time_s", "yaw_rate_rad_s", "lateral_force_n"};
  return c;
}

const std::vector<std::string>& steadyStateColumns() {
  static const std::vector<std::string> c{"slip_deg", "camber_deg", "load_n", "pressure_bar", "force_n", "torque_nm"};
  return c;
}

Result<std::vector<HarmonicYawRecord>> harmonicYawRecords(const NumericTable& t, const std::string& source) {
  const int cf = t.column("frequency_hz"), ct = t.column("time_s"), cr = t.column("yaw_rate_rad_s"),
            cF = t.column("lateral_force_n");
  if (std::min({cf, ct, cr, cF}) < 0)
    return makeError(ErrorCode::ParseError,
                     "a harmonic yaw test needs the columns frequency_hz, time_s, "
                     "yaw_rate_rad_s, lateral_force_n",
                     source);
  std::vector<HarmonicYawRecord> recs;
  std::size_t i = 0;
  while (i < t.rows.size()) {
    std::size_t j = i;
    while (j < t.rows.size() && t.rows[j][cf] == t.rows[i][cf]) ++j;
    const std::size_t n = j - i;
    if (n < 4) return makeError(ErrorCode::ParseError, "fewer than 4 samples at one frequency", at(source, t.lines[i]));
    const double dt = (t.rows[j - 1][ct] - t.rows[i][ct]) / static_cast<double>(n - 1);
    for (std::size_t k = i + 1; k < j; ++k) {
      const double step = t.rows[k][ct] - t.rows[k - 1][ct];
      if (!(dt > 0.0) || !(std::abs(step - dt) <= 1e-3 * dt))
        return makeError(ErrorCode::ParseError, "time_s is not uniformly sampled and increasing",
                         at(source, t.lines[k]));
    }
    HarmonicYawRecord r;
    r.excitationFrequencyHz = t.rows[i][cf];
    r.sampleRateHz = 1.0 / dt;
    if (!std::isfinite(r.sampleRateHz))
      return makeError(ErrorCode::ParseError, "time step too small", at(source, t.lines[i]));
    r.yawRate.resize(static_cast<Eigen::Index>(n));
    r.lateralForce.resize(static_cast<Eigen::Index>(n));
    for (std::size_t k = 0; k < n; ++k) {
      r.yawRate[static_cast<Eigen::Index>(k)] = t.rows[i + k][cr];
      r.lateralForce[static_cast<Eigen::Index>(k)] = t.rows[i + k][cF];
    }
    recs.push_back(std::move(r));
    i = j;
  }
  return recs;
}

Result<std::vector<SteadyStateSweepRows>> steadyStateSweeps(const NumericTable& t, const std::string& source) {
  const int cs = t.column("slip_deg"), cg = t.column("camber_deg"), cl = t.column("load_n"),
            cp = t.column("pressure_bar"), cf = t.column("force_n"), cm = t.column("torque_nm");
  if (std::min({cs, cg, cl, cp, cf, cm}) < 0)
    return makeError(ErrorCode::ParseError,
                     "a steady-state sweep file needs the columns slip_deg, camber_deg, "
                     "load_n, pressure_bar, force_n, torque_nm",
                     source);
  std::map<std::tuple<double, double, bool>, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const auto& r = t.rows[i];
    if (r[cg] == 0.0) groups[{r[cl], r[cp], false}].push_back(i);
    if (r[cs] == 0.0) groups[{r[cl], r[cp], true}].push_back(i);
  }
  std::vector<SteadyStateSweepRows> out;
  for (const auto& [key, idx] : groups) {
    if (idx.size() < 4) continue;  // a lone zero-angle point of the other sweep kind
    SteadyStateSweepRows s;
    s.camberSweep = std::get<2>(key);
    s.firstLine = t.lines[idx.front()];
    s.sweep.verticalLoad = std::get<0>(key);
    s.sweep.pressure = std::get<1>(key) * 1e5;
    const auto n = static_cast<Eigen::Index>(idx.size());
    s.sweep.angle.resize(n);
    s.sweep.force.resize(n);
    s.sweep.torque.resize(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      const auto& r = t.rows[idx[static_cast<std::size_t>(k)]];
      s.sweep.angle[k] = (s.camberSweep ? r[cg] : r[cs]) * kDeg;
      s.sweep.force[k] = r[cf];
      s.sweep.torque[k] = r[cm];
    }
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<SteadyStatePoint> steadyStatePoints(const NumericTable& t) {
  const int cs = t.column("slip_deg"), cg = t.column("camber_deg"), cl = t.column("load_n"),
            cp = t.column("pressure_bar"), cf = t.column("force_n"), cm = t.column("torque_nm");
  std::vector<SteadyStatePoint> pts;
  if (std::min({cs, cg, cl, cp, cf, cm}) < 0) return pts;
  for (const auto& r : t.rows) pts.push_back({r[cs] * kDeg, r[cg] * kDeg, r[cl], r[cp] * 1e5, r[cf], r[cm]});
  return pts;
}

Result<std::vector<std::vector<double>>> parseNumberTuples(std::string_view text, std::size_t width,
                                                           const std::string& what) {
  if (trim(text).empty()) return makeError(ErrorCode::InvalidArgument, "empty list", what);
  std::vector<std::vector<double>> out;
  for (const auto item : split(text, ',')) {
    std::vector<double> v;
    for (const auto field : split(item, ':')) {
      double x = 0.0;
      if (!toNumber(field, x))
        return makeError(ErrorCode::InvalidArgument, "'" + std::string(item) + "' is not a list of numbers", what);
      v.push_back(x);
    }
    if (v.size() != width)
      return makeError(ErrorCode::InvalidArgument,
                       "'" + std::string(item) + "' needs " + std::to_string(width) + " fields separated by ':'", what);
    out.push_back(std::move(v));
  }
  return out;
}

}  // namespace mozzi::core::tire
