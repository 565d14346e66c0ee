#include "core/io/mat/mat_import.h"

#include <matio.h>  // types only: the functions come from matio_library.h
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "core/io/csv/csv_exchange.h"
#include "core/io/mat/matio_library.h"

namespace mozzi::core::io::mat {
namespace {

// Largest array read from a .mat file: 2^28 elements (2 GiB as double).
constexpr std::uint64_t kMaxElements = std::uint64_t{1} << 28;

// The loaded library. openMat (and matV73Supported) load it and report a
// failure; everything else runs only after one of them succeeded.
const MatioLibrary* api() {
  return *matioLibrary();
}

struct MatCloser {
  void operator()(mat_t* m) const { api()->close(m); }
};
struct VarFreer {
  void operator()(matvar_t* v) const { api()->varFree(v); }
};
using MatFile = std::unique_ptr<mat_t, MatCloser>;
using MatVar = std::unique_ptr<matvar_t, VarFreer>;

std::string className(matio_classes c) {
  switch (c) {
    case MAT_C_DOUBLE: return "double";
    case MAT_C_SINGLE: return "single";
    case MAT_C_INT8: return "int8";
    case MAT_C_UINT8: return "uint8";
    case MAT_C_INT16: return "int16";
    case MAT_C_UINT16: return "uint16";
    case MAT_C_INT32: return "int32";
    case MAT_C_UINT32: return "uint32";
    case MAT_C_INT64: return "int64";
    case MAT_C_UINT64: return "uint64";
    case MAT_C_STRUCT: return "struct";
    case MAT_C_CELL: return "cell";
    case MAT_C_CHAR: return "char";
    case MAT_C_SPARSE: return "sparse";
    case MAT_C_FUNCTION: return "function";
    case MAT_C_OBJECT: return "object";
    default: return "unknown";
  }
}

Result<MatFile> openMat(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    return makeError(ErrorCode::NotFound, "the .mat file does not exist", path);
  }
  auto lib = matioLibrary();
  if (!lib) return makeError(lib.error().code, lib.error().message, path);
  mat_t* m = (*lib)->open(path.c_str(), MAT_ACC_RDONLY);
  if (!m) return makeError(ErrorCode::ParseError, "not a MATLAB .mat file libmatio can read (v4, v5, v7, v7.3)", path);
  return MatFile(m);
}

// A numeric array of a file converted to double, column-major, with its dims.
struct Array {
  std::vector<std::size_t> dims;
  std::vector<double> re;
  std::vector<double> im;  // empty when real
  std::size_t size() const { return re.size(); }
};

template <class T>
void convert(const void* data, std::size_t n, std::vector<double>& out) {
  const T* p = static_cast<const T*>(data);
  out.resize(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<double>(p[i]);
}

Result<void> convertData(const void* data, matio_types type, std::size_t n, std::vector<double>& out,
                         const std::string& where) {
  if (n > 0 && !data) return makeError(ErrorCode::ParseError, "variable has no data", where);
  switch (type) {
    case MAT_T_DOUBLE: convert<double>(data, n, out); break;
    case MAT_T_SINGLE: convert<float>(data, n, out); break;
    case MAT_T_INT8: convert<std::int8_t>(data, n, out); break;
    case MAT_T_UINT8: convert<std::uint8_t>(data, n, out); break;
    case MAT_T_INT16: convert<std::int16_t>(data, n, out); break;
    case MAT_T_UINT16: convert<std::uint16_t>(data, n, out); break;
    case MAT_T_INT32: convert<std::int32_t>(data, n, out); break;
    case MAT_T_UINT32: convert<std::uint32_t>(data, n, out); break;
    case MAT_T_INT64: convert<std::int64_t>(data, n, out); break;
    case MAT_T_UINT64: convert<std::uint64_t>(data, n, out); break;
    default: return makeError(ErrorCode::Unsupported, "variable is not a numeric array", where);
  }
  return {};
}

bool isNumericClass(matio_classes c) {
  return c == MAT_C_DOUBLE || c == MAT_C_SINGLE || c == MAT_C_INT8 || c == MAT_C_UINT8 || c == MAT_C_INT16 ||
         c == MAT_C_UINT16 || c == MAT_C_INT32 || c == MAT_C_UINT32 || c == MAT_C_INT64 || c == MAT_C_UINT64;
}

Result<std::uint64_t> elementCount(const matvar_t* v, const std::string& where) {
  if (v->rank < 1 || v->rank > 8 || !v->dims) return makeError(ErrorCode::ParseError, "implausible array rank", where);
  std::uint64_t n = 1;
  for (int d = 0; d < v->rank; ++d) {
    const std::uint64_t k = v->dims[d];
    if (k != 0 && n > kMaxElements / k) {
      return makeError(ErrorCode::Unsupported, "array larger than 2^28 elements", where);
    }
    n *= k;
  }
  return n;
}

// Reads a numeric variable "name" or "struct.field" fully.
Result<Array> readArray(mat_t* mat, const std::string& name, const std::string& path) {
  const std::string where = path + ", variable '" + name + "'";
  if (name.empty()) return makeError(ErrorCode::InvalidArgument, "no variable name given", path);
  const std::size_t dot = name.find('.');
  const std::string top = name.substr(0, dot);
  MatVar info(api()->varReadInfo(mat, top.c_str()));
  if (!info) return makeError(ErrorCode::NotFound, "no such variable in the file", where);
  const matvar_t* target = info.get();
  if (dot != std::string::npos) {
    if (info->class_type != MAT_C_STRUCT)
      return makeError(ErrorCode::InvalidArgument, "'" + top + "' is not a struct", where);
    target = api()->varGetStructFieldByName(info.get(), name.substr(dot + 1).c_str(), 0);
    if (!target) return makeError(ErrorCode::NotFound, "no such struct field", where);
  }
  if (!isNumericClass(target->class_type)) {
    return makeError(ErrorCode::Unsupported,
                     "variable is of class " + className(target->class_type) + ", not a numeric array", where);
  }
  auto n = elementCount(target, where);
  if (!n) return n.error();
  // Sizes are plausible: read the data.
  MatVar full(api()->varRead(mat, top.c_str()));
  if (!full) return makeError(ErrorCode::ParseError, "libmatio cannot read the variable's data", where);
  const matvar_t* v = full.get();
  if (dot != std::string::npos) {
    v = api()->varGetStructFieldByName(full.get(), name.substr(dot + 1).c_str(), 0);
    if (!v) return makeError(ErrorCode::NotFound, "no such struct field", where);
  }
  auto n2 = elementCount(v, where);
  if (!n2) return n2.error();
  if (*n2 != *n) return makeError(ErrorCode::ParseError, "variable header and data disagree in size", where);
  Array a;
  for (int d = 0; d < v->rank; ++d) a.dims.push_back(v->dims[d]);
  const auto count = static_cast<std::size_t>(*n2);
  if (v->isComplex) {
    const auto* split = static_cast<const mat_complex_split_t*>(v->data);
    if (!split) return makeError(ErrorCode::ParseError, "complex variable has no data", where);
    if (auto r = convertData(split->Re, v->data_type, count, a.re, where); !r) return r.error();
    if (auto r = convertData(split->Im, v->data_type, count, a.im, where); !r) return r.error();
  } else {
    if (auto r = convertData(v->data, v->data_type, count, a.re, where); !r) return r.error();
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (!std::isfinite(a.re[i]) || (!a.im.empty() && !std::isfinite(a.im[i]))) {
      return makeError(ErrorCode::InvalidArgument, "element " + std::to_string(i + 1) + " is not finite", where);
    }
  }
  return a;
}

// Dimensions without trailing singletons (MATLAB keeps at least two).
std::vector<std::size_t> squeezeTail(std::vector<std::size_t> d) {
  while (d.size() > 2 && d.back() == 1) d.pop_back();
  return d;
}

bool isVector(const Array& a) {
  const auto d = squeezeTail(a.dims);
  return d.size() == 2 && (d[0] == 1 || d[1] == 1);
}

}  // namespace

bool matV73Supported() {
  static const bool supported = [] {
    const auto path =
        std::filesystem::temp_directory_path() / ("mozzi_matio_probe_" + std::to_string(::getpid()) + ".mat");
    auto lib = matioLibrary();
    if (!lib) return false;
    mat_t* m = (*lib)->createVer(path.string().c_str(), nullptr, MAT_FT_MAT73);
    const bool ok = m != nullptr;
    if (m) (*lib)->close(m);
    std::error_code ec;
    std::filesystem::remove(path, ec);
    return ok;
  }();
  return supported;
}

Result<std::vector<MatVariableInfo>> listVariables(const std::string& path) {
  auto mat = openMat(path);
  if (!mat) return mat.error();
  std::vector<MatVariableInfo> out;
  for (;;) {
    MatVar v(api()->varReadNextInfo(mat->get()));
    if (!v) break;
    MatVariableInfo info;
    info.name = v->name ? v->name : "";
    info.className = className(v->class_type);
    for (int d = 0; d < v->rank && v->dims && d < 8; ++d) info.dims.push_back(v->dims[d]);
    info.isComplex = v->isComplex != 0;
    out.push_back(std::move(info));
    if (out.size() > 100000) return makeError(ErrorCode::Unsupported, "more than 10^5 variables", path);
  }
  return out;
}

Result<TimeTable> importTimeRecord(const std::string& path, const TimeImportOptions& options) {
  auto mat = openMat(path);
  if (!mat) return mat.error();
  auto data = readArray(mat->get(), options.dataVariable, path);
  if (!data) return data.error();
  const std::string where = path + ", variable '" + options.dataVariable + "'";
  const auto dims = squeezeTail(data->dims);
  if (dims.size() != 2) return makeError(ErrorCode::InvalidArgument, "time data must be a 2-D array", where);
  if (!data->im.empty()) return makeError(ErrorCode::InvalidArgument, "time data must be real", where);

  // Rate: explicit value, scalar variable, or time vector.
  std::optional<double> rate = options.sampleRateHz;
  std::optional<Array> time;
  if (!rate && !options.sampleRateVariable.empty()) {
    auto fs = readArray(mat->get(), options.sampleRateVariable, path);
    if (!fs) return fs.error();
    if (fs->size() != 1) {
      return makeError(ErrorCode::InvalidArgument, "sample rate variable must be a scalar",
                       path + ", variable '" + options.sampleRateVariable + "'");
    }
    rate = fs->re[0];
  }
  if (!rate && !options.timeVariable.empty()) {
    auto t = readArray(mat->get(), options.timeVariable, path);
    if (!t) return t.error();
    if (!isVector(*t) || t->size() < 2) {
      return makeError(ErrorCode::InvalidArgument, "time variable must be a vector of at least 2 samples",
                       path + ", variable '" + options.timeVariable + "'");
    }
    time = std::move(*t);
  }
  // Orientation: rows are samples unless only the transposed reading agrees
  // with the time vector, or there are more columns than rows (fewer samples
  // than channels is never a measurement).
  std::size_t samples = dims[0], columns = dims[1];
  bool transposed = false;
  if (time) {
    if (time->size() != samples && time->size() == columns) transposed = true;
  } else if (columns > samples) {
    transposed = true;
  }
  if (transposed) std::swap(samples, columns);
  if (time) {
    if (time->size() != samples) {
      return makeError(
          ErrorCode::InvalidArgument,
          "time vector has " + std::to_string(time->size()) + " samples, the data " + std::to_string(samples), where);
    }
    const double dt = (time->re.back() - time->re.front()) / static_cast<double>(samples - 1);
    if (!(dt > 0)) return makeError(ErrorCode::InvalidArgument, "time vector does not increase", where);
    for (std::size_t k = 0; k < samples; ++k) {
      // Evenly spaced to 0.1 % of a period, as for CSV time columns.
      if (std::abs(time->re[k] - (time->re.front() + static_cast<double>(k) * dt)) > 1e-3 * dt) {
        return makeError(ErrorCode::InvalidArgument,
                         "time vector is not evenly spaced at element " + std::to_string(k + 1), where);
      }
    }
    rate = 1.0 / dt;
  }
  if (!rate) {
    return makeError(ErrorCode::InvalidArgument, "no sample rate: give a rate, a rate variable or a time variable",
                     where);
  }
  if (!(*rate > 0) || !std::isfinite(*rate))
    return makeError(ErrorCode::InvalidArgument, "sample rate must be positive", where);

  std::vector<ChannelMap> map = options.channels;
  if (map.empty()) {
    for (std::size_t c = 0; c < columns; ++c)
      map.push_back({static_cast<int>(c), "channel " + std::to_string(c + 1), {}, "1"});
  }
  TimeTable out;
  out.sampleRateHz = *rate;
  out.startTimeS = time ? time->re.front() : 0.0;
  out.samples.resize(static_cast<Eigen::Index>(samples), static_cast<Eigen::Index>(map.size()));
  for (std::size_t k = 0; k < map.size(); ++k) {
    const ChannelMap& m = map[k];
    if (m.column < 0 || static_cast<std::size_t>(m.column) >= columns) {
      return makeError(ErrorCode::InvalidArgument,
                       "channel map names column " + std::to_string(m.column) + " of " + std::to_string(columns),
                       where);
    }
    auto unit = csv::siUnit(m.unit);
    if (!unit)
      return makeError(ErrorCode::InvalidArgument, unit.error().message + " for column " + std::to_string(m.column),
                       where);
    out.channels.push_back(
        {m.name.empty() ? "channel " + std::to_string(m.column + 1) : m.name, m.dof, unit->quantity, unit->unit});
    for (std::size_t r = 0; r < samples; ++r) {
      // Column-major: element (row, col) of a rows x cols array is at row + col * rows.
      const std::size_t index = transposed ? static_cast<std::size_t>(m.column) + r * columns
                                           : r + static_cast<std::size_t>(m.column) * samples;
      out.samples(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(k)) = unit->factor * data->re[index];
    }
  }
  return out;
}

Result<FrfMatrix> importFrfMatrix(const std::string& path, const FrfImportOptions& options) {
  auto mat = openMat(path);
  if (!mat) return mat.error();
  const std::string where = path + ", variable '" + options.frfVariable + "'";
  auto h = readArray(mat->get(), options.frfVariable, path);
  if (!h) return h.error();
  auto f = readArray(mat->get(), options.frequencyVariable, path);
  if (!f) return f.error();
  if (!isVector(*f)) return makeError(ErrorCode::InvalidArgument, "frequency variable must be a vector", where);
  const std::size_t nf = f->size();
  std::vector<std::size_t> dims = squeezeTail(h->dims);
  if (dims.size() > 3) return makeError(ErrorCode::InvalidArgument, "FRF array has more than 3 dimensions", where);
  if (dims.size() == 2) dims.push_back(1);
  bool transposed = false;  // 2-D responses x lines instead of lines x responses
  if (dims[0] != nf) {
    if (dims[2] == 1 && dims[1] == nf) {
      transposed = true;
      std::swap(dims[0], dims[1]);
    } else {
      return makeError(ErrorCode::InvalidArgument,
                       "FRF array's first dimension (" + std::to_string(dims[0]) + ") is not the number of lines (" +
                           std::to_string(nf) + ")",
                       where);
    }
  }
  const std::size_t fileResponses = dims[1], fileReferences = dims[2];
  std::optional<Array> coh;
  if (!options.coherenceVariable.empty()) {
    auto c = readArray(mat->get(), options.coherenceVariable, path);
    if (!c) return c.error();
    if (c->size() != h->size() || !c->im.empty()) {
      return makeError(ErrorCode::InvalidArgument, "coherence must be real and shaped like the FRFs",
                       path + ", variable '" + options.coherenceVariable + "'");
    }
    coh = std::move(*c);
  }
  auto unit = [&]() -> Result<std::pair<FrfType, double>> {
    const std::size_t slash = options.unit.rfind('/');
    if (slash == std::string::npos) return makeError(ErrorCode::InvalidArgument, "FRF unit needs '/N'", where);
    auto force = csv::siUnit(options.unit.substr(slash + 1));
    auto response = csv::siUnit(options.unit.substr(0, slash));
    if (!force || force->quantity != "force" || !response) {
      return makeError(ErrorCode::InvalidArgument, "FRF unit '" + options.unit + "' is not a response per force",
                       where);
    }
    if (response->quantity == "displacement")
      return std::make_pair(FrfType::Receptance, response->factor / force->factor);
    if (response->quantity == "velocity") return std::make_pair(FrfType::Mobility, response->factor / force->factor);
    if (response->quantity == "acceleration")
      return std::make_pair(FrfType::Accelerance, response->factor / force->factor);
    return makeError(ErrorCode::InvalidArgument, "FRF unit '" + options.unit + "' is not a response per force", where);
  }();
  if (!unit) return unit.error();

  auto columns = [](const std::vector<int>& given, std::size_t count) {
    std::vector<int> c = given;
    if (c.empty()) {
      for (std::size_t k = 0; k < count; ++k) c.push_back(static_cast<int>(k));
    }
    return c;
  };
  const std::vector<int> responseCols = columns(options.responseColumns, options.responses.size());
  const std::vector<int> referenceCols = columns(options.referenceColumns, options.references.size());
  if (options.responses.empty() || options.references.empty()) {
    return makeError(ErrorCode::InvalidArgument, "the channel map needs response and reference DOFs", where);
  }
  if (responseCols.size() != options.responses.size() || referenceCols.size() != options.references.size()) {
    return makeError(ErrorCode::InvalidArgument, "the channel map needs one column per DOF", where);
  }
  for (int c : responseCols) {
    if (c < 0 || static_cast<std::size_t>(c) >= fileResponses) {
      return makeError(ErrorCode::InvalidArgument,
                       "response column " + std::to_string(c) + " outside the file's " + std::to_string(fileResponses),
                       where);
    }
  }
  for (int c : referenceCols) {
    if (c < 0 || static_cast<std::size_t>(c) >= fileReferences) {
      return makeError(
          ErrorCode::InvalidArgument,
          "reference column " + std::to_string(c) + " outside the file's " + std::to_string(fileReferences), where);
    }
  }
  FrfMatrix frf;
  frf.type = unit->first;
  frf.responses = options.responses;
  frf.references = options.references;
  frf.frequencyHz = Eigen::Map<const Vector>(f->re.data(), static_cast<Eigen::Index>(nf));
  const auto no = static_cast<Eigen::Index>(frf.responses.size());
  frf.h.assign(frf.references.size(), ComplexMatrix(static_cast<Eigen::Index>(nf), no));
  if (coh) frf.coherence.assign(frf.references.size(), Matrix(static_cast<Eigen::Index>(nf), no));
  for (std::size_t i = 0; i < referenceCols.size(); ++i) {
    for (Eigen::Index o = 0; o < no; ++o) {
      const auto fo = static_cast<std::size_t>(responseCols[static_cast<std::size_t>(o)]);
      const auto fi = static_cast<std::size_t>(referenceCols[i]);
      for (std::size_t k = 0; k < nf; ++k) {
        // Column-major index of (k, fo, fi) in nf x no x ni, or (fo, k) when transposed.
        const std::size_t index = transposed ? fo + k * fileResponses : k + nf * (fo + fileResponses * fi);
        const double im = h->im.empty() ? 0.0 : h->im[index];
        frf.h[i](static_cast<Eigen::Index>(k), o) = unit->second * Complex(h->re[index], im);
        if (coh) frf.coherence[i](static_cast<Eigen::Index>(k), o) = coh->re[index];
      }
    }
  }
  if (auto v = frf.validate(); !v)
    return makeError(ErrorCode::InvalidArgument, v.error().message, where + ": " + v.error().where);
  return frf;
}

}  // namespace mozzi::core::io::mat
