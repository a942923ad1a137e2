// SPDX-License-Identifier: MIT
// The clip planes of shaders/common/clip_planes.glsl, set on a program: normalized planes
// in coordinates relative to `origin` (the model center the geometry is uploaded around).
#pragma once

#include <volpost/core/ClipPlane.hpp>
#include <volpost/render/GlObjects.hpp>

#include <glm/vec3.hpp>

#include <vector>

namespace volpost {

/// At most kMaxClipPlanes are set; planes with a zero normal are left out. `tolerance`:
/// how far (model units) on the cut side a fragment is still kept.
void setClipUniforms(GLuint program, const std::vector<ClipPlane>& planes, const glm::dvec3& origin,
                     double tolerance = 0.0);

}  // namespace volpost
