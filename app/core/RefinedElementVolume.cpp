// SPDX-License-Identifier: MIT
#include "RefinedElementVolume.hpp"

#include <volpost/core/Progress.hpp>

#include <chrono>
#include <cstdio>

namespace volpost::app {
namespace {

std::string withThousands(std::size_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string shortNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", v);
  return text;
}

}  // namespace

bool drawsCellsFieldOnPieces(const VolumeRendererTraits& traits, FieldInterpolation interpolation,
                             FieldLocation location, const Model& model) {
  if (traits.elementInterpolation || interpolation != FieldInterpolation::Element || location != FieldLocation::Node)
    return false;
  if (model.grid && traits.drawsGrids) return false;  // drawn as the grid it is
  return hasNonlinearCells(model.mesh());
}

std::vector<std::string> refinedVolumeNotes(const RefinedElementMesh& mesh) {
  if (mesh.unrefined)
    return {"the cells' own field would be cut from a copy of the split's " + withThousands(mesh.chosen) +
            " tetrahedra, more than half of the " + withThousands(mesh.goal.maxTetrahedra) +
            " pieces it may take: drawn linear on the split; the cpu renderer draws the cells' field itself"};
  const RefinedTetrahedra& r = mesh.refined;
  std::string note = "the cells' own field drawn on " + withThousands(r.tets.mesh.cellCount()) +
                     " tetrahedra (the split's " + withThousands(mesh.chosen) + ", halved up to " +
                     std::to_string(r.bisections) +
                     " times where the transfer function shows the field), a pixel's channel within " +
                     shortNumber(r.deviation) + " of it (estimated)";
  if (!r.toleranceReached)
    note += "; the tolerance " + shortNumber(mesh.goal.perChannel) + " would need more than " +
            withThousands(mesh.goal.maxTetrahedra) + " tetrahedra: the cpu renderer draws the cells' field itself";
  return {note};
}

std::shared_ptr<const RefinedElementMesh> RefinedElementVolume::wanted(const RefinedElementKey& key, const Work& work,
                                                                       bool asynchronous) {
  if (readyFor_ == key) return ready_;
  if (running_ && running_->key != key) stop();
  if (!asynchronous) {
    auto done = std::make_shared<const RefinedElementMesh>(work(Progress()));
    readyFor_ = key;
    return ready_ = done;
  }
  if (!running_) {
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    auto fraction = std::make_shared<std::atomic<double>>(0.0);
    running_ = Running{key, cancel, fraction, std::async(std::launch::async, [work, cancel, fraction] {
                         return work(Progress([cancel, fraction](double done, const std::string&) {
                           *fraction = done;
                           return !*cancel;
                         }));
                       })};
  }
  if (running_->result.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return nullptr;
  std::future<RefinedElementMesh> result = std::move(running_->result);
  running_.reset();
  auto done = std::make_shared<const RefinedElementMesh>(result.get());  // the worker's error, if any, is the frame's
  readyFor_ = key;
  return ready_ = done;
}

void RefinedElementVolume::stop() {
  readyFor_.reset();
  ready_.reset();
  if (!running_) return;
  *running_->cancel = true;
  try {
    running_->result.get();  // waits for the worker, which stops at its next report
  } catch (...) {
    // Cancelled, or failed: nothing of it is shown.
  }
  running_.reset();
}

}  // namespace volpost::app
