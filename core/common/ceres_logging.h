#pragma once
// Ceres reports through glog. A near-singular covariance is an answer its
// callers turn into their own message (parameters held, rank deficient,
// standard errors absent), not an error line on the user's terminal before
// logging was even set up: only fatal messages are printed.

#include <glog/logging.h>

namespace mozzi::core {

inline void quietCeresLogging() {
  static const bool quiet = [] {
    FLAGS_minloglevel = google::GLOG_FATAL;
    return true;
  }();
  (void)quiet;
}

}  // namespace mozzi::core
