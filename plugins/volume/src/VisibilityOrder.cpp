// SPDX-License-Identifier: MIT
#include "VisibilityOrder.hpp"

#include <volpost/core/WorkerThreads.hpp>

#include "TetMeshGpu.hpp"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <atomic>
#include <array>
#include <chrono>
#include <cmath>
#include <queue>
#include <thread>

namespace volpost::volume {
namespace {

constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};

// Entry and exit parameters of the ray o + t d in a tet (t >= 0), or nothing.
bool rayInterval(const std::array<glm::dvec3, 4>& p, const glm::dvec3& o, const glm::dvec3& d, double& t0, double& t1) {
  t0 = 0.0;
  t1 = INFINITY;
  for (int f = 0; f < 4; ++f) {
    const glm::dvec3 a = p[std::size_t(kFaces[f][0])], b = p[std::size_t(kFaces[f][1])], c = p[std::size_t(kFaces[f][2])];
    glm::dvec3 n = glm::cross(b - a, c - a);
    if (glm::dot(n, p[std::size_t(f)] - a) > 0.0) n = -n;  // outward: away from the opposite vertex
    const double denom = glm::dot(n, d), dist = glm::dot(n, a - o);
    if (denom == 0.0) {
      if (dist < 0.0) return false;  // parallel and outside
      continue;
    }
    const double t = dist / denom;
    if (denom < 0.0) t0 = std::max(t0, t);  // entering through this face
    else t1 = std::min(t1, t);
  }
  return t1 > t0;
}

}  // namespace

std::vector<std::uint32_t> priorityTopologicalOrder(std::size_t n, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges,
                                                    const std::vector<double>& priority, std::size_t* cycleBreaks) {
  std::vector<std::uint32_t> indegree(n, 0), start(n + 1, 0), next(edges.size());
  for (const auto& [a, b] : edges) ++indegree[b], ++start[a + 1];
  for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (const auto& [a, b] : edges) next[fill[a]++] = b;
  using Entry = std::pair<double, std::uint32_t>;
  std::priority_queue<Entry> ready;
  for (std::uint32_t i = 0; i < n; ++i)
    if (indegree[i] == 0) ready.push({priority[i], i});
  std::vector<char> placed(n, 0);
  std::vector<std::uint32_t> order;
  order.reserve(n);
  // Remaining items by priority, for breaking cycles at the farthest one.
  std::priority_queue<Entry> remaining;
  for (std::uint32_t i = 0; i < n; ++i) remaining.push({priority[i], i});
  std::size_t breaks = 0;
  while (order.size() < n) {
    std::uint32_t item;
    if (!ready.empty()) {
      item = ready.top().second;
      ready.pop();
      if (placed[item]) continue;
    } else {  // a cycle: every remaining item waits for another
      while (placed[remaining.top().second]) remaining.pop();
      item = remaining.top().second;
      ++breaks;
    }
    placed[item] = 1;
    order.push_back(item);
    for (std::uint32_t e = start[item]; e < start[item + 1]; ++e)
      if (!placed[next[e]] && --indegree[next[e]] == 0) ready.push({priority[next[e]], next[e]});
  }
  if (cycleBreaks) *cycleBreaks = breaks;
  return order;
}

namespace {

std::vector<glm::ivec4> neighborsOf(const Mesh& tets) {
  std::vector<glm::uvec4> v(tets.cellCount());
  for (std::size_t t = 0; t < v.size(); ++t) {
    const auto n = tets.cellNodes(t);
    v[t] = glm::uvec4(n[0], n[1], n[2], n[3]);
  }
  return faceNeighbors(v);
}

}  // namespace

VisibilitySorter::VisibilitySorter(const Mesh& tets) : VisibilitySorter(tets, neighborsOf(tets)) {}

