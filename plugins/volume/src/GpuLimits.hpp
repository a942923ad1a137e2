// SPDX-License-Identifier: MIT
// The counts and sizes a GPU structure must stay within, checked before the work instead
// of overflowing: each throws std::length_error with a message naming the limit, the
// figure and what would have happened.
#pragma once

#include <cstddef>
#include <cstdint>

namespace volpost::volume {

/// A shader storage buffer of `bytes` must fit GL_MAX_SHADER_STORAGE_BLOCK_SIZE (`limit`,
/// as the driver reports it: llvmpipe says 128 MiB and does not enforce it, other drivers
/// do, and a larger buffer then reads as zeros or faults).
void requireStorageBlockFits(const char* what, std::size_t bytes, std::int64_t limit);

/// Vertices of one cell-projection draw (two triangles per tet), refused past GLsizei
/// (which would wrap at 358M tets and draw a fraction of them).
int projectionVertexCount(std::size_t tets);

/// Steps a ray may take through `tets` tetrahedra before it is stopped as lost: a safety
/// net against a cycle in a broken mesh (a real ray crosses each tet once), so every tet
/// once plus slack, but never more than 2^20 (a ray through a million tets needs a mesh of
/// about 10^17 tets in a cube; a cycling ray must not hold the GPU for minutes).
inline constexpr std::size_t kMaxRaySteps = std::size_t(1) << 20;
int rayStepCap(std::size_t tets);

}  // namespace volpost::volume
