// CSV exchange of modal tables (docs/formats/csv.md, "Modal table").

#include "core/io/csv/csv_exchange.h"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>

#include "core/io/csv/csv_internal.h"

namespace mozzi::core::io::csv {

using namespace detail;  // NOLINT(google-build-using-namespace): the exchange's private helpers

// --- modal tables --------------------------------------------------------------------------

Result<void> writeModalCsv(const ModalTable& table, std::ostream& out) {
  if (table.modes.empty()) return makeError(ErrorCode::InvalidArgument, "no modes to write", "CSV export");
  for (std::size_t m = 0; m < table.modes.size(); ++m) {
    const auto& mode = table.modes[m];
    if (!std::isfinite(mode.frequencyHz) || !std::isfinite(mode.dampingRatio) || !mode.shape.allFinite() ||
        (mode.shape.size() != 0 && mode.shape.size() != static_cast<Eigen::Index>(table.dofs.size()))) {
      return makeError(ErrorCode::InvalidArgument,
                       "mode " + std::to_string(m + 1) +
                           " is not finite or its shape "
                           "does not match the DOFs",
                       "CSV export");
    }
  }
  out << kMagic << ", modal\nmode [1],frequency [Hz],damping ratio [1]";
  const bool shapes =
      std::any_of(table.modes.begin(), table.modes.end(), [](const auto& m) { return m.shape.size() > 0; });
  if (shapes) {
    for (const Dof& d : table.dofs) out << ',' << formatDof(d) << " re [1]," << formatDof(d) << " im [1]";
  }
  out << '\n';
  for (std::size_t m = 0; m < table.modes.size(); ++m) {
    const auto& mode = table.modes[m];
    out << (m + 1) << ',' << num(mode.frequencyHz) << ',' << num(mode.dampingRatio);
    if (shapes) {
      for (std::size_t d = 0; d < table.dofs.size(); ++d) {
        const Complex v = mode.shape.size() ? mode.shape[static_cast<Eigen::Index>(d)] : Complex(0.0, 0.0);
        out << ',' << num(v.real()) << ',' << num(v.imag());
      }
    }
    out << '\n';
  }
  return written(out);
}

Result<ModalTable> readModalCsv(std::string_view text, const std::string& source) {
  MOZZI_TRY_ASSIGN(const Table t, parseTableOf(text, source, "modal", "modes"));
  int freqCol = -1, dampCol = -1;
  double dampFactor = 1.0;  // to viscous ratio zeta
  double freqFactor = 1.0;
  struct ShapeCols {
    Dof dof;
    int re = -1, im = -1;
  };
  std::vector<ShapeCols> shape;
  for (std::size_t c = 0; c < t.titles.size(); ++c) {
    const int col = static_cast<int>(c + 1);
    const Title title = splitTitle(t.titles[c]);
    const std::string name = lower(title.name);
    if (name == "mode") continue;
    if (name == "frequency") {
      auto u = siUnit(title.unit.value_or(""));
      if (!u || u->quantity != "frequency") return parseError("frequency unit must be Hz", source, t.headerLine, col);
      freqFactor = u->factor;
      freqCol = static_cast<int>(c);
      continue;
    }
    if (name == "damping ratio" || name == "loss factor") {
      auto u = siUnit(title.unit.value_or("1"));
      if (!u || !u->quantity.empty())
        return parseError("damping must be dimensionless ([1] or [%])", source, t.headerLine, col);
      // Loss factor eta = 2 zeta (DESIGN.md conventions); stored as zeta.
      dampFactor = u->factor * (name == "loss factor" ? 0.5 : 1.0);
      dampCol = static_cast<int>(c);
      continue;
    }
    std::istringstream words(title.name);
    std::string dofText, part;
    words >> dofText >> part;
    auto dof = parseDof(dofText);
    part = lower(part);
    if (!dof || (part != "re" && part != "im")) {
      return parseError("column title '" + t.titles[c] +
                            "' is not mode, frequency, damping ratio, loss factor or "
                            "'<DOF> re|im'",
                        source, t.headerLine, col);
    }
    auto it = std::find_if(shape.begin(), shape.end(), [&](const ShapeCols& s) { return s.dof == *dof; });
    if (it == shape.end()) {
      shape.push_back({*dof});
      it = shape.end() - 1;
    }
    int& slot = part == "re" ? it->re : it->im;
    if (slot >= 0) return parseError(part + " part of " + dofText + " appears twice", source, t.headerLine, col);
    slot = static_cast<int>(c);
  }
  if (freqCol < 0) return parseError("no 'frequency [Hz]' column", source, t.headerLine);
  if (dampCol < 0) return parseError("no 'damping ratio [1]' or 'loss factor [1]' column", source, t.headerLine);
  ModalTable out;
  for (const auto& s : shape) {
    if (s.re < 0 || s.im < 0) return parseError("shape " + formatDof(s.dof) + " lacks re or im", source, t.headerLine);
    out.dofs.push_back(s.dof);
  }
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    StoredMode m;
    m.frequencyHz = freqFactor * t.rows[r][static_cast<std::size_t>(freqCol)];
    m.dampingRatio = dampFactor * t.rows[r][static_cast<std::size_t>(dampCol)];
    if (m.frequencyHz < 0) return parseError("negative natural frequency", source, t.rowLines[r], freqCol + 1);
    m.shape.resize(static_cast<Eigen::Index>(shape.size()));
    for (std::size_t d = 0; d < shape.size(); ++d) {
      m.shape[static_cast<Eigen::Index>(d)] =
          Complex(t.rows[r][static_cast<std::size_t>(shape[d].re)], t.rows[r][static_cast<std::size_t>(shape[d].im)]);
    }
    out.modes.push_back(std::move(m));
  }
  return out;
}

}  // namespace mozzi::core::io::csv
