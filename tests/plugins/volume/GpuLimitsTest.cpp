// SPDX-License-Identifier: MIT
// The limits a GPU structure must stay within, tested at their boundaries with small
// figures (the real ones need billions of tets): each refuses past the limit with a
// message naming it, and accepts the limit itself.
#include "GpuLimits.hpp"

#include <volpost/core/TetAdjacency.hpp>

#include <gtest/gtest.h>

#include <climits>
#include <stdexcept>
#include <string>

using namespace volpost;
using namespace volpost::volume;

namespace {

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::length_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(GpuLimits, AStorageBufferPastTheDeviceLimitIsRefusedNamingIt) {
  EXPECT_NO_THROW(requireStorageBlockFits("tetrahedra", 64, 64));
  const std::string m = messageOf([] { requireStorageBlockFits("tetrahedra", 65, 64); });
  EXPECT_NE(m.find("65 bytes"), std::string::npos) << m;
  EXPECT_NE(m.find("at most 64 bytes"), std::string::npos) << m;
  EXPECT_NE(m.find("GL_MAX_SHADER_STORAGE_BLOCK_SIZE"), std::string::npos) << m;
  EXPECT_NO_THROW(requireStorageBlockFits("tetrahedra", std::size_t(1) << 40, 0)) << "0: the driver states no limit";
}

TEST(GpuLimits, CellProjectionVertexCountStopsBeforeGLsizeiWraps) {
  const std::size_t most = std::size_t(INT_MAX) / 6;
  EXPECT_EQ(projectionVertexCount(most), int(most * 6));
  EXPECT_EQ(projectionVertexCount(0), 0);
  const std::string m = messageOf([&] { projectionVertexCount(most + 1); });
  EXPECT_NE(m.find(std::to_string(most)), std::string::npos) << m;
  EXPECT_NE(m.find("ray caster"), std::string::npos) << m;
}

TEST(GpuLimits, TheRayStepCapCoversEveryTetUpToItsBoundAndNeverWraps) {
  EXPECT_EQ(rayStepCap(0), 16);
  EXPECT_EQ(rayStepCap(1000), 1016);
  EXPECT_EQ(rayStepCap(kMaxRaySteps - 16), int(kMaxRaySteps));
  EXPECT_EQ(rayStepCap(kMaxRaySteps), int(kMaxRaySteps));
  EXPECT_EQ(rayStepCap(std::size_t(1) << 40), int(kMaxRaySteps)) << "huge counts stay within int";
}

TEST(GpuLimits, FaceIndicesStopBeforeTetTimesFourWrapsIn32Bits) {
  EXPECT_NO_THROW(requireFaceIndexable(kMaxTetsForFaceIndex));
  EXPECT_EQ(std::uint64_t(kMaxTetsForFaceIndex) * 4 + 3, std::uint64_t(UINT32_MAX)) << "the last face is the last uint";
  const std::string m = messageOf([] { requireFaceIndexable(kMaxTetsForFaceIndex + 1); });
  EXPECT_NE(m.find(std::to_string(kMaxTetsForFaceIndex + 1)), std::string::npos) << m;
  EXPECT_NE(m.find("32 bits"), std::string::npos) << m;
}
