// SPDX-License-Identifier: MIT
// What a volume renderer draws and which settings it takes, said by the renderer itself
// (VolumeRenderer::traits()). The host builds its menus, its refusals of options and its
// messages from these, so it names no renderer: a new renderer plugin is offered, refused
// and explained like the bundled ones.
#pragma once

#include <volpost/render/IntegrationMode.hpp>

#include <string>
#include <vector>

namespace volpost {

struct VolumeRendererTraits {
  /// What a user reads in a menu, in plain words ("Ray casting").
  std::string label;
  /// setVolume takes meshes (any cells, split into tetrahedra by the host).
  bool drawsMeshes = true;
  /// A GridVolumeRenderer: regular grids' point values are sampled as a grid.
  bool drawsGrids = false;
  /// 2D transfer functions (value x gradient magnitude) on grids.
  bool transferFunction2D = false;
  /// Shading by the gradient, on grids.
  bool shading = false;
  /// The integration modes it offers, in menu order; empty where it integrates the transfer
  /// function exactly and offers no choice.
  std::vector<IntegrationMode> modes;
  /// setSamplingStep is used on meshes (its Sampling mode) and on grids (the step of a
  /// march along rays).
  bool samplingStepOnMeshes = true;
  bool samplingStepOnGrids = true;
  /// setTerminationThreshold is used (rays stop early).
  bool earlyTermination = true;
  /// It computes on the CPU's cores, not through OpenGL: the quick choice where OpenGL is a
  /// software rasterizer.
  bool runsOnCpu = false;
  /// It draws a mesh's field through the cells' own shape functions when asked
  /// (FieldInterpolation::Element), not only linear on their tetrahedra.
  bool elementInterpolation = false;
  /// It draws the cells' own field within a tolerance it is given (setElementTolerance),
  /// faster than exactly; false: exactly or not at all.
  bool elementTolerance = false;
};

}  // namespace volpost
