// SPDX-License-Identifier: MIT
#include "FloatImageFile.hpp"

#include "host/AtomicFile.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>

namespace volpost::app {
namespace {

std::string extensionOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

template <typename T>
void append(std::string& out, const T* data, std::size_t count) {
  out.append(reinterpret_cast<const char*>(data), count * sizeof(T));
}

// NumPy's .npy, version 1.0: magic, header length, a Python dict padded so the data
// starts on a 64-byte boundary, then the raw little-endian floats in C order.
std::string npy(int width, int height, const std::vector<float>& rgba) {
  std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (" + std::to_string(height) + ", " +
                       std::to_string(width) + ", 4), }";
  const std::size_t unpadded = 10 + header.size() + 1;
  header.append((64 - unpadded % 64) % 64, ' ');
  header += '\n';
  std::string out = "\x93NUMPY";
  out += char(1);
  out += char(0);
  const std::uint16_t length = std::uint16_t(header.size());
  out += char(length & 0xff);
  out += char(length >> 8);
  out += header;
  append(out, rgba.data(), rgba.size());
  return out;
}

std::string pfm(int width, int height, const std::vector<float>& rgba, const glm::dvec3& background) {
  std::string out = "PF\n" + std::to_string(width) + " " + std::to_string(height) + "\n-1.0\n";  // negative: little endian
  std::vector<float> row(std::size_t(width) * 3);
  for (int y = height - 1; y >= 0; --y) {
    for (int x = 0; x < width; ++x) {
      const float* p = &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
      for (int k = 0; k < 3; ++k) row[std::size_t(3 * x + k)] = float(p[k] + (1.0 - p[3]) * background[k]);
    }
    append(out, row.data(), row.size());
  }
  return out;
}

}  // namespace

std::string floatImageBytes(const std::string& path, int width, int height, const std::vector<float>& rgba,
                            const glm::dvec3& background) {
  if (rgba.size() != std::size_t(width) * std::size_t(height) * 4)
    throw WriteError(path, "no float image to write (the picture has no volume)");
  const std::string ext = extensionOf(path);
  if (ext == ".npy") return npy(width, height, rgba);
  if (ext == ".pfm") return pfm(width, height, rgba, background);
  throw WriteError(path,
                   "float images are written as .npy (RGBA) or .pfm (RGB over the background), not '" + ext + "'");
}

void writeFloatImage(const std::string& path, int width, int height, const std::vector<float>& rgba,
                     const glm::dvec3& background) {
  writeFileAtomically(path, floatImageBytes(path, width, height, rgba, background));
}

}  // namespace volpost::app
