#pragma once
// Scalar root finding for critical speeds (weave, capsize, wobble): Brent's
// method (R.P. Brent, "Algorithms for minimization without derivatives", 1973,
// ch. 4), bracketing, so it always converges when f(a) f(b) <= 0.

#include <functional>

#include "core/common/result.h"

namespace mozzi::core::stability {

// Root of f in [a, b]; f(a) and f(b) must have opposite signs (or one is 0).
// Converges to |x - root| <= 2 eps |x| + tolerance. Errors name `what` when the
// bracket is invalid or f returns a non-finite value.
Result<double> brentRoot(const std::function<double(double)>& f, double a, double b, double tolerance,
                         const std::string& what);

}  // namespace mozzi::core::stability
