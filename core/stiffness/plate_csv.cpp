#include "core/stiffness/plate_csv.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "core/common/enum_names.h"
#include "core/io/text_file.h"

namespace mozzi::core::stiffness {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream s(line);
  while (std::getline(s, field, ',')) {
    const auto b = field.find_first_not_of(" \t\r");
    const auto e = field.find_last_not_of(" \t\r");
    out.push_back(b == std::string::npos ? std::string() : field.substr(b, e - b + 1));
  }
  if (out.empty()) out.emplace_back();
  return out;
}

// The whole field as a number (nan and inf included: the caller decides);
// false when it is not a number at all.
bool parsesAsNumber(const std::string& t, double& v) {
  if (t.empty()) return false;
  char* end = nullptr;
  v = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size();
}

std::string numberText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// "what = v is out of range; valid: [-m, m] unit", as the CLI's ranges say it.
Result<void> checkRange(double v, double most, const std::string& what, const std::string& unit,
                        const std::string& where) {
  if (std::isfinite(v) && v >= -most && v <= most) return {};
  return makeError(ErrorCode::ParseError,
                   what + " = " + numberText(v) + " is out of range; valid: [" + numberText(-most) + ", " +
                       numberText(most) + "]" + (unit.empty() ? std::string() : " " + unit),
                   where);
}

// The twist files need the plate's sensors (the readers ask for them, a
// PlateCsv built otherwise may lack them).
Result<void> needSensors(const PlateCsv& csv) {
  if (csv.sensors.size() >= 3) return {};
  return makeError(ErrorCode::ParseError,
                   "at least 3 'sensor,u,v' rows are needed, found " + std::to_string(csv.sensors.size()), csv.source);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

std::string PlateCsv::where(std::size_t row) const {
  if (row < rowLines.size()) return source + ":" + std::to_string(rowLines[row]);
  return source;
}

Result<PlateCsv> parsePlateCsv(const std::string& text, const std::string& source, bool needSensors, bool needRows) {
  std::istringstream in(text);
  PlateCsv csv;
  csv.source = source;
  std::string line;
  int lineNo = 0;
  std::vector<std::string> lastHeader;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string where = source + ":" + std::to_string(lineNo);
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const auto fields = splitFields(line);
    if (fields[0] == "sensor" || fields[0] == "load") {
      double u = 0, v = 0;
      if (fields.size() != 3 || !parsesAsNumber(fields[1], u) || !parsesAsNumber(fields[2], v) || !std::isfinite(u) ||
          !std::isfinite(v)) {
        return makeError(ErrorCode::ParseError, "expected '" + fields[0] + ",u,v' with numbers", where);
      }
      for (double x : {u, v}) MOZZI_TRY(checkRange(x, kMaxPlatePosition, fields[0] + " position", "m", where));
      if (fields[0] == "sensor") {
        csv.sensors.emplace_back(u, v);
      } else {
        csv.load = Vector2(u, v);
        csv.hasLoad = true;
      }
      continue;
    }
    double probe = 0;
    if (!parsesAsNumber(fields[0], probe)) {  // a header row ("nan" is data, and an error below)
      if (csv.rows.empty()) lastHeader = fields;
      continue;
    }
    std::vector<double> row;
    row.reserve(fields.size());
    for (std::size_t k = 0; k < fields.size(); ++k) {
      const auto& f = fields[k];
      double v = 0;
      if (!parsesAsNumber(f, v)) {
        return makeError(ErrorCode::ParseError,
                         "column " + std::to_string(k + 1) + " is not a number: '" + f.substr(0, 40) + "'", where);
      }
      MOZZI_TRY(checkRange(v, kMaxPlateValue, "column " + std::to_string(k + 1), "", where));
      row.push_back(v);
    }
    if (!csv.rows.empty() && row.size() != csv.rows.front().size()) {
      return makeError(
          ErrorCode::ParseError,
          "row has " + std::to_string(row.size()) + " fields, expected " + std::to_string(csv.rows.front().size()),
          where);
    }
    csv.rows.push_back(std::move(row));
    csv.rowLines.push_back(lineNo);
  }
  csv.header = std::move(lastHeader);
  if (needSensors && csv.sensors.size() < 3) {
    return makeError(ErrorCode::ParseError,
                     "at least 3 'sensor,u,v' rows are needed, found " + std::to_string(csv.sensors.size()), source);
  }
  if (needRows && csv.rows.empty()) return makeError(ErrorCode::ParseError, "no data rows", source);
  return csv;
}