VisibilitySorter::VisibilitySorter(const Mesh& tets, std::vector<glm::ivec4> neighbors)
    : mesh_(tets), neighbors_(std::move(neighbors)) {
  centroids_.resize(tets.cellCount());
  for (std::size_t t = 0; t < tets.cellCount(); ++t) {
    const auto v = tets.cellNodes(t);
    centroids_[t] = 0.25 * (tets.nodes[v[0]] + tets.nodes[v[1]] + tets.nodes[v[2]] + tets.nodes[v[3]]);
  }
}

std::vector<std::uint32_t> VisibilitySorter::tetsAlongRay(const glm::dvec3& o, const glm::dvec3& d) const {
  std::vector<std::pair<double, std::uint32_t>> hits;
  for (std::uint32_t t = 0; t < mesh_.cellCount(); ++t) {
    const auto v = mesh_.cellNodes(t);
    const std::array<glm::dvec3, 4> p = {mesh_.nodes[v[0]], mesh_.nodes[v[1]], mesh_.nodes[v[2]], mesh_.nodes[v[3]]};
    double t0, t1;
    if (rayInterval(p, o, d, t0, t1)) hits.push_back({0.5 * (t0 + t1), t});
  }
  std::sort(hits.begin(), hits.end());
  std::vector<std::uint32_t> out;
  for (const auto& h : hits) out.push_back(h.second);
  return out;
}

// Rays through pixel centres: consecutive tets that do not share a face are ordered by
// the ray (the farther first). Tets are binned by the pixels their projection covers, so a
// pixel only tests its candidates; rows are shared out among threads.
void VisibilitySorter::imageSpaceRelations(const Camera& camera, int width, int height,
                                           std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges,
                                           VisibilityOrder& result) const {
  const std::size_t n = mesh_.cellCount();
  const double aspect = double(width) / double(height);
  const glm::dmat4 viewProjection = camera.projectionMatrix(aspect) * camera.viewMatrix();
  const glm::dmat4 inverse = glm::inverse(viewProjection);
  std::vector<std::array<int, 4>> box(n);  // pixel x0, x1, y0, y1 (inclusive), x0 > x1: none
  for (std::size_t t = 0; t < n; ++t) {
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    bool behind = false;
    for (NodeIndex v : mesh_.cellNodes(t)) {
      const glm::dvec4 clip = viewProjection * glm::dvec4(mesh_.nodes[v], 1.0);
      if (clip.w <= 0.0) behind = true;
      const double px = (clip.x / clip.w * 0.5 + 0.5) * width - 0.5, py = (0.5 - clip.y / clip.w * 0.5) * height - 0.5;
      x0 = std::min(x0, px), x1 = std::max(x1, px), y0 = std::min(y0, py), y1 = std::max(y1, py);
    }
    if (behind) x0 = 0, y0 = 0, x1 = width - 1, y1 = height - 1;  // crosses the eye plane: every pixel
    box[t] = {std::max(0, int(std::ceil(x0))), std::min(width - 1, int(std::floor(x1))), std::max(0, int(std::ceil(y0))),
              std::min(height - 1, int(std::floor(y1)))};
  }
  std::vector<std::uint32_t> start(std::size_t(width) * std::size_t(height) + 1, 0);
  for (const auto& b : box)
    for (int y = b[2]; y <= b[3]; ++y)
      for (int x = b[0]; x <= b[1]; ++x) ++start[std::size_t(y) * std::size_t(width) + std::size_t(x) + 1];
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  std::vector<std::uint32_t> items(start.back()), fill(start.begin(), start.end() - 1);
  for (std::uint32_t t = 0; t < n; ++t)
    for (int y = box[t][2]; y <= box[t][3]; ++y)
      for (int x = box[t][0]; x <= box[t][1]; ++x) items[fill[std::size_t(y) * std::size_t(width) + std::size_t(x)]++] = t;

  const unsigned workers = std::clamp(usableCores(), 1u, 16u);
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> found(workers);
  std::atomic<int> nextRow{0};
  runOnThreads(workers, [&](unsigned w) {
      std::vector<std::pair<double, std::uint32_t>> hits;
      for (int y; (y = nextRow++) < height;)
        for (int x = 0; x < width; ++x) {
          const double nx = (x + 0.5) / width * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / height * 2.0;
          glm::dvec4 a = inverse * glm::dvec4(nx, ny, -1.0, 1.0), b = inverse * glm::dvec4(nx, ny, 1.0, 1.0);
          a /= a.w;
          b /= b.w;
          const glm::dvec3 o(a), d = glm::dvec3(b) - glm::dvec3(a);
          hits.clear();
          const std::size_t pixel = std::size_t(y) * std::size_t(width) + std::size_t(x);
          for (std::uint32_t k = start[pixel]; k < start[pixel + 1]; ++k) {
            const std::uint32_t t = items[k];
            const auto v = mesh_.cellNodes(t);
            const std::array<glm::dvec3, 4> p = {mesh_.nodes[v[0]], mesh_.nodes[v[1]], mesh_.nodes[v[2]], mesh_.nodes[v[3]]};
            double t0, t1;
            if (rayInterval(p, o, d, t0, t1)) hits.push_back({0.5 * (t0 + t1), t});
          }
          std::sort(hits.begin(), hits.end());
          for (std::size_t i = 0; i + 1 < hits.size(); ++i) {
            const std::uint32_t nearTet = hits[i].second, farTet = hits[i + 1].second;
            const glm::ivec4 nb = neighbors_[nearTet];
            if (nb.x == int(farTet) || nb.y == int(farTet) || nb.z == int(farTet) || nb.w == int(farTet)) continue;
            found[w].push_back({farTet, nearTet});
          }
        }
    });
  for (const auto& f : found) {
    edges.insert(edges.end(), f.begin(), f.end());
    result.imageRelations += f.size();
  }
}

