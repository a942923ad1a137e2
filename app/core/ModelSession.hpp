// SPDX-License-Identifier: MIT
// What the user is looking at: the model, its boundary, the chosen quantity and step.
// Shared by the window and the command line so both show the same thing.
#pragma once

#include <volpost/core/Model.hpp>
#include <volpost/core/Quantity.hpp>
#include <volpost/core/ReaderRegistry.hpp>
#include <volpost/core/Tetrahedralize.hpp>

#include "Formula.hpp"
#include "host/BoundarySurface.hpp"
#include "host/PointLocator.hpp"

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace volpost::app {

/// A quantity's values at one step. A field's own scalar kept in its file's type (a
/// 16-bit seismic cube) is viewed where the field keeps it, never copied to doubles; any
/// other quantity (a component, von Mises ...) is computed into doubles the view owns.
/// Copies share the values.
struct ScalarView {
  Quantity quantity;
  FieldLocation location = FieldLocation::Node;
  SampleView values;  ///< one per node or per cell, alive while `owner` is
  ValueRange range;
  std::string stepLabel;
  std::shared_ptr<const void> owner;  ///< the computed doubles, or the field holding the samples

  /// Makes `computed` the view's values (owned by it); the range is left to the caller.
  void setValues(std::vector<double> computed);
};

class ModelSession {
 public:
  /// When the boundary surface is extracted: at once (the window, a surface picture: the
  /// long part runs here, with progress), or on the first call of surface() (a volume
  /// picture, a probe, `info` never need it; at 12.6M tets it costs 9 s and 100 B/tet).
  enum class Boundary { Now, OnFirstUse };

  /// Reads and checks the model (the long part, runs on a worker thread).
  /// `options`: the reader's settings (SEG-Y header bytes ...); one it does not take, or a
  /// bad value, throws ReaderOptionError naming it before anything is read.
  static std::shared_ptr<ModelSession> load(const ReaderRegistry& readers, const std::string& path,
                                            const Progress& progress = {}, Boundary boundary = Boundary::OnFirstUse,
                                            const ReaderOptions& options = {});
  /// A session on a model already in memory (checked or made by the caller).
  static std::shared_ptr<ModelSession> fromModel(std::shared_ptr<Model> model, const Progress& progress = {},
                                                 Boundary boundary = Boundary::OnFirstUse);

  /// This model with the fields of `formulas` after its own (each formula may read the ones
  /// before it), sharing the mesh and what is built from it (boundary, tetrahedra, point
  /// locator). Throws FormulaError naming the formula at fault.
  static std::shared_ptr<ModelSession> withFormulas(const ModelSession& base, const std::vector<FormulaSpec>& formulas);
  /// The formulas whose fields this session's model holds after the file's own.
  const std::vector<FormulaSpec>& formulas() const { return formulas_; }
  /// This model with `sets` in place of the sets of origin `origin` it held (the user's
  /// selection: see Selection.hpp), sharing the mesh and what is built from it.
  static std::shared_ptr<ModelSession> withSets(const ModelSession& base, const std::string& origin,
                                                std::vector<EntitySet> sets);

  const Model& model() const { return *model_; }
  /// The reader options the model was read with (for state files and reopening).
  const ReaderOptions& readerOptions() const { return readerOptions_; }
  /// The boundary surface (extracted on first use, kept; any thread).
  const BoundarySurface& surface() const;
  /// Whether surface() has been extracted yet (what a volume picture must not pay for).
  bool surfaceExtracted() const { return geometry_->surfaceExtracted.load(); }
  /// The point every float position on the GPU is relative to: the centre of the used
  /// nodes' bounds (the boundary surface's origin too), known without extracting it.
  const glm::dvec3& origin() const { return origin_; }
  /// The used nodes' bounds, found once at load (Mesh::bounds() walks every cell).
  const Bounds& bounds() const { return bounds_; }

  /// All quantities of all fields, in field order.
  std::vector<Quantity> quantities() const;
  /// The quantity an analyst wants first: a stress's von Mises, else the first field.
  std::optional<Quantity> defaultQuantity() const;
  /// Finds a quantity by its written form ("S.mises", "U.x", "T"). Throws
  /// std::invalid_argument listing the valid names when there is none.
  Quantity findQuantity(const std::string& key) const;
  const Field& fieldOf(const Quantity& q) const;

  /// Values of the quantity at a step (0-based), with their range.
  ScalarView evaluate(const Quantity& q, std::size_t step) const;
  /// The quantity's range over every step of its field (evaluated once, kept; any thread):
  /// one color scale for a whole animation.
  ValueRange rangeOverSteps(const Quantity& q) const;

  /// The cells as conforming tetrahedra for volume rendering (built on first use, kept).
  const TetMesh& tetrahedra() const;
  /// A view's values on those tetrahedra (Steiner points get their cell's corner mean).
  std::vector<double> tetValues(const ScalarView& view) const;
  /// Finds points in those tetrahedra (built on first use, kept; any thread).
  const PointLocator& locator() const;

 private:
  ReaderOptions readerOptions_;
  mutable std::mutex rangesMutex_;
  mutable std::map<std::string, ValueRange> rangesOverSteps_;  ///< by quantity key
  /// The range of every (quantity key, step) evaluated so far: the range over the steps
  /// then evaluates only the steps not seen (a large field is not evaluated twice at once).
  mutable std::map<std::pair<std::string, std::size_t>, ValueRange> stepRanges_;
  /// What is worked out from the mesh alone, built on first use and shared with the
  /// sessions withFormulas() makes from this one (same mesh, more fields).
  struct Geometry {
    std::once_flag tetOnce;
    std::unique_ptr<TetMesh> tets;
    std::once_flag locatorOnce;
    std::unique_ptr<PointLocator> locator;
    std::once_flag surfaceOnce;
    std::unique_ptr<BoundarySurface> surface;
    std::atomic<bool> surfaceExtracted{false};
  };
  std::shared_ptr<Geometry> geometry_ = std::make_shared<Geometry>();
  std::vector<FormulaSpec> formulas_;
  std::shared_ptr<Model> model_;
  glm::dvec3 origin_{0.0};
  Bounds bounds_;
  /// Per node, whether a cell uses it; null where all are (ranges then cross every node).
  std::shared_ptr<const std::vector<char>> usedNodes_;
};

}  // namespace volpost::app
