// SPDX-License-Identifier: MIT
#include "host/AdaptiveElementRefinement.hpp"

#include "host/ElementCellMap.hpp"

#include <volpost/core/WorkerThreads.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace volpost {
namespace {

// A piece's corners are named by their barycentric weights in the split tetrahedron it
// came from, in fixed point: halving an edge is then exact for the 30 halvings a
// coordinate can take, and a weight costs 4 bytes instead of 8.
constexpr std::uint32_t kOne = 1u << 30;
constexpr int kMaxBisections = 60;  // about 2^-20 of the split's edge: far below any budget

using Weights = std::array<std::uint32_t, 3>;  // of the split's corners 1..3; corner 0 has the rest

struct Piece {
  std::array<NodeIndex, 4> nodes;
  std::uint32_t splitTet;
  std::array<Weights, 4> weights;
  float error;  ///< the estimated change of a pixel's channel the piece makes
  std::uint8_t bisections;
};

constexpr std::array<std::array<int, 2>, 6> kEdges{{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

std::array<double, 4> barycentric(const Weights& w) {
  const double a = w[0] / double(kOne), b = w[1] / double(kOne), c = w[2] / double(kOne);
  return {1.0 - a - b - c, a, b, c};
}

Weights halfway(const Weights& a, const Weights& b) {
  Weights m;
  for (int k = 0; k < 3; ++k)
    m[std::size_t(k)] = std::uint32_t((std::uint64_t(a[std::size_t(k)]) + b[std::size_t(k)]) / 2);
  return m;
}

std::uint64_t edgeKey(NodeIndex a, NodeIndex b) {
  return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

// What the transfer function does between the values lo and hi: the largest change of a
// pixel per unit of value and of ray (pixelChangePerValue), and the largest extinction.
struct Sensitivity {
  double perValue = 0.0, extinction = 0.0;
};

Sensitivity sensitivityOf(const TransferFunction& tf, double lo, double hi) {
  const auto& points = tf.points();
  Sensitivity out;
  if (points.empty() || !(lo <= hi)) return out;
  out.extinction = std::min(std::max(tf.extinction(lo), tf.extinction(hi)), kMaxFloatExtinction);
  if (points.size() < 2 || hi < points.front().value || lo > points.back().value) return out;
  const auto after =
      std::upper_bound(points.begin(), points.end(), lo, [](double v, const ControlPoint& p) { return v < p.value; });
  std::size_t i = after == points.begin() ? 0 : std::size_t(after - points.begin()) - 1;
  // A step (two points at one value) has no slope: it counts as a ramp over a millionth of
  // the function's range, so a piece across it is cut as finely as the budget allows.
  const double narrowest = 1e-6 * std::max(points.back().value - points.front().value, 1e-300);
  for (; i + 1 < points.size() && points[i].value <= hi; ++i) {
    const ControlPoint &a = points[i], &b = points[i + 1];
    const double width = std::max(b.value - a.value, narrowest);
    const glm::dvec3 dc = glm::abs(b.color - a.color) / width;
    const double extinction = std::min(std::max(a.extinction, b.extinction), kMaxFloatExtinction);
    const double slope = std::min(std::abs(b.extinction - a.extinction), kMaxFloatExtinction) / width;
    out.perValue = std::max(out.perValue, std::max({dc.x, dc.y, dc.z}) * extinction + slope);
    if (b.value <= hi) out.extinction = std::max(out.extinction, std::min(b.extinction, kMaxFloatExtinction));
  }
  return out;
}

// The pieces and their points while they are bisected, with which pieces hold each point
// (a cut must find every piece around the edge it halves).
class Bisection {
 public:
  Bisection(const optics::ElementField& field, const VolumeRefinementGoal& goal)
      : field_(field),
        goal_(goal),
        splitValues_(field.split().nodeValues(field.mesh(), field.values())),
        map_(field.mesh(), field, field.split(), splitValues_) {}

  void start(std::span<const std::uint32_t> chosen, const Progress& progress) {
    const TetMesh& split = field_.split();
    std::unordered_map<NodeIndex, NodeIndex> pointOf;
    pieces_.reserve(chosen.size());
    for (std::uint32_t tet : chosen) {
      if (pieces_.size() % 65536 == 0) progress.report(0.0);
      map_.select(tet);
      const auto corners = split.mesh.cellNodes(tet);
      Piece p{};
      p.splitTet = tet;
      for (int k = 0; k < 4; ++k) {
        Weights w{0, 0, 0};
        if (k > 0) w[std::size_t(k - 1)] = kOne;
        p.weights[std::size_t(k)] = w;
        const auto [it, added] = pointOf.try_emplace(corners[std::size_t(k)], NodeIndex(values_.size()));
        if (added) addPoint(w);
        p.nodes[std::size_t(k)] = it->second;
      }
      add(p);
    }
  }

  std::size_t size() const { return pieces_.size(); }

  /// Estimates the new pieces, on every core (each with a map of its own), and queues
  /// those above the tolerance.
  void estimateNew(const Progress& progress, double fraction) {
    std::atomic<std::size_t> next{0};
    runOnThreads(usableCores(), [&](unsigned) {
      CellMap map(field_.mesh(), field_, field_.split(), splitValues_);
      constexpr std::size_t kChunk = 1024;
      for (std::size_t begin; (begin = next.fetch_add(kChunk)) < unestimated_.size();) {
        progress.report(fraction);
        for (std::size_t k = begin; k < std::min(unestimated_.size(), begin + kChunk); ++k) {
          Piece& p = pieces_[unestimated_[k]];
          p.error = float(errorOf(map, p));
        }
      }
    });
    for (std::uint32_t index : unestimated_) {
      const Piece& p = pieces_[index];
      if (p.error > goal_.perChannel && p.bisections < kMaxBisections) {
        queue_.push_back({p.error, index, versions_[index]});
        std::push_heap(queue_.begin(), queue_.end());
      }
    }
    unestimated_.clear();
  }

  /// The largest estimate of a piece still to cut (0 when none is left).
  double worst() {
    dropStale();
    return queue_.empty() ? 0.0 : double(queue_.front().error);
  }

  /// Cuts the worst piece across its longest edge, with every piece around that edge (and
  /// first, Rivara's rule, any of those whose own longest edge is another: cut across that).
  void cutWorst() {
    dropStale();
    const Queued top = queue_.front();
    std::pop_heap(queue_.begin(), queue_.end());
    queue_.pop_back();
    const Piece& p = pieces_[top.piece];
    const int e = longestEdge(p);
    cutAround(p.nodes[std::size_t(kEdges[std::size_t(e)][0])], p.nodes[std::size_t(kEdges[std::size_t(e)][1])], 0);
  }

  RefinedTetrahedra result() && {
    RefinedTetrahedra out;
    std::vector<NodeIndex> connectivity;
    connectivity.reserve(pieces_.size() * 4);
    out.tets.cellOfTet.reserve(pieces_.size());
    int deepest = 0;
    for (const Piece& p : pieces_) {
      std::array<NodeIndex, 4> v = p.nodes;
      const auto& x = positions_;
      // Positive, as the split's tetrahedra are (the cell's map keeps orientation).
      if (glm::dot(x[v[1]] - x[v[0]], glm::cross(x[v[2]] - x[v[0]], x[v[3]] - x[v[0]])) < 0.0) std::swap(v[2], v[3]);
      connectivity.insert(connectivity.end(), v.begin(), v.end());
      out.tets.cellOfTet.push_back(field_.split().sourceCell(p.splitTet));
      out.deviation = std::max(out.deviation, double(p.error));
      deepest = std::max(deepest, int(p.bisections));
    }
    pieces_ = {};
    holders_ = {};
    out.tets.mesh.nodes = std::move(positions_);
    out.tets.mesh.takeCells(CellType::Tet4, std::move(connectivity));
    out.tets.originalNodes = out.tets.mesh.nodes.size();
    out.values = std::move(values_);
    out.bisections = deepest;
    out.toleranceReached = out.deviation <= goal_.perChannel;
    return out;
  }

 private:
  struct Queued {
    float error;
    std::uint32_t piece, version;
    bool operator<(const Queued& o) const { return error < o.error; }
  };

  const optics::ElementField& field_;
  const VolumeRefinementGoal& goal_;
  std::vector<double> splitValues_;
  CellMap map_;
  std::vector<Piece> pieces_;
  std::vector<std::uint32_t> versions_;  ///< per piece: how often it was replaced by a half
  std::vector<glm::dvec3> positions_;
  std::vector<double> values_;
  std::vector<std::vector<std::uint32_t>> holders_;  ///< per point: the pieces it is a corner of
  std::vector<Queued> queue_;                        ///< pieces above the tolerance, worst first
  std::vector<std::uint32_t> unestimated_;           ///< new pieces, not in queue_ yet

  // The map must have selected the piece's split tetrahedron.
  void addPoint(const Weights& w) {
    glm::dvec3 position;
    double value = 0.0;
    map_.at(barycentric(w), position, value);
    positions_.push_back(position);
    values_.push_back(value);
    holders_.emplace_back();
  }

  void add(const Piece& p) {
    const auto index = std::uint32_t(pieces_.size());
    pieces_.push_back(p);
    versions_.push_back(0);
    for (NodeIndex v : p.nodes) holders_[v].push_back(index);
    unestimated_.push_back(index);
  }

  void dropStale() {
    while (!queue_.empty() && queue_.front().version != versions_[queue_.front().piece]) {
      std::pop_heap(queue_.begin(), queue_.end());
      queue_.pop_back();
    }
  }

  // The longest edge, ties broken by the points' numbers: every piece sharing two edges of
  // one length picks the same one, which the cuts' conformity rests on.
  int longestEdge(const Piece& p) const {
    int best = 0;
    double bestLength = -1.0;
    std::uint64_t bestKey = 0;
    for (int e = 0; e < 6; ++e) {
      const NodeIndex a = p.nodes[std::size_t(kEdges[std::size_t(e)][0])];
      const NodeIndex b = p.nodes[std::size_t(kEdges[std::size_t(e)][1])];
      const glm::dvec3 d = positions_[b] - positions_[a];
      const double length = glm::dot(d, d);
      const std::uint64_t key = edgeKey(a, b);
      if (length > bestLength || (length == bestLength && key > bestKey)) best = e, bestLength = length, bestKey = key;
    }
    return best;
  }

  // Halves the edge a-b in every piece around it, once each of those has it as its longest
  // edge (a piece whose longest edge is another has that one halved first, which cuts it; a
  // longer edge each time, so this ends).
  void cutAround(NodeIndex a, NodeIndex b, int depth) {
    if (depth > 1000) throw std::logic_error("longest-edge bisection: no end to the chain of longer edges");
    const std::uint64_t edge = edgeKey(a, b);
    for (;;) {
      std::vector<std::uint32_t> around;
      for (std::uint32_t i : holders_[a]) {
        const auto& v = pieces_[i].nodes;
        if (std::find(v.begin(), v.end(), b) != v.end()) around.push_back(i);
      }
      bool ready = true;
      for (std::uint32_t i : around) {
        const Piece& p = pieces_[i];
        const int e = longestEdge(p);
        const NodeIndex pa = p.nodes[std::size_t(kEdges[std::size_t(e)][0])];
        const NodeIndex pb = p.nodes[std::size_t(kEdges[std::size_t(e)][1])];
        if (edgeKey(pa, pb) != edge) {
          cutAround(pa, pb, depth + 1);
          ready = false;
          break;
        }
      }
      if (!ready) continue;  // the pieces around a-b changed: look again
      if (around.empty()) return;
      NodeIndex middle = 0;
      for (std::size_t k = 0; k < around.size(); ++k)
        middle = bisect(around[k], a, b, k == 0 ? std::nullopt : std::optional(middle));
      return;
    }
  }

  // Cuts piece i across its edge a-b at `middle` (made here from the piece's cell where not
  // given); the first half takes the piece's place, the second is added.
  NodeIndex bisect(std::uint32_t i, NodeIndex a, NodeIndex b, std::optional<NodeIndex> middle) {
    const Piece p = pieces_[i];
    const auto corner = [&p](NodeIndex v) {
      return int(std::find(p.nodes.begin(), p.nodes.end(), v) - p.nodes.begin());
    };
    const int ca = corner(a), cb = corner(b);
    const Weights halfwayWeights = halfway(p.weights[std::size_t(ca)], p.weights[std::size_t(cb)]);
    if (!middle) {
      map_.select(p.splitTet);
      middle = NodeIndex(values_.size());
      addPoint(halfwayWeights);
    }
    Piece first = p, second = p;
    first.nodes[std::size_t(cb)] = second.nodes[std::size_t(ca)] = *middle;
    first.weights[std::size_t(cb)] = second.weights[std::size_t(ca)] = halfwayWeights;
    first.bisections = second.bisections = std::uint8_t(p.bisections + 1);
    auto& holdersOfB = holders_[b];
    holdersOfB.erase(std::find(holdersOfB.begin(), holdersOfB.end(), i));
    holders_[*middle].push_back(i);
    pieces_[i] = first;
    ++versions_[i];
    unestimated_.push_back(i);
    add(second);
    return *middle;
  }

  // How far the piece's straight edges and linear values stray from the cell's map and
  // field (at the middles of its edges and at its centre), and what that does to a pixel.
  double errorOf(CellMap& map, const Piece& p) const {
    if (!map.select(p.splitTet)) return 0.0;  // a cell drawn linearly: its pieces are exact
    std::array<std::array<double, 4>, 4> w;
    for (int k = 0; k < 4; ++k) w[std::size_t(k)] = barycentric(p.weights[std::size_t(k)]);
    double stray = 0.0, bend = 0.0, shift = 0.0, lo = std::numeric_limits<double>::infinity(), hi = -lo, longest = 0.0;
    const auto probe = [&](const std::array<double, 4>& at, const glm::dvec3& straight, double linear, double length) {
      glm::dvec3 m;
      double fm = 0.0;
      map.at(at, m, fm);
      const glm::dvec3 moved = straight - m;
      if (length > 0.0 && !map.flatFaced()) {
        bend = std::max(bend, glm::length(moved) / length);
        shift = std::max(shift, glm::length(moved));
      }
      // The straight piece gives its straight middle the mean of the ends; the field there
      // is the value at m carried along the gradient by the move.
      // (The gradient is the costly part: only where the map moved the point at all.)
      const double carried = glm::dot(moved, moved) > 1e-24 * length * length ? glm::dot(map.gradient(at), moved) : 0.0;
      const double d = std::abs(fm + carried - linear);
      if (std::isfinite(d)) stray = std::max(stray, d);
      if (std::isfinite(fm)) lo = std::min(lo, fm), hi = std::max(hi, fm);
    };
    for (NodeIndex v : p.nodes)
      if (std::isfinite(values_[v])) lo = std::min(lo, values_[v]), hi = std::max(hi, values_[v]);
    for (const auto& [a, b] : kEdges) {
      std::array<double, 4> mid;
      for (int k = 0; k < 4; ++k)
        mid[std::size_t(k)] = 0.5 * (w[std::size_t(a)][std::size_t(k)] + w[std::size_t(b)][std::size_t(k)]);
      const glm::dvec3 xa = positions_[p.nodes[std::size_t(a)]], xb = positions_[p.nodes[std::size_t(b)]];
      const double length = glm::length(xb - xa);
      longest = std::max(longest, length);
      probe(mid, 0.5 * (xa + xb), 0.5 * (values_[p.nodes[std::size_t(a)]] + values_[p.nodes[std::size_t(b)]]), length);
    }
    std::array<double, 4> centre{};
    glm::dvec3 straight(0.0);
    double linear = 0.0;
    for (int k = 0; k < 4; ++k) {
      for (int j = 0; j < 4; ++j) centre[std::size_t(j)] += 0.25 * w[std::size_t(k)][std::size_t(j)];
      straight += 0.25 * positions_[p.nodes[std::size_t(k)]];
      linear += 0.25 * values_[p.nodes[std::size_t(k)]];
    }
    probe(centre, straight, linear, longest);
    if (!(hi >= lo)) return 0.0;  // no value is a number: the volume leaves the piece out
    return pixelChange(stray, bend, shift, lo - stray, hi + stray, longest);
  }

  double pixelChange(double stray, double bend, double shift, double lo, double hi, double size) const {
    const TransferFunction* tf = goal_.transferFunction;
    if (!tf || tf->points().size() < 2) return std::max(10.0 * stray / field_.valueScale(), 10.0 * bend);
    if (tf->transparentOver(lo, hi)) return 0.0;
    // A field off by `stray` along the piece (`size`, its longest edge: the most ray it
    // holds) changes a channel by about stray times the change per value times that length;
    // a curved face `shift` away from the straight one adds or takes that much ray, of
    // optical depth shift times the extinction.
    const Sensitivity seen = sensitivityOf(*tf, lo, hi);
    return std::max(size * stray * seen.perValue, shift * seen.extinction);
  }
};

}  // namespace

double pixelChangePerValue(const TransferFunction& tf, double lo, double hi) {
  return sensitivityOf(tf, lo, hi).perValue;
}

RefinedTetrahedra refineVolumeAdaptively(const optics::ElementField& field, std::span<const std::uint32_t> chosen,
                                         const VolumeRefinementGoal& goal, const Progress& progress) {
  Bisection pieces(field, goal);
  pieces.start(chosen, progress);
  pieces.estimateNew(progress, 0.0);
  const double first = pieces.worst();
  double fraction = 0.0;
  while (pieces.worst() > 0.0 && pieces.size() < goal.maxTetrahedra) {
    // Worst first, in rounds: a round cuts at most an eighth of what the budget has left
    // (the cuts that keep the pieces conforming add more), so the budget goes where the
    // error is; the new pieces are estimated together, on every core.
    const std::size_t room = std::max<std::size_t>((goal.maxTetrahedra - pieces.size()) / 8, 1);
    for (std::size_t cut = 0; cut < room && pieces.worst() > 0.0 && pieces.size() < goal.maxTetrahedra; ++cut)
      pieces.cutWorst();
    pieces.estimateNew(progress, fraction);
    if (pieces.worst() > 0.0) {
      // How far along: the worst piece's way down to the tolerance, or the budget's use.
      const double byError = std::log(first / pieces.worst()) / std::log(first / goal.perChannel);
      fraction =
          std::clamp(std::max({fraction, byError, double(pieces.size()) / double(goal.maxTetrahedra)}), 0.0, 0.99);
    }
    progress.report(fraction);
  }
  progress.report(1.0);
  return std::move(pieces).result();
}

}  // namespace volpost
