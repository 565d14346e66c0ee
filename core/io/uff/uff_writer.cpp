// UFF writer: the record layouts listed in uff_reader.cpp, written with the
// format's own widths (E13.5 single, E20.12 / D25.16 / D25.17 double; 'E' is
// written where the description says 'D', which every reader accepts).

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/io/output_file.h"
#include "core/io/uff/uff.h"

namespace mozzi::core::io::uff {
namespace {

bool hostLittle() {
  const std::uint16_t probe = 1;
  unsigned char first = 0;
  std::memcpy(&first, &probe, 1);
  return first == 1;
}

// Appends printf-formatted text.
template <class... A>
void put(std::string& s, const char* fmt, A... args) {
  char buf[256];
  const int n = std::snprintf(buf, sizeof(buf), fmt, args...);
  if (n > 0) s.append(buf, static_cast<std::size_t>(std::min<int>(n, static_cast<int>(sizeof(buf)) - 1)));
}

// A text record: at most `width` bytes, no line breaks.
std::string textRecord(const std::string& s, std::size_t width = 80) {
  std::string out = s.substr(0, width);
  for (char& c : out)
    if (c == '\n' || c == '\r') c = ' ';
  return out;
}

// Fixed-width text field: exactly `width` bytes, left-aligned, blank-padded.
std::string padded(const std::string& s, std::size_t width) {
  std::string out = textRecord(s, width);
  out.resize(width, ' ');
  return out;
}

Error writeError(int type, const std::string& what) {
  return makeError(ErrorCode::InvalidArgument, "cannot write dataset " + std::to_string(type) + ": " + what,
                   "dataset " + std::to_string(type));
}

bool allFinite(const double* p, Eigen::Index n) {
  for (Eigen::Index i = 0; i < n; ++i)
    if (!std::isfinite(p[i])) return false;
  return true;
}

void open(std::string& s, const char* number) {
  s += "    -1\n";
  s += number;
  s += '\n';
}
void close(std::string& s) {
  s += "    -1\n";
}

Result<void> write151(std::string& s, const Header151& h) {
  open(s, "   151");
  for (const std::string* r :
       {&h.modelName, &h.description, &h.dbProgram, &h.dbCreated, &h.dbSaved, &h.uffProgram, &h.uffWritten}) {
    s += textRecord(r->empty() ? std::string("NONE") : *r);
    s += '\n';
  }
  close(s);
  return {};
}

Result<void> write164(std::string& s, const Units164& u) {
  for (double v : {u.lengthFactor, u.forceFactor, u.temperatureFactor, u.temperatureOffset}) {
    if (!std::isfinite(v)) return writeError(164, "a unit factor is not finite");
  }
  if (u.lengthFactor == 0 || u.forceFactor == 0 || u.temperatureFactor == 0) {
    return writeError(164, "a unit factor is zero");
  }
  open(s, "   164");
  put(s, "%10d%s%10d\n", u.unitsCode, padded(u.description, 20).c_str(), u.temperatureMode);
  // (3D25.17) (1D25.17): 18 significant digits, exact for doubles.
  put(s, "%25.17E%25.17E%25.17E\n", u.lengthFactor, u.forceFactor, u.temperatureFactor);
  put(s, "%25.17E\n", u.temperatureOffset);
  close(s);
  return {};
}

Result<void> writeNodes(std::string& s, const NodeSet& n) {
  if (n.datasetType != 15 && n.datasetType != 2411) return writeError(n.datasetType, "node sets are 15 or 2411");
  for (const auto& node : n.nodes)
    if (!node.xyz.allFinite())
      return writeError(n.datasetType, "node " + std::to_string(node.label) + " has a non-finite coordinate");
  if (n.datasetType == 15) {
    open(s, "    15");
    for (const auto& node : n.nodes) {
      put(s, "%10d%10d%10d%10d%13.5E%13.5E%13.5E\n", node.label, node.definitionCs, node.displacementCs, node.color,
          node.xyz.x(), node.xyz.y(), node.xyz.z());
    }
  } else {
    open(s, "  2411");
    for (const auto& node : n.nodes) {
      put(s, "%10d%10d%10d%10d\n", node.label, node.definitionCs, node.displacementCs, node.color);
      // (1P3D25.16): 17 significant digits, exact for doubles.
      put(s, "%25.16E%25.16E%25.16E\n", node.xyz.x(), node.xyz.y(), node.xyz.z());
    }
  }
  close(s);
  return {};
}

Result<void> writeSystems(std::string& s, const CoordinateSystemSet& c) {
  for (const auto& cs : c.systems) {
    if (!cs.origin.allFinite() || !cs.axes.allFinite() || !cs.xPoint.allFinite() || !cs.xzPoint.allFinite()) {
      return writeError(c.datasetType, "coordinate system " + std::to_string(cs.label) + " has a non-finite value");
    }
  }
  if (c.datasetType == 18) {
    open(s, "    18");
    for (const auto& cs : c.systems) {
      put(s, "%10d%10d%10d%10d%10d\n", cs.label, cs.type, cs.referenceCs, cs.color, cs.definitionMethod);
      s += textRecord(cs.name.empty() ? std::string("NONE") : cs.name, 40) + "\n";
      put(s, "%13.5E%13.5E%13.5E%13.5E%13.5E%13.5E\n", cs.origin.x(), cs.origin.y(), cs.origin.z(), cs.xPoint.x(),
          cs.xPoint.y(), cs.xPoint.z());
      put(s, "%13.5E%13.5E%13.5E\n", cs.xzPoint.x(), cs.xzPoint.y(), cs.xzPoint.z());
    }
  } else if (c.datasetType == 2420) {
    open(s, "  2420");
    put(s, "%10d\n", c.partUid);
    s += textRecord(c.partName.empty() ? std::string("NONE") : c.partName) + "\n";
    for (const auto& cs : c.systems) {
      put(s, "%10d%10d%10d\n", cs.label, cs.type, cs.color);
      s += textRecord(cs.name.empty() ? std::string("NONE") : cs.name) + "\n";
      for (int i = 0; i < 3; ++i) put(s, "%25.16E%25.16E%25.16E\n", cs.axes(i, 0), cs.axes(i, 1), cs.axes(i, 2));
      put(s, "%25.16E%25.16E%25.16E\n", cs.origin.x(), cs.origin.y(), cs.origin.z());
    }
  } else {
    return writeError(c.datasetType, "coordinate system sets are 18 or 2420");
  }
  close(s);
  return {};
}

Result<void> write82(std::string& s, const TraceLine82& t) {
  open(s, "    82");
  put(s, "%10d%10d%10d\n", t.traceNumber, static_cast<int>(t.nodes.size()), t.color);
  s += textRecord(t.description.empty() ? std::string("NONE") : t.description) + "\n";
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    put(s, "%10d", t.nodes[i]);
    if (i % 8 == 7 || i + 1 == t.nodes.size()) s += '\n';
  }
  close(s);
  return {};
}

Result<void> write55(std::string& s, const ModalData55& m) {
  for (const auto& nv : m.nodes) {
    if (nv.values.size() != m.valuesPerNode) {
      return writeError(55, "node " + std::to_string(nv.node) + " has " + std::to_string(nv.values.size()) +
                                " values, valuesPerNode is " + std::to_string(m.valuesPerNode));
    }
    if (!allFinite(reinterpret_cast<const double*>(nv.values.data()), 2 * nv.values.size())) {
      return writeError(55, "node " + std::to_string(nv.node) + " has a non-finite value");
    }
  }
  for (double v : m.realValues)
    if (!std::isfinite(v)) return writeError(55, "a record 8 value is not finite");
  open(s, "    55");
  for (const auto& id : m.idLines) s += textRecord(id.empty() ? std::string("NONE") : id) + "\n";
  put(s, "%10d%10d%10d%10d%10d%10d\n", m.modelType, static_cast<int>(m.analysisType), m.dataCharacteristic,
      m.specificDataType, m.complexData ? 5 : 2, m.valuesPerNode);
  std::vector<int> r7 = {static_cast<int>(m.integerValues.size()), static_cast<int>(m.realValues.size())};
  r7.insert(r7.end(), m.integerValues.begin(), m.integerValues.end());
  for (std::size_t i = 0; i < r7.size(); ++i) {
    put(s, "%10d", r7[i]);
    if (i % 8 == 7 || i + 1 == r7.size()) s += '\n';
  }
  for (std::size_t i = 0; i < m.realValues.size(); ++i) {
    put(s, "%13.5E", m.realValues[i]);
    if (i % 6 == 5 || i + 1 == m.realValues.size()) s += '\n';
  }
  for (const auto& nv : m.nodes) {
    put(s, "%10d\n", nv.node);
    std::vector<double> v;
    for (Eigen::Index i = 0; i < nv.values.size(); ++i) {
      v.push_back(nv.values[i].real());
      if (m.complexData) v.push_back(nv.values[i].imag());
    }
    for (std::size_t i = 0; i < v.size(); ++i) {
      put(s, "%13.5E", v[i]);
      if (i % 6 == 5 || i + 1 == v.size()) s += '\n';
    }
  }
  close(s);
  return {};
}

void axisRecord(std::string& s, const AxisInfo& a) {
  put(s, "%10d%5d%5d%5d %s %s\n", a.specificDataType, a.lengthExponent, a.forceExponent, a.temperatureExponent,
      padded(a.label.empty() ? "NONE" : a.label, 20).c_str(),
      padded(a.unitsLabel.empty() ? "NONE" : a.unitsLabel, 20).c_str());
}

Result<void> write58(std::string& s, std::ostream& out, const Function58& f, const WriteOptions& options) {
  const bool cplx = isComplex(f.ordinateType);
  const int ord = static_cast<int>(f.ordinateType);
  if (ord != 2 && ord != 4 && ord != 5 && ord != 6)
    return writeError(58, "ordinate type " + std::to_string(ord) + " is not 2, 4, 5 or 6");
  const Eigen::Index n = cplx ? f.complex.size() : f.real.size();
  if ((cplx && f.real.size() != 0) || (!cplx && f.complex.size() != 0)) {
    return writeError(
        58, std::string("ordinate type says ") + (cplx ? "complex" : "real") + " but the other data vector is filled");
  }
  if (!f.evenSpacing && f.abscissa.size() != n) {
    return writeError(58, "uneven abscissa has " + std::to_string(f.abscissa.size()) + " values for " +
                              std::to_string(n) + " points");
  }
  const double* y = cplx ? reinterpret_cast<const double*>(f.complex.data()) : f.real.data();
  const Eigen::Index ny = cplx ? 2 * n : n;
  if (!allFinite(y, ny) || (!f.evenSpacing && !f.abscissa.allFinite())) {
    return writeError(58, "the data hold NaN or infinity (response " + std::to_string(f.response.node) + ")");
  }
  if (!std::isfinite(f.abscissaMin) || !std::isfinite(f.abscissaIncrement) || !std::isfinite(f.zAxisValue)) {
    return writeError(58, "abscissa minimum, increment or z value is not finite");
  }
  const bool binary = options.encoding == Encoding58::Binary || (options.encoding == Encoding58::AsStored && f.binary);
  const ByteOrder order = options.byteOrder.value_or(f.byteOrder);
  const bool dbl = isDouble(f.ordinateType);
  const std::size_t valueBytes = dbl ? 8 : 4;
  const std::size_t perPoint = (cplx ? 2 : 1) + (f.evenSpacing ? 0 : 1);
  const std::uint64_t byteCount = static_cast<std::uint64_t>(n) * perPoint * valueBytes;

  s += "    -1\n";
  if (binary) {
    put(s, "%6d%c%6d%6d%12d%12llu%6d%6d%12d%12d\n", 58, 'b', static_cast<int>(order), 2, 11,
        static_cast<unsigned long long>(byteCount), 0, 0, 0, 0);
  } else {
    s += "    58\n";
  }
  for (const auto& id : f.idLines) s += textRecord(id.empty() ? std::string("NONE") : id) + "\n";
  put(s, "%5d%10d%5d%10d %s%10d%4d %s%10d%4d\n", static_cast<int>(f.functionType), f.functionId, f.versionNumber,
      f.loadCase, padded(f.response.entityName.empty() ? "NONE" : f.response.entityName, 10).c_str(), f.response.node,
      f.response.direction, padded(f.reference.entityName.empty() ? "NONE" : f.reference.entityName, 10).c_str(),
      f.reference.node, f.reference.direction);
  put(s, "%10d%10lld%10d%13.5E%13.5E%13.5E\n", ord, static_cast<long long>(n), f.evenSpacing ? 1 : 0, f.abscissaMin,
      f.evenSpacing ? f.abscissaIncrement : 0.0, f.zAxisValue);
  axisRecord(s, f.abscissaAxis);
  axisRecord(s, f.ordinateNumerator);
  axisRecord(s, f.ordinateDenominator);
  axisRecord(s, f.zAxis);

  const double* x = f.evenSpacing ? nullptr : f.abscissa.data();
  const std::size_t ordPerPoint = cplx ? 2 : 1;
  if (binary) {
    out.write(s.data(), static_cast<std::streamsize>(s.size()));
    s.clear();
    const bool swap = (order == ByteOrder::LittleEndian) != hostLittle();
    constexpr std::size_t kChunkPoints = 1 << 14;
    std::vector<unsigned char> chunk(kChunkPoints * perPoint * valueBytes);
    for (Eigen::Index p0 = 0; p0 < n; p0 += static_cast<Eigen::Index>(kChunkPoints)) {
      const Eigen::Index p1 = std::min<Eigen::Index>(n, p0 + static_cast<Eigen::Index>(kChunkPoints));
      unsigned char* w = chunk.data();
      auto emit = [&](double v) {
        unsigned char b[8];
        if (dbl) {
          std::memcpy(b, &v, 8);
        } else {
          const float fv = static_cast<float>(v);
          std::memcpy(b, &fv, 4);
        }
        for (std::size_t i = 0; i < valueBytes; ++i) w[i] = swap ? b[valueBytes - 1 - i] : b[i];
        w += valueBytes;
      };
      for (Eigen::Index p = p0; p < p1; ++p) {
        if (x) emit(x[p]);
        for (std::size_t c = 0; c < ordPerPoint; ++c) emit(y[static_cast<std::size_t>(p) * ordPerPoint + c]);
      }
      out.write(reinterpret_cast<const char*>(chunk.data()), w - chunk.data());
    }
    s += "\n    -1\n";
    return {};
  }
  // ASCII data layouts of record 12.
  Eigen::Index perLine = 0;
  const char* fmt = nullptr;
  if (!dbl) {
    perLine = cplx ? (x ? 2 : 3) : (x ? 3 : 6);
    fmt = "%13.5E";
  } else {
    perLine = cplx ? (x ? 1 : 2) : (x ? 2 : 4);
    fmt = "%20.12E";
  }
  for (Eigen::Index p = 0; p < n; ++p) {
    if (x) put(s, "%13.5E", x[p]);
    for (std::size_t c = 0; c < ordPerPoint; ++c) put(s, fmt, y[static_cast<std::size_t>(p) * ordPerPoint + c]);
    if ((p + 1) % perLine == 0 || p + 1 == n) s += '\n';
    if (s.size() > (1u << 20)) {
      out.write(s.data(), static_cast<std::streamsize>(s.size()));
      s.clear();
    }
  }
  close(s);
  return {};
}

}  // namespace

