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
#include <thread>

namespace mozzi::core {

// Starts `body` on a new thread placed on a core other than the caller's,
// among the cores the caller may run on; once running, the thread may again
// run on any of those cores (the placement is a start, not a pinning). With
// one allowed core, or where placement is not supported, a plain std::thread.
std::thread startThreadOnAnotherCore(std::function<void()> body);

}  // namespace mozzi::core
