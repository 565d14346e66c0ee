#pragma once
// Real-to-complex FFT on FFTW 3 with plans created once per length and reused.
// FFTW's planner is not thread-safe: every plan creation and destruction goes
// through one process-wide mutex; execution uses the new-array interface
// (fftw_execute_dft_r2c) and is safe from many threads at once on distinct
// arrays. FFTW types stay out of this header (STYLE 5).

#include <complex>
#include <cstddef>
#include <memory>
#include <mutex>

#include "core/common/eigen_types.h"
#include "core/common/result.h"

namespace mozzi::core::signal {

// The process-wide lock of FFTW's planner. Code that calls FFTW directly
// (pLSCF's and LSCE's plans in core/modal) makes and destroys its plans
// through withFftwPlanner, so that it never plans while RealFft does on
// another thread (the workbench identifies on a worker thread).
std::mutex& fftwPlannerMutex();

// Runs `planning` (fftw_plan_* or fftw_destroy_plan calls) under that lock
// and returns its result.
template <class Planning>
auto withFftwPlanner(Planning&& planning) -> decltype(planning()) {
  std::lock_guard<std::mutex> lock(fftwPlannerMutex());
  return planning();
}

// Heap block aligned as FFTW wants it (fftw_malloc), for inputs and outputs of
// RealFft::forward; move-only. Contents start uninitialised.
template <class T>
class AlignedBuffer {
 public:
  AlignedBuffer() = default;
  explicit AlignedBuffer(std::size_t count);
  ~AlignedBuffer();
  AlignedBuffer(AlignedBuffer&& other) noexcept : data_(other.data_), size_(other.size_) {
    other.data_ = nullptr;
    other.size_ = 0;
  }
  AlignedBuffer& operator=(AlignedBuffer&& other) noexcept;
  AlignedBuffer(const AlignedBuffer&) = delete;
  AlignedBuffer& operator=(const AlignedBuffer&) = delete;

  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

extern template class AlignedBuffer<double>;
extern template class AlignedBuffer<std::complex<double>>;

class RealFft {
 public:
  // The shared plan for length n (created on first use, FFTW_ESTIMATE; for the
  // lengths of core/signal/fftw_wisdom.h from the measured plans kept there). n >= 2.
  static Result<std::shared_ptr<const RealFft>> forLength(Eigen::Index n);

  Eigen::Index length() const { return n_; }
  Eigen::Index lineCount() const { return n_ / 2 + 1; }

  // X_k = sum_i x_i exp(-2 pi i k i / n), k = 0..n/2 (unnormalised, FFTW's
  // sign convention). in: n values, out: n/2 + 1 values. Buffers from
  // AlignedBuffer run in place; other pointers are copied through a
  // thread-local aligned scratch first.
  void forward(const double* in, std::complex<double>* out) const;

  // Inverse: x_i = sum_k X_k exp(+2 pi i k i / n) over the full Hermitian
  // spectrum (unnormalised: inverse(forward(x)) = n x). in: n/2 + 1 values
  // (left untouched), out: n values; any pointers (copied through scratch).
  // Its plan is made on the first call (most users only go forward: planning
  // the c2r transform of 65,536 samples cost `mozzi-cli frf` 1.4 ms); false
  // (out untouched) when FFTW could not make it.
  [[nodiscard]] bool inverse(const std::complex<double>* in, double* out) const;

  // Convenience for tests and one-off use; x must hold length() values.
  Result<ComplexVector> transform(const VectorRef& x) const;

  ~RealFft();
  RealFft(const RealFft&) = delete;
  RealFft& operator=(const RealFft&) = delete;

 private:
  RealFft(Eigen::Index n, void* plan, int inAlign, int outAlign)
      : n_(n), plan_(plan), inAlign_(inAlign), outAlign_(outAlign) {}
  Eigen::Index n_;
  void* plan_;                           // fftw_plan, r2c
  mutable std::once_flag inverseOnce_;   // inversePlan_ made once, on first use
  mutable void* inversePlan_ = nullptr;  // fftw_plan, c2r
  int inAlign_;
  int outAlign_;
};

}  // namespace mozzi::core::signal
