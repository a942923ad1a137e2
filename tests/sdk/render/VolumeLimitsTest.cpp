// SPDX-License-Identifier: MIT
// The one check of clip planes and iso-surfaces that the scene and every renderer share,
// and the limits the shaders receive.
#include <volpost/render/VolumeLimits.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

using namespace volpost;

namespace {

std::string messageOf(const auto& check) {
  try {
    check();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

}  // namespace

TEST(VolumeLimits, ShadersGetTheSameLimitsAsTheChecks) {
  EXPECT_EQ(volumeLimitDefines(), "#define MAX_CLIP_PLANES " + std::to_string(kMaxClipPlanes) +
                                      "\n#define MAX_ISO_SURFACES " + std::to_string(kMaxIsoSurfaces) + "\n");
}

TEST(VolumeLimits, ClipPlanesUpToTheLimitPassAndOneMoreIsRefusedWithTheCount) {
  std::vector<ClipPlane> planes(std::size_t(kMaxClipPlanes), ClipPlane{{0, 0, 0}, {1, 0, 0}});
  EXPECT_NO_THROW(checkClipPlanes(planes));
  planes.push_back(planes.front());
  const std::string m = messageOf([&] { checkClipPlanes(planes); });
  EXPECT_NE(m.find(std::to_string(kMaxClipPlanes + 1) + " clip planes"), std::string::npos) << m;
  EXPECT_NE(m.find("at most " + std::to_string(kMaxClipPlanes)), std::string::npos) << m;
}

TEST(VolumeLimits, APlaneWithoutADirectionOrAPlaceIsRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const ClipPlane& bad : {ClipPlane{{0, 0, 0}, {0, 0, 0}}, ClipPlane{{0, 0, 0}, {nan, 0, 1}},
                               ClipPlane{{0, 0, 0}, {inf, 0, 0}}, ClipPlane{{nan, 0, 0}, {0, 0, 1}}}) {
    const std::vector<ClipPlane> one{bad};
    EXPECT_NE(messageOf([&] { checkClipPlanes(one); }).find("finite"), std::string::npos);
  }
  const std::vector<ClipPlane> tiny{ClipPlane{{0, 0, 0}, {1e-300, 0, 0}}};
  EXPECT_NO_THROW(checkClipPlanes(tiny)) << "a tiny normal still has a direction";
}

TEST(VolumeLimits, IsoSurfacesNeedAFiniteValueAnOpacityIn01AndAtMostTheLimit) {
  std::vector<optics::IsoSurface> surfaces(std::size_t(kMaxIsoSurfaces), optics::IsoSurface{1.0, {1, 0, 0}, 1.0});
  EXPECT_NO_THROW(checkIsoSurfaces(surfaces));
  surfaces.push_back(surfaces.front());
  EXPECT_NE(messageOf([&] { checkIsoSurfaces(surfaces); }).find("at most"), std::string::npos);
  for (const optics::IsoSurface& bad :
       {optics::IsoSurface{std::nan(""), {1, 0, 0}, 1.0}, optics::IsoSurface{1.0, {1, 0, 0}, 1.5},
        optics::IsoSurface{1.0, {1, 0, 0}, -0.1}}) {
    const std::vector<optics::IsoSurface> one{bad};
    EXPECT_NE(messageOf([&] { checkIsoSurfaces(one); }).find("iso-surface needs"), std::string::npos);
  }
}
