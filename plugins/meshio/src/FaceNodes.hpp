// SPDX-License-Identifier: MIT
// The nodes of one face of a cell, for surfaces and side sets that files define by
// (element, face number): the face's corners and, on a quadratic cell, the midside nodes of
// the face's edges. Each format numbers faces its own way; the caller maps its numbering
// to the corners' local indices in VTK's order.
#pragma once

#include <volpost/core/Mesh.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace volpost::meshio {

/// Appends the nodes of the face of `cell` whose corners are `vtkCorners` (local indices
/// in VTK's order) to `out`.
void appendFaceNodes(const Mesh& mesh, std::size_t cell, std::span<const int> vtkCorners,
                     std::vector<std::uint32_t>& out);

/// Appends the nodes of the faces of `cells` that no other of them shares (the outside of
/// that group of cells) to `out`.
void appendFreeFaceNodes(const Mesh& mesh, std::span<const std::uint32_t> cells, std::vector<std::uint32_t>& out);

}  // namespace volpost::meshio
