#pragma once
// MATLAB .mat import (libmatio) of time records and FRF matrices with a
// channel map: which column of the file's array is which DOF, in which unit.
// Reads level-5 files (v5, v7 compressed) and v7.3 (HDF5) files when the
// linked libmatio was built with HDF5 (matV73Supported() says; Debian 12's
// libmatio 1.5.23 is). Variables may be top-level or one struct level deep
// ("meas.data"). Sizes are checked from the variable's header before any data
// is read, so a file claiming 10^12 elements is an error, not an allocation.

#include <optional>
#include <string>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/io/time_table.h"

namespace mozzi::core::io::mat {

// True when this libmatio reads and writes v7.3 (HDF5-based) files.
bool matV73Supported();

struct MatVariableInfo {
  std::string name;
  std::string className;          // "double", "single", "int16", "struct", ...
  std::vector<std::size_t> dims;  // MATLAB order (rows, columns, pages...)
  bool isComplex = false;
};

// Top-level variables of a file, for the import dialog.
Result<std::vector<MatVariableInfo>> listVariables(const std::string& path);

// One channel of the map: column `column` (0-based) of the data array becomes
// a channel with this DOF and unit. The unit is converted to SI on import
// ("g" -> m/s^2, "mm" -> m, ...; see csv::siUnit).
struct ChannelMap {
  int column = 0;
  std::string name;
  std::optional<Dof> dof;
  std::string unit = "1";
};

struct TimeImportOptions {
  std::string dataVariable;            // samples x channels (channels x samples is transposed when unambiguous)
  std::string sampleRateVariable;      // scalar [Hz], or
  std::string timeVariable;            // evenly spaced time vector [s], or
  std::optional<double> sampleRateHz;  // the rate given by the user
  std::vector<ChannelMap> channels;    // empty: every column, dimensionless, named "channel k"
};

Result<TimeTable> importTimeRecord(const std::string& path, const TimeImportOptions& options);

struct FrfImportOptions {
  std::string frfVariable;        // complex, lines x responses [x references]
  std::string frequencyVariable;  // lines [Hz]
  std::string coherenceVariable;  // optional, real, same shape as the FRFs
  // Channel map: responseColumns[k] (0-based index into the file's response
  // dimension) becomes responses[k]; empty columns = 0, 1, 2, ... in order.
  std::vector<Dof> responses;
  std::vector<int> responseColumns;
  std::vector<Dof> references;  // one per page of the reference dimension
  std::vector<int> referenceColumns;
  std::string unit = "m/s^2/N";  // FRF unit in the file: sets type and scale ("g/N", "mm/N", "m/s/N", ...)
};

Result<FrfMatrix> importFrfMatrix(const std::string& path, const FrfImportOptions& options);

}  // namespace mozzi::core::io::mat
