#pragma once
// Impact-hammer hits (or blocks of a shaker test) from the UFF 58 time
// records of a file, streamed: one hit per load case (record 6), channels in
// file order, as `mozzi-cli frf` reads them (docs/cli/frf.md). The samples
// are read straight from the file into the hit's sample matrix (the reader's
// ordinate sink), four hits' matrices are reused for the whole file, so
// memory is four hits whatever the file's length and nothing is copied
// (issue 19). The records of one load case must be consecutive in the file
// (every writer does so); a load case that comes back after another one is an
// error naming it.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/common/dof.h"
#include "core/common/result.h"
#include "core/signal/time_record.h"

namespace mozzi::core::io {

struct UffHit {
  int loadCase = 0;
  signal::TimeRecord record;  // channels in file order, samples in file units
};

class UffHitReader {
 public:
  // `references`: the DOFs the user named as references. Among channels at
  // such a DOF the one typed as force (record 9 specific data type 13) is
  // taken; the chosen channels become the force channels and any other force
  // channel is typed Other. Empty: the channels typed force in the file.
  static Result<UffHitReader> open(const std::string& path, std::vector<Dof> references = {});

  UffHitReader(UffHitReader&&) noexcept;
  UffHitReader& operator=(UffHitReader&&) noexcept;
  ~UffHitReader();

  // `callback` is called once, with the sample count of the first time
  // record, when its header has been read and before its samples are: a
  // consumer may prepare for that length (plan its FFT on another thread)
  // while the first hit is read. Set it before the first next().
  void onFirstLength(std::function<void(Eigen::Index)> callback);

  // The next hit, nullptr after the last one. The hit stays valid until the
  // third call after this one starts, so another thread may work on it and
  // on the next one while the hit after them is read (not while the one after
  // that is). Errors name the
  // file, load case and channel. NotFound when the file holds no
  // time-response record at all.
  Result<const UffHit*> next();

 private:
  struct Impl;
  explicit UffHitReader(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace mozzi::core::io
