// SPDX-License-Identifier: MIT
// GPU ray casting through tetrahedra (compute shader, one invocation per pixel): rays enter
// at boundary faces found in a BVH, walk tet to tet through face adjacency, integrate each
// segment, and the float image is composited over the target.
#pragma once

#include "TetVolumeRenderer.hpp"

namespace volpost::volume {

class RayCaster final : public TetVolumeRenderer {
 public:
  std::string name() const override { return "raycast"; }
  void initialize() override { volume_.initialize(); }
  void release() override { volume_.release(); }
  void render(const RenderContext& ctx) override;
};

}  // namespace volpost::volume
