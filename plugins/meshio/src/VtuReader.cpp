// SPDX-License-Identifier: MIT
#include "VtuReader.hpp"

#include "VtkXmlReading.hpp"

#include <volpost/core/ResourceLimits.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <sstream>

namespace volpost::meshio {

void VtkXmlReading::readPiece(const pugi::xml_node& piece, Model& model) {
  const long long points = piece.attribute("NumberOfPoints").as_llong(-1);
  const long long cellCount = piece.attribute("NumberOfCells").as_llong(-1);
  if (points < 0 || cellCount < 0) failAt(piece, "<Piece> needs NumberOfPoints and NumberOfCells");
  const std::size_t nodeBase = model.nodeCount();

  if (points > 0) {
    const pugi::xml_node pts = piece.child("Points").child("DataArray");
    if (!pts) failAt(piece, "<Piece> has no <Points> DataArray");
    const VtuArraySource s = source(pts);
    if (s.components != 3) failAt(pts, "Points must have 3 components, not " + std::to_string(s.components));
    if (std::uint64_t(points) > std::numeric_limits<std::size_t>::max() / 24)
      failAt(piece, "NumberOfPoints " + std::to_string(points) + " is more than any file or memory can hold (corrupt)");
    const std::size_t expected = std::size_t(points) * 3;
    const auto xyz = guarded(pts, [&] { return vtuDoubles(s, enc_); });
    if (xyz.size() != expected)
      failAt(pts, "Points holds " + std::to_string(xyz.size() / 3) + " points, NumberOfPoints says " +
                      std::to_string(points));
    model.mesh().nodes.reserve(nodeBase + std::size_t(points));
    for (std::size_t i = 0; i < std::size_t(points); ++i)
      model.mesh().nodes.push_back({xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
  }
  progress_.report(0.4);

  VtkCellArrays cells;
  if (cellCount > 0) {
    const pugi::xml_node cellsNode = piece.child("Cells");
    if (!cellsNode) failAt(piece, "<Piece> has cells but no <Cells>");
    const pugi::xml_node offsetsNode = arrayNamed(cellsNode, "offsets");
    const pugi::xml_node typesNode = arrayNamed(cellsNode, "types");
    const pugi::xml_node connectivityNode = arrayNamed(cellsNode, "connectivity");
    const VtuArraySource connectivitySource = source(connectivityNode);
    const std::size_t entries = guarded(connectivityNode, [&] { return vtuValueCount(connectivitySource, enc_); });
    cells.types = integers(typesNode);
    const std::size_t n = std::size_t(cellCount);
    if (cells.types.size() != n)
      failAt(typesNode,
             "types holds " + std::to_string(cells.types.size()) + " cells, NumberOfCells says " + std::to_string(n));
    cells.offsets = integers(offsetsNode);
    std::vector<std::int64_t>& offsets = cells.offsets;
    if (offsets.size() == n + 1 && offsets.front() == 0) offsets.erase(offsets.begin());
    if (offsets.size() != n)
      failAt(offsetsNode,
             "offsets holds " + std::to_string(offsets.size()) + " cells, NumberOfCells says " + std::to_string(n));
    for (std::size_t i = 0; i < n; ++i)
      if (offsets[i] < (i ? offsets[i - 1] : 0) || std::uint64_t(offsets[i]) > entries)
        failAt(offsetsNode, "offset of cell " + std::to_string(i) + " (" + std::to_string(offsets[i]) +
                                ") is out of order or beyond the " + std::to_string(entries) + " connectivity entries");
    offsets.insert(offsets.begin(), 0);
    // Each piece numbers its own points from 0: an index outside them (negative, or past
    // this piece's points) must not silently land on another piece's nodes.
    if (std::uint64_t(nodeBase) + std::uint64_t(points) > std::numeric_limits<NodeIndex>::max())
      failAt(piece, "the pieces hold " + std::to_string(nodeBase + std::size_t(points)) +
                        " points, more than volpost's 32-bit node numbers can count (4,294,967,295)");
    try {
      cells.connectivity = vtuIndices(connectivitySource, enc_, std::uint64_t(points), NodeIndex(nodeBase));
    } catch (const VtuArrayError& e) {
      failAt(connectivityNode, e.message);
    } catch (const VtuIndexError& e) {
      const auto cell =
          std::upper_bound(offsets.begin(), offsets.end(), std::int64_t(e.position)) - offsets.begin() - 1;
      failAt(connectivityNode, "cell " + std::to_string(cell) + " uses point " + std::to_string(e.value) +
                                   ", outside this piece's " + std::to_string(points) + " points (0.." +
                                   std::to_string(points - 1) + ")");
    }
    if (cells.connectivity.size() != entries)
      failAt(connectivityNode, "holds " + std::to_string(cells.connectivity.size()) + " values, its header says " +
                                   std::to_string(entries));
  }
  const std::size_t pointTotal = nodeBase + std::size_t(points);
  const pugi::xml_node cellsNode = piece.child("Cells");
  VtkCellMapping mapping = addVtkCells(cells, pointTotal, model.mesh(),
                                       [&](const std::string& m) { failAt(cellsNode ? cellsNode : piece, m); });
  if (mapping.skipped)
    model.diagnostics.push_back(
        {Severity::Info,
         "skipped-cells",
         std::to_string(mapping.skipped) + " lower-dimensional cells (points, lines, faces) skipped",
         {}});
  progress_.report(0.7);
  collectArrays(piece.child("PointData"), FieldLocation::Node, std::size_t(points), nullptr, model);
  collectArrays(piece.child("CellData"), FieldLocation::Cell, std::size_t(cellCount), &mapping, model);
  ++pieceCount_;
}

int VtuReader::sniff(std::string_view head) const {
  const auto xml = head.find("<VTKFile");
  if (xml == std::string_view::npos) return 0;
  return head.find("UnstructuredGrid", xml) != std::string_view::npos ? 100 : 30;
}

std::unique_ptr<Model> VtuReader::read(const std::string& path, const Progress& progress) const {
  auto model = VtkXmlReading(path, progress, readInPlaceFrom_).run();
  model->formatName = model->grid ? "VTK XML image data" : formatName();
  progress.report(1.0);
  return model;
}

}  // namespace volpost::meshio
