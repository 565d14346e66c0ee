#pragma once
// Tyre test files (formats in docs/cli/tire.md): comma-separated numbers
// under one header row of column names, blank and '#' lines ignored. Two
// kinds are read into the inputs of the tyre computations:
// - harmonic yaw test (§1.9): frequency_hz, time_s, yaw_rate_rad_s,
//   lateral_force_n; consecutive rows at one frequency are one record,
//   uniformly sampled;
// - steady-state sweeps (appendix 2, §7.1): slip_deg, camber_deg, load_n,
//   pressure_bar, force_n, torque_nm; rows with camber 0 at one load and
//   pressure are a side-slip sweep, rows with slip 0 a camber sweep.
// Every error names the source and line.

#include <string>
#include <string_view>
#include <vector>

#include "core/common/result.h"
#include "core/tire/magic_formula.h"
#include "core/tire/relaxation_length.h"
#include "core/tire/steady_state.h"

namespace mozzi::core::tire {

struct NumericTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;      // every row has header.size() finite numbers
  std::vector<int> lines;                     // 1-based line of each row in the source
  int column(const std::string& name) const;  // -1 when absent
};

// Errors: no header, an empty or repeated column name, a row with another
// number of cells, a cell that is not a finite number, a required column
// missing, no data rows.
Result<NumericTable> parseNumericTable(std::string_view text, const std::string& source,
                                       const std::vector<std::string>& required);
Result<NumericTable> readNumericTable(const std::string& path, const std::vector<std::string>& required);

const std::vector<std::string>& harmonicYawColumns();
const std::vector<std::string>& steadyStateColumns();

// Records of the harmonic yaw test. Errors: fewer than 4 samples at one
// frequency, time not increasing with a uniform step (0.1% of the step).
Result<std::vector<HarmonicYawRecord>> harmonicYawRecords(const NumericTable& table, const std::string& source);

struct SteadyStateSweepRows {
  SteadyStateSweep sweep;  // angle [rad], force [N], torque [N m], load [N], pressure [Pa]
  bool camberSweep = false;
  int firstLine = 0;
};
// Sweeps with at least 4 rows, ordered by load, pressure, kind; a lone
// zero-angle row of the other kind is not a sweep. The angle order is kept as
// acquired (characteriseSweep rejects a non-monotonic one).
Result<std::vector<SteadyStateSweepRows>> steadyStateSweeps(const NumericTable& table, const std::string& source);
// Every row as a Magic Formula point (angles in rad, pressure in Pa).
std::vector<SteadyStatePoint> steadyStatePoints(const NumericTable& table);

// "a:b:c,d:e:f" (command-line lists): rows of exactly `width` finite numbers.
Result<std::vector<std::vector<double>>> parseNumberTuples(std::string_view text, std::size_t width,
                                                           const std::string& what);

}  // namespace mozzi::core::tire
