#pragma once
// The plate CSV files of `mozzi-cli twist static|dynamic|modal` and `mozzi-cli
// mozzi` (format: docs/cli/stiffness.md), read in one place for the CLI and
// the Twist Axes page (thesis §1.2 to §1.5):
//   '#' comments and blank lines ignored; "sensor,u,v" and "load,u,v" rows
//   give the plate geometry; a row whose first field is text that does not
//   read as a number at all is a header (kept, not data); every other row is
//   numeric data, all of one length, and "nan" or "inf" there is an error.
// Every error names the file and, for a row, its line (file:line).
// Ranges: positions within 100 m of the plate origin, data values within 1e9
// in SI units, the file at most 64 MiB.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/stiffness/dynamic_twist.h"
#include "core/stiffness/plate_motion.h"

namespace mozzi::core::stiffness {

inline constexpr double kMaxPlatePosition = 100.0;  // [m]
inline constexpr double kMaxPlateValue = 1e9;       // [N, m, Hz, deg, m/N ...]
inline constexpr std::uint64_t kMaxPlateFileBytes = std::uint64_t{64} << 20;

struct PlateCsv {
  std::string source;  // the file's name, for messages
  std::vector<Vector2> sensors;
  Vector2 load = Vector2::Zero();
  bool hasLoad = false;
  std::vector<std::string> header;  // fields of the last header row before the first data row; empty if none
  std::vector<std::vector<double>> rows;
  std::vector<int> rowLines;  // 1-based line of each data row
  // "file:line" of data row k (of the file alone when there are no rows).
  std::string where(std::size_t row = 0) const;
};

// Parses the text of a plate CSV named `source`. `needSensors`: at least 3
// sensor rows; `needRows`: at least one data row.
Result<PlateCsv> parsePlateCsv(const std::string& text, const std::string& source, bool needSensors,
                               bool needRows = true);
// Reads and parses the file at `path` (errors: cannot read, over 64 MiB, as above).
Result<PlateCsv> readPlateCsv(const std::string& path, bool needSensors, bool needRows = true);

// What a twist CSV holds, from its column count against the sensor count and,
// where that is ambiguous (1 + 2n columns: dynamic or modal), its header:
//   static   force_N, d1 ... dn                              (n + 1 columns)
//   dynamic  freq_Hz, A1, phi1_deg, ... [, F_N, phiF_deg]     (1 + 2n or 3 + 2n)
//   modal    freq_Hz, Re1, Im1, ...                           (1 + 2n)
// A header naming "re"/"im" columns is modal, one naming amplitudes or
// phases ("A", "amp", "phi", "phase", "deg") is dynamic. Error when the file
// fits none, or fits both without a header that tells.
enum class PlateCsvKind { Static, Dynamic, Modal };
const char* plateCsvKindName(PlateCsvKind kind);  // "static", "dynamic", "modal"
Result<PlateCsvKind> guessPlateCsvKind(const PlateCsv& csv);

// `twist static`: one data row is the single-load form (eq. 29), several a
// load ramp (eq. 29 to 32). Errors: no load row, rows not force + n
// displacements, and those of staticTwistSingleLoad / staticTwistTest.
Result<StaticTwistResult> staticTwistFromCsv(const PlateCsv& csv, const StaticTestOptions& options = {});

// `twist dynamic`: the sweep points (phases in the file in degrees).
Result<std::vector<SweepPoint>> sweepFromCsv(const PlateCsv& csv);

// `twist modal` without --frf: the FRFs (one reference, the sensors as
// responses 1 to n, +Y) of the given type. Errors: rows not freq + Re, Im per
// sensor, frequencies not strictly ascending (naming the line).
Result<FrfMatrix> modalFrfFromCsv(const PlateCsv& csv, FrfType type);

// The frequencies of the `most` highest local maxima of sum_o |H_o| over the
// lines of reference `reference`, in ascending frequency (a first guess at the
// bending and torsion modes of a hammer test, §1.4 and §1.7).
std::vector<double> frfPeakFrequencies(const FrfMatrix& frf, std::size_t most, int reference = 0);

}  // namespace mozzi::core::stiffness
