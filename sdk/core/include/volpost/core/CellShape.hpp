// SPDX-License-Identifier: MIT
// Isoparametric shape functions of the FE cell types (VTK node order) and the inverse map
// from a point to a cell's natural coordinates: values inside a cell interpolated as the
// FE program's element does (trilinear in hex8, quadratic in tet10, serendipity in hex20
// and wedge15), which is also what ParaView's probe does, rather than piecewise linearly
// over the tetrahedra the renderers use.
//
// Natural coordinates: tet (r, s, t) >= 0 with r + s + t <= 1; hex (xi, eta, zeta) in
// [-1, 1]^3; wedge (r, s) on the triangle r, s >= 0, r + s <= 1, and zeta in [-1, 1]
// (nodes 0-2 at -1); pyramid (r, s, t) in [0, 1]^3, the apex at t = 1.
#pragma once

#include <volpost/core/CellType.hpp>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <span>

namespace volpost {

inline constexpr int kMaxCellNodes = 20;
using ShapeValues = std::array<double, kMaxCellNodes>;

/// The shape functions of the cell type at natural coordinates `xi` (topology(type).nodeCount
/// of them; they sum to 1).
ShapeValues shapeFunctions(CellType type, const glm::dvec3& xi);

/// The natural coordinates of a cell's node (the corners, then the midside nodes).
glm::dvec3 naturalCoordinatesOfNode(CellType type, int node);

/// The reference cell's centre, where the inverse map starts.
glm::dvec3 referenceCentre(CellType type);

/// How far `xi` lies outside the reference cell, in natural units (0 inside or on it).
double outsideReference(CellType type, const glm::dvec3& xi);

/// How far `xi` lies outside the reference cell, negative inside: the least margin to its
/// faces (outsideReference without its floor at 0), smooth across each face.
double signedOutsideReference(CellType type, const glm::dvec3& xi);

/// How far the cell's faces leave the flat facets of its split: the largest distance of a
/// midside node from its edge's middle and of a quadrilateral face's corner from the plane
/// of its other three (0 for a cell with straight edges and flat faces).
double faceBend(CellType type, std::span<const glm::dvec3> nodes);

/// A point of the reference cell near `xi` (xi itself when inside): each coordinate clamped
/// to the cell's range, a simplex part scaled back onto its slanted face.
glm::dvec3 clampToReference(CellType type, const glm::dvec3& xi);

/// The position of natural coordinates `xi` in the cell with these node positions.
glm::dvec3 positionAt(CellType type, std::span<const glm::dvec3> nodes, const glm::dvec3& xi);

/// The natural coordinates of `p` in the cell with these node positions (Newton's method
/// from `start`, the Jacobian exact by forward differentiation of the shape functions);
/// nullopt when the iteration does not converge (a degenerate or folded cell, or a point
/// far outside it).
std::optional<glm::dvec3> naturalCoordinates(CellType type, std::span<const glm::dvec3> nodes, const glm::dvec3& p,
                                             const glm::dvec3& start);

/// The Jacobian of the cell's map at `xi` (column k: dx/dxi_k), exact by forward
/// differentiation of the shape functions.
glm::dmat3 jacobianAt(CellType type, std::span<const glm::dvec3> nodes, const glm::dvec3& xi);

/// The gradient per length unit, at natural coordinates `xi`, of the field with these node
/// values interpolated by the shape functions (the inverse transposed Jacobian times the
/// natural gradient); zero where the map is singular there.
glm::dvec3 fieldGradient(CellType type, std::span<const glm::dvec3> nodes, std::span<const double> values,
                         const glm::dvec3& xi);

/// Whether the cell's map can be inverted: its Jacobian determinant has one strict sign at
/// every corner (a pyramid's apex, where every pyramid's map is singular, aside) and at the
/// centre. A folded, inverted or collapsed cell fails.
bool mapInvertible(CellType type, std::span<const glm::dvec3> nodes);

}  // namespace volpost
