#pragma once
// One pass over a channel's samples for what every hit check needs first:
// the smallest and largest sample and whether all are finite. Eigen's
// minCoeff, maxCoeff and sum are separate passes each waiting on one chain of
// dependent instructions; independent packed lanes let the processor overlap
// them (assessHit spent a third of its time in those reductions, issue 19).

#include "core/common/eigen_types.h"

namespace mozzi::core::signal {

struct SampleExtremes {
  double min = 0.0;    // smallest sample, meaningful when `finite`
  double max = 0.0;    // largest sample, meaningful when `finite`
  bool finite = true;  // no sample is NaN or infinite
};

// n >= 1.
SampleExtremes scanSamples(const double* x, Eigen::Index n);

// How many samples lie at or above `above` and at or below `below`, in one pass.
struct ThresholdCounts {
  Eigen::Index atOrAbove = 0;
  Eigen::Index atOrBelow = 0;
};
ThresholdCounts countBeyond(const double* x, Eigen::Index n, double above, double below);

}  // namespace mozzi::core::signal
