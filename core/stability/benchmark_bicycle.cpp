#include "core/stability/benchmark_bicycle.h"

#include "core/stability/parameter_file.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace mozzi::core::stability {

BenchmarkParameters meijaard2007Parameters() {
  BenchmarkParameters p;
  // Meijaard et al. (2007) Table 1
  p.w = 1.02;
  p.c = 0.08;
  p.lambda = M_PI / 10.0;
  p.g = 9.81;
  p.rR = 0.3;
  p.mR = 2.0;
  p.IRxx = 0.0603;
  p.IRyy = 0.12;
  p.xB = 0.3;
  p.zB = -0.9;
  p.mB = 85.0;
  p.IBxx = 9.2;
  p.IBxz = 2.4;
  p.IByy = 11.0;
  p.IBzz = 2.8;
  p.xH = 0.9;
  p.zH = -0.7;
  p.mH = 4.0;
  p.IHxx = 0.05892;
  p.IHxz = -0.00756;
  p.IHyy = 0.06;
  p.IHzz = 0.00708;
  p.rF = 0.35;
  p.mF = 3.0;
  p.IFxx = 0.1405;
  p.IFyy = 0.28;
  return p;
}

Result<BenchmarkParameters> loadBenchmarkParameters(const std::string& path) {
  MOZZI_TRY_ASSIGN(auto file, readParameterFile(path, "benchmark bicycle"));
  BenchmarkParameters p;
  const std::vector<std::pair<const char*, double*>> fields = {
      {"w", &p.w},       {"c", &p.c},       {"lambda", &p.lambda}, {"g", &p.g},       {"rR", &p.rR}, {"mR", &p.mR},
      {"IRxx", &p.IRxx}, {"IRyy", &p.IRyy}, {"xB", &p.xB},         {"zB", &p.zB},     {"mB", &p.mB}, {"IBxx", &p.IBxx},
      {"IBxz", &p.IBxz}, {"IByy", &p.IByy}, {"IBzz", &p.IBzz},     {"xH", &p.xH},     {"zH", &p.zH}, {"mH", &p.mH},
      {"IHxx", &p.IHxx}, {"IHxz", &p.IHxz}, {"IHyy", &p.IHyy},     {"IHzz", &p.IHzz}, {"rF", &p.rF}, {"mF", &p.mF},
      {"IFxx", &p.IFxx}, {"IFyy", &p.IFyy}};
  MOZZI_TRY(takeParameters(file, fields, path));
  MOZZI_TRY(validate(p));
  return p;
}

Result<void> validate(const BenchmarkParameters& p) {
  const std::pair<const char*, double> positive[] = {
      {"w", p.w},   {"g", p.g},   {"rR", p.rR},     {"rF", p.rF},     {"mR", p.mR},     {"mB", p.mB},
      {"mH", p.mH}, {"mF", p.mF}, {"IRxx", p.IRxx}, {"IRyy", p.IRyy}, {"IFxx", p.IFxx}, {"IFyy", p.IFyy}};
  for (const auto& [name, x] : positive) {
    if (!(x > 0.0) || !std::isfinite(x)) {
      return makeError(ErrorCode::InvalidArgument, "must be positive and finite",
                       std::string("benchmark parameter ") + name);
    }
  }
  if (!(std::fabs(p.lambda) < M_PI / 2.0)) {
    return makeError(ErrorCode::InvalidArgument, "steer axis tilt must be within (-pi/2, pi/2)",
                     "benchmark parameter lambda");
  }
  for (const auto& [name, xx, xz, zz] :
       {std::tuple<const char*, double, double, double>{"B", p.IBxx, p.IBxz, p.IBzz}, {"H", p.IHxx, p.IHxz, p.IHzz}}) {
    Eigen::Matrix2d I;
    I << xx, xz, xz, zz;
    if (!I.allFinite() || Eigen::LLT<Eigen::Matrix2d>(I).info() != Eigen::Success) {
      return makeError(ErrorCode::InvalidArgument, "inertia tensor (xx, xz, zz) is not positive definite",
                       std::string("benchmark body ") + name);
    }
  }
  if (!std::isfinite(p.c + p.xB + p.zB + p.xH + p.zH + p.IByy + p.IHyy)) {
    return makeError(ErrorCode::InvalidArgument, "a geometry value is not finite", "benchmark parameters");
  }
  return Result<void>();
}