Result<PlateCsv> readPlateCsv(const std::string& path, bool needSensors, bool needRows) {
  MOZZI_TRY_ASSIGN(auto text, io::readTextFile(path, "plate CSV", kMaxPlateFileBytes));
  return parsePlateCsv(text, path, needSensors, needRows);
}

const char* plateCsvKindName(PlateCsvKind kind) {
  static constexpr auto kNames = enumTable<PlateCsvKind>(
      {{PlateCsvKind::Static, "static"}, {PlateCsvKind::Dynamic, "dynamic"}, {PlateCsvKind::Modal, "modal"}}, "static");
  return kNames.of(kind);
}

Result<PlateCsvKind> guessPlateCsvKind(const PlateCsv& csv) {
  const std::size_t ns = csv.sensors.size();
  if (ns < 3) {
    return makeError(ErrorCode::ParseError, "at least 3 'sensor,u,v' rows are needed, found " + std::to_string(ns),
                     csv.source);
  }
  if (csv.rows.empty()) return makeError(ErrorCode::ParseError, "no data rows", csv.source);
  const std::size_t nc = csv.rows.front().size();
  if (nc == ns + 1) return PlateCsvKind::Static;
  if (nc == 3 + 2 * ns) return PlateCsvKind::Dynamic;
  if (nc == 1 + 2 * ns) {
    bool modal = false, dynamic = false;
    for (std::size_t k = 1; k < csv.header.size(); ++k) {
      const std::string h = lower(csv.header[k]);
      if (h.rfind("re", 0) == 0 || h.rfind("im", 0) == 0) modal = true;
      if (h.rfind('a', 0) == 0 || h.rfind("phi", 0) == 0 || h.find("phase") != std::string::npos ||
          h.find("deg") != std::string::npos)
        dynamic = true;
    }
    if (modal != dynamic) return modal ? PlateCsvKind::Modal : PlateCsvKind::Dynamic;
    return makeError(ErrorCode::ParseError,
                     std::to_string(nc) + " columns fit a dynamic sweep (freq, amplitude, phase per sensor) and " +
                         "modal FRFs (freq, Re, Im per sensor) alike, and no header names them: choose the kind",
                     csv.where());
  }
  return makeError(ErrorCode::ParseError,
                   "data rows have " + std::to_string(nc) + " fields; with " + std::to_string(ns) +
                       " sensors a static file has " + std::to_string(ns + 1) + ", a dynamic sweep " +
                       std::to_string(1 + 2 * ns) + " or " + std::to_string(3 + 2 * ns) + ", modal FRFs " +
                       std::to_string(1 + 2 * ns),
                   csv.where());
}

Result<StaticTwistResult> staticTwistFromCsv(const PlateCsv& csv, const StaticTestOptions& options) {
  MOZZI_TRY(needSensors(csv));
  if (!csv.hasLoad) return makeError(ErrorCode::ParseError, "no 'load,u,v' row", csv.source);
  const std::size_t ns = csv.sensors.size();
  if (csv.rows.empty()) return makeError(ErrorCode::ParseError, "no data rows", csv.source);
  if (csv.rows.front().size() != ns + 1) {
    return makeError(ErrorCode::ParseError, "data rows need force + " + std::to_string(ns) + " displacements",
                     csv.where());
  }
  if (csv.rows.size() == 1) {
    std::vector<double> w(csv.rows[0].begin() + 1, csv.rows[0].end());
    return staticTwistSingleLoad(csv.sensors, w, csv.rows[0][0], csv.load, options.plane);
  }
  Vector f(static_cast<Eigen::Index>(csv.rows.size()));
  Matrix d(static_cast<Eigen::Index>(csv.rows.size()), static_cast<Eigen::Index>(ns));
  for (std::size_t k = 0; k < csv.rows.size(); ++k) {
    f(static_cast<Eigen::Index>(k)) = csv.rows[k][0];
    for (std::size_t i = 0; i < ns; ++i)
      d(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(i)) = csv.rows[k][i + 1];
  }
  return staticTwistTest(csv.sensors, f, d, csv.load, options);
}

