// SPDX-License-Identifier: MIT
#include "ReferenceVolumeImage.hpp"

#include "host/optics/GridReference.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace volpost::app {

// Cells whose map cannot be inverted are drawn by their split, and the user is told which.
std::vector<std::string> elementFieldNotes(const optics::ElementField& field, const Mesh& mesh, BentCells bent) {
  std::vector<std::string> notes;
  std::size_t bentCount = 0;
  double most = 0.0;  // the largest bend, in parts of its cell's size
  for (std::uint32_t c = 0; c < mesh.cellCount(); ++c) {
    if (!(field.bend(c) > 0.0)) continue;
    ++bentCount;
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (NodeIndex n : mesh.cellNodes(c)) lo = glm::min(lo, mesh.nodes[n]), hi = glm::max(hi, mesh.nodes[n]);
    most = std::max(most, field.bend(c) / glm::length(hi - lo));
  }
  if (bentCount > 0) {
    char share[32];
    std::snprintf(share, sizeof share, "%.2g%%", 100.0 * most);
    const bool one = bentCount == 1;
    notes.push_back(std::to_string(bentCount) + (one ? " cell bends" : " cells bend") +
                    " away from the flat faces of " + (one ? "its" : "their") + " tetrahedra (by up to " + share +
                    " of a cell): " +
                    (bent == BentCells::Followed
                         ? std::string("drawn to ") + (one ? "its" : "their") + " own curved faces"
                         : std::string("this renderer draws the field within the tetrahedra's flat faces; the "
                                       "reference renderer and the GPU renderers follow the curved faces")));
  }
  const auto& cells = field.uninvertibleCells();
  if (!cells.empty()) {
    std::string ids;
    for (std::size_t i = 0; i < cells.size() && i < 10; ++i)
      ids += (i ? ", " : "") + std::to_string(mesh.cellId(cells[i]));
    if (cells.size() > 10) ids += ", ...";
    notes.push_back(std::to_string(cells.size()) + " cell" + (cells.size() == 1 ? "" : "s") +
                    " folded, inverted or collapsed (no inverse map): drawn linear on their tetrahedra; cell id" +
                    (cells.size() == 1 ? " " : "s ") + ids);
  }
  if (field.fallbacks() > 0)
    notes.push_back(std::to_string(field.fallbacks()) +
                    " ray crossings of a cell where its inverse map did not converge: drawn linear on its tetrahedra");
  return notes;
}

optics::ReferenceImage renderVolumeReference(const Scene& scene, int width, int height, int threads,
                                             const Progress& progress) {
  if (!scene.session() || !scene.view()) throw std::invalid_argument("the reference renderer needs a result to render");
  const ScalarView& view = *scene.view();
  optics::RaySettings settings;
  settings.clipPlanes = scene.volume().allClipPlanes();
  settings.isoSurfaces = scene.volume().isoSurfaces;
  settings.shading = scene.volume().shading;
  // A regular grid's own field is the trilinear interpolant of its points (what the
  // texture renderers draw); a mesh's is linear on its tetrahedra.
  const Model& model = scene.session()->model();
  if (const auto& tf2d = scene.volume().transferFunction2D) {
    if (!model.grid || view.location != FieldLocation::Node)
      throw std::invalid_argument("2D transfer functions (over the value and its gradient) are drawn on regular grids' "
                                  "point values; this model is a mesh or the quantity is given per cell");
    // No exact integral: the midpoint rule, the step halved until each ray changes by < 1e-5.
    return optics::renderGridReference2D(*model.grid, view.values, *tf2d, scene.pictureCamera(width, height), width,
                                         height, settings, 1e-5, progress, threads);
  }
  if (model.grid && view.location == FieldLocation::Node)
    return optics::renderGridReference(*model.grid, view.values, scene.transferFunction(),
                                       scene.pictureCamera(width, height), width, height, settings, progress, threads);
  const TetMesh& tets = scene.session()->tetrahedra();
  const optics::TetVolume volume(tets.mesh, view.location, scene.session()->tetValues(view));
  // Values per cell are constant in it: both interpolations are the same field.
  std::optional<optics::ElementField> field;
  if (scene.volume().interpolation == FieldInterpolation::Element && view.location == FieldLocation::Node) {
    std::vector<double> converted;
    field.emplace(model.mesh(), view.values.doubles(converted), tets, volume.origin());
    settings.elementField = &*field;
  }
  optics::ReferenceImage image = optics::renderReference(
      volume, scene.transferFunction(), scene.pictureCamera(width, height), width, height, settings, progress, threads);
  if (field) image.notes = elementFieldNotes(*field, model.mesh());
  return image;
}

}  // namespace volpost::app
