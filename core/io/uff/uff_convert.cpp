// Conversions between UFF records and the core types: dataset 58 <-> FrfMatrix,
// dataset 55 <-> ModalData.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>

#include "core/common/enum_names.h"
#include "core/io/uff/uff.h"

namespace mozzi::core::io::uff {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

std::string pairName(const Dof& o, const Dof& i) {
  return "response " + formatDof(o) + ", reference " + formatDof(i);
}

// Record 9 specific data type of the numerator <-> FRF type (displacement 8,
// velocity 11, acceleration 12 over force), and the numerator's units.
constexpr auto kNumeratorCodes =
    enumTable<FrfType>({{FrfType::Receptance, 8}, {FrfType::Mobility, 11}, {FrfType::Accelerance, 12}}, 0);
constexpr auto kNumeratorUnits = enumTable<FrfType>(
    {{FrfType::Receptance, "m"}, {FrfType::Mobility, "m/s"}, {FrfType::Accelerance, "m/s^2"}}, "NONE");

std::optional<FrfType> frfTypeOf(const Function58& f) {
  return kNumeratorCodes.find(f.ordinateNumerator.specificDataType);
}

// Same abscissa: relative agreement to 1e-9 of the axis span (ASCII records
// of one file share printed values, so they agree exactly in practice).
bool sameAxis(const Vector& a, const Vector& b) {
  if (a.size() != b.size()) return false;
  if (a.size() == 0) return true;
  const double span = std::max(std::abs(a[a.size() - 1]), std::abs(a[0])) + 1e-300;
  return ((a - b).cwiseAbs().maxCoeff()) <= 1e-9 * span;
}

}  // namespace

