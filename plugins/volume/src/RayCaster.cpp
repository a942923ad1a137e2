// SPDX-License-Identifier: MIT
#include "RayCaster.hpp"

#include "GpuLimits.hpp"

#include <algorithm>

namespace volpost::volume {

void RayCaster::render(const RenderContext& ctx) {
  if (!volume_.initialized() || !volume_.hasTets() || ctx.width <= 0 || ctx.height <= 0) return;
  volume_.prepare(ctx);
  const GLuint p = volume_.program({"volume/raycast.comp"});
  glUseProgram(p);
  volume_.setSegmentUniforms(p, ctx);
  const std::size_t tets = volume_.mesh().tets.size();
  glProgramUniform1i(p, glGetUniformLocation(p, "maxSteps"), rayStepCap(tets));
  volume_.bindSegmentResources(ctx);
  glBindImageTexture(0, volume_.image(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glDispatchCompute(GLuint((ctx.width + 7) / 8), GLuint((ctx.height + 7) / 8), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  volume_.compositeOver(ctx);
  gl::check("RayCaster::render");
}

}  // namespace volpost::volume
