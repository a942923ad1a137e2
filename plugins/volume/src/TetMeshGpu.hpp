// SPDX-License-Identifier: MIT
// What the GPU ray caster holds per mesh, prepared on the CPU (no GL here, so it is
// tested directly). Per tetrahedron: 4 vertex ids (16 B) and its 4 face neighbours packed
// in 12 B (below); per node its position relative to the mesh center and its value (16 B);
// plus the boundary faces and a BVH over them to find where rays enter (and re-enter) the
// mesh. Face planes, barycentric weights and gradients are computed in the shader from the
// vertices, which trades arithmetic for memory (Espinha 2005 stored 96 B per tet, Table 5).
#pragma once

#include <volpost/core/Field.hpp>
#include <volpost/core/Mesh.hpp>
#include <volpost/core/Quantity.hpp>
#include <volpost/core/SampleView.hpp>
#include <volpost/core/TetAdjacency.hpp>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace volpost::volume {

struct TetMeshGpu {
  glm::dvec3 origin{0.0};                 ///< model coordinates of the mesh center
  std::vector<glm::vec4> nodes;           ///< xyz relative to origin, w = nodal value (gpuValue)
  /// Positively oriented vertex ids: a list of their own, or (every cell kept, tet4 and
  /// positive as given) the mesh's own cells, shared (16 bytes per tet not held twice).
  /// Neither once the tets are only on the GPU. Read through tetNodes().
  std::vector<glm::uvec4> tets;
  std::shared_ptr<const Mesh> sharedCells;
  /// The tet across the face opposite each vertex, as the shader reads it (empty once only
  /// on the GPU, as `tets`): three words per tet holding four 24-bit fields (face k in bits
  /// 24k..24k+23 of the 96), each 0 for the boundary, 1 for "far" (below), else the signed
  /// step from this tet's index to the one across in bits 2..23 (within +-(2^21 - 1)) and the
  /// face of that tet the ray enters it through in bits 0..1. After 3 x tetCount words, the
  /// far ones as pairs (tet x 4 + face, across x 4 + entry face), ascending. 28 bytes per tet
  /// with the vertex ids (32 with four plain indices), and the step needs no search for the
  /// entry face. Read on the CPU with neighborsOf().
  std::vector<std::uint32_t> neighbors;
  std::size_t farNeighbors = 0;           ///< pairs after the packed words
  std::size_t tetCount = 0;               ///< tets, also when `tets` is let go after the upload
  std::vector<float> cellValues;          ///< one per tet (element results, gpuValue), else empty
  /// The mesh cell each tet comes from; empty when every cell is kept (tet t is cell t).
  std::vector<std::uint32_t> cellOfTet;
  std::vector<std::uint32_t> boundaryFaces;  ///< tet * 4 + face, in BVH leaf order
  std::vector<glm::vec4> bvh;             ///< 2 per node: (lo, first), (hi, count); count 0 = inner
  std::size_t skippedTets = 0;            ///< zero volume or non-finite values
  double maxEdge = 0.0;                   ///< longest tet edge, model units
  double diagonal = 0.0;                  ///< of the mesh's bounding box, model units
  /// Values travel in the frame of their own range, as positions do relative to origin:
  /// gpuValue(v) = (v - valueOffset) * valueScale, 0 at the field's minimum and 1 at its
  /// maximum. Float32 then resolves the range rather than the magnitude (a temperature
  /// field of 293.0..293.1 keeps its detail), and no shader arithmetic meets denormals: a
  /// concentration field of 1e-37 would otherwise be flushed to zero in the products of
  /// the integration. Everything compared with values (control points, iso-values, table
  /// ranges) goes through gpuValue too.
  double valueOffset = 0.0, valueScale = 1.0;
  double valueMin = 0.0, valueMax = 0.0;  ///< range of the finite values (0, 0 when none)

  float gpuValue(double v) const { return float((v - valueOffset) * valueScale); }
  std::uint32_t sourceCell(std::size_t tet) const { return cellOfTet.empty() ? std::uint32_t(tet) : cellOfTet[tet]; }
  glm::uvec4 tetNodes(std::size_t t) const {
    if (!sharedCells) return tets[t];
    const NodeIndex* n = sharedCells->connectivity().data() + 4 * t;
    return {n[0], n[1], n[2], n[3]};
  }
  /// The vertex ids of all tets, 16 bytes each, where they are (for the upload).
  const void* tetData() const { return sharedCells ? static_cast<const void*>(sharedCells->connectivity().data()) : tets.data(); }
  bool holdsTets() const { return sharedCells || !tets.empty(); }
  void letGoOfTets() {
    std::vector<glm::uvec4>().swap(tets);
    sharedCells.reset();
  }
  /// The tets across tet t's faces (-1: boundary), decoded from `neighbors`.
  glm::ivec4 neighborsOf(std::size_t tet) const;

  std::size_t bytes() const;
};

using volpost::faceNeighbors;  // volpost/core/TetAdjacency.hpp: shared by the GPU structure and the sorter

/// The largest index step a packed neighbour field holds; farther ones go to the pairs.
inline constexpr std::int64_t kNearNeighborStep = (std::int64_t(1) << 21) - 1;

/// Packs a tet-per-4-words adjacency (tet across each face, 0xffffffff for none, as
/// faceNeighborsInto writes it) into the GPU's form, in place, and lists the boundary
/// faces (tet x 4 + face). Words past the packed ones hold the far pairs; the rest is cut.
void packNeighbors(std::vector<std::uint32_t>& words, std::size_t tetCount, std::size_t& farCount,
                   std::vector<std::uint32_t>& boundaryFaces);

/// A BVH over triangles (faces[i] names one as tet x 4 + face, faceNodes[i] its corners
/// in `nodes`), two vec4 per node as TetMeshGpu::bvh holds them; `faces` is put in leaf
/// order. Empty for no faces.
std::vector<glm::vec4> buildFaceBvh(std::vector<std::uint32_t>& faces, std::span<const glm::uvec3> faceNodes,
                                    std::span<const glm::vec4> nodes);

/// Sets valueMin/Max and the frame (valueOffset, valueScale) from the finite values.
void setValueFrame(TetMeshGpu& gpu, SampleView values);
/// The same from the values' range, already known.
void setValueFrame(TetMeshGpu& gpu, const ValueRange& range);

/// Throws std::invalid_argument for cells that are not tetrahedra or a wrong value count.
/// Built on all cores.
TetMeshGpu buildTetMeshGpu(const Mesh& mesh, FieldLocation location, std::span<const double> values);

/// Puts new values (another result or step, same location) into the prepared structure
/// without touching its geometry. Returns false, changing nothing, when the values would
/// change which tets are left out (a value became or stopped being NaN): rebuild then.
bool replaceValues(TetMeshGpu& gpu, const Mesh& mesh, FieldLocation location, std::span<const double> values);

}  // namespace volpost::volume