namespace {

// FRF and coherence records -> FrfMatrix (toFrfMatrix's rules). The
// ordinates of a complex FRF record are pool->col(column(f)) when column(f)
// >= 0 (read there by readFrfMatrix), else the record's own. One reference
// with the pool's columns in response order: the pool becomes h[0], no copy.
Result<FrfMatrix> assemble(const std::vector<const Function58*>& frfs, const std::vector<const Function58*>& cohs,
                           const FrfConversionOptions& options, ComplexMatrix* pool,
                           const std::function<Eigen::Index(const Function58*)>& column) {
  FrfMatrix m;
  if (frfs.empty()) {
    return makeError(ErrorCode::NotFound, "no FRF record (dataset 58 with function type 4) in the input", "dataset 58");
  }
  std::map<std::pair<Dof, Dof>, const Function58*> byPair;
  std::optional<FrfType> type;
  for (const Function58* f : frfs) {
    auto o = f->response.dof();
    auto i = f->reference.dof();
    if (!o || !i) {
      return makeError(ErrorCode::InvalidArgument,
                       "FRF record with response " + std::to_string(f->response.node) + "/" +
                           std::to_string(f->response.direction) + " and reference " +
                           std::to_string(f->reference.node) + "/" + std::to_string(f->reference.direction) +
                           " has no valid DOF: " + (!o ? o.error().message : i.error().message),
                       "dataset 58");
    }
    if (!byPair.emplace(std::make_pair(*o, *i), f).second) {
      return makeError(ErrorCode::InvalidArgument, "two FRF records for " + pairName(*o, *i), "dataset 58");
    }
    if (std::find(m.responses.begin(), m.responses.end(), *o) == m.responses.end()) m.responses.push_back(*o);
    if (std::find(m.references.begin(), m.references.end(), *i) == m.references.end()) m.references.push_back(*i);
    const FrfType t = frfTypeOf(*f).value_or(options.typeWhenUnknown);
    if (type && *type != t) {
      return makeError(ErrorCode::InvalidArgument,
                       std::string("FRF records mix ") + frfTypeName(*type) + " and " + frfTypeName(t) + " (" +
                           pairName(*o, *i) + ")",
                       "dataset 58");
    }
    type = t;
  }
  m.type = *type;
  m.frequencyHz = frfs.front()->abscissaValues();
  const Eigen::Index nf = m.frequencyHz.size();
  std::vector<const Function58*> ordered;  // reference-major, response order
  for (std::size_t ii = 0; ii < m.references.size(); ++ii) {
    for (Eigen::Index oo = 0; oo < m.responseCount(); ++oo) {
      const Dof& o = m.responses[static_cast<std::size_t>(oo)];
      const Dof& i = m.references[ii];
      auto it = byPair.find({o, i});
      if (it == byPair.end()) {
        return makeError(ErrorCode::NotFound, "no FRF record for " + pairName(o, i) + " (the matrix needs every pair)",
                         "dataset 58");
      }
      const Function58& f = *it->second;
      if (!sameAxis(f.abscissaValues(), m.frequencyHz)) {
        return makeError(ErrorCode::InvalidArgument,
                         "FRF record for " + pairName(o, i) + " has another frequency axis (" +
                             std::to_string(f.pointCount()) + " lines) than the first record (" + std::to_string(nf) +
                             " lines)",
                         "dataset 58");
      }
      ordered.push_back(&f);
    }
  }
  bool inPlace = pool && m.references.size() == 1 && pool->rows() == nf;
  for (std::size_t q = 0; inPlace && q < ordered.size(); ++q)
    inPlace = column(ordered[q]) == static_cast<Eigen::Index>(q);
  if (inPlace) {
    pool->conservativeResize(nf, m.responseCount());  // shrinks in place
    m.h.push_back(std::move(*pool));
  } else {
    m.h.assign(m.references.size(), ComplexMatrix(nf, m.responseCount()));
    for (std::size_t q = 0; q < ordered.size(); ++q) {
      const Function58& f = *ordered[q];
      auto dst = m.h[q / static_cast<std::size_t>(m.responseCount())].col(
          static_cast<Eigen::Index>(q % static_cast<std::size_t>(m.responseCount())));
      const Eigen::Index c = pool ? column(&f) : -1;
      if (c >= 0) {
        dst = pool->col(c);
      } else if (isComplex(f.ordinateType)) {
        dst = f.complex;
      } else {
        dst = f.real.cast<Complex>();
      }
    }
  }
  // Coherence: attached only when every pair has one on the same axis.
  std::map<std::pair<Dof, Dof>, const Function58*> cohByPair;
  for (const Function58* c : cohs) {
    auto o = c->response.dof();
    auto i = c->reference.dof();
    if (o && i) cohByPair.emplace(std::make_pair(*o, *i), c);
  }
  bool complete = !cohByPair.empty();
  std::vector<Matrix> coherence;
  if (complete) coherence.assign(m.references.size(), Matrix::Zero(nf, m.responseCount()));
  for (std::size_t ii = 0; complete && ii < m.references.size(); ++ii) {
    for (Eigen::Index oo = 0; complete && oo < m.responseCount(); ++oo) {
      auto it = cohByPair.find({m.responses[static_cast<std::size_t>(oo)], m.references[ii]});
      if (it == cohByPair.end() || !sameAxis(it->second->abscissaValues(), m.frequencyHz)) {
        complete = false;
        break;
      }
      const Function58& c = *it->second;
      coherence[ii].col(oo) = isComplex(c.ordinateType) ? Vector(c.complex.real()) : c.real;
    }
  }
  if (complete) m.coherence = std::move(coherence);
  MOZZI_TRY(m.validate());
  return m;
}

Result<FrfMatrix> assembleRecords(const std::vector<const Function58*>& functions,
                                  const FrfConversionOptions& options) {
  std::vector<const Function58*> frfs, cohs;
  for (const Function58* f : functions) {
    if (f->functionType == FunctionType::Frf) frfs.push_back(f);
    if (f->functionType == FunctionType::Coherence) cohs.push_back(f);
  }
  return assemble(frfs, cohs, options, nullptr, {});
}

}  // namespace

Result<FrfMatrix> toFrfMatrix(const std::vector<Function58>& functions, const FrfConversionOptions& options) {
  std::vector<const Function58*> ptrs;
  for (const auto& f : functions) ptrs.push_back(&f);
  return assembleRecords(ptrs, options);
}

Result<FrfMatrix> toFrfMatrix(const UffFile& file, const FrfConversionOptions& options) {
  return assembleRecords(file.all<Function58>(), options);
}

