// SPDX-License-Identifier: MIT
#include "VolumeImage.hpp"

#include "CameraSpec.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace volpost::app {
namespace {

glm::dvec3 composite(const glm::dvec4& p, const glm::dvec3& background) {
  return glm::dvec3(p) + (1.0 - p.a) * background;
}

}  // namespace

TransferFunction defaultTransferFunction(const ScalarView& view, double modelDiagonal) {
  const double lo = view.range.valid() ? view.range.min : 0.0;
  const double hi = view.range.valid() && view.range.max > lo ? view.range.max : lo + 1.0;
  // A thin fog everywhere (10%) so the part's shape shows, dense where the result peaks.
  const double tauMax = 24.0 / std::max(modelDiagonal, 1e-300);
  std::vector<ControlPoint> points = TransferFunction::ramp(lo, hi, "cool-warm", tauMax).points();
  for (auto& p : points) p.extinction = tauMax * (0.1 + 0.9 * (p.value - lo) / (hi - lo));
  return TransferFunction(std::move(points));
}

optics::ReferenceImage renderVolumeReference(const ModelSession& session, const VolumeRequest& request,
                                             const Progress& progress) {
  const Mesh& mesh = session.model().mesh;
  const ScalarView view = session.evaluate(request.quantity, request.step);
  const TransferFunction tf =
      request.transferFunction ? *request.transferFunction : defaultTransferFunction(view, mesh.bounds().diagonal());
  const optics::TetVolume volume(session.tetrahedra().mesh, view.location, session.tetValues(view));
  Camera camera;
  camera.fit(mesh.bounds());
  applyCameraSpec(camera, request.camera);
  optics::RaySettings settings;
  settings.clipPlanes = request.clipPlanes;
  settings.isoSurfaces = request.isoSurfaces;
  return optics::renderReference(volume, tf, camera, request.width, request.height, settings, progress, request.threads);
}

QImage toQImage(const optics::ReferenceImage& image, const glm::dvec3& background) {
  QImage out(image.width, image.height, QImage::Format_RGB888);
  for (int y = 0; y < image.height; ++y) {
    uchar* line = out.scanLine(y);
    for (int x = 0; x < image.width; ++x) {
      const glm::dvec3 c = composite(image.pixels[std::size_t(y * image.width + x)], background);
      for (int k = 0; k < 3; ++k) line[3 * x + k] = uchar(std::lround(std::clamp(c[k], 0.0, 1.0) * 255.0));
    }
  }
  return out;
}

bool writePfm(const optics::ReferenceImage& image, const glm::dvec3& background, const std::string& path) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return false;
  std::fprintf(f, "PF\n%d %d\n-1.0\n", image.width, image.height);  // negative scale: little endian
  std::vector<float> row(std::size_t(image.width) * 3);
  for (int y = image.height - 1; y >= 0; --y) {
    for (int x = 0; x < image.width; ++x) {
      const glm::dvec3 c = composite(image.pixels[std::size_t(y * image.width + x)], background);
      for (int k = 0; k < 3; ++k) row[std::size_t(3 * x + k)] = float(c[k]);
    }
    std::fwrite(row.data(), sizeof(float), row.size(), f);
  }
  return std::fclose(f) == 0;
}

}  // namespace volpost::app
