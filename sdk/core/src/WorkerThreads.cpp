// SPDX-License-Identifier: MIT
#include <volpost/core/WorkerThreads.hpp>

#if defined(__linux__)
#include <sched.h>
#endif

#include <algorithm>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace volpost {

unsigned usableCores() {
#if defined(__linux__)
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return unsigned(CPU_COUNT(&set));
#endif
  return std::max(1u, std::thread::hardware_concurrency());
}

unsigned runOnThreads(unsigned count, const std::function<void(unsigned worker)>& work) {
  std::exception_ptr failure;
  std::mutex failureMutex;
  const auto guarded = [&](unsigned worker) {
    try {
      work(worker);
    } catch (...) {
      const std::lock_guard lock(failureMutex);
      if (!failure) failure = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (unsigned w = 1; w < count; ++w) {
    try {
      pool.emplace_back(guarded, w);
    } catch (const std::system_error&) {
      break;  // no more threads to be had: the ones running (and this one) do the rest
    } catch (const std::bad_alloc&) {
      break;
    }
  }
  guarded(0);
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  return unsigned(pool.size()) + 1;
}

}  // namespace volpost
