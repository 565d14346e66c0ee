#include "core/signal/pooled_buffer.h"

#include <algorithm>
#include <mutex>
#include <vector>

namespace mozzi::core::signal {

namespace {
// A handful of blocks is enough for the usual pattern (one averager per
// measurement point, a few alive at once); more are freed normally.
constexpr std::size_t kPoolBlocks = 8;

struct Pool {
  std::mutex mutex;
  std::vector<AlignedBuffer<double>> blocks;
};

Pool& pool() {
  static auto* p = new Pool();  // never destroyed: blocks may return during static destruction
  return *p;
}

// A pooled block with capacity in [count, 2 count] (so a small request does not
// pin a huge block), or a new one.
AlignedBuffer<double> acquire(std::size_t count) {
  {
    Pool& p = pool();
    std::lock_guard<std::mutex> lock(p.mutex);
    for (auto it = p.blocks.begin(); it != p.blocks.end(); ++it) {
      if (it->size() >= count && it->size() / 2 <= count) {
        AlignedBuffer<double> b = std::move(*it);
        p.blocks.erase(it);
        return b;
      }
    }
  }
  return AlignedBuffer<double>(count);
}
}  // namespace

PooledBuffer::PooledBuffer(std::size_t count, Init init) : buffer_(acquire(count)), size_(count) {
  if (init == Init::Zero) setZero();
}

PooledBuffer::~PooledBuffer() {
  release();
}

void PooledBuffer::release() {
  if (buffer_.data() == nullptr) return;
  Pool& p = pool();
  std::lock_guard<std::mutex> lock(p.mutex);
  if (p.blocks.size() < kPoolBlocks) p.blocks.push_back(std::move(buffer_));
  buffer_ = AlignedBuffer<double>();
  size_ = 0;
}

PooledBuffer& PooledBuffer::operator=(PooledBuffer&& other) noexcept {
  if (this != &other) {
    release();
    buffer_ = std::move(other.buffer_);
    size_ = other.size_;
    other.size_ = 0;
  }
  return *this;
}

PooledBuffer::PooledBuffer(const PooledBuffer& other) : buffer_(acquire(other.size_)), size_(other.size_) {
  std::copy(other.data(), other.data() + size_, buffer_.data());
}

PooledBuffer& PooledBuffer::operator=(const PooledBuffer& other) {
  if (this != &other) {
    PooledBuffer copy(other);
    *this = std::move(copy);
  }
  return *this;
}

void PooledBuffer::setZero() {
  std::fill(buffer_.data(), buffer_.data() + size_, 0.0);
}

}  // namespace mozzi::core::signal
