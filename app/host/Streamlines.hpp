// SPDX-License-Identifier: MIT
// Streamlines of a nodal vector field through the conforming tetrahedra of a model
// (Araujo & Farias): the velocity is linear in each tet; each step is an adaptive
// Runge-Kutta step (second order with an embedded first-order estimate, as the paper;
// classical fourth order with step doubling and Dormand-Prince 5(4) for comparison); the
// tet holding the next point is found by walking the face adjacency along the step, so a
// line that leaves the mesh stops exactly on the boundary face it crosses.
#pragma once

#include "host/PointLocator.hpp"

#include <volpost/core/Progress.hpp>
#include <volpost/core/Tetrahedralize.hpp>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace volpost {

enum class StreamlineMethod { RK2, RK4, RK45 };
enum class StreamlineDirection { Forward, Backward, Both };
/// Why a line ended (each direction on its own).
enum class StreamlineStop { None, LeftMesh, MaxSteps, MaxLength, Stagnation, ClosedOrbit, StepTooSmall, PointBudget };

/// The most points all lines of one tracing hold together (about 100 MB with their
/// velocities and values, and within the tubes' vertex limit): lines that reach it stop.
inline constexpr std::size_t kMaxStreamlinePoints = std::size_t(2) << 20;

const char* toString(StreamlineMethod method);  ///< "rk2", "rk4", "rk45"
const char* toString(StreamlineDirection direction);  ///< "forward", "backward", "both"
const char* describe(StreamlineStop stop);  ///< "left the mesh", ...

struct StreamlineSettings {
  StreamlineMethod method = StreamlineMethod::RK2;
  StreamlineDirection direction = StreamlineDirection::Both;
  /// Largest position error per step, as a fraction of the model's size (its diagonal).
  double tolerance = 1e-5;
  std::size_t maxSteps = 20000;   ///< per direction
  double maxLength = 0.0;         ///< per direction, model units; 0: 20 x the model's size
  /// |v| below this fraction of the field's largest |v| is a stagnation point.
  double stagnation = 1e-6;
  /// Stop where the line comes back to its seed (a closed orbit), instead of circling on.
  bool stopOnClosedOrbits = true;
  /// Model units between written points inside a step (0: the step ends only). Each extra
  /// point is a Runge-Kutta step of its own from the step's start, as accurate as the ends.
  double pointSpacing = 0.0;
  bool operator==(const StreamlineSettings&) const = default;
};

struct Streamline {
  std::vector<glm::dvec3> points;    ///< backward end ... seed ... forward end
  std::vector<glm::dvec3> velocity;  ///< the field at each point
  std::size_t seedIndex = 0;         ///< where the seed is in `points`
  StreamlineStop backwardStop = StreamlineStop::None, forwardStop = StreamlineStop::None;
  std::size_t steps = 0, rejected = 0;  ///< accepted and rejected steps, both directions
  double length = 0.0;
  /// For a closed orbit: how far the line came back from its seed (model units).
  double closureError = 0.0;
};

class StreamlineTracer {
 public:
  /// `vectors`: one per node of tets.mesh (original nodes, then Steiner points). With
  /// `cells` (the mesh `tets` splits), the velocity inside a cell other than a tet4 is the
  /// cells' own interpolation of the node vectors (trilinear in a hex8, quadratic in a tet10;
  /// its natural coordinates found by Newton's method from the split's), not the split's
  /// linear one; the walk still goes through the split's tetrahedra. `cells` must outlive this.
  StreamlineTracer(const TetMesh& tets, std::vector<glm::dvec3> vectors, const Mesh* cells = nullptr);

  /// Throws std::invalid_argument naming the point when the seed is not in the mesh.
  /// `pointsLeft`, where given, is shared by lines traced together: each point written takes
  /// one, and a line stops (PointBudget) when none is left.
  Streamline trace(const glm::dvec3& seed, const StreamlineSettings& settings,
                   std::atomic<std::int64_t>* pointsLeft = nullptr) const;
  /// Every seed, on all cores, with at most `maxPoints` points in all; seeds outside the
  /// mesh are skipped and counted.
  std::vector<Streamline> traceAll(const std::vector<glm::dvec3>& seeds, const StreamlineSettings& settings,
                                   std::size_t* outside = nullptr, const Progress& progress = {},
                                   std::size_t maxPoints = kMaxStreamlinePoints) const;

  double modelSize() const { return modelSize_; }
  double maxSpeed() const { return maxSpeed_; }
  /// The field at a point inside `tet` (linear interpolation, or its cell's own).
  glm::dvec3 velocityIn(std::uint32_t tet, const glm::dvec3& p) const;

 private:
  struct Walk {
    bool inside = true;        ///< the segment's end is in the mesh
    std::uint32_t tet = 0;     ///< the tet holding the end (or the last one before leaving)
    glm::dvec3 end{0.0};       ///< the segment's end, or the point where it left the mesh
  };
  glm::dvec4 barycentric(std::uint32_t tet, const glm::dvec3& p) const;
  /// Follows the straight segment a -> b from tet `from` (which holds a) through the face
  /// adjacency; stops at the first boundary face it crosses.
  Walk walk(std::uint32_t from, const glm::dvec3& a, const glm::dvec3& b) const;
  double cellSize(std::uint32_t tet) const;
  double gradientNorm(std::uint32_t tet) const;
  void traceOneWay(const glm::dvec3& seed, std::uint32_t tet, double sign, const StreamlineSettings& settings,
                   std::vector<glm::dvec3>& points, std::vector<glm::dvec3>& velocity, StreamlineStop& stop,
                   std::size_t& steps, std::size_t& rejected, double& length, double& closure,
                   std::atomic<std::int64_t>* pointsLeft) const;

  /// The cell's own interpolation at p, barycentric weights `w` in the split's `tet`;
  /// nullopt where the cell's map is not inverted there.
  std::optional<glm::dvec3> ownVelocity(std::uint32_t tet, const glm::dvec4& w, const glm::dvec3& p) const;

  const TetMesh& tets_;
  std::vector<glm::dvec3> vectors_;
  const Mesh* cells_ = nullptr;
  std::vector<char> ownField_;  ///< per cell: drawn by its own shape functions
  std::vector<glm::ivec4> neighbors_;
  PointLocator locator_;
  double modelSize_ = 1.0, maxSpeed_ = 0.0;
};

/// The field's vectors on the tetrahedra's nodes, from a nodal field's values (3 per node of
/// the source mesh; Steiner points get their cell's corner mean).
std::vector<glm::dvec3> tetNodeVectors(const TetMesh& tets, const Mesh& source, const std::vector<double>& nodal);
/// Element vectors (3 per cell) averaged at the nodes over the cells that share them: the
/// stated approximation for fields the solver gives per element.
std::vector<double> averageCellVectorsToNodes(const Mesh& mesh, const std::vector<double>& perCell);

}  // namespace volpost
