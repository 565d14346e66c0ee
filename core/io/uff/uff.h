#pragma once
// Universal File Format (UFF / "universal file", SDRC I-DEAS heritage): typed
// datasets, a streaming reader, a writer, and conversions to the core types.
//
// Datasets handled (field layouts as in the SDRC/Siemens universal file format
// description, cited per record in uff_reader.cpp):
//   151 header, 164 units, 15 and 2411 nodes, 18 and 2420 coordinate systems,
//   82 trace lines, 55 data at nodes (modal data), 58 function at nodal DOF
//   (ASCII) and 58b (binary, either byte order, IEEE 754).
// Every other dataset type (2400, 2412, 2414, 2467, 1858, ...) is returned as a
// SkippedDataset with its type and a warning, never an error.
//
// Values are kept in the units of the file; Units164 says how to reach SI
// (SI value = file value / factor). Text fields keep their bytes (vendors write
// Latin-1 or UTF-8); trailing blanks are trimmed.
//
// Reading is streaming: DatasetReader holds one dataset at a time plus a fixed
// read buffer (1 MiB), so memory follows the largest dataset, not the file.
// A header that claims more data than the file can hold is an error before any
// allocation (a 58 claiming 10^12 points does not reserve 8 TB).

#include <array>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/common/dof.h"
#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/result.h"

namespace mozzi::core::io::uff {

// ---------------------------------------------------------------------------
// Diagnostics

// A quirk read anyway (CR/LF, short line, missing columns, fewer points than
// declared) or a dataset skipped. `line` is 1-based in the file.
struct Warning {
  int datasetType = 0;    // dataset number, e.g. 58
  std::int64_t line = 0;  // 1-based line of the offending record
  std::string message;
  // "dataset 58, line 12: <message>"
  std::string describe() const;
};

// ---------------------------------------------------------------------------
// Dataset 151: header (seven 80-character records).
struct Header151 {
  std::string modelName;    // record 1
  std::string description;  // record 2
  std::string dbProgram;    // record 3: program which created the model
  std::string dbCreated;    // record 4: date, time, version fields as written
  std::string dbSaved;      // record 5: date and time last saved
  std::string uffProgram;   // record 6: program which wrote this file
  std::string uffWritten;   // record 7: date and time written
};

// Dataset 164: units. Unit factors convert file units to SI by division:
// SI = value / factor (e.g. length factor 1000 for millimetres).
struct Units164 {
  int unitsCode = 1;        // 1 SI, 2 BG, 3 MG, 4 BA, 5 MM, 6 CM, 7 IN, 8 GM, 9 user defined, 10 MN
  std::string description;  // e.g. "SI: Meter (newton)"
  int temperatureMode = 2;  // 1 absolute, 2 relative
  double lengthFactor = 1.0;
  double forceFactor = 1.0;
  double temperatureFactor = 1.0;
  double temperatureOffset = 273.15;
};

// Datasets 15 (single precision) and 2411 (double precision): nodes.
struct Node {
  int label = 0;
  int definitionCs = 0;    // coordinate system the coordinates are given in
  int displacementCs = 0;  // coordinate system of the node's DOF directions
  int color = 0;
  Vector3 xyz = Vector3::Zero();  // file length units
};
struct NodeSet {
  int datasetType = 2411;  // 15 or 2411 (decides the precision written)
  std::vector<Node> nodes;
};

// Datasets 18 and 2420: coordinate systems. Both are kept as origin plus axes:
// 18 stores origin, a point on +x and a point in the +xz plane; 2420 stores a
// 3x3 rotation (rows = x, y, z axis directions) plus the origin. `axes` holds
// the unit axis directions as rows either way.
struct CoordinateSystem {
  int label = 0;
  int type = 0;         // 0 cartesian, 1 cylindrical, 2 spherical
  int referenceCs = 0;  // 18: system the definition points are given in
  int color = 0;
  int definitionMethod = 1;  // 18 only (1 = origin, +x point, +xz point)
  std::string name;
  Vector3 origin = Vector3::Zero();
  Vector3 xPoint = Vector3::UnitX();   // 18: point on +x axis
  Vector3 xzPoint = Vector3::UnitZ();  // 18: point in the +xz plane
  Matrix3 axes = Matrix3::Identity();  // rows: x, y, z unit vectors
};
struct CoordinateSystemSet {
  int datasetType = 2420;  // 18 or 2420
  int partUid = 1;         // 2420 record 1
  std::string partName;    // 2420 record 2
  std::vector<CoordinateSystem> systems;
};

// Dataset 82: trace line. Node 0 means "lift the pen" (move without drawing).
struct TraceLine82 {
  int traceNumber = 1;
  int color = 0;
  std::string description;
  std::vector<int> nodes;
};

// Dataset 55: data at nodes (one mode, one frequency, ...).
enum class AnalysisType : int {
  Unknown = 0,
  Static = 1,
  NormalMode = 2,
  ComplexEigenFirstOrder = 3,
  Transient = 4,
  FrequencyResponse = 5,
  Buckling = 6,
  ComplexEigenSecondOrder = 7,
};
struct NodeValues55 {
  int node = 0;
  ComplexVector values;  // NDV values (imaginary part 0 for real data)
};
struct ModalData55 {
  std::array<std::string, 5> idLines;
  int modelType = 1;  // 0 unknown, 1 structural, 2 heat transfer, 3 fluid flow
  AnalysisType analysisType = AnalysisType::NormalMode;
  int dataCharacteristic = 2;      // 1 scalar, 2 3-DOF translation, 3 6-DOF translation+rotation, 4/5 tensor
  int specificDataType = 8;        // 8 displacement, 11 velocity, 12 acceleration, ...
  bool complexData = false;        // data type 5 (complex) vs 2 (real)
  int valuesPerNode = 3;           // NDV
  std::vector<int> integerValues;  // record 7 after NINT, NRVAL: load case, mode number, ...
  std::vector<double> realValues;  // record 8, see the accessors below
  std::vector<NodeValues55> nodes;

