#pragma once
// Reference data of the six motorcycle and scooter tyres of thesis chapter 5,
// as printed (Table 15 torus radius, Table 16 modal stiffness at nominal
// pressure, Table 17 contact half-length against pressure), plus the inputs the
// thesis does not print, marked as assumptions (docs/validation/tire.md).

#include <array>
#include <cstddef>
#include <string>

namespace mozzi::core::tire {

struct ThesisTyre {
  std::string size;  // e.g. "120/70 R17"
  std::string use;   // "motorcycle front", ...
  bool radial = false;
  double torusRadius = 0.0;  // cross-section radius of curvature [m], Table 15
  // Table 16 [N/m] (printed in kN/m = N/mm): camber (k=1), lateral (k=0),
  // C-shaped (k=2), S-shaped (k=3), nominal pressure (2 bar).
  double camberStiffness = 0.0, lateralStiffness = 0.0, cShapedStiffness = 0.0, sShapedStiffness = 0.0;
  std::array<double, 7> halfLength{};  // a [m] at kThesisPressures, Table 17
  double testLoad = 0.0;               // F_z [N] of the cornering-stiffness tests, §5.4 (1500 N; 1000 N for 12" tyres)
  // ---- assumptions (not in the thesis) ----
  double outerRadius = 0.0;  // r [m] from the size designation: rim/2 + width x aspect
  double tyreMass = 0.0;     // [kg], typical catalogue mass of the size
};

// Inflation pressures of §5.1 and Table 17 [Pa]: 0.5, 0.75, 1, 1.5, 2, 3, 4 bar.
inline constexpr std::array<double, 7> kThesisPressures = {0.5e5, 0.75e5, 1.0e5, 1.5e5, 2.0e5, 3.0e5, 4.0e5};

// Assumed normalised cornering stiffness C_bFalpha/F_z [1/rad] (about 0.23/deg,
// the order of Sharp 1971: 11.1 /rad front) and friction lambda for eq. 49.
inline constexpr double kAssumedNormalisedCorneringStiffness = 13.0;
inline constexpr double kAssumedFriction = 1.0;
inline constexpr double kAssumedDampingRatio = 0.03;

inline const std::array<ThesisTyre, 6>& thesisTyres() {
  static const std::array<ThesisTyre, 6> tyres = {{
      {"120/70 R17",
       "motorcycle front",
       true,
       0.043,
       463e3,
       1906e3,
       1239e3,
       4690e3,
       {0.106, 0.098, 0.088, 0.078, 0.070, 0.065, 0.054},
       1500.0,
       0.2159 + 0.120 * 0.70,
       4.3},
      {"180/55 R17",
       "motorcycle rear",
       true,
       0.097,
       515e3,
       1178e3,
       978e3,
       2258e3,
       {0.115, 0.101, 0.087, 0.075, 0.065, 0.055, 0.050},
       1500.0,
       0.2159 + 0.180 * 0.55,
       6.5},
      {"110/70-16",
       "high-wheel scooter front",
       false,
       0.039,
       398e3,
       1181e3,
       1847e3,
       5357e3,
       {0.090, 0.081, 0.076, 0.065, 0.060, 0.054, 0.052},
       1500.0,
       0.2032 + 0.110 * 0.70,
       3.5},
      {"140/70-14",
       "high-wheel scooter rear",
       false,
       0.066,
       222e3,
       767e3,
       3043e3,
       10851e3,
       {0.095, 0.081, 0.073, 0.068, 0.058, 0.055, 0.051},
       1500.0,
       0.1778 + 0.140 * 0.70,
       4.2},
      {"120/70-12",
       "scooter front",
       false,
       0.041,
       343e3,
       742e3,
       2589e3,
       10494e3,
       {0.062, 0.074, 0.056, 0.050, 0.047, 0.042, 0.040},
       1000.0,
       0.1524 + 0.120 * 0.70,
       3.3},
      {"130/70-12",
       "scooter rear",
       false,
       0.055,
       360e3,
       709e3,
       2842e3,
       10318e3,
       {0.072, 0.069, 0.060, 0.056, 0.051, 0.046, 0.043},
       1000.0,
       0.1524 + 0.130 * 0.70,
       3.6},
  }};
  return tyres;
}

// Table 17's contact half-length a [m] of `tyre` at `pressurePa`, linear in
// pressure between the tabulated ones, held beyond them.
inline double table17HalfLength(const ThesisTyre& tyre, double pressurePa) {
  const auto& p = kThesisPressures;
  if (pressurePa <= p.front()) return tyre.halfLength.front();
  for (std::size_t i = 1; i < p.size(); ++i)
    if (pressurePa <= p[i]) {
      const double u = (pressurePa - p[i - 1]) / (p[i] - p[i - 1]);
      return tyre.halfLength[i - 1] + u * (tyre.halfLength[i] - tyre.halfLength[i - 1]);
    }
  return tyre.halfLength.back();
}

}  // namespace mozzi::core::tire
