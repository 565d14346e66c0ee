#include "core/io/modelab_ascii.h"

#include "core/io/text_file.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace mozzi::core::io {

namespace {
constexpr int kHeaderLines = 9;

// Parses one number starting at p; advances p. False when none is found.
bool parseNumber(const char*& p, double& out) {
  while (*p == ' ' || *p == '\t') ++p;
  if (*p == '\0' || *p == '\r') return false;
  char* end = nullptr;
  errno = 0;
  out = std::strtod(p, &end);
  if (end == p || errno == ERANGE || !std::isfinite(out)) return false;
  p = end;
  return true;
}
}  // namespace

Result<SignalCalcFrf> readSignalCalcAscii(const std::string& path) {
  auto text = readTextFile(path, "SignalCalc ASCII");  // size cap: core/io/text_file.h
  if (!text) return text.error();
  std::istringstream in(*text);
  SignalCalcFrf out;
  std::string line;
  int lineNo = 0;
  for (; lineNo < kHeaderLines; ++lineNo) {
    if (!std::getline(in, line)) {
      return makeError(ErrorCode::ParseError, "file ends inside the 9-line header",
                       path + ":" + std::to_string(lineNo + 1));
    }
    if (lineNo == 0 && line.rfind("Units", 0) != 0) {
      return makeError(ErrorCode::ParseError, "not a SignalCalc ASCII export (first line must start with 'Units')",
                       path + ":1");
    }
    if (lineNo == 8) out.unitsLine = line;
  }
  std::vector<double> f, re, im;
  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    const char* p = line.c_str();
    double a = 0, b = 0, c = 0;
    if (!parseNumber(p, a) || !parseNumber(p, b) || !parseNumber(p, c)) {
      return makeError(ErrorCode::ParseError, "expected three numbers: frequency, real, imaginary",
                       path + ":" + std::to_string(lineNo));
    }
    while (*p == ' ' || *p == '\t') ++p;
    if (*p != '\0') {
      return makeError(ErrorCode::ParseError, "unexpected text after the third column",
                       path + ":" + std::to_string(lineNo));
    }
    if (!f.empty() && !(a > f.back())) {
      return makeError(ErrorCode::ParseError, "frequencies are not strictly ascending",
                       path + ":" + std::to_string(lineNo));
    }
    if (a < 0.0) return makeError(ErrorCode::ParseError, "negative frequency", path + ":" + std::to_string(lineNo));
    f.push_back(a);
    re.push_back(b);
    im.push_back(c);
  }
  if (f.empty()) return makeError(ErrorCode::ParseError, "no data rows after the header", path);
  const Eigen::Index n = static_cast<Eigen::Index>(f.size());
  out.frequencyHz = Eigen::Map<const Vector>(f.data(), n);
  out.h.resize(n);
  for (Eigen::Index k = 0; k < n; ++k)
    out.h[k] = Complex(re[static_cast<std::size_t>(k)], im[static_cast<std::size_t>(k)]);
  return out;
}

Result<FrfMatrix> readSignalCalcRovingHammer(const std::vector<std::string>& files, const std::vector<Dof>& hammerDofs,
                                             const Dof& response, FrfType type) {
  if (files.empty() || files.size() != hammerDofs.size()) {
    return makeError(ErrorCode::InvalidArgument, "need one hammer DOF per file (and at least one file)",
                     "SignalCalc roving hammer");
  }
  FrfMatrix frf;
  frf.type = type;
  frf.references = {response};
  frf.responses = hammerDofs;
  for (std::size_t i = 0; i < files.size(); ++i) {
    auto one = readSignalCalcAscii(files[i]);
    if (!one) return one.error();
    if (i == 0) {
      frf.frequencyHz = one->frequencyHz;
      frf.h.push_back(ComplexMatrix(frf.frequencyHz.size(), static_cast<Eigen::Index>(files.size())));
    } else if (one->frequencyHz.size() != frf.frequencyHz.size() ||
               (one->frequencyHz - frf.frequencyHz).cwiseAbs().maxCoeff() >
                   1e-9 * std::max(1.0, frf.frequencyHz.cwiseAbs().maxCoeff())) {
      return makeError(ErrorCode::InvalidArgument, "frequency axis differs from the first file's", files[i]);
    }
    frf.h[0].col(static_cast<Eigen::Index>(i)) = one->h;
  }
  if (auto ok = frf.validate(); !ok) return ok.error();
  return frf;
}

}  // namespace mozzi::core::io