  // Record 7/8 meaning by analysis type (normal mode: freq [Hz], modal mass,
  // viscous damping ratio, hysteretic damping ratio; complex eigenvalue: Re, Im
  // of lambda [rad/s], modal A, modal B; frequency response: frequency [Hz]).
  int loadCase() const { return integerValues.empty() ? 0 : integerValues[0]; }
  int modeNumber() const { return integerValues.size() < 2 ? 0 : integerValues[1]; }
};

// Dataset 58 / 58b: function at a nodal DOF.
enum class FunctionType : int {
  General = 0,
  TimeResponse = 1,
  AutoSpectrum = 2,
  CrossSpectrum = 3,
  Frf = 4,
  Transmissibility = 5,
  Coherence = 6,
  AutoCorrelation = 7,
  CrossCorrelation = 8,
  Psd = 9,
  Esd = 10,
  ProbabilityDensity = 11,
  Spectrum = 12,
  CumulativeFrequency = 13,
  PeaksValley = 14,
  StressCycles = 15,
  StrainCycles = 16,
  Orbit = 17,
  ModeIndicator = 18,
  ForcePattern = 19,
  PartialPower = 20,
  PartialCoherence = 21,
  Eigenvalue = 22,
  Eigenvector = 23,
  ShockResponseSpectrum = 24,
  FirFilter = 25,
  MultipleCoherence = 26,
  OrderFunction = 27,
  PhaseCompensation = 28,
};
const char* functionTypeName(FunctionType type);  // "FRF", "time response", ...; "type N" when unknown

// Record 7 ordinate data type.
enum class OrdinateType : int { RealSingle = 2, RealDouble = 4, ComplexSingle = 5, ComplexDouble = 6 };
inline bool isComplex(OrdinateType t) {
  return t == OrdinateType::ComplexSingle || t == OrdinateType::ComplexDouble;
}
inline bool isDouble(OrdinateType t) {
  return t == OrdinateType::RealDouble || t == OrdinateType::ComplexDouble;
}

// Response or reference of a 58 record. Direction 0 means a scalar channel
// (no direction), which core::Dof cannot express: use dof() to get one.
struct Channel58 {
  std::string entityName = "NONE";
  int node = 0;
  int direction = 0;  // UFF code +/-1..6, 0 = none / scalar
  Result<Dof> dof() const { return dofFromUff(node, direction); }
  static Channel58 fromDof(const Dof& dof, std::string entity = "NONE") {
    return Channel58{std::move(entity), dof.node, dof.uffCode()};
  }
};

// Records 8-11: axis data characteristics.
struct AxisInfo {
  int specificDataType = 0;  // 0 unknown, 1 general, 8 displacement, 11 velocity, 12 acceleration,
                             // 13 excitation force, 15 pressure, 17 time, 18 frequency, ...
  int lengthExponent = 0;
  int forceExponent = 0;
  int temperatureExponent = 0;
  std::string label = "NONE";
  std::string unitsLabel = "NONE";
};

enum class ByteOrder { LittleEndian = 1, BigEndian = 2 };

struct Function58 {
  std::array<std::string, 5> idLines;  // records 1-5 (record 3 is usually date/time)
  FunctionType functionType = FunctionType::General;
  int functionId = 0;
  int versionNumber = 0;
  int loadCase = 0;
  Channel58 response;
  Channel58 reference;
  OrdinateType ordinateType = OrdinateType::RealDouble;
  bool evenSpacing = true;
  double abscissaMin = 0.0;
  double abscissaIncrement = 0.0;  // ignored when uneven
  double zAxisValue = 0.0;
  AxisInfo abscissaAxis;         // record 8
  AxisInfo ordinateNumerator;    // record 9
  AxisInfo ordinateDenominator;  // record 10
  AxisInfo zAxis;                // record 11
  // Data. Real ordinates in `real`, complex in `complex` (the other empty).
  // `abscissa` is filled only for uneven spacing; use abscissaValues().
  Vector abscissa;
  Vector real;
  ComplexVector complex;
  // How it was stored in the file it came from (the writer may override).
  bool binary = false;
  ByteOrder byteOrder = ByteOrder::LittleEndian;