Result<std::vector<SweepPoint>> sweepFromCsv(const PlateCsv& csv) {
  MOZZI_TRY(needSensors(csv));
  const std::size_t ns = csv.sensors.size();
  if (csv.rows.empty()) return makeError(ErrorCode::ParseError, "no data rows", csv.source);
  const std::size_t nc = csv.rows.front().size();
  if (nc != 1 + 2 * ns && nc != 3 + 2 * ns) {
    return makeError(ErrorCode::ParseError,
                     "rows need freq_Hz, then amplitude_m, phase_deg per laser, optionally force_N, force_phase_deg",
                     csv.where());
  }
  std::vector<SweepPoint> sweep;
  for (const auto& r : csv.rows) {
    SweepPoint p;
    p.frequencyHz = r[0];
    p.amplitude.resize(static_cast<Eigen::Index>(ns));
    p.phase.resize(static_cast<Eigen::Index>(ns));
    for (std::size_t i = 0; i < ns; ++i) {
      p.amplitude(static_cast<Eigen::Index>(i)) = r[1 + 2 * i];
      p.phase(static_cast<Eigen::Index>(i)) = r[2 + 2 * i] * kDegToRad;
    }
    if (nc == 3 + 2 * ns) {
      p.forceAmplitude = r[1 + 2 * ns];
      p.forcePhase = r[2 + 2 * ns] * kDegToRad;
    }
    sweep.push_back(p);
  }
  return sweep;
}

Result<FrfMatrix> modalFrfFromCsv(const PlateCsv& csv, FrfType type) {
  MOZZI_TRY(needSensors(csv));
  const std::size_t ns = csv.sensors.size();
  if (csv.rows.empty()) return makeError(ErrorCode::ParseError, "no data rows", csv.source);
  if (csv.rows.front().size() != 1 + 2 * ns) {
    return makeError(ErrorCode::ParseError, "rows need freq_Hz, then Re, Im per accelerometer", csv.where());
  }
  FrfMatrix frf;
  frf.type = type;
  const auto nf = static_cast<Eigen::Index>(csv.rows.size());
  frf.frequencyHz.resize(nf);
  ComplexMatrix h(nf, static_cast<Eigen::Index>(ns));
  for (Eigen::Index k = 0; k < nf; ++k) {
    const auto& r = csv.rows[static_cast<std::size_t>(k)];
    if (k > 0 && !(r[0] > frf.frequencyHz(k - 1))) {
      return makeError(ErrorCode::ParseError,
                       "frequency " + numberText(r[0]) + " Hz does not follow " + numberText(frf.frequencyHz(k - 1)) +
                           " Hz: the lines must ascend strictly",
                       csv.where(static_cast<std::size_t>(k)));
    }
    frf.frequencyHz(k) = r[0];
    for (std::size_t i = 0; i < ns; ++i) h(k, static_cast<Eigen::Index>(i)) = Complex(r[1 + 2 * i], r[2 + 2 * i]);
  }
  for (std::size_t i = 0; i < ns; ++i) frf.responses.push_back(Dof{static_cast<int>(i + 1), Direction::Y, false});
  frf.references.push_back(Dof{100, Direction::Y, false});
  frf.h.push_back(h);
  return frf;
}

std::vector<double> frfPeakFrequencies(const FrfMatrix& frf, std::size_t most, int reference) {
  std::vector<double> out;
  if (reference < 0 || reference >= frf.referenceCount() || most == 0) return out;
  const auto& h = frf.h[static_cast<std::size_t>(reference)];
  const Eigen::Index nf = h.rows();
  if (nf < 3) return out;
  const Vector sum = h.cwiseAbs().rowwise().sum();
  std::vector<std::pair<double, double>> peaks;  // (height, frequency)
  for (Eigen::Index k = 1; k + 1 < nf; ++k)
    if (sum(k) > sum(k - 1) && sum(k) >= sum(k + 1)) peaks.emplace_back(sum(k), frf.frequencyHz(k));
  std::sort(peaks.begin(), peaks.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t i = 0; i < peaks.size() && i < most; ++i) out.push_back(peaks[i].second);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace mozzi::core::stiffness
