// SPDX-License-Identifier: MIT
// A volume's float image on disk, for comparisons with other renderers and references.
#pragma once

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace volpost::app {

/// Writes premultiplied RGBA floats (top row first) by the file's extension:
///  .npy  the RGBA values themselves, float32, shape (height, width, 4) (NumPy's format);
///  .pfm  RGB composited over `background`, float32 Portable Float Map (bottom row first).
/// Throws WriteError naming the file (unknown extension, folder missing, disk full); the
/// previous file stays intact on failure.
void writeFloatImage(const std::string& path, int width, int height, const std::vector<float>& rgba,
                     const glm::dvec3& background);
/// What writeFloatImage writes, as bytes.
std::string floatImageBytes(const std::string& path, int width, int height, const std::vector<float>& rgba,
                            const glm::dvec3& background);

}  // namespace volpost::app
