// SPDX-License-Identifier: MIT
// Empty-space skipping for the GPU tet renderers: the part of the mesh the transfer
// function and the iso-surfaces can show (a bit per tet), and a BVH over the faces where
// that part ends. The ray caster walks only that part: a ray leaves it where it would enter
// a hidden tet and finds where it comes back in the BVH, as it finds where it re-enters a
// non-convex mesh; cell projection draws no hidden tet. A transfer function transparent
// over most of the range (the usual case, and the sharp peaks this is for) leaves most
// tets out. Found on the GPU (visible_tets.comp: the tets and their neighbours need not be
// kept in host memory); the BVH is built on the host over the faces read back.
#pragma once

#include "TetMeshGpu.hpp"

#include <volpost/render/GlObjects.hpp>

#include <cstddef>

namespace volpost::volume {

class VisibleTetsGpu {
 public:
  /// Finds the visible part of `mesh` with `program` (volume/visible_tets.comp, linked, its
  /// segment uniforms set and the volume's buffers bound).
  void update(GLuint program, const TetMeshGpu& mesh);
  /// Binds the bits; when only part of the mesh shows, also the BVH and the faces of that
  /// part in place of the mesh's boundary (the entry search then finds that part).
  void bind() const;
  /// Whether rays skip hidden tets: some but not all of them show. (None showing is a part
  /// too: an empty one, which no ray enters.)
  bool skipping() const { return visibleTets_ < tetCount_; }
  std::size_t visibleTets() const { return visibleTets_; }
  std::size_t boundaryFaces() const { return faceCount_; }
  std::size_t bytes() const;
  void release();

 private:
  gl::Buffer bits_, found_, faces_, bvh_;
  std::size_t bytesOfBits_ = 0;
  std::size_t capacity_ = 0;       ///< faces the found list holds
  std::size_t tetCount_ = 0, visibleTets_ = 0, faceCount_ = 0, bvhNodes_ = 0;
};

}  // namespace volpost::volume
