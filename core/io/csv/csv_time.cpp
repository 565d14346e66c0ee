// CSV exchange of time records (docs/formats/csv.md, "Time record").

#include "core/io/csv/csv_exchange.h"

#include <charconv>
#include <cmath>
#include <ostream>
#include <sstream>

#include "core/io/csv/csv_internal.h"

namespace mozzi::core::io::csv {

using namespace detail;  // NOLINT(google-build-using-namespace): the exchange's private helpers

// --- time records ----------------------------------------------------------------------

Result<void> writeTimeCsv(const TimeTable& table, std::ostream& out) {
  if (!(table.sampleRateHz > 0.0) || !std::isfinite(table.sampleRateHz)) {
    return makeError(ErrorCode::InvalidArgument, "sample rate must be positive", "CSV export");
  }
  if (table.samples.rows() == 0 || table.samples.cols() == 0 ||
      table.samples.cols() != static_cast<Eigen::Index>(table.channels.size())) {
    return makeError(ErrorCode::InvalidArgument, "time table needs samples and one description per channel",
                     "CSV export");
  }
  if (!table.samples.allFinite()) return makeError(ErrorCode::InvalidArgument, "samples are not finite", "CSV export");
  out << kMagic << ", time-record\n# sample_rate_hz = " << num(table.sampleRateHz) << "\ntime [s]";
  for (const auto& ch : table.channels) {
    std::string name = ch.name.empty() ? ch.quantity : ch.name;
    if (ch.dof && !dofInName(name)) name += (name.empty() ? "" : " ") + formatDof(*ch.dof);
    if (name.empty()) name = "channel";
    out << ',' << name << " [" << (ch.unit.empty() ? "1" : ch.unit) << ']';
  }
  out << '\n';
  for (Eigen::Index r = 0; r < table.samples.rows(); ++r) {
    out << num(table.startTimeS + static_cast<double>(r) / table.sampleRateHz);
    for (Eigen::Index c = 0; c < table.samples.cols(); ++c) out << ',' << num(table.samples(r, c));
    out << '\n';
  }
  return written(out);
}

Result<TimeTable> readTimeCsv(std::string_view text, const std::string& source) {
  MOZZI_TRY_ASSIGN(const Table t, parseTableOf(text, source, "time-record", "a time record"));
  TimeTable out;
  // Columns: optional leading time column, then channels.
  const Title firstTitle = splitTitle(t.titles[0]);
  std::size_t firstChannel = 0;
  double timeFactor = 1.0;
  if (lower(firstTitle.name) == "time" || lower(firstTitle.name) == "t") {
    firstChannel = 1;
    auto u = siUnit(firstTitle.unit.value_or("s"));
    if (!u || u->quantity != "time") return parseError("time column unit must be s or ms", source, t.headerLine, 1);
    timeFactor = u->factor;
  }
  if (firstChannel >= t.titles.size()) return parseError("no channel columns", source, t.headerLine);
  for (std::size_t c = firstChannel; c < t.titles.size(); ++c) {
    const Title title = splitTitle(t.titles[c]);
    if (!title.unit) {
      return parseError("column title '" + t.titles[c] + "' has no unit in brackets, e.g. 'force 1:+Z [N]'", source,
                        t.headerLine, static_cast<int>(c + 1));
    }
    auto unit = siUnit(*title.unit);
    if (!unit) return parseError(unit.error().message, source, t.headerLine, static_cast<int>(c + 1));
    out.channels.push_back({title.name, dofInName(title.name), unit->quantity, unit->unit});
  }
  const auto n = static_cast<Eigen::Index>(t.rows.size());
  out.samples.resize(n, static_cast<Eigen::Index>(out.channels.size()));
  for (Eigen::Index r = 0; r < n; ++r) {
    for (std::size_t c = firstChannel; c < t.titles.size(); ++c) {
      const auto unit = siUnit(*splitTitle(t.titles[c]).unit);
      out.samples(r, static_cast<Eigen::Index>(c - firstChannel)) =
          unit->factor * t.rows[static_cast<std::size_t>(r)][c];
    }
  }
  // Sample rate: the comment key wins; otherwise the time column, which must
  // be evenly spaced to 0.1 % of a sample period (printing with 6 digits, as
  // many programs do, stays well inside that for records below 10^5 samples).
  std::optional<double> rate;
  if (auto it = t.keys.find("sample_rate_hz"); it != t.keys.end()) {
    double v = 0;
    auto [ptr, ec] = std::from_chars(it->second.data(), it->second.data() + it->second.size(), v);
    if (ec != std::errc() || ptr != it->second.data() + it->second.size() || !(v > 0) || !std::isfinite(v)) {
      return parseError("sample_rate_hz '" + it->second + "' is not a positive number", source, 1);
    }
    rate = v;
  }
  if (firstChannel == 1) {
    const double t0 = t.rows.front()[0] * timeFactor;
    out.startTimeS = t0;
    if (n >= 2) {
      const double dt = (t.rows.back()[0] - t.rows.front()[0]) * timeFactor / static_cast<double>(n - 1);
      if (!(dt > 0)) return parseError("time column does not increase", source, t.rowLines.back(), 1);
      for (Eigen::Index r = 0; r < n; ++r) {
        const double expected = t0 + static_cast<double>(r) * dt;
        if (std::abs(t.rows[static_cast<std::size_t>(r)][0] * timeFactor - expected) > 1e-3 * dt) {
          return parseError("time column is not evenly spaced (expected " + num(expected) + " s)", source,
                            t.rowLines[static_cast<std::size_t>(r)], 1);
        }
      }
      if (rate && std::abs(*rate * dt - 1.0) > 1e-3) {
        return parseError("sample_rate_hz disagrees with the time column", source, t.headerLine, 1);
      }
      if (!rate) rate = 1.0 / dt;
    }
  }
  if (!rate) return parseError("no time column and no '# sample_rate_hz = ...' line", source, t.headerLine);
  out.sampleRateHz = *rate;
  return out;
}

}  // namespace mozzi::core::io::csv
