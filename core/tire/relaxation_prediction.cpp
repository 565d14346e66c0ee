#include "core/tire/relaxation_prediction.h"

#include <cmath>
#include <sstream>

namespace mozzi::core::tire {

Result<double> adhesionFraction(const ContactPatchInputs& in) {
  const char* where = "adhesion fraction m (thesis eq. 49)";
  if (!std::isfinite(in.corneringStiffness) || in.corneringStiffness <= 0.0)
    return makeError(ErrorCode::InvalidArgument, "cornering stiffness must be positive", where);
  if (!std::isfinite(in.verticalLoad) || in.verticalLoad <= 0.0)
    return makeError(ErrorCode::InvalidArgument, "vertical load must be positive", where);
  if (!std::isfinite(in.friction) || in.friction <= 0.0)
    return makeError(ErrorCode::InvalidArgument, "friction coefficient must be positive", where);
  if (!std::isfinite(in.slipAngle) || std::abs(in.slipAngle) >= 1.5)
    return makeError(ErrorCode::InvalidArgument, "slip angle must be finite and well below 90 deg", where);
  const double m =
      1.0 - in.corneringStiffness * std::tan(std::abs(in.slipAngle)) / (3.0 * in.friction * in.verticalLoad);  // eq. 49
  if (m <= 0.0) {
    std::ostringstream s;
    s << "m = " << m << ": the whole contact patch slides at this slip angle (C tan(alpha) >= 3 lambda F_z)";
    return makeError(ErrorCode::NumericalFailure, s.str(), where);
  }
  return m;
}

Result<RelaxationPrediction> predictRelaxationLength(const RingModel& ring, const ContactPatchInputs& in) {
  const char* where = "relaxation length prediction (thesis eq. 48)";
  if (!std::isfinite(in.halfLength) || in.halfLength < 0.0)
    return makeError(ErrorCode::InvalidArgument, "contact half-length must not be negative", where);
  auto m = adhesionFraction(in);
  if (!m) return m.error();
  const RingMode* lateral = ring.mode(0);
  const RingMode* camber = ring.mode(1);
  if (!lateral || !camber)
    return makeError(ErrorCode::InvalidArgument, "the lateral (k=0) and camber (k=1) modes are both needed", where);
  const double C = in.corneringStiffness;
  RelaxationPrediction p;
  p.adhesionFraction = *m;
  p.contactPatch = in.halfLength * *m;      // a m
  p.lateral = C / lateral->modalStiffness;  // C/C_y
  p.camber = C / camber->modalStiffness;    // C r^2/C_xx, C_xx = C_1 r^2
  for (const auto& mode : ring.modes) {     // C/C_res, eq. 50
    if (mode.k == 2)
      p.cShaped = C / mode.modalStiffness;
    else if (mode.k == 3)
      p.sShaped = C / mode.modalStiffness;
    else if (mode.k >= 4)
      p.higherModes += C / mode.modalStiffness;
  }
  return p;
}

Result<std::vector<PressurePrediction>> predictOverPressures(const std::vector<PressureCase>& cases) {
  std::vector<PressurePrediction> out;
  for (const auto& c : cases) {
    auto p = predictRelaxationLength(c.ring, c.contact);
    if (!p) {
      std::ostringstream w;
      w << p.error().where << ", pressure " << c.pressure / 1e5 << " bar";
      return makeError(p.error().code, p.error().message, w.str());
    }
    out.push_back({c.pressure, *p});
  }
  return out;
}

}  // namespace mozzi::core::tire