  // With ReadOptions::skip58Data the data are not read: the vectors stay
  // empty and declaredPoints holds record 7's point count.
  std::int64_t declaredPoints = -1;
  // Ordinates written to the reader's ordinate sink (ReadOptions) instead of
  // `real` / `complex`, which then stay empty; 0 otherwise.
  std::uint64_t sinkPoints = 0;

  Eigen::Index pointCount() const {
    if (declaredPoints >= 0) return static_cast<Eigen::Index>(declaredPoints);
    const Eigen::Index held = isComplex(ordinateType) ? complex.size() : real.size();
    return held > 0 ? held : static_cast<Eigen::Index>(sinkPoints);
  }
  // x_k = abscissaMin + k * abscissaIncrement when even, else the stored abscissa.
  Vector abscissaValues() const;
};

// A dataset Mozzi does not interpret: listed, skipped, warned about.
struct SkippedDataset {
  std::int64_t lineCount = 0;  // lines between the number and the closing -1
};

using DatasetData = std::variant<Header151, Units164, NodeSet, CoordinateSystemSet, TraceLine82, ModalData55,
                                 Function58, SkippedDataset>;

struct Dataset {
  int type = 0;           // dataset number as written (58 also for 58b)
  std::int64_t line = 0;  // 1-based line of the dataset number
  DatasetData data;

  template <class T>
  const T* get() const {
    return std::get_if<T>(&data);
  }
  template <class T>
  T* get() {
    return std::get_if<T>(&data);
  }
};

struct UffFile {
  std::vector<Dataset> datasets;  // file order
  std::vector<Warning> warnings;

  // All datasets of one kind, in file order (pointers into `datasets`).
  template <class T>
  std::vector<const T*> all() const {
    std::vector<const T*> out;
    for (const auto& d : datasets)
      if (const T* p = d.get<T>()) out.push_back(p);
    return out;
  }
};

// ---------------------------------------------------------------------------
// Reading

struct ReadOptions {
  // Refuse a single dataset whose data would need more than this many bytes in
  // memory (protects against absurd headers and hostile files).
  std::uint64_t maxDatasetBytes = std::uint64_t{8} << 30;  // 8 GiB
  // Read only the headers of 58 records (records 1-11) and skip their data
  // without holding it: for a summary of a file of any size (e.g. a replay
  // recording's channels). Function58::declaredPoints then gives the length.
  bool skip58Data = false;
  // Where the ordinates of a 58 record go, so that a caller streaming a file
  // reads them straight into its own arrays (no copy, no allocation per
  // record). Called once records 1-11 are parsed, before any value is read,
  // with the record so far and its point count: return room for `points`
  // ordinates as doubles (Re, Im interleaved for complex ordinates, i.e. the
  // layout of std::complex<double>), or nullptr to let the record hold them.
  // Written ordinates are not kept in the record (Function58::sinkPoints).
  // A record cut short (fewer points than declared) leaves the rest unwritten.
  std::function<double*(const Function58& header, std::uint64_t points)> ordinateSink;
};

// Streaming reader: one dataset per next() call. Only the current dataset and a
// fixed buffer are held in memory.
class DatasetReader {
 public:
  static Result<DatasetReader> open(const std::string& path, ReadOptions options = {});
  // Reads from memory (tests, fuzzing, data already loaded). Copies `bytes`.
  static DatasetReader fromBytes(std::string_view bytes, ReadOptions options = {});

  DatasetReader(DatasetReader&&) noexcept;
  DatasetReader& operator=(DatasetReader&&) noexcept;
  ~DatasetReader();

