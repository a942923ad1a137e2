// SPDX-License-Identifier: MIT
#include <volpost/render/VolumeLimits.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace volpost {

std::string volumeLimitDefines() {
  return "#define MAX_CLIP_PLANES " + std::to_string(kMaxClipPlanes) + "\n#define MAX_ISO_SURFACES " +
         std::to_string(kMaxIsoSurfaces) + "\n";
}

void checkClipPlanes(std::span<const ClipPlane> planes) {
  if (planes.size() > std::size_t(kMaxClipPlanes))
    throw std::invalid_argument(std::to_string(planes.size()) + " clip planes: a volume takes at most " +
                                std::to_string(kMaxClipPlanes) + ", the clip box's six included");
  for (const ClipPlane& p : planes) {
    const double scale = std::max({std::abs(p.normal.x), std::abs(p.normal.y), std::abs(p.normal.z)});
    if (!(scale > 0.0) || !std::isfinite(scale) || !std::isfinite(p.point.x) || !std::isfinite(p.point.y) ||
        !std::isfinite(p.point.z))
      throw std::invalid_argument("a clip plane needs a finite point and a finite, non-zero normal");
  }
}

void checkIsoSurfaces(std::span<const optics::IsoSurface> surfaces) {
  if (surfaces.size() > std::size_t(kMaxIsoSurfaces))
    throw std::invalid_argument(std::to_string(surfaces.size()) + " iso-surfaces: a volume takes at most " +
                                std::to_string(kMaxIsoSurfaces));
  for (const optics::IsoSurface& s : surfaces)
    if (!std::isfinite(s.value) || !(s.opacity >= 0.0 && s.opacity <= 1.0))
      throw std::invalid_argument("an iso-surface needs a finite value and an opacity in 0..1");
}

}  // namespace volpost
