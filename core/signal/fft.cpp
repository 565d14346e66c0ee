#include "core/signal/fft.h"

#include <fftw3.h>

#include <algorithm>
#include <cstring>
#include <iterator>
#include <map>
#include <mutex>
#include <string>

#include "core/signal/fftw_wisdom.h"

namespace mozzi::core::signal {

// One lock for every call into FFTW's planner (fftw_plan_*, fftw_destroy_plan):
// the planner shares global state and is not thread-safe (FFTW manual §5.4).
std::mutex& fftwPlannerMutex() {
  static std::mutex m;
  return m;
}

template <class T>
AlignedBuffer<T>::AlignedBuffer(std::size_t count)
    : data_(static_cast<T*>(fftw_malloc(sizeof(T) * (count == 0 ? 1 : count)))), size_(count) {
  if (data_ == nullptr) throw std::bad_alloc();
}

template <class T>
AlignedBuffer<T>::~AlignedBuffer() {
  if (data_ != nullptr) fftw_free(data_);
}

template <class T>
AlignedBuffer<T>& AlignedBuffer<T>::operator=(AlignedBuffer&& other) noexcept {
  if (this != &other) {
    if (data_ != nullptr) fftw_free(data_);
    data_ = other.data_;
    size_ = other.size_;
    other.data_ = nullptr;
    other.size_ = 0;
  }
  return *this;
}

template class AlignedBuffer<double>;
template class AlignedBuffer<std::complex<double>>;

Result<std::shared_ptr<const RealFft>> RealFft::forLength(Eigen::Index n) {
  if (n < 2) {
    return makeError(ErrorCode::InvalidArgument, "FFT length must be at least 2, got " + std::to_string(n), "FFT plan");
  }
  // Cache lives for the whole process (deliberately never destroyed, so no
  // plan outlives FFTW at static destruction).
  static std::mutex cacheMutex;
  static auto* cache = new std::map<Eigen::Index, std::shared_ptr<const RealFft>>();
  std::lock_guard<std::mutex> cacheLock(cacheMutex);
  if (auto it = cache->find(n); it != cache->end()) return it->second;

  AlignedBuffer<double> in(static_cast<std::size_t>(n));
  AlignedBuffer<std::complex<double>> out(static_cast<std::size_t>(n / 2 + 1));
  fftw_plan plan;
  {
    std::lock_guard<std::mutex> lock(fftwPlannerMutex());
    // The measured plans kept in core/signal/fftw_wisdom.h (scripts/fftw-wisdom.sh)
    // for the usual lengths: 40% faster transforms than FFTW_ESTIMATE's and
    // half the planning time. The wisdom is forgotten right after, so that no
    // other plan of the process (pLSCF's, LSCE's) changes. An FFTW that refuses
    // it (another version or CPU) plans by estimate as before.
    const bool wise = std::find(std::begin(fftw_wisdom::kLengths), std::end(fftw_wisdom::kLengths), n) !=
                          std::end(fftw_wisdom::kLengths) &&
                      fftw_import_wisdom_from_string(fftw_wisdom::kText) != 0;
    plan = fftw_plan_dft_r2c_1d(static_cast<int>(n), in.data(), reinterpret_cast<fftw_complex*>(out.data()),
                                FFTW_ESTIMATE);
    if (wise) fftw_forget_wisdom();
  }
  if (plan == nullptr) {
    return makeError(ErrorCode::NumericalFailure, "FFTW could not create a plan of length " + std::to_string(n),
                     "FFT plan");
  }
  std::shared_ptr<const RealFft> fft(
      new RealFft(n, plan, fftw_alignment_of(in.data()), fftw_alignment_of(reinterpret_cast<double*>(out.data()))));
  (*cache)[n] = fft;
  return fft;
}

RealFft::~RealFft() {
  std::lock_guard<std::mutex> lock(fftwPlannerMutex());
  fftw_destroy_plan(static_cast<fftw_plan>(plan_));
  if (inversePlan_ != nullptr) fftw_destroy_plan(static_cast<fftw_plan>(inversePlan_));
}

bool RealFft::inverse(const std::complex<double>* in, double* out) const {
  std::call_once(inverseOnce_, [this] {
    AlignedBuffer<std::complex<double>> spectrum(static_cast<std::size_t>(lineCount()));
    AlignedBuffer<double> samples(static_cast<std::size_t>(n_));
    std::lock_guard<std::mutex> lock(fftwPlannerMutex());
    inversePlan_ = fftw_plan_dft_c2r_1d(static_cast<int>(n_), reinterpret_cast<fftw_complex*>(spectrum.data()),
                                        samples.data(), FFTW_ESTIMATE);
  });
  if (inversePlan_ == nullptr) return false;
  // c2r overwrites its input, so the spectrum always goes through scratch.
  thread_local AlignedBuffer<std::complex<double>> scratchIn;
  thread_local AlignedBuffer<double> scratchOut;
  if (scratchIn.size() < static_cast<std::size_t>(lineCount())) {
    scratchIn = AlignedBuffer<std::complex<double>>(static_cast<std::size_t>(lineCount()));
  }
  if (scratchOut.size() < static_cast<std::size_t>(n_))
    scratchOut = AlignedBuffer<double>(static_cast<std::size_t>(n_));
  std::memcpy(static_cast<void*>(scratchIn.data()), in,
              sizeof(std::complex<double>) * static_cast<std::size_t>(lineCount()));
  fftw_execute_dft_c2r(static_cast<fftw_plan>(inversePlan_), reinterpret_cast<fftw_complex*>(scratchIn.data()),
                       scratchOut.data());
  std::memcpy(out, scratchOut.data(), sizeof(double) * static_cast<std::size_t>(n_));
  return true;
}

void RealFft::forward(const double* in, std::complex<double>* out) const {
  auto plan = static_cast<fftw_plan>(plan_);
  double* inPtr = const_cast<double*>(in);  // out-of-place r2c leaves the input untouched
  const bool inOk = fftw_alignment_of(inPtr) == inAlign_;
  const bool outOk = fftw_alignment_of(reinterpret_cast<double*>(out)) == outAlign_;
  if (inOk && outOk) {
    fftw_execute_dft_r2c(plan, inPtr, reinterpret_cast<fftw_complex*>(out));
    return;
  }
  thread_local AlignedBuffer<double> scratchIn;
  thread_local AlignedBuffer<std::complex<double>> scratchOut;
  if (scratchIn.size() < static_cast<std::size_t>(n_)) scratchIn = AlignedBuffer<double>(static_cast<std::size_t>(n_));
  if (scratchOut.size() < static_cast<std::size_t>(lineCount())) {
    scratchOut = AlignedBuffer<std::complex<double>>(static_cast<std::size_t>(lineCount()));
  }
  std::memcpy(scratchIn.data(), in, sizeof(double) * static_cast<std::size_t>(n_));
  fftw_execute_dft_r2c(plan, scratchIn.data(), reinterpret_cast<fftw_complex*>(scratchOut.data()));
  std::memcpy(static_cast<void*>(out), scratchOut.data(),
              sizeof(std::complex<double>) * static_cast<std::size_t>(lineCount()));
}

Result<ComplexVector> RealFft::transform(const VectorRef& x) const {
  if (x.size() != n_) {
    return makeError(ErrorCode::InvalidArgument,
                     "input has " + std::to_string(x.size()) + " samples, plan expects " + std::to_string(n_), "FFT");
  }
  ComplexVector out(lineCount());
  Vector copy = x;
  forward(copy.data(), out.data());
  return out;
}

}  // namespace mozzi::core::signal
