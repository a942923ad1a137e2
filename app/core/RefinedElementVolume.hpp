// SPDX-License-Identifier: MIT
// The cells' own field for a volume renderer that draws tetrahedra only (the GPU ray caster,
// cell projection): the split's tetrahedra refined in the cells' natural coordinates until
// the linear pieces follow the cells' field and shape to the element tolerance
// (ElementRefinement.hpp), handed to the renderer as an ordinary tet mesh. In the window the
// refinement runs on a worker thread while the split's field is drawn; a headless picture
// waits for it.
#pragma once

#include "host/AdaptiveElementRefinement.hpp"
#include "host/ElementRefinement.hpp"

#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/Model.hpp>
#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/optics/ElementField.hpp>
#include <volpost/render/FieldInterpolation.hpp>
#include <volpost/render/VolumeRendererTraits.hpp>

#include <atomic>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace volpost::app {

class ModelSession;

/// A refined volume and what it was made of (the field names cells it could not invert).
struct RefinedElementMesh {
  std::shared_ptr<const ModelSession> session;  ///< keeps the cells and the split the field references
  std::vector<double> nodeValues;               ///< the field's node values (the field references them)
  std::shared_ptr<const optics::ElementField> field;
  RefinedTetrahedra refined;
  VolumeRefinementGoal goal;  ///< its transfer function is not kept
  /// Not refined at all: the split's `chosen` tetrahedra leave too little room in
  /// goal.maxTetrahedra to cut; the split's field is drawn, and the note says so.
  bool unrefined = false;
  std::size_t chosen = 0;
};

/// What a refinement is for: the scene's geometry and values, the tets the clip box keeps,
/// the tolerance and the transfer function (which decides where the pieces are cut).
struct RefinedElementKey {
  std::uint64_t geometry = 0, values = 0;
  std::vector<ClipPlane> cullPlanes;
  double tolerance = 0.0;
  TransferFunction transferFunction;
  bool operator==(const RefinedElementKey&) const = default;
  /// Pieces refined for `other` draw the same field (refined for another transfer function
  /// or tolerance, perhaps).
  bool sameField(const RefinedElementKey& other) const {
    return geometry == other.geometry && values == other.values && cullPlanes == other.cullPlanes;
  }
};

/// Whether a volume renderer with `traits` draws `model`'s field on pieces refined to the
/// element tolerance (and so cannot take the exact tolerance, 0): it has no cells' own field
/// of its own (the elementInterpolation trait), the cells' own field of a node field is
/// asked for, the model is not drawn as a grid, and it has cells other than tet4 (a tet4 mesh
/// is its own split). The command line, the window and the drawing all ask this.
bool drawsCellsFieldOnPieces(const VolumeRendererTraits& traits, FieldInterpolation interpolation,
                             FieldLocation location, const Model& model);

/// The user's words for a refined volume: how many pieces, within what, and where the
/// limits stopped short of the tolerance.
std::vector<std::string> refinedVolumeNotes(const RefinedElementMesh& mesh);

class RefinedElementVolume {
 public:
  using Work = std::function<RefinedElementMesh(const Progress&)>;
  RefinedElementVolume() = default;
  RefinedElementVolume(const RefinedElementVolume&) = delete;
  RefinedElementVolume& operator=(const RefinedElementVolume&) = delete;
  ~RefinedElementVolume() { stop(); }

  /// The refined volume for `key` when it is ready; otherwise starts `work` for it (on a
  /// worker thread when `asynchronous`, else here, and then returns its result) and returns
  /// nullptr. A refinement under way for another key is cancelled.
  std::shared_ptr<const RefinedElementMesh> wanted(const RefinedElementKey& key, const Work& work, bool asynchronous);
  /// A refinement is under way.
  bool pending() const { return running_.has_value(); }
  /// How far the refinement under way has got (0..1); nullopt when none is.
  std::optional<double> progress() const {
    return running_ ? std::optional<double>(running_->fraction->load()) : std::nullopt;
  }
  /// Cancels the refinement under way and forgets the last result.
  void stop();

 private:
  struct Running {
    RefinedElementKey key;
    std::shared_ptr<std::atomic<bool>> cancel;
    std::shared_ptr<std::atomic<double>> fraction;  ///< reported by the worker
    std::future<RefinedElementMesh> result;
  };
  std::optional<Running> running_;
  std::optional<RefinedElementKey> readyFor_;
  std::shared_ptr<const RefinedElementMesh> ready_;
};

}  // namespace volpost::app
