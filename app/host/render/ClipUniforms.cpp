// SPDX-License-Identifier: MIT
#include "host/render/ClipUniforms.hpp"

#include <volpost/render/VolumeLimits.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

namespace volpost {

void setClipUniforms(GLuint program, const std::vector<ClipPlane>& planes, const glm::dvec3& origin, double tolerance) {
  std::vector<glm::vec4> packed;
  for (const ClipPlane& c : planes) {
    // Scaled first so a tiny or huge normal normalizes without underflow or overflow.
    const double scale = std::max({std::abs(c.normal.x), std::abs(c.normal.y), std::abs(c.normal.z)});
    if (!(scale > 0.0) || !std::isfinite(scale) || packed.size() == std::size_t(kMaxClipPlanes)) continue;
    const glm::dvec3 n = glm::normalize(c.normal / scale);
    packed.push_back(glm::vec4(glm::vec3(n), float(-glm::dot(n, c.point - origin))));
  }
  glProgramUniform1i(program, glGetUniformLocation(program, "clipCount"), int(packed.size()));
  glProgramUniform1f(program, glGetUniformLocation(program, "clipTolerance"), float(tolerance));
  if (!packed.empty())
    glProgramUniform4fv(program, glGetUniformLocation(program, "clipPlanes"), GLsizei(packed.size()),
                        glm::value_ptr(packed[0]));
}

}  // namespace volpost
