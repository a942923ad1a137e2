// SPDX-License-Identifier: MIT
#include <volpost/core/Model.hpp>

#include <volpost/core/ResourceLimits.hpp>

#include <set>

namespace volpost {

Model::Model(const Model& other)
    : sourcePath(other.sourcePath),
      formatName(other.formatName),
      title(other.title),
      grid(other.grid),
      fields(other.fields),
      diagnostics(other.diagnostics),
      sets(other.sets) {
  if (other.meshBuilt()) setMesh(other.mesh());  // cells shared copy-on-write, nodes copied
}

Model& Model::operator=(const Model& other) {
  if (this != &other) *this = Model(other);
  return *this;
}

// A grid model builds its hexahedra on the first call that needs them, unless its reader
// gave a mesh. Readers set `grid` before the model is shared, so reading it here is safe.
Model::MeshSlot& Model::slot() const {
  if (!slot_) slot_ = std::make_unique<MeshSlot>();  // a moved-from model is empty again
  MeshSlot& s = *slot_;
  if (grid && !s.ready.load(std::memory_order_acquire)) {
    const std::lock_guard lock(s.mutex);
    if (!s.ready.load(std::memory_order_relaxed)) {
      if (grid->defect().empty() && s.mesh.nodeCount() == 0 && s.mesh.cellCount() == 0) {
        // The reader checked the samples only: what needs the cells checks them here (a
        // throw leaves the grid without them, and the next call asks again).
        requireMemory(double(grid->pointCount()) * kGridHexahedraBytesPerPoint, sourcePath,
                      "the grid's " + std::to_string(grid->cellCount()) + " hexahedra as explicit cells (" +
                          std::to_string(int(kGridHexahedraBytesPerPoint)) + " bytes per point)");
        s.mesh = hexahedraOfGrid(*grid);
      }
      s.ready.store(true, std::memory_order_release);
    }
  }
  return s;
}

const Mesh& Model::mesh() const { return slot().mesh; }

Mesh& Model::mesh() { return slot().mesh; }

void Model::setMesh(Mesh mesh) {
  if (!slot_) slot_ = std::make_unique<MeshSlot>();
  const std::lock_guard lock(slot_->mutex);
  slot_->mesh = std::move(mesh);
  slot_->ready.store(true, std::memory_order_release);
}

bool Model::meshBuilt() const { return !grid || (slot_ && slot_->ready.load(std::memory_order_acquire)); }

std::size_t Model::nodeCount() const { return meshBuilt() ? mesh().nodeCount() : grid->pointCount(); }

std::size_t Model::cellCount() const { return meshBuilt() ? mesh().cellCount() : grid->cellCount(); }

std::map<CellType, std::size_t> Model::countsByType() const {
  if (meshBuilt()) return mesh().countsByType();
  return {{CellType::Hex8, grid->cellCount()}};
}

glm::dvec3 Model::nodePosition(std::size_t node) const {
  return meshBuilt() ? mesh().nodes[node] : grid->pointPosition(node);
}

Bounds Model::bounds() const { return meshBuilt() ? mesh().bounds() : grid->bounds(); }

const Field* Model::findField(const std::string& name) const {
  for (const auto& f : fields)
    if (f->name() == name) return f.get();
  return nullptr;
}

void Model::makeFieldNamesUnique() {
  std::set<std::string> taken;
  for (const auto& f : fields) taken.insert(f->name());
  std::set<std::string> seen;
  for (const auto& f : fields) {
    if (seen.insert(f->name()).second) continue;
    const std::string original = f->name();
    std::string name = original + (f->location() == FieldLocation::Cell ? " (cells)" : " (nodes)");
    for (int n = 2; taken.count(name); ++n) name = original + " (" + std::to_string(n) + ")";
    f->rename(name);
    taken.insert(name);
    seen.insert(name);
    diagnostics.push_back({Severity::Info,
                           "field-renamed",
                           "two fields are named \"" + original + "\": the " + toString(f->location()) +
                               " field is shown as \"" + name + "\"",
                           {}});
  }
}

}  // namespace volpost