  // The next dataset, std::nullopt at the end of the file, or an Error naming
  // the dataset number and line. After an error the reader is at its end.
  Result<std::optional<Dataset>> next();

  // Warnings so far (accumulated over all next() calls).
  const std::vector<Warning>& warnings() const;
  // Bytes consumed so far (progress reporting).
  std::uint64_t bytesRead() const;

 private:
  struct Impl;
  explicit DatasetReader(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// Whole file (built on DatasetReader).
Result<UffFile> readFile(const std::string& path, ReadOptions options = {});
Result<UffFile> readBytes(std::string_view bytes, ReadOptions options = {});

// ---------------------------------------------------------------------------
// Writing

enum class Encoding58 {
  AsStored,  // each Function58 as its `binary` flag says
  Ascii,     // every 58 as ASCII
  Binary,    // every 58 as 58b
};

struct WriteOptions {
  Encoding58 encoding = Encoding58::AsStored;
  std::optional<ByteOrder> byteOrder;  // 58b byte order; default: each record's own
};

// Writes the dataset with its -1 delimiters. ASCII precision follows the
// format: E13.5 for single, E20.12/D25.16/D25.17 for double precision fields.
// A dataset that cannot be written (SkippedDataset, inconsistent sizes, NaN in
// a field the format cannot hold) is an error naming the dataset.
// writeFile and writeBytes leave SkippedDataset entries out (their content
// is not kept when reading) and write everything else in order.
Result<void> writeDataset(std::ostream& out, const Dataset& dataset, const WriteOptions& options = {});
Result<void> writeFile(const std::string& path, const UffFile& file, const WriteOptions& options = {});
Result<std::string> writeBytes(const UffFile& file, const WriteOptions& options = {});

// Convenience: wrap a typed record as a Dataset with its number.
Dataset makeDataset(DatasetData data);

// ---------------------------------------------------------------------------
// Conversions

struct FrfConversionOptions {
  // Used when record 9 does not say displacement (8), velocity (11) or
  // acceleration (12).
  FrfType typeWhenUnknown = FrfType::Accelerance;
};

// FRF (function type 4) records -> FrfMatrix. Responses and references are
// the distinct DOFs in order of first appearance; every (response, reference)
// pair must be present once, on one common frequency axis (abscissa in Hz).
// Coherence records (type 6) with the same DOFs and axis are attached when
// every pair has one. Other function types are ignored.
Result<FrfMatrix> toFrfMatrix(const std::vector<Function58>& functions, const FrfConversionOptions& options = {});
Result<FrfMatrix> toFrfMatrix(const UffFile& file, const FrfConversionOptions& options = {});
// The same from a file, streamed: complex FRF records are read straight into
// the FRF matrix (one reference: no copy at all), other datasets are dropped
// as they are read, so memory is the FRF matrix, not the file (issue 19).
Result<FrfMatrix> readFrfMatrix(const std::string& path, const FrfConversionOptions& options = {});

// FrfMatrix -> one FRF record (complex double) per pair, response-major
// within each reference, then one coherence record (real double) per pair when
// coherence is present. Even abscissa when the frequency lines are uniform.
Result<std::vector<Function58>> fromFrfMatrix(const FrfMatrix& frf);

// Plain modal data: one column per mode, one row per DOF.
struct ModalData {
  std::vector<Dof> dofs;       // rows of `shapes`
  Vector frequencyHz;          // undamped natural frequency per mode [Hz]
  Vector dampingRatio;         // viscous zeta per mode
  Vector modalMass;            // per mode (0 when unknown)
  ComplexMatrix shapes;        // dofs x modes
  bool complexShapes = false;  // false: imaginary parts are zero
};

// Dataset 55 records (normal-mode or complex-eigenvalue analyses, 3- or
// 6-DOF data) -> ModalData. Complex eigenvalue lambda = sigma + i omega_d:
// f = |lambda| / (2 pi), zeta = -sigma / |lambda|. DOFs follow the first
// record's node order (X, Y, Z[, RX, RY, RZ] per node); every record must have
// the same nodes.
Result<ModalData> toModalData(const std::vector<ModalData55>& records);
Result<ModalData> toModalData(const UffFile& file);

// ModalData -> one 55 record per mode (normal mode with real shapes, complex
// eigenvalue second order with complex shapes). DOFs with directions other
// than +X..+RZ per node are an error (55 stores node vectors in global axes).
Result<std::vector<ModalData55>> fromModalData(const ModalData& modal);

}  // namespace mozzi::core::io::uff
