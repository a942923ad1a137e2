// SPDX-License-Identifier: MIT
#include "ReferenceVolumeImage.hpp"

#include <stdexcept>

namespace volpost::app {

optics::ReferenceImage renderVolumeReference(const Scene& scene, int width, int height, int threads,
                                             const Progress& progress) {
  if (!scene.session() || !scene.view()) throw std::invalid_argument("the reference renderer needs a result to render");
  const ScalarView& view = *scene.view();
  const optics::TetVolume volume(scene.session()->tetrahedra().mesh, view.location, scene.session()->tetValues(view));
  optics::RaySettings settings;
  settings.clipPlanes = scene.volume().allClipPlanes();
  settings.isoSurfaces = scene.volume().isoSurfaces;
  return optics::renderReference(volume, scene.transferFunction(), scene.pictureCamera(width, height), width, height, settings, progress,
                                 threads);
}

}  // namespace volpost::app
