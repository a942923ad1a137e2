// SPDX-License-Identifier: MIT
// Running one piece of work on several threads without trusting the system to give them:
// a thread that cannot start (a thread or memory limit, `--threads 2000` under ulimit) is
// simply not there, and the threads that did start share everything out. No thread object
// is ever destroyed while running (which aborts the process).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <thread>

namespace volpost {

/// The cores this process may run on: those of its CPU affinity where the system says
/// (an MPI rank pinned to one core, a container given two), else every core. At least 1.
unsigned usableCores();

/// Runs work(worker) on up to `count` threads at once, the calling thread being worker 0,
/// and waits for all. work() must share out its items itself (an atomic counter), since
/// fewer threads than asked may start. The first exception a worker throws is rethrown
/// once all have finished. Returns the number of threads that ran.
unsigned runOnThreads(unsigned count, const std::function<void(unsigned worker)>& work);

/// Runs body(begin, end) over [0, n) in chunks of `chunk` items, the chunks shared out over
/// every usable core (runOnThreads). Chunks start at multiples of `chunk`, so begin / chunk
/// numbers a chunk (for per-chunk results kept in order).
template <typename Body>
void forEachChunk(std::size_t n, std::size_t chunk, Body body) {
  std::atomic<std::size_t> next{0};
  runOnThreads(usableCores(), [&](unsigned) {
    for (std::size_t begin; (begin = next.fetch_add(chunk)) < n;) body(begin, std::min(n, begin + chunk));
  });
}

}  // namespace volpost
