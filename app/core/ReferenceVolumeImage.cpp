// SPDX-License-Identifier: MIT
#include "ReferenceVolumeImage.hpp"

#include "host/optics/GridReference.hpp"

#include <stdexcept>

namespace volpost::app {

optics::ReferenceImage renderVolumeReference(const Scene& scene, int width, int height, int threads,
                                             const Progress& progress) {
  if (!scene.session() || !scene.view()) throw std::invalid_argument("the reference renderer needs a result to render");
  const ScalarView& view = *scene.view();
  optics::RaySettings settings;
  settings.clipPlanes = scene.volume().allClipPlanes();
  settings.isoSurfaces = scene.volume().isoSurfaces;
  settings.shading = scene.volume().shading;
  // A regular grid's own field is the trilinear interpolant of its points (what the
  // texture renderers draw); a mesh's is linear on its tetrahedra.
  const Model& model = scene.session()->model();
  if (const auto& tf2d = scene.volume().transferFunction2D) {
    if (!model.grid || view.location != FieldLocation::Node)
      throw std::invalid_argument("2D transfer functions (over the value and its gradient) are drawn on regular grids' "
                                  "point values; this model is a mesh or the quantity is given per cell");
    // No exact integral: the midpoint rule, the step halved until each ray changes by < 1e-5.
    return optics::renderGridReference2D(*model.grid, view.values, *tf2d, scene.pictureCamera(width, height), width,
                                         height, settings, 1e-5, progress, threads);
  }
  if (model.grid && view.location == FieldLocation::Node)
    return optics::renderGridReference(*model.grid, view.values, scene.transferFunction(),
                                       scene.pictureCamera(width, height), width, height, settings, progress, threads);
  const optics::TetVolume volume(scene.session()->tetrahedra().mesh, view.location, scene.session()->tetValues(view));
  return optics::renderReference(volume, scene.transferFunction(), scene.pictureCamera(width, height), width, height, settings, progress,
                                 threads);
}

}  // namespace volpost::app
