// SPDX-License-Identifier: MIT
// A loaded FE model (or a regular grid such as a seismic cube): the mesh, its result fields and what was found wrong with it.
#pragma once

#include <volpost/core/Diagnostics.hpp>
#include <volpost/core/EntitySet.hpp>
#include <volpost/core/Field.hpp>
#include <volpost/core/Mesh.hpp>
#include <volpost/core/RegularGrid.hpp>

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace volpost {

class Model {
 public:
  std::string sourcePath;
  std::string formatName;   ///< e.g. "VTK XML unstructured grid"
  std::string title;        ///< header/title line of the file, if any
  /// Set when the model is a regular grid: grid renderers then sample its point fields as a
  /// 3D texture, and the mesh is this grid's hexahedra (hexahedraOfGrid).
  std::optional<RegularGrid> grid;
  std::vector<std::shared_ptr<Field>> fields;
  std::vector<Diagnostic> diagnostics;
  /// Element and node sets the file defines (see EntitySet.hpp; modelSets adds the groups
  /// that region fields offer).
  std::vector<EntitySet> sets;

  /// The cells and nodes. A grid model read without them (readers of grids leave the mesh
  /// alone) gets its hexahedra here on the first call, once, thread-safe: a grid drawn only
  /// by the grid renderers never holds the 57 bytes per point of explicit hexahedra.
  const Mesh& mesh() const;
  Mesh& mesh();
  /// Replaces the mesh (a grid model's too: the given mesh is then what mesh() returns).
  void setMesh(Mesh mesh);
  /// False while a grid model's hexahedra have not been built: what only needs the grid
  /// (its bounds, counts, the grid renderers) asks the grid instead.
  bool meshBuilt() const;
  /// Point and cell counts without building a grid's hexahedra.
  std::size_t nodeCount() const;
  std::size_t cellCount() const;
  /// Cells per type, as Mesh::countsByType (a grid's are all hex8).
  std::map<CellType, std::size_t> countsByType() const;
  /// Position of node n (mesh().nodes[n], or a grid point without building the cells).
  glm::dvec3 nodePosition(std::size_t node) const;
  /// Bounds of the used nodes (mesh().bounds()), or of a grid without building its cells.
  Bounds bounds() const;

  const Field* findField(const std::string& name) const;
  /// Gives fields that share a name names of their own ("T" per node and per cell: the
  /// second becomes "T (cells)"; else "T (2)"), saying so in an info diagnostic: a
  /// quantity named in a state file or on the command line must mean one field.
  void makeFieldNamesUnique();

  Model() = default;
  Model(const Model& other);
  Model& operator=(const Model& other);
  Model(Model&&) noexcept = default;
  Model& operator=(Model&&) noexcept = default;

 private:
  struct MeshSlot {
    std::mutex mutex;
    /// Set once a grid's hexahedra are built (or a mesh was given): `mesh` is final.
    std::atomic<bool> ready{false};
    Mesh mesh;
  };
  MeshSlot& slot() const;
  mutable std::unique_ptr<MeshSlot> slot_ = std::make_unique<MeshSlot>();
};

}  // namespace volpost
