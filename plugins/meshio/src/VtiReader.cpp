// SPDX-License-Identifier: MIT
#include "VtiReader.hpp"

#include "VtkXmlReading.hpp"

#include <volpost/core/ResourceLimits.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <sstream>

namespace volpost::meshio {

std::vector<double> VtkXmlReading::numbers(const pugi::xml_node& node, const char* attribute,
                                           std::vector<double> defaults) {
  const pugi::xml_attribute a = node.attribute(attribute);
  if (!a) return defaults;
  std::vector<double> out;
  std::istringstream in(a.as_string());
  for (double v; in >> v;) out.push_back(v);
  if (out.size() != defaults.size() || !std::all_of(out.begin(), out.end(), [](double v) { return std::isfinite(v); }))
    failAt(node, std::string(attribute) + "=\"" + a.as_string() + "\" needs " + std::to_string(defaults.size()) +
                     " finite numbers");
  return out;
}

VtkXmlReading::Extent VtkXmlReading::extentOf(const pugi::xml_node& node, const char* attribute) {
  const std::vector<double> v = numbers(node, attribute, std::vector<double>(6, NAN));
  Extent x;
  for (int a = 0; a < 6; ++a) {
    if (!(std::abs(v[std::size_t(a)]) < 1e15) || v[std::size_t(a)] != std::floor(v[std::size_t(a)]))
      failAt(node, std::string(attribute) + " needs 6 integers");
    x.e[std::size_t(a)] = (long long)v[std::size_t(a)];
  }
  for (int a = 0; a < 3; ++a)
    if (x.e[std::size_t(2 * a + 1)] < x.e[std::size_t(2 * a)])
      failAt(node, std::string(attribute) + " runs backwards along axis " + std::to_string(a));
  return x;
}

std::unique_ptr<Model> VtkXmlReading::readImage(const pugi::xml_node& image) {
  const Extent whole = extentOf(image, "WholeExtent");
  const std::vector<double> origin = numbers(image, "Origin", {0, 0, 0});
  const std::vector<double> spacing = numbers(image, "Spacing", {1, 1, 1});
  const std::vector<double> d = numbers(image, "Direction", {1, 0, 0, 0, 1, 0, 0, 0, 1});
  RegularGrid grid;
  grid.dims = whole.points();
  for (int a = 0; a < 3; ++a)  // VTK's Direction is row-major, its columns the index axes
    grid.axes[std::size_t(a)] =
        spacing[std::size_t(a)] * glm::dvec3(d[std::size_t(a)], d[std::size_t(3 + a)], d[std::size_t(6 + a)]);
  grid.origin = glm::dvec3(origin[0], origin[1], origin[2]) + double(whole.e[0]) * grid.axes[0] +
                double(whole.e[2]) * grid.axes[1] + double(whole.e[4]) * grid.axes[2];
  grid.axisNames = {"i", "j", "k"};
  grid.firstLabel = {double(whole.e[0]), double(whole.e[2]), double(whole.e[4])};
  if (const std::string defect = grid.defect(); !defect.empty())
    failAt(image, defect + " (WholeExtent, Spacing, Direction): volpost reads volumes, not 2D images");
  const std::size_t pointCount =
      checkedProduct(checkedProduct(grid.dims[0], grid.dims[1], path_, "the image"), grid.dims[2], path_, "the image");
  // One field's values (up to 8 bytes as stored, 8 more while decoded) and a renderer's
  // copy; the image holds no cells until something needs them (Model::mesh checks those).
  requireMemory(double(pointCount) * (16.0 + kGridDrawingBytesPerPoint), path_,
                "an image of " + std::to_string(pointCount) + " points");

  auto model = std::make_unique<Model>();
  model->title = image.attribute("VolpostTitle").as_string("");
  struct ImageArray {
    Extent extent;  // the piece's points
    VtuArraySource source;
  };
  std::map<std::string, std::vector<ImageArray>> arrays;
  std::map<std::string, int> components;
  std::vector<std::string> order;
  for (pugi::xml_node piece : image.children("Piece")) {
    const Extent e = extentOf(piece, "Extent");
    for (int a = 0; a < 3; ++a)
      if (e.e[std::size_t(2 * a)] < whole.e[std::size_t(2 * a)] ||
          e.e[std::size_t(2 * a + 1)] > whole.e[std::size_t(2 * a + 1)])
        failAt(piece, "the piece's Extent reaches outside the WholeExtent");
    const std::array<std::size_t, 3> pp = e.points();
    for (const auto& [section, location] :
         {std::pair{"PointData", FieldLocation::Node}, std::pair{"CellData", FieldLocation::Cell}})
      for (pugi::xml_node array : piece.child(section).children("DataArray")) {
        VtuArraySource s = source(array);
        if (s.name.empty()) failAt(array, "DataArray without a Name");
        const std::size_t entities = location == FieldLocation::Node
                                         ? pp[0] * pp[1] * pp[2]
                                         : std::max<std::size_t>(pp[0] - 1, 1) * std::max<std::size_t>(pp[1] - 1, 1) *
                                               std::max<std::size_t>(pp[2] - 1, 1);
        const std::size_t values = guarded(array, [&] { return vtuValueCount(s, enc_); });
        if (values != entities * std::size_t(s.components))
          failAt(array, "DataArray \"" + s.name + "\" holds " + std::to_string(values) + " values; the piece's " +
                            std::to_string(entities) + (location == FieldLocation::Node ? " points" : " cells") +
                            " x " + std::to_string(s.components) + " components need " +
                            std::to_string(entities * std::size_t(s.components)));
        const std::string key = std::string(location == FieldLocation::Node ? "n:" : "c:") + s.name;
        const auto [it, inserted] = components.try_emplace(key, s.components);
        if (it->second != s.components)
          failAt(array, "DataArray \"" + s.name + "\" changes its components between pieces");
        if (inserted) order.push_back(key);
        Extent cellsOrPoints = e;
        if (location == FieldLocation::Cell)  // the piece's cells: one fewer than its points along each axis
          for (int a = 0; a < 3; ++a) cellsOrPoints.e[std::size_t(2 * a + 1)] -= 1;
        arrays[key].push_back({cellsOrPoints, std::move(s)});
      }
  }
  model->grid = grid;
  const std::array<long long, 3> low = {whole.e[0], whole.e[2], whole.e[4]};
  // The type an image array is kept in: the pieces' own when they all share it and
  // together cover the image (VTK's pieces do not overlap); else floats wide enough for
  // it, so that a gap can be NaN (32-bit for small integers, 64-bit for the rest).
  // How many of the image's points (or cells) no piece gives a value: pieces may share
  // their boundary planes, so this is counted point by point, not from their sizes.
  const auto uncovered = [&](const std::vector<ImageArray>& parts, const std::array<std::size_t, 3>& size) {
    std::vector<bool> covered(size[0] * size[1] * size[2], false);
    for (const ImageArray& part : parts) {
      const auto n = part.extent.points();
      for (std::size_t k = 0; k < n[2]; ++k)
        for (std::size_t j = 0; j < n[1]; ++j)
          for (std::size_t i = 0; i < n[0]; ++i)
            covered[std::size_t(part.extent.e[0] - low[0]) + i +
                    size[0] * (std::size_t(part.extent.e[2] - low[1]) + j +
                               size[1] * (std::size_t(part.extent.e[4] - low[2]) + k))] = true;
    }
    return std::size_t(std::count(covered.begin(), covered.end(), false));
  };
  const auto imageSampleType = [](const std::vector<ImageArray>& parts, std::size_t missing) {
    bool same = !parts.empty();
    for (const ImageArray& part : parts) same = same && part.source.type == parts.front().source.type;
    const NumericType type = same ? parts.front().source.type : NumericType::Float64;
    const bool covers = same && missing == 0;
    switch (type) {
      case NumericType::Int8:
        return covers ? SampleType::Int8 : SampleType::Float32;
      case NumericType::UInt8:
        return covers ? SampleType::UInt8 : SampleType::Float32;
      case NumericType::Int16:
        return covers ? SampleType::Int16 : SampleType::Float32;
      case NumericType::UInt16:
        return covers ? SampleType::UInt16 : SampleType::Float32;
      case NumericType::Int32:
        return covers ? SampleType::Int32 : SampleType::Float64;
      case NumericType::UInt32:
        return covers ? SampleType::UInt32 : SampleType::Float64;
      case NumericType::Float32:
        return SampleType::Float32;
      default:
        return SampleType::Float64;  // 64-bit integers as doubles, as they are read
    }
  };
  for (const std::string& key : order) {
    const FieldLocation location = key[0] == 'n' ? FieldLocation::Node : FieldLocation::Cell;
    const int comps = components[key];
    std::array<std::size_t, 3> size = grid.dims;
    if (location == FieldLocation::Cell)
      for (std::size_t& n : size) n -= 1;
    const std::size_t entities = size[0] * size[1] * size[2];
    auto parts = std::make_shared<std::vector<ImageArray>>(std::move(arrays[key]));
    // Kept in the file's type when every piece has it and the pieces cover the image;
    // else as floats wide enough for it, NaN where no piece is.
    const std::size_t missing = uncovered(*parts, size);
    const SampleType stored = imageSampleType(*parts, missing);
    if (missing > 0)
      model->diagnostics.push_back({Severity::Warning,
                                    "image-gap",
                                    std::to_string(missing) + " of the " + std::to_string(entities) + " " +
                                        (location == FieldLocation::Node ? "points" : "cells") + " of \"" +
                                        key.substr(2) +
                                        "\" lie in no <Piece> (the pieces overlap or leave a gap): "
                                        "they have no value (drawn gray)",
                                    {}});
    // Every piece's values placed at its extent in the whole image.
    SampleLoader loader = [parts, size, low, comps, entities, stored, enc = enc_, path = path_](std::size_t) {
      SampleArray all(stored, entities * std::size_t(comps));
      if (stored == SampleType::Float32 || stored == SampleType::Float64)
        for (std::size_t i = 0; i < all.size(); ++i) all.set(i, NAN);
      for (const ImageArray& part : *parts) {
        const std::array<std::size_t, 3> n = part.extent.points();
        const std::size_t pieceValues = n[0] * n[1] * n[2] * std::size_t(comps);
        if (pieceValues == 0) continue;
        // Each run of values goes straight to its place in the image (no array of the
        // piece's values as doubles): value q is component q % comps of the piece's point
        // q / comps, x fastest.
        const auto place = [&](std::size_t first, const double* values, std::size_t count) {
          for (std::size_t q = first; q < first + count && q < pieceValues; ++q) {
            const std::size_t at = q / std::size_t(comps), c = q % std::size_t(comps);
            const std::size_t gi = std::size_t(part.extent.e[0] - low[0]) + at % n[0],
                              gj = std::size_t(part.extent.e[2] - low[1]) + at / n[0] % n[1],
                              gk = std::size_t(part.extent.e[4] - low[2]) + at / (n[0] * n[1]);
            const double x = values[q - first];
            // Text that does not fit its declared type ("300" in an Int8 array) is kept as written.
            if (!all.fitsExactly(x)) all = all.widenedTo(SampleType::Float64);
            all.set((gi + size[0] * (gj + size[1] * gk)) * std::size_t(comps) + c, x);
          }
        };
        try {
          vtuDoubleRuns(part.source, enc, place);
        } catch (const VtuArrayError& e) {
          throw ReadError(path, e.message);
        }
      }
      return all;
    };
    model->fields.push_back(
        Field::fromSamples(key.substr(2), location, comps, entities, std::vector<Step>{{"", 0.0}}, std::move(loader)));
  }
  return model;
}

int VtiReader::sniff(std::string_view head) const {
  const auto xml = head.find("<VTKFile");
  if (xml == std::string_view::npos) return 0;
  return head.find("ImageData", xml) != std::string_view::npos ? 100 : 0;
}

std::unique_ptr<Model> VtiReader::read(const std::string& path, const Progress& progress) const {
  auto model = VtkXmlReading(path, progress, readInPlaceFrom_).run();
  if (!model->grid) throw ReadError(path, "this VTK XML file holds no <ImageData>; for unstructured grids use .vtu");
  model->formatName = formatName();
  progress.report(1.0);
  return model;
}

}  // namespace volpost::meshio
