#pragma once
// Starting a helper thread where it can run at once.
//
// A new thread is queued on its creator's core; Linux moves it to an idle
// core only when the creator blocks or at the next load balancing, which on
// the 2-core reference machine took 2-3 ms (median 2.4-3.0 ms against
// 0.12-0.14 ms when placed, measured with a creator busy for 3 ms). A
// command's helper that should overlap the first 2 ms of its creator's work
// (`mozzi-cli frf` plans its FFT while the first hit is read, issue 19)
// would otherwise start after them.

#include <functional>
#include <memory>
#include <thread>

namespace mozzi::core {

// Starts `body` on a new thread placed on a core other than the caller's,
// among the cores the caller may run on; once running, the thread may again
// run on any of those cores (the placement is a start, not a pinning). With
// one allowed core, or where placement is not supported, a plain std::thread.
std::thread startThreadOnAnotherCore(std::function<void()> body);

// A helper thread that works hand in hand with its creator, as a pipeline's
// second stage: the creator hands work over and at times waits for it, the
// helper sleeps between pieces. Linux may wake a thread on its waker's core
// when it judges that cheaper than a move, so two such threads end up taking
// turns on one core while the other idles: `mozzi-cli frf` took 29 ms at
// rest with its averaging thread merely placed at its start, 21 ms with the
// two held apart (median of 40; docs/performance/commands.md, eighth pass).
// While the helper runs, the creator is held on the core it was on and the
// helper on another of the creator's cores; join() restores the creator's
// cores. With one allowed core, or where that is not supported, a plain
// thread and nothing held. Under load the pair shares its two cores with the
// other processes as any two threads do (measured beside a busy process:
// no slower than unheld).
class PairedThread {
 public:
  PairedThread();
  explicit PairedThread(std::function<void()> body);
  PairedThread(PairedThread&&) noexcept;
  PairedThread& operator=(PairedThread&&) noexcept;
  PairedThread(const PairedThread&) = delete;
  PairedThread& operator=(const PairedThread&) = delete;
  ~PairedThread();  // joins when still joinable

  bool joinable() const { return thread_.joinable(); }
  // Waits for the helper, then gives the creator back its cores.
  void join();

 private:
  struct CreatorCores;  // the creator's thread and the cores it had
  std::thread thread_;
  std::unique_ptr<CreatorCores> creator_;
};

}  // namespace mozzi::core
