// SPDX-License-Identifier: MIT
// Matching the faces of a volume mesh without a list of every face with its corners: each
// face is listed under its smallest corner (both copies of a shared face land in one group)
// as a small id, and each group, a few dozen faces, is matched on its own. Large meshes go
// in passes over shares of the vertex numbers holding about equal numbers of faces, so the
// lists hold a share of the faces at once. Every step runs on all cores. Installed with the
// SDK for plugins that match faces of their own (the host's boundary surface does).
#pragma once

#include <volpost/core/WorkerThreads.hpp>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace volpost {

/// listFaces(visit) calls visit(smallest corner, id) for every face, the same faces each
/// time it is called (from several threads: visit is thread-safe). matchGroup(ids) is called
/// once per vertex that is the smallest corner of any face, with those faces' ids, from
/// several threads. `passes` >= 1 shares of the vertices are listed one after the other.
template <typename Id, typename ListFaces, typename MatchGroup>
void forEachFaceGroup(std::size_t vertexCount, std::size_t passes, ListFaces listFaces, MatchGroup matchGroup) {
  if (vertexCount == 0) return;
  // How many faces each vertex is the smallest corner of (one pass over the faces), then
  // where its group starts.
  std::vector<std::atomic<std::uint32_t>> cursor(vertexCount);
  listFaces([&cursor](std::size_t v, Id) { cursor[v].fetch_add(1, std::memory_order_relaxed); });
  std::vector<std::uint64_t> start(vertexCount + 1, 0);
  for (std::size_t v = 0; v < vertexCount; ++v) {
    start[v + 1] = start[v] + cursor[v].load(std::memory_order_relaxed);
    cursor[v].store(0, std::memory_order_relaxed);
  }
  const std::uint64_t total = start.back();
  std::size_t lo = 0;
  for (std::size_t pass = 0; pass < passes && lo < vertexCount; ++pass) {
    // This pass' vertices: up to the one where about (pass + 1) / passes of the faces end.
    const std::uint64_t until = pass + 1 == passes ? total : total * (pass + 1) / passes;
    std::size_t hi = std::size_t(std::upper_bound(start.begin() + std::ptrdiff_t(lo) + 1, start.end(), until) - start.begin()) - 1;
    hi = std::max(hi, lo + 1);
    if (pass + 1 == passes) hi = vertexCount;
    const std::uint64_t first = start[lo];
    std::vector<Id> listed(std::size_t(start[hi] - first));
    listFaces([&](std::size_t v, Id id) {
      if (v >= lo && v < hi) listed[std::size_t(start[v] - first) + cursor[v].fetch_add(1, std::memory_order_relaxed)] = id;
    });
    forEachChunk(hi - lo, std::size_t(1) << 12, [&](std::size_t begin, std::size_t end) {
      for (std::size_t v = lo + begin; v < lo + end; ++v)
        if (start[v + 1] > start[v])
          matchGroup(std::span<const Id>(listed.data() + (start[v] - first), std::size_t(start[v + 1] - start[v])));
    });
    lo = hi;
  }
}

}  // namespace volpost