VisibilityOrder VisibilitySorter::order(const Camera& camera, OrderMethod method, int width, int height) const {
  const auto start = std::chrono::steady_clock::now();
  const std::size_t n = mesh_.cellCount();
  const glm::dvec3 eye = camera.eye();
  const bool ortho = camera.projection() == Camera::Projection::Orthographic;
  const glm::dvec3 viewDir = glm::normalize(camera.target() - eye);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(n * 2);
  // MPVO: across each interior face, the tet on the far side of the face from the eye
  // comes first.
  for (std::uint32_t t = 0; t < n; ++t) {
    const auto v = mesh_.cellNodes(t);
    for (int f = 0; f < 4; ++f) {
      const int other = neighbors_[t][f];
      if (other < 0 || std::uint32_t(other) < t) continue;  // each face once
      const glm::dvec3 a = mesh_.nodes[v[std::size_t(kFaces[f][0])]], b = mesh_.nodes[v[std::size_t(kFaces[f][1])]],
                       c = mesh_.nodes[v[std::size_t(kFaces[f][2])]];
      glm::dvec3 normal = glm::cross(b - a, c - a);
      if (glm::dot(normal, mesh_.nodes[v[std::size_t(f)]] - a) > 0.0) normal = -normal;  // out of t
      const double side = ortho ? -glm::dot(normal, viewDir) : glm::dot(normal, eye - a);
      if (side > 0.0) edges.push_back({t, std::uint32_t(other)});  // eye beyond the face: t is behind
      else if (side < 0.0) edges.push_back({std::uint32_t(other), t});
    }
  }
  VisibilityOrder result;
  if (method == OrderMethod::ImageSpace && width > 0 && height > 0) imageSpaceRelations(camera, width, height, edges, result);
  std::vector<double> distance(n);
  for (std::size_t t = 0; t < n; ++t)
    distance[t] = method == OrderMethod::Mpvo ? 0.0 : ortho ? glm::dot(centroids_[t] - eye, viewDir) : glm::length(centroids_[t] - eye);
  result.backToFront = priorityTopologicalOrder(n, edges, distance, &result.cycleBreaks);
  result.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace volpost::volume