Result<FrfMatrix> readFrfMatrix(const std::string& path, const FrfConversionOptions& options) {
  // Complex FRF records are read into the columns of one pool, sized from
  // the file (no FRF record takes fewer than 4 bytes a point in either
  // encoding), so that untouched capacity is address space, not memory.
  std::error_code ec;
  const std::uint64_t fileBytes = std::filesystem::file_size(path, ec);
  ComplexMatrix pool;
  std::vector<Function58> records;  // FRF headers (ordinates in the pool) and coherence records
  std::vector<Eigen::Index> columns;
  Eigen::Index used = 0, lastColumn = -1;  // pool column of the record the sink saw last
  ReadOptions ro;
  ro.ordinateSink = [&](const Function58& f, std::uint64_t points) -> double* {
    lastColumn = -1;
    if (f.functionType != FunctionType::Frf || !isComplex(f.ordinateType)) return nullptr;
    const Eigen::Index n = static_cast<Eigen::Index>(points);
    if (pool.size() == 0) {
      // at most 1 GiB of address space up front; more grows by doubling
      const std::uint64_t bound = (std::uint64_t{1} << 30) / (16 * std::max<std::uint64_t>(points, 1)) + 1;
      const std::uint64_t capacity =
          std::min(bound, ec ? std::uint64_t{16} : fileBytes / std::max<std::uint64_t>(4 * points, 1) + 1);
      pool.resize(n, static_cast<Eigen::Index>(capacity));
    }
    if (n != pool.rows()) return nullptr;  // another axis: kept in the record, reported by assemble()
    if (used == pool.cols()) pool.conservativeResize(n, 2 * pool.cols());
    lastColumn = used++;
    return reinterpret_cast<double*>(pool.col(lastColumn).data());
  };
  MOZZI_TRY_ASSIGN(auto reader, DatasetReader::open(path, std::move(ro)));
  for (;;) {
    MOZZI_TRY_ASSIGN(auto ds, reader.next());
    if (!ds) break;
    Function58* f = ds->get<Function58>();
    if (!f || (f->functionType != FunctionType::Frf && f->functionType != FunctionType::Coherence)) continue;
    columns.push_back(f->functionType == FunctionType::Frf ? lastColumn : -1);
    records.push_back(std::move(*f));
  }
  std::vector<const Function58*> frfs, cohs;
  std::map<const Function58*, Eigen::Index> columnOf;
  for (std::size_t q = 0; q < records.size(); ++q) {
    const Function58* f = &records[q];
    columnOf[f] = columns[q];
    (f->functionType == FunctionType::Frf ? frfs : cohs).push_back(f);
  }
  return assemble(frfs, cohs, options, &pool, [&](const Function58* f) { return columnOf.at(f); });
}

Result<std::vector<Function58>> fromFrfMatrix(const FrfMatrix& frf) {
  MOZZI_TRY(frf.validate());
  const Eigen::Index nf = frf.lineCount();
  bool even = nf >= 2;
  const double df = nf >= 2 ? (frf.frequencyHz[nf - 1] - frf.frequencyHz[0]) / static_cast<double>(nf - 1) : 0.0;
  for (Eigen::Index k = 0; even && k < nf; ++k) {
    // Uniform within 1e-9 of the step: x_k = f_0 + k df.
    even = std::abs(frf.frequencyHz[k] - (frf.frequencyHz[0] + static_cast<double>(k) * df)) <= 1e-9 * std::abs(df);
  }
  auto base = [&](const Dof& o, const Dof& i, FunctionType type) {
    Function58 f;
    f.idLines = {type == FunctionType::Frf ? "FRF" : "Coherence", "NONE", "NONE", "Mozzi", "NONE"};
    f.idLines[1] = formatDof(o) + " / " + formatDof(i);
    f.functionType = type;
    f.response = Channel58::fromDof(o);
    f.reference = Channel58::fromDof(i);
    f.evenSpacing = even;
    if (even) {
      f.abscissaMin = frf.frequencyHz[0];
      f.abscissaIncrement = df;
    } else {
      f.abscissa = frf.frequencyHz;
    }
    f.abscissaAxis = AxisInfo{18, 0, 0, 0, "Frequency", "Hz"};
    return f;
  };
  std::vector<Function58> out;
  for (std::size_t ii = 0; ii < frf.references.size(); ++ii) {
    for (Eigen::Index oo = 0; oo < frf.responseCount(); ++oo) {
      Function58 f = base(frf.responses[static_cast<std::size_t>(oo)], frf.references[ii], FunctionType::Frf);
      f.ordinateType = OrdinateType::ComplexDouble;
      f.complex = frf.h[ii].col(oo);
      f.ordinateNumerator =
          AxisInfo{kNumeratorCodes.of(frf.type), 0, 0, 0, frfTypeName(frf.type), kNumeratorUnits.of(frf.type)};
      f.ordinateDenominator = AxisInfo{13, 0, 0, 0, "Force", "N"};
      out.push_back(std::move(f));
    }
  }
  if (!frf.coherence.empty()) {
    for (std::size_t ii = 0; ii < frf.references.size(); ++ii) {
      for (Eigen::Index oo = 0; oo < frf.responseCount(); ++oo) {
        Function58 f = base(frf.responses[static_cast<std::size_t>(oo)], frf.references[ii], FunctionType::Coherence);
        f.ordinateType = OrdinateType::RealDouble;
        f.real = frf.coherence[ii].col(oo);
        f.ordinateNumerator = AxisInfo{0, 0, 0, 0, "Coherence", "NONE"};
        out.push_back(std::move(f));
      }
    }
  }
  return out;
}

