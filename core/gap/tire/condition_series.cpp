#include "core/gap/tire/condition_series.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numeric>
#include <sstream>

namespace mozzi::core::gap {

namespace {
std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  const auto b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}
}  // namespace

int NumericTable::column(const std::string& name) const {
  const auto it = std::find(header.begin(), header.end(), name);
  return it == header.end() ? -1 : static_cast<int>(it - header.begin());
}

Result<NumericTable> readNumericCsv(const std::string& text, const std::string& source,
                                    const std::vector<std::string>& required,
                                    const std::vector<std::string>& textColumns) {
  NumericTable t;
  std::vector<int> textIndex;  // for each header column: its position in textColumns, or -1
  std::istringstream in(text);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    line = trim(line);
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(trim(cell));
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    const std::string where = source + ":" + std::to_string(n);
    if (t.header.empty()) {
      for (const auto& c : cells)
        if (c.empty()) return makeError(ErrorCode::ParseError, "empty column name in the header", where);
      t.header = cells;
      for (const auto& c : cells) {
        const auto it = std::find(textColumns.begin(), textColumns.end(), c);
        textIndex.push_back(it == textColumns.end() ? -1 : static_cast<int>(it - textColumns.begin()));
      }
      continue;
    }
    if (cells.size() != t.header.size())
      return makeError(
          ErrorCode::ParseError,
          "expected " + std::to_string(t.header.size()) + " columns, found " + std::to_string(cells.size()), where);
    std::vector<double> row;
    std::vector<std::string> words(textColumns.size());
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (textIndex[i] >= 0) {
        if (cells[i].empty()) return makeError(ErrorCode::ParseError, "column " + t.header[i] + " is empty", where);
        words[static_cast<std::size_t>(textIndex[i])] = cells[i];
        row.push_back(0.0);
        continue;
      }
      char* end = nullptr;
      const double v = std::strtod(cells[i].c_str(), &end);
      if (cells[i].empty() || end != cells[i].c_str() + cells[i].size() || !std::isfinite(v))
        return makeError(ErrorCode::ParseError, "column " + t.header[i] + " is not a finite number: '" + cells[i] + "'",
                         where);
      row.push_back(v);
    }
    t.rows.push_back(std::move(row));
    t.text.push_back(std::move(words));
    t.lines.push_back(n);
  }
  if (t.header.empty()) return makeError(ErrorCode::ParseError, "no header row", source);
  for (const auto& r : required)
    if (t.column(r) < 0) return makeError(ErrorCode::ParseError, "missing column '" + r + "'", source);
  if (t.rows.empty()) return makeError(ErrorCode::ParseError, "no data rows", source);
  return t;
}

Result<std::string> readTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return makeError(ErrorCode::IoError, "cannot open file", path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool whitenedResiduals(const std::vector<ConditionPoint>& points, const std::vector<double>& predicted, double* r) {
  for (std::size_t j = 0; j < points.size(); ++j) {
    if (!std::isfinite(predicted[j])) return false;
    r[j] = (predicted[j] - points[j].measured) / points[j].sigma;
  }
  return true;
}

void holmFlags(std::vector<GapEntry>& entries, double alpha) {
  // Two-sided p-value of a standard normal |z|; compare the i-th smallest with
  // alpha / (m - i) and stop at the first that fails (Holm 1979).
  const std::size_t m = entries.size();
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), 0);
  std::vector<double> p(m);
  for (std::size_t i = 0; i < m; ++i) p[i] = std::erfc(std::abs(entries[i].z) / std::sqrt(2.0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
  for (auto& e : entries) e.flagged = false;
  for (std::size_t i = 0; i < m; ++i) {
    if (p[order[i]] > alpha / static_cast<double>(m - i)) break;
    entries[order[i]].flagged = true;
  }
}

GapMetrics conditionMetrics(const std::vector<ConditionPoint>& points, const std::vector<double>& predicted,
                            const std::string& residualName,
                            const std::vector<std::vector<std::pair<std::string, double>>>& extraDetails,
                            double alpha) {
  GapMetrics m;
  m.residualName = residualName;
  double num = 0.0, den = 0.0;
  for (std::size_t j = 0; j < points.size(); ++j) {
    const auto& pt = points[j];
    const double d = predicted[j] - pt.measured;
    num += d * d;
    den += pt.measured * pt.measured;
    GapEntry e;
    e.kind = "condition";
    e.label = pt.label;
    e.value = pt.measured != 0.0 ? 100.0 * d / std::abs(pt.measured) : 0.0;
    e.z = d / pt.sigma;
    e.details = {{"measured", pt.measured}, {"predicted", predicted[j]}, {"uncertainty", pt.sigma}};
    if (j < extraDetails.size()) e.details.insert(e.details.end(), extraDetails[j].begin(), extraDetails[j].end());
    m.entries.push_back(std::move(e));
  }
  holmFlags(m.entries, alpha);
  m.overall = den > 0.0 ? std::sqrt(num / den) : std::sqrt(num);
  return m;
}

std::vector<ConditionPoint> simulatedPoints(const std::vector<ConditionPoint>& points,
                                            const std::vector<double>& predicted, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<ConditionPoint> out = points;
  for (std::size_t j = 0; j < out.size(); ++j) out[j].measured = predicted[j] + out[j].sigma * noise(rng);
  return out;
}

}  // namespace mozzi::core::gap
