#include "core/modal/pole_selection.h"

#include <cmath>
#include <limits>

#include "core/common/text.h"
#include "core/modal/shape_tools.h"
#include "core/signal/window.h"

namespace mozzi::core::modal {

int representativePole(const StabilizationDiagram& diagram, Complex pole, double tol) {
  const double f = poleFrequencyHz(pole);
  int best = -1;
  bool bestStable = false;
  for (std::size_t i = 0; i < diagram.poles.size(); ++i) {
    const auto& p = diagram.poles[i];
    if (std::abs(p.frequencyHz - f) > tol * f) continue;
    const bool stable = p.status == PoleStatus::Stable;
    if (best < 0) {
      best = static_cast<int>(i);
      bestStable = stable;
      continue;
    }
    const auto& b = diagram.poles[static_cast<std::size_t>(best)];
    const bool better =
        (stable && !bestStable) ||
        (stable == bestStable &&
         (p.order > b.order || (p.order == b.order && std::abs(p.frequencyHz - f) < std::abs(b.frequencyHz - f))));
    if (better) {
      best = static_cast<int>(i);
      bestStable = stable;
    }
  }
  return best;
}

int nearestDiagramPole(const StabilizationDiagram& diagram, double frequencyHz, double order, double hzScale,
                       double orderScale, double maxDistance) {
  int best = -1;
  double bestD = std::numeric_limits<double>::infinity();
  if (!(hzScale > 0.0) || !(orderScale > 0.0)) return -1;
  for (std::size_t i = 0; i < diagram.poles.size(); ++i) {
    const double dx = (diagram.poles[i].frequencyHz - frequencyHz) / hzScale;
    const double dy = (diagram.poles[i].order - order) / orderScale;
    const double d = std::hypot(dx, dy);
    if (d < bestD) {
      bestD = d;
      best = static_cast<int>(i);
    }
  }
  return bestD <= maxDistance ? best : -1;
}

Result<std::vector<ModalTableRow>> modalTableRows(const ModalModel& model, const std::vector<double>& fStd,
                                                  const std::vector<double>& zStd) {
  std::vector<ModalTableRow> rows;
  if (model.modes.empty()) return rows;
  MOZZI_TRY_ASSIGN(const auto measured, measuredShapes(model));
  const ShapeSet& shapes = measured.set;
  for (std::size_t r = 0; r < model.modes.size(); ++r) {
    ModalTableRow row;
    row.frequencyHz = model.modes[r].frequencyHz();
    row.zeta = model.modes[r].zeta();
    row.eta = lossFactorFromZeta(row.zeta);
    if (r < fStd.size()) row.frequencyStdHz = fStd[r];
    if (r < zStd.size()) {
      row.zetaStd = zStd[r];
      row.etaStd = 2.0 * zStd[r];
    }
    const auto col = shapes.shapes.col(static_cast<Eigen::Index>(r));
    row.mpc = mpc(col);
    row.mpdDegrees = mpdDegrees(col);
    row.complexity = 1.0 - row.mpc;
    rows.push_back(row);
  }
  return rows;
}

Result<Matrix> residualPerFrf(const FrfMatrix& measured, const FrfMatrix& synthesis, double lo, double hi) {
  if (measured.lineCount() != synthesis.lineCount() || measured.h.size() != synthesis.h.size() ||
      measured.responseCount() != synthesis.responseCount()) {
    return makeError(ErrorCode::InvalidArgument, "the synthesis and the measured FRFs differ in size",
                     "residual per FRF");
  }
  const Eigen::Index no = measured.responseCount(), ni = measured.referenceCount();
  Matrix num = Matrix::Zero(no, ni), den = Matrix::Zero(no, ni);
  Eigen::Index lines = 0;
  for (Eigen::Index k = 0; k < measured.lineCount(); ++k) {
    const double f = measured.frequencyHz[k];
    if (f < lo || f > hi) continue;
    ++lines;
    for (Eigen::Index i = 0; i < ni; ++i) {
      const auto& h = measured.h[static_cast<std::size_t>(i)];
      const auto& s = synthesis.h[static_cast<std::size_t>(i)];
      for (Eigen::Index o = 0; o < no; ++o) {
        num(o, i) += std::norm(h(k, o) - s(k, o));
        den(o, i) += std::norm(h(k, o));
      }
    }
  }
  if (lines == 0) return makeError(ErrorCode::InvalidArgument, "no line in the band", "residual per FRF");
  Matrix out(no, ni);
  for (Eigen::Index i = 0; i < ni; ++i)
    for (Eigen::Index o = 0; o < no; ++o) out(o, i) = den(o, i) > 0.0 ? std::sqrt(num(o, i) / den(o, i)) : 0.0;
  return out;
}

std::vector<SelectionWarning> selectionWarnings(const std::vector<ModeCandidate>& chosen,
                                                const SameModeCriteria& criteria) {
  std::vector<SelectionWarning> out;
  for (const auto& p : findSameModes(chosen, criteria)) {
    out.push_back({p.first, p.second, p, describeSameMode(p, chosen, criteria)});
  }
  return out;
}

std::string storedMethodName(const std::string& key) {
  if (key == "plscf") return "PolyMAX";
  if (key == "lsce") return "LSCE";
  if (key == "peak") return "peak picking";
  if (key == "circle") return "circle fit";
  return key;
}

std::string defaultModalResultName(const std::string& key, double lo, double hi) {
  return storedMethodName(key) + " " + formatNumber(lo, 6) + " .. " + formatNumber(hi, 6) + " Hz";
}

std::string uniqueModalResultName(const std::vector<io::ModalResultInfo>& existing, std::int64_t specimenId,
                                  const std::string& name) {
  auto taken = [&](const std::string& n) {
    for (const auto& r : existing) {
      if (r.specimenId == specimenId && r.name == n) return true;
    }
    return false;
  };
  std::string candidate = name;
  for (int k = 2; taken(candidate); ++k) candidate = name + " (" + std::to_string(k) + ")";
  return candidate;
}

Result<io::ModalTable> modalTableOf(const ModalModel& model, const std::vector<double>& frequencyStdHz,
                                    const std::vector<double>& zetaStd) {
  io::ModalTable table;
  if (model.modes.empty()) {
    table.dofs = model.referenceCount() > model.responseCount() ? model.references : model.responses;
    return table;
  }
  MOZZI_TRY_ASSIGN(const auto measured, measuredShapes(model));
  table.dofs = measured.dofs;
  const ShapeSet& shapes = measured.set;
  for (std::size_t r = 0; r < model.modes.size(); ++r) {
    io::StoredMode m;
    m.frequencyHz = model.modes[r].frequencyHz();
    m.dampingRatio = model.modes[r].zeta();
    m.shape = shapes.shapes.col(static_cast<Eigen::Index>(r));
    if (r < frequencyStdHz.size()) m.frequencyStdHz = frequencyStdHz[r];
    if (r < zetaStd.size()) m.dampingRatioStd = zetaStd[r];
    table.modes.push_back(std::move(m));
  }
  return table;
}

namespace {

Result<signal::PoleEstimate> unwindowed(double frequencyHz, double zeta, double tauS, std::size_t mode) {
  auto c = signal::correctExponentialWindowDamping({frequencyHz, zeta}, tauS);
  if (!c) {
    Error e = c.error();
    e.message = "mode " + std::to_string(mode + 1) + ": " + e.message;
    return e;
  }
  return c;
}

}  // namespace

Result<void> removeExponentialWindow(std::vector<ModalTableRow>& rows, double tauS) {
  if (!(tauS > 0.0)) return {};
  for (std::size_t r = 0; r < rows.size(); ++r) {
    MOZZI_TRY_ASSIGN(auto c, unwindowed(rows[r].frequencyHz, rows[r].zeta, tauS, r));
    rows[r].frequencyHz = c.naturalFrequencyHz;
    rows[r].zeta = c.zeta;
    rows[r].eta = 2.0 * c.zeta;
    if (rows[r].zetaStd) rows[r].etaStd = 2.0 * *rows[r].zetaStd;
  }
  return {};
}

Result<void> removeExponentialWindow(io::ModalTable& table, double tauS) {
  if (!(tauS > 0.0)) return {};
  for (std::size_t r = 0; r < table.modes.size(); ++r) {
    MOZZI_TRY_ASSIGN(auto c, unwindowed(table.modes[r].frequencyHz, table.modes[r].dampingRatio, tauS, r));
    table.modes[r].frequencyHz = c.naturalFrequencyHz;
    table.modes[r].dampingRatio = c.zeta;
  }
  return {};
}

Result<std::int64_t> storeModalResult(io::ProjectStore& store, const ModalModel& model, io::ModalResultInfo info,
                                      const std::string& methodKey, double tauS,
                                      const std::vector<double>& frequencyStdHz, const std::vector<double>& zetaStd) {
  MOZZI_TRY_ASSIGN(auto table, modalTableOf(model, frequencyStdHz, zetaStd));
  MOZZI_TRY(removeExponentialWindow(table, tauS));
  MOZZI_TRY_ASSIGN(auto existing, store.modalResults());
  info.method = storedMethodName(methodKey);
  info.name = uniqueModalResultName(existing, info.specimenId,
                                    defaultModalResultName(methodKey, info.bandLowHz, info.bandHighHz));
  return store.addModalResult(info, table);
}

}  // namespace mozzi::core::modal
