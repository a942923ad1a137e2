// SPDX-License-Identifier: MIT
// The cells' own field and shape, on tetrahedra that surfaces are drawn from. Each chosen
// tetrahedron of a cell's split is subdivided n times along every edge in the cell's
// natural coordinates; its new points are placed by the cell's isoparametric map and take
// the value of the cell's shape functions there. Marching tetrahedra over the result then
// finds the finite-element field's own level set (rounded where a hex8's trilinear field
// is, not faceted like its split's) and the section of a curved cell by a plane, colored
// by the cell's interpolation, to the tolerance (docs/methods/element_field.md).
#pragma once

#include "host/BoundarySurface.hpp"

#include <volpost/core/Mesh.hpp>
#include <volpost/core/Progress.hpp>
#include <volpost/core/Tetrahedralize.hpp>
#include <volpost/core/optics/ElementField.hpp>

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace volpost {

struct RefinementLimits {
  /// The most a linear piece may stray from the cell's field (a fraction of the values'
  /// range) and from its shape (a fraction of the piece's edge), estimated at edge midpoints.
  double tolerance = 1e-3;
  int maxLevel = 8;                       ///< subdivisions along an edge at most
  std::size_t maxTetrahedra = 4'000'000;  ///< the level is lowered to stay below this
  std::size_t maxTriangles = 4'000'000;   ///< and for a surface, below this
  bool operator==(const RefinementLimits&) const = default;
};

/// The limits surfaces of the cells' own field are refined to for the element tolerance
/// `perChannel` (the most a pixel's channel may differ from the exact picture, as the volume
/// takes it): the field within a tenth of it relative to the values' range (a color map
/// changes a channel by at most 10 per unit of its range: the usual maps by 1.5 to 4), the
/// shape within a tenth of it relative to a piece's side; 0 (exact): as finely as the level
/// and triangle limits allow. The default 0.01 gives RefinementLimits' 1/1000.
RefinementLimits limitsForElementTolerance(double perChannel);

struct RefinedTetrahedra {
  /// The pieces: tet4 cells; cellOfTet names each piece's cell of the model. Points shared
  /// by neighbouring pieces (across cells too) are one node, so surfaces stay closed.
  TetMesh tets;
  std::vector<double> values;  ///< one per node of tets.mesh: the cell's field there
  int level = 1;               ///< subdivisions along each edge of the split's tetrahedra
  int bisections = 0;          ///< where pieces were bisected instead: the most times one was halved
  /// The estimated largest deviation left (of the field, relative to the values' range, or
  /// of the shape, relative to a piece's edge) and the tolerance it was measured against.
  double deviation = 0.0;
  bool toleranceReached = true;  ///< false where maxLevel or maxTetrahedra stopped it
};

/// The tetrahedra `chosen` (indices into field.split()), refined in their cells of
/// field.mesh(). Tet4 cells and cells whose map cannot be inverted are subdivided linearly
/// (their field and shape are the split's). Throws volpost::Cancelled when `progress` cancels.
RefinedTetrahedra refineTetrahedra(const optics::ElementField& field, std::span<const std::uint32_t> chosen,
                                   const RefinementLimits& limits = {}, const Progress& progress = {});

/// Where a point of a refined surface comes from: its triangle of the boundary (in the
/// boundary's face order) and its place there, weights (level - i - j, i, j) / level on the
/// triangle's corners.
struct RefinedPoint {
  std::uint32_t triangle = 0;
  std::uint16_t i = 0, j = 0;
  std::uint16_t level = 1;
};

struct RefinedSurface {
  /// The boundary with each triangle subdivided in the cell's natural coordinates as
  /// finely as it and its neighbours need, placed by the cell's map (curved where a
  /// quadratic cell's faces are): a vertex's node is its point's index in `values`, a face
  /// keeps its cell of the model, and the element edges follow the curved sides in pieces.
  BoundarySurface surface;
  std::vector<double> values;        ///< the cell's field at each point
  std::vector<RefinedPoint> points;  ///< where each point comes from (revalueBoundary)
  int level = 1;                     ///< the most subdivisions along a side of a boundary triangle
  std::vector<int> levels;           ///< what each boundary triangle asked for (revalueBoundary)
  double deviation = 0.0;            ///< the estimated largest deviation left, as RefinedTetrahedra's
  bool toleranceReached = true;
};

/// The field at a refined surface's points for other node values (another step).
struct RefinedValues {
  std::vector<double> values;  ///< one per point of the surface
  double deviation = 0.0;
  bool toleranceReached = true;
};

/// The boundary surface `boundary` (of field.mesh()) in its cells' own shape and field,
/// each triangle subdivided along its sides the fewest times that bring it within the
/// tolerance; a side shared by two triangles takes the larger of their levels, and a
/// triangle cut more finely than a side is stitched to that side's points, so the surface
/// stays closed. Throws volpost::Cancelled when `progress` cancels.
RefinedSurface refineBoundary(const optics::ElementField& field, const BoundarySurface& boundary,
                              const RefinementLimits& limits = {}, const Progress& progress = {});

/// `refined` (refineBoundary of the same boundary and mesh) colored by `field`, another
/// field on the same cells (the next step): the points stay, only their values are
/// evaluated, far quicker than refining again. nullopt where `field` asks some triangle for
/// another cut than refined.levels (then refine again). Throws volpost::Cancelled when `progress` cancels.
std::optional<RefinedValues> revalueBoundary(const optics::ElementField& field, const BoundarySurface& boundary,
                                             const RefinedSurface& refined, const RefinementLimits& limits = {},
                                             const Progress& progress = {});

/// The natural coordinates, in `cell` of `cells`, of a node of the cell's split: the cell's
/// own node's, or for a point the split added, the mean of the cell's corners'.
glm::dvec3 naturalCoordinatesOfSplitNode(const Mesh& cells, std::uint32_t cell, NodeIndex node);

/// Whether any cell of `cells` has a field or shape of its own beyond its split's (a cell
/// other than a tet4).
bool hasNonlinearCells(const Mesh& cells);

}  // namespace volpost
