// SPDX-License-Identifier: MIT
// The float pictures `volpost render --float FILE.npy` writes, read back and compared.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

// The float32 values of a .npy file (version 1 header).
inline std::vector<float> readNpyFloats(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < 10) return {};
  const std::size_t header = 10 + std::size_t(std::uint8_t(bytes[8])) + 256 * std::size_t(std::uint8_t(bytes[9]));
  std::vector<float> values((bytes.size() - header) / 4);
  std::memcpy(values.data(), bytes.data() + header, values.size() * 4);
  return values;
}

// Two float pictures (--float .npy) of `floats` values each: their largest difference and
// the first one's largest alpha (so a test can tell that something shows). Sizes that
// differ fail the test and give an infinite difference.
struct FloatPicturesApart {
  float worst = 0.0f, alpha = 0.0f;
};
inline FloatPicturesApart compareFloatPictures(const std::string& picture, const std::string& reference,
                                               std::size_t floats) {
  const std::vector<float> a = readNpyFloats(picture), b = readNpyFloats(reference);
  EXPECT_EQ(a.size(), floats) << picture;
  EXPECT_EQ(b.size(), floats) << reference;
  FloatPicturesApart apart;
  if (a.size() != floats || b.size() != floats) return {std::numeric_limits<float>::infinity(), 0.0f};
  for (std::size_t i = 0; i < a.size(); ++i) apart.worst = std::max(apart.worst, std::abs(a[i] - b[i]));
  for (std::size_t i = 3; i < a.size(); i += 4) apart.alpha = std::max(apart.alpha, a[i]);
  return apart;
}