Dataset makeDataset(DatasetData data) {
  Dataset d;
  d.data = std::move(data);
  d.type = std::visit(
      [](const auto& v) -> int {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, Header151>) return 151;
        if constexpr (std::is_same_v<T, Units164>) return 164;
        if constexpr (std::is_same_v<T, NodeSet>) return v.datasetType;
        if constexpr (std::is_same_v<T, CoordinateSystemSet>) return v.datasetType;
        if constexpr (std::is_same_v<T, TraceLine82>) return 82;
        if constexpr (std::is_same_v<T, ModalData55>) return 55;
        if constexpr (std::is_same_v<T, Function58>) return 58;
        return 0;
      },
      d.data);
  return d;
}

Result<void> writeDataset(std::ostream& out, const Dataset& dataset, const WriteOptions& options) {
  std::string s;
  Result<void> r = std::visit(
      [&](const auto& v) -> Result<void> {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, Header151>) return write151(s, v);
        if constexpr (std::is_same_v<T, Units164>) return write164(s, v);
        if constexpr (std::is_same_v<T, NodeSet>) return writeNodes(s, v);
        if constexpr (std::is_same_v<T, CoordinateSystemSet>) return writeSystems(s, v);
        if constexpr (std::is_same_v<T, TraceLine82>) return write82(s, v);
        if constexpr (std::is_same_v<T, ModalData55>) return write55(s, v);
        if constexpr (std::is_same_v<T, Function58>) return write58(s, out, v, options);
        return makeError(ErrorCode::Unsupported,
                         "dataset " + std::to_string(dataset.type) + " was skipped when read; its content is not kept",
                         "dataset " + std::to_string(dataset.type) + " at line " + std::to_string(dataset.line));
      },
      dataset.data);
  if (!r) return r;
  out.write(s.data(), static_cast<std::streamsize>(s.size()));
  if (!out) return makeError(ErrorCode::IoError, "write failed", "dataset " + std::to_string(dataset.type));
  return {};
}

Result<std::string> writeBytes(const UffFile& file, const WriteOptions& options) {
  std::ostringstream out(std::ios::binary);
  for (const auto& d : file.datasets) {
    if (d.get<SkippedDataset>()) continue;
    MOZZI_TRY(writeDataset(out, d, options));
  }
  return out.str();
}

Result<void> writeFile(const std::string& path, const UffFile& file, const WriteOptions& options) {
  // Through the output helper: a temporary file renamed into place after a
  // checked flush, fsync and close (core/io/output_file.h).
  return writeOutputFile(path, [&](std::ostream& out) -> Result<void> {
    for (const auto& d : file.datasets) {
      if (d.get<SkippedDataset>()) continue;  // content not kept; the reader warned
      MOZZI_TRY(writeDataset(out, d, options));
    }
    return {};
  });
}

}  // namespace mozzi::core::io::uff
