#pragma once
// Zeroed, FFTW-aligned blocks of doubles recycled through a small process-wide
// pool. Large accumulators (the spectral averager's, megabytes per measurement
// point) otherwise come fresh from the kernel each time an averager is created
// per estimate, and the page faults that zero them cost a third of the FFTs'
// time (docs/performance/signal.md). A block goes back to the pool when its
// owner is destroyed; the pool keeps a few blocks and is thread-safe.

#include <cstddef>
#include <utility>

#include "core/signal/fft.h"

namespace mozzi::core::signal {

class PooledBuffer {
 public:
  PooledBuffer() = default;
  enum class Init { Zero, Uninitialised };
  explicit PooledBuffer(std::size_t count, Init init = Init::Zero);  // count doubles
  ~PooledBuffer();
  PooledBuffer(PooledBuffer&& other) noexcept : buffer_(std::move(other.buffer_)), size_(other.size_) {
    other.size_ = 0;
  }
  PooledBuffer& operator=(PooledBuffer&& other) noexcept;
  PooledBuffer(const PooledBuffer& other);  // deep copy
  PooledBuffer& operator=(const PooledBuffer& other);

  double* data() { return buffer_.data(); }
  const double* data() const { return buffer_.data(); }
  std::size_t size() const { return size_; }
  void setZero();

 private:
  void release();
  AlignedBuffer<double> buffer_;  // capacity buffer_.size() >= size_
  std::size_t size_ = 0;
};

}  // namespace mozzi::core::signal