// --- 55 <-> ModalData ----------------------------------------------------------
namespace {

bool isComplexAnalysis(AnalysisType a) {
  return a == AnalysisType::ComplexEigenFirstOrder || a == AnalysisType::ComplexEigenSecondOrder;
}

}  // namespace

Result<ModalData> toModalData(const std::vector<ModalData55>& records) {
  std::vector<const ModalData55*> modes;
  for (const auto& r : records) {
    if (r.analysisType == AnalysisType::NormalMode || isComplexAnalysis(r.analysisType)) modes.push_back(&r);
  }
  if (modes.empty()) {
    return makeError(ErrorCode::NotFound, "no dataset 55 with normal-mode (2) or complex-eigenvalue (3, 7) analysis",
                     "dataset 55");
  }
  ModalData md;
  const ModalData55& first = *modes.front();
  const int ndv = first.valuesPerNode;
  if (ndv != 3 && ndv != 6) {
    return makeError(ErrorCode::Unsupported,
                     "dataset 55 with " + std::to_string(ndv) + " values per node is not a 3- or 6-DOF shape",
                     "dataset 55, mode " + std::to_string(first.modeNumber()));
  }
  for (const auto& nv : first.nodes) {
    for (int d = 1; d <= ndv; ++d) md.dofs.push_back(Dof{nv.node, static_cast<Direction>(d), false});
  }
  const Eigen::Index nm = static_cast<Eigen::Index>(modes.size());
  md.frequencyHz.resize(nm);
  md.dampingRatio.resize(nm);
  md.modalMass.resize(nm);
  md.shapes.resize(static_cast<Eigen::Index>(md.dofs.size()), nm);
  for (Eigen::Index k = 0; k < nm; ++k) {
    const ModalData55& r = *modes[static_cast<std::size_t>(k)];
    const std::string where = "dataset 55, mode " + std::to_string(r.modeNumber());
    if (r.valuesPerNode != ndv || r.nodes.size() != first.nodes.size()) {
      return makeError(ErrorCode::InvalidArgument, "mode has other nodes or values per node than the first mode",
                       where);
    }
    if (isComplexAnalysis(r.analysisType)) {
      if (r.realValues.size() < 2) return makeError(ErrorCode::InvalidArgument, "record 8 lacks the eigenvalue", where);
      // lambda = sigma + i omega_d [rad/s]; |lambda| = omega_n, zeta = -sigma/|lambda|.
      const Complex lambda(r.realValues[0], r.realValues[1]);
      const double wn = std::abs(lambda);
      if (wn == 0.0) return makeError(ErrorCode::InvalidArgument, "eigenvalue is zero", where);
      md.frequencyHz[k] = wn / kTwoPi;
      md.dampingRatio[k] = -lambda.real() / wn;
      md.modalMass[k] = 0.0;
      md.complexShapes = true;
    } else {
      if (r.realValues.empty()) return makeError(ErrorCode::InvalidArgument, "record 8 lacks the frequency", where);
      // Record 8: frequency [Hz], modal mass, viscous damping ratio, hysteretic damping ratio.
      md.frequencyHz[k] = r.realValues[0];
      md.modalMass[k] = r.realValues.size() > 1 ? r.realValues[1] : 0.0;
      md.dampingRatio[k] = r.realValues.size() > 2 ? r.realValues[2] : 0.0;
      if (md.dampingRatio[k] == 0.0 && r.realValues.size() > 3) {
        md.dampingRatio[k] = r.realValues[3] / 2.0;  // zeta = eta / 2 (DESIGN.md conventions)
      }
    }
    for (std::size_t n = 0; n < r.nodes.size(); ++n) {
      if (r.nodes[n].node != first.nodes[n].node) {
        return makeError(ErrorCode::InvalidArgument,
                         "node " + std::to_string(r.nodes[n].node) + " where the first mode has node " +
                             std::to_string(first.nodes[n].node),
                         where);
      }
      for (int d = 0; d < ndv; ++d) {
        md.shapes(static_cast<Eigen::Index>(n) * ndv + d, k) = r.nodes[n].values[d];
        if (r.complexData && r.nodes[n].values[d].imag() != 0.0) md.complexShapes = true;
      }
    }
  }
  return md;
}