Result<BicycleModel> benchmarkModel(const BenchmarkParameters& p) {
  MOZZI_TRY(validate(p));
  const double sl = std::sin(p.lambda), cl = std::cos(p.lambda);
  // Appendix A: totals of the whole bicycle T.
  const double mT = p.mR + p.mB + p.mH + p.mF;
  const double xT = (p.xB * p.mB + p.xH * p.mH + p.w * p.mF) / mT;
  const double zT = (-p.rR * p.mR + p.zB * p.mB + p.zH * p.mH - p.rF * p.mF) / mT;
  const double ITxx = p.IRxx + p.IBxx + p.IHxx + p.IFxx + p.mR * p.rR * p.rR + p.mB * p.zB * p.zB + p.mH * p.zH * p.zH +
                      p.mF * p.rF * p.rF;
  const double ITxz = p.IBxz + p.IHxz - p.mB * p.xB * p.zB - p.mH * p.xH * p.zH + p.mF * p.w * p.rF;
  const double IRzz = p.IRxx, IFzz = p.IFxx;  // Appendix A: wheels are rotationally symmetric
  const double ITzz = IRzz + p.IBzz + p.IHzz + IFzz + p.mB * p.xB * p.xB + p.mH * p.xH * p.xH + p.mF * p.w * p.w;
  // Appendix A: front assembly A = H + F.
  const double mA = p.mH + p.mF;
  const double xA = (p.xH * p.mH + p.w * p.mF) / mA;
  const double zA = (p.zH * p.mH - p.rF * p.mF) / mA;
  const double IAxx = p.IHxx + p.IFxx + p.mH * (p.zH - zA) * (p.zH - zA) + p.mF * (p.rF + zA) * (p.rF + zA);
  const double IAxz = p.IHxz - p.mH * (p.xH - xA) * (p.zH - zA) + p.mF * (p.w - xA) * (p.rF + zA);
  const double IAzz = p.IHzz + IFzz + p.mH * (p.xH - xA) * (p.xH - xA) + p.mF * (p.w - xA) * (p.w - xA);
  // Appendix A: perpendicular distance of A's mass centre ahead of the steer axis.
  const double uA = (xA - p.w - p.c) * cl - zA * sl;
  // Appendix A: inertia of A about the steer axis and products with x, z.
  const double IAll = mA * uA * uA + IAxx * sl * sl + 2.0 * IAxz * sl * cl + IAzz * cl * cl;
  const double IAlx = -mA * uA * zA + IAxx * sl + IAxz * cl;
  const double IAlz = mA * uA * xA + IAxz * sl + IAzz * cl;
  // Appendix A: ratio of trail to wheel base: gyrostatic coefficients.
  const double mu = p.c / p.w * cl;
  const double SR = p.IRyy / p.rR, SF = p.IFyy / p.rF, ST = SR + SF;
  // Appendix A: static moment term.
  const double SA = mA * uA + mu * mT * xT;

  BicycleModel m;
  m.g = p.g;
  m.coordinates = {"roll", "steer"};
  m.M.resize(2, 2);
  m.C1.resize(2, 2);
  m.K0.resize(2, 2);
  m.K2.resize(2, 2);
  // Appendix A: mass matrix M
  m.M << ITxx, IAlx + mu * ITxz,  //
      IAlx + mu * ITxz, IAll + 2.0 * mu * IAlz + mu * mu * ITzz;
  // Appendix A: gravity stiffness K0
  m.K0 << mT * zT, -SA,  //
      -SA, -SA * sl;
  // Appendix A: velocity-squared stiffness K2
  m.K2 << 0.0, (ST - mT * zT) / p.w * cl,  //
      0.0, (SA + SF * sl) / p.w * cl;
  // Appendix A: damping-like matrix C1
  m.C1 << 0.0, mu * ST + SF * cl + ITxz / p.w * cl - mu * mT * zT,  //
      -(mu * ST + SF * cl), IAlz / p.w * cl + mu * (SA + ITzz / p.w * cl);
  m.C = Matrix::Zero(2, 2);
  m.K = Matrix::Zero(2, 2);
  return m;
}

}  // namespace mozzi::core::stability
