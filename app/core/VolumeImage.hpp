// SPDX-License-Identifier: MIT
// Volume images of a model: the exact CPU reference renderer, for reports and as the
// yardstick of the GPU renderers.
#pragma once

#include "ModelSession.hpp"

#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/optics/ReferenceRenderer.hpp>

#include <QImage>

#include <optional>
#include <string>

namespace volpost::app {

struct VolumeRequest {
  Quantity quantity;
  std::size_t step = 0;
  std::string camera = "iso";
  int width = 800, height = 600;
  std::optional<TransferFunction> transferFunction;  ///< nullopt: defaultTransferFunction
  std::vector<ClipPlane> clipPlanes;
  std::vector<optics::IsoSurface> isoSurfaces;
  int threads = 0;
  bool edges = false;  ///< GPU renderers: draw the element edges, which end the rays
};

/// A first transfer function for a result: the cool-warm map over its range; extinction
/// rises linearly from 10% to 100% of 24 / (model diagonal) (1 / length unit), so the
/// part shows as a light fog and the highest values as dense color.
TransferFunction defaultTransferFunction(const ScalarView& view, double modelDiagonal);

/// Throws std::invalid_argument if the mesh is not made of tetrahedra, Cancelled on request.
optics::ReferenceImage renderVolumeReference(const ModelSession& session, const VolumeRequest& request,
                                             const Progress& progress = {});

/// The image composited over a background color, 8 bits per channel.
QImage toQImage(const optics::ReferenceImage& image, const glm::dvec3& background);

/// Writes the composited image as a Portable Float Map (RGB, 32-bit float, bottom row
/// first, little endian). Returns false if the file cannot be written.
bool writePfm(const optics::ReferenceImage& image, const glm::dvec3& background, const std::string& path);

}  // namespace volpost::app