Result<ModalData> toModalData(const UffFile& file) {
  std::vector<ModalData55> rs;
  for (const ModalData55* r : file.all<ModalData55>()) rs.push_back(*r);
  return toModalData(rs);
}

Result<std::vector<ModalData55>> fromModalData(const ModalData& modal) {
  const Eigen::Index nm = modal.frequencyHz.size();
  if (modal.dampingRatio.size() != nm || modal.shapes.cols() != nm ||
      modal.shapes.rows() != static_cast<Eigen::Index>(modal.dofs.size()) ||
      (modal.modalMass.size() != 0 && modal.modalMass.size() != nm)) {
    return makeError(ErrorCode::InvalidArgument, "frequencies, damping, masses and shapes disagree in size",
                     "modal data");
  }
  if (!modal.frequencyHz.allFinite() || !modal.dampingRatio.allFinite() || !modal.shapes.allFinite()) {
    return makeError(ErrorCode::InvalidArgument, "modal data hold NaN or infinity", "modal data");
  }
  // Nodes in order of first appearance; 6 values per node if any rotation.
  std::vector<int> nodes;
  bool rotations = false;
  for (const Dof& d : modal.dofs) {
    if (std::find(nodes.begin(), nodes.end(), d.node) == nodes.end()) nodes.push_back(d.node);
    rotations = rotations || d.isRotation();
  }
  const int ndv = rotations ? 6 : 3;
  std::vector<ModalData55> out;
  for (Eigen::Index k = 0; k < nm; ++k) {
    ModalData55 r;
    r.idLines = {"Mode " + std::to_string(k + 1), "NONE", "NONE", "Mozzi", "NONE"};
    r.modelType = 1;
    r.dataCharacteristic = rotations ? 3 : 2;
    r.specificDataType = 8;
    r.valuesPerNode = ndv;
    const double f = modal.frequencyHz[k];
    const double zeta = modal.dampingRatio[k];
    if (modal.complexShapes) {
      // lambda = -zeta omega_n + i omega_n sqrt(1 - zeta^2) [rad/s].
      if (std::abs(zeta) >= 1.0) {
        return makeError(ErrorCode::InvalidArgument, "damping ratio >= 1 has no complex eigenvalue pair",
                         "mode " + std::to_string(k + 1));
      }
      const double wn = kTwoPi * f;
      r.analysisType = AnalysisType::ComplexEigenSecondOrder;
      r.complexData = true;
      r.integerValues = {1, static_cast<int>(k + 1)};
      r.realValues = {-zeta * wn, wn * std::sqrt(1.0 - zeta * zeta), 0.0, 0.0, 0.0, 0.0};
    } else {
      r.analysisType = AnalysisType::NormalMode;
      r.complexData = false;
      r.integerValues = {1, static_cast<int>(k + 1)};
      r.realValues = {f, modal.modalMass.size() ? modal.modalMass[k] : 0.0, zeta, 0.0};
    }
    for (int node : nodes) {
      NodeValues55 nv;
      nv.node = node;
      nv.values = ComplexVector::Zero(ndv);
      for (std::size_t row = 0; row < modal.dofs.size(); ++row) {
        const Dof& d = modal.dofs[row];
        if (d.node != node) continue;
        // A negative direction holds -1 times the component along the axis.
        const Complex v = modal.shapes(static_cast<Eigen::Index>(row), k);
        nv.values[static_cast<int>(d.direction) - 1] = d.negative ? -v : v;
      }
      if (!modal.complexShapes) nv.values = nv.values.real().cast<Complex>();
      r.nodes.push_back(std::move(nv));
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace mozzi::core::io::uff
