// SPDX-License-Identifier: MIT
// Draws a model's boundary surface colored by the active quantity, with its element
// edges (also alone, over a volume). A layer of the Scene; holds GL objects, so
// initialize() and release() need the context current.
#pragma once

#include "ModelSession.hpp"
#include "SceneState.hpp"

#include <volpost/core/ColorMap.hpp>
#include "host/render/SurfaceRenderer.hpp"

#include <glm/vec3.hpp>

#include <memory>

namespace volpost::app {

class BoundaryRenderer {
 public:
  void initialize();
  void release();
  bool initialized() const { return initialized_; }

  void setSession(std::shared_ptr<const ModelSession> session);
  /// Colors by the view's values; nullptr shows the plain surface.
  void setScalars(const ScalarView* view, DisplayRange range);
  void setColorMap(const ColorMap& map) { surface_.setColorMap(map); }
  void setShowEdges(bool show) { surface_.setShowEdges(show); }
  bool showEdges() const { return surface_.showEdges(); }
  /// Faces off: render() draws only the element edges (the opaque geometry over a volume).
  void setShowFaces(bool show) { surface_.setShowFaces(show); }
  void setLighting(bool on) { surface_.setLighting(on); }

  void setOpacity(float opacity) { surface_.setOpacity(opacity); }

  /// Clears ctx.framebuffer to the background and draws.
  void render(const RenderContext& ctx);
  /// Draws over what the target holds (no clear): the see-through surface over lines.
  void renderOver(const RenderContext& ctx);
  /// Only clears to the background (under a volume).
  void renderBackground(const RenderContext& ctx);

  glm::vec3 background{0.96f, 0.96f, 0.97f};

 private:
  SurfaceRenderer surface_;
  std::shared_ptr<const ModelSession> session_;
  bool initialized_ = false;
};

/// The range a view maps onto the color map: its own, or a tiny span around a constant.
DisplayRange autoRange(const ScalarView& view);

}  // namespace volpost::app
