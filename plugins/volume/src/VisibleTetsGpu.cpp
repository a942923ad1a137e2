// SPDX-License-Identifier: MIT
#include "VisibleTetsGpu.hpp"

#include "StorageUpload.hpp"
#include "VolumeBindings.hpp"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace volpost::volume {
namespace {

constexpr std::size_t kHeaderBytes = 16;  // foundFaces, visibleTets, two unused words
constexpr GLuint kGroupSize = 64;         // visible_tets.comp's local size
constexpr GLuint kMaxGroupsX = 65535;     // the least every device allows per dimension

void dispatchOverTets(std::size_t tetCount) {
  const std::size_t groups = (tetCount + kGroupSize - 1) / kGroupSize;
  const GLuint x = GLuint(std::min<std::size_t>(groups, kMaxGroupsX));
  const GLuint y = GLuint((groups + x - 1) / x);
  glDispatchCompute(x, y, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

gl::Buffer storage(std::size_t bytes) {
  gl::Buffer b = gl::createBuffer();
  glNamedBufferStorage(b.id(), GLsizeiptr(std::max<std::size_t>(bytes, 16)), nullptr, GL_DYNAMIC_STORAGE_BIT);
  return b;
}

}  // namespace

void VisibleTetsGpu::update(GLuint program, const TetMeshGpu& mesh) {
  tetCount_ = mesh.tetCount;
  const std::size_t words = (tetCount_ + 31) / 32;
  if (!bits_ || words * 4 > bytesOfBits_) {
    bits_ = storage(words * 4);
    bytesOfBits_ = words * 4;
  }
  glClearNamedBufferSubData(bits_.id(), GL_R32UI, 0, GLsizeiptr(words * 4), GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
  // Room for 4096 faces at first; when a part has more, stage 1 runs again with room for
  // all of them, and the room stays for the next changes.
  if (!found_) {
    capacity_ = 4096;
    found_ = storage(kHeaderBytes + capacity_ * sizeof(glm::uvec4));
  }
  glUseProgram(program);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kVisibleTets, bits_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kFoundFaces, found_.id());
  const auto u = [program](const char* name) { return glGetUniformLocation(program, name); };
  glProgramUniform1ui(program, u("tetCount"), GLuint(tetCount_));
  glProgramUniform1ui(program, u("farNeighborBase"), GLuint(tetCount_ * 3));
  glProgramUniform1ui(program, u("farNeighborCount"), GLuint(mesh.farNeighbors));
  const GLuint zeros[2] = {0, 0};
  glNamedBufferSubData(found_.id(), 0, sizeof zeros, zeros);
  glProgramUniform1i(program, u("stage"), 0);
  dispatchOverTets(tetCount_);
  GLuint counts[2] = {0, 0};
  glGetNamedBufferSubData(found_.id(), 0, sizeof counts, counts);  // waits for stage 0
  if (counts[1] == tetCount_) {  // everything shows: rays walk the whole mesh, no part to list
    visibleTets_ = tetCount_;
    faceCount_ = bvhNodes_ = 0;
    faces_.reset();
    bvh_.reset();
    return;
  }
  for (;;) {
    glProgramUniform1ui(program, u("capacity"), GLuint(capacity_));
    glProgramUniform1i(program, u("stage"), 1);
    dispatchOverTets(tetCount_);
    glGetNamedBufferSubData(found_.id(), 0, sizeof counts, counts);  // waits for the dispatches
    if (counts[0] <= capacity_) break;
    capacity_ = counts[0];
    found_ = storage(kHeaderBytes + capacity_ * sizeof(glm::uvec4));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kFoundFaces, found_.id());
    const GLuint restart[2] = {0, counts[1]};  // no face found yet; the visible tets counted
    glNamedBufferSubData(found_.id(), 0, sizeof restart, restart);
  }
  visibleTets_ = counts[1];
  faceCount_ = counts[0];
  std::vector<glm::uvec4> found(faceCount_);
  if (faceCount_ > 0)
    glGetNamedBufferSubData(found_.id(), GLintptr(kHeaderBytes), GLsizeiptr(faceCount_ * sizeof(glm::uvec4)), found.data());
  // The order the GPU appended them in varies; sorted, the BVH (and so every picture) is the same each time.
  std::sort(found.begin(), found.end(), [](const glm::uvec4& a, const glm::uvec4& b) { return a.x < b.x; });
  std::vector<std::uint32_t> faces(faceCount_);
  std::vector<glm::uvec3> corners(faceCount_);
  for (std::size_t i = 0; i < faceCount_; ++i) {
    faces[i] = found[i].x;
    corners[i] = {found[i].y, found[i].z, found[i].w};
  }
  std::vector<glm::vec4> bvh = buildFaceBvh(faces, corners, mesh.nodes);
  if (bvh.empty()) {  // nothing shows: one leaf whose box no ray meets
    const std::uint32_t bits[2] = {0, 1};
    float asFloat[2];
    std::memcpy(asFloat, bits, sizeof bits);
    bvh = {glm::vec4(glm::vec3(INFINITY), asFloat[0]), glm::vec4(glm::vec3(-INFINITY), asFloat[1])};
    faces = {0};
  }
  bvhNodes_ = bvh.size() / 2;
  upload(faces_, faces);
  upload(bvh_, bvh);
}

void VisibleTetsGpu::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kVisibleTets, bits_.id());
  if (!skipping()) return;
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kBvh, bvh_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kBoundaryFaces, faces_.id());
}

std::size_t VisibleTetsGpu::bytes() const {
  return bytesOfBits_ + (found_ ? kHeaderBytes + capacity_ * sizeof(glm::uvec4) : 0) +
         faceCount_ * sizeof(std::uint32_t) + bvhNodes_ * 2 * sizeof(glm::vec4);
}

void VisibleTetsGpu::release() {
  for (gl::Buffer* b : {&bits_, &found_, &faces_, &bvh_}) b->reset();
  capacity_ = bytesOfBits_ = tetCount_ = visibleTets_ = faceCount_ = bvhNodes_ = 0;
}

}  // namespace volpost::volume
