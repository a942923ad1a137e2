// SPDX-License-Identifier: MIT
#include "GpuLimits.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace volpost::volume {
namespace {

std::string mebibytes(double bytes) { return std::to_string(std::int64_t(bytes / 1048576.0 + 0.5)) + " MiB"; }

}  // namespace

void requireStorageBlockFits(const char* what, std::size_t bytes, std::int64_t limit) {
  if (limit <= 0 || bytes <= std::size_t(limit)) return;  // 0: the driver states no limit
  throw std::length_error(std::string("the volume's ") + what + " take " + std::to_string(bytes) + " bytes (" +
                          mebibytes(double(bytes)) + ") but this GPU's shader storage blocks hold at most " +
                          std::to_string(limit) + " bytes (" + mebibytes(double(limit)) +
                          ", GL_MAX_SHADER_STORAGE_BLOCK_SIZE): clip the model (a clip box keeps only the tets "
                          "inside it on the GPU) or use the CPU renderer (--renderer cpu)");
}

int projectionVertexCount(std::size_t tets) {
  constexpr std::size_t kMaxTets = std::size_t(std::numeric_limits<int>::max()) / 6;
  if (tets > kMaxTets)
    throw std::length_error("cell projection draws 6 vertices per tet in one call, at most " +
                            std::to_string(kMaxTets) + " tets; this volume has " + std::to_string(tets) +
                            ": use the ray caster (--renderer raycast) or the CPU renderer");
  return int(tets * 6);
}

int rayStepCap(std::size_t tets) { return int(std::min(tets, kMaxRaySteps - 16) + 16); }

}  // namespace volpost::volume
