// SPDX-License-Identifier: MIT
#include "Probe.hpp"

#include <volpost/core/CellShape.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace volpost::app {

namespace {

// Natural coordinates a point may lie outside its element and still count as in it (on a
// face shared with a neighbour, rounding), and how far the shape functions may be
// extrapolated for a point on the faceted surface the renderers draw: the chord of a
// curved face lies up to a few percent outside the curved element.
constexpr double kInsideSlack = 1e-9;
constexpr double kExtrapolation = 0.05;

std::vector<glm::dvec3> positionsOf(const Mesh& mesh, std::size_t cell) {
  std::vector<glm::dvec3> x;
  for (NodeIndex n : mesh.cellNodes(cell)) x.push_back(mesh.nodes[n]);
  return x;
}

// Natural coordinates of a node of the tet split in its source cell: an original node is
// one of the cell's; a Steiner point is the mean of its corners, the reference centre.
glm::dvec3 naturalOfSplitNode(const Mesh& mesh, const TetMesh& tets, std::size_t cell, NodeIndex node) {
  const CellType type = mesh.cellType(cell);
  const auto nodes = mesh.cellNodes(cell);
  if (node < tets.originalNodes)
    for (std::size_t k = 0; k < nodes.size(); ++k)
      if (nodes[k] == node) return naturalCoordinatesOfNode(type, int(k));
  return referenceCentre(type);
}

// Where p is in the element found by the tet split (its natural coordinates), found from
// the tet's barycentric weights as the first guess.
std::optional<glm::dvec3> naturalInLocatedCell(const Mesh& mesh, const TetMesh& tets, const PointLocation& at,
                                               const glm::dvec3& p) {
  const CellType type = mesh.cellType(at.cell);
  glm::dvec3 guess(0.0);
  for (int k = 0; k < 4; ++k) guess += at.weights[std::size_t(k)] * naturalOfSplitNode(mesh, tets, at.cell, at.nodes[std::size_t(k)]);
  if (type == CellType::Tet4) return guess;  // the split is the cell: barycentric is exact
  return naturalCoordinates(type, positionsOf(mesh, at.cell), p, guess);
}

struct Found {
  ProbeMethod method = ProbeMethod::Outside;
  std::size_t cell = 0;
  glm::dvec3 natural{0.0};
  std::optional<PointLocation> tet;  ///< for TetSplit
};

// Whether natural coordinates xi put p in the cell: inside the reference cell, or within
// the locator's tolerance of it in model units (a point on a curved face, rounded).
bool holds(const Mesh& mesh, std::size_t cell, const glm::dvec3& xi, const glm::dvec3& p, double tolerance) {
  const CellType type = mesh.cellType(cell);
  if (outsideReference(type, xi) <= kInsideSlack) return true;
  return glm::length(positionAt(type, positionsOf(mesh, cell), clampToReference(type, xi)) - p) <= tolerance;
}

// The element holding p: the one the tet split finds, when p is in it by its shape
// functions; else a neighbouring element whose curved faces hold p (quadratic elements
// bulge past their faceted split); else the found element, extrapolated a little or
// linear in its split.
Found findElement(const ModelSession& session, const glm::dvec3& p) {
  const Mesh& mesh = session.model().mesh();
  const TetMesh& tets = session.tetrahedra();
  const PointLocator& locator = session.locator();
  const double tolerance = kOnMeshTolerance * locator.modelSize();
  const std::optional<PointLocation> at = locator.locate(p);
  std::optional<glm::dvec3> xiAt;
  if (at) {
    xiAt = naturalInLocatedCell(mesh, tets, *at, p);
    if (xiAt && outsideReference(mesh.cellType(at->cell), *xiAt) <= kInsideSlack)
      return {ProbeMethod::Isoparametric, at->cell, *xiAt, {}};
  }
  std::vector<std::size_t> cells;
  for (std::uint32_t t : locator.tetsNear(p, locator.gridSpacing())) cells.push_back(tets.sourceCell(t));
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  for (std::size_t cell : cells) {
    const CellType type = mesh.cellType(cell);
    if (!topology(type).quadratic || (at && cell == at->cell) || cellRepeatsANode(mesh, cell)) continue;
    const auto xi = naturalCoordinates(type, positionsOf(mesh, cell), p, referenceCentre(type));
    if (xi && holds(mesh, cell, *xi, p, tolerance)) return {ProbeMethod::Isoparametric, cell, *xi, {}};
  }
  if (!at) return {};
  if (xiAt && outsideReference(mesh.cellType(at->cell), *xiAt) <= kExtrapolation)
    return {ProbeMethod::Isoparametric, at->cell, *xiAt, {}};
  return {ProbeMethod::TetSplit, at->cell, glm::dvec3(0.0), at};
}

// Weights on original nodes that interpolate node data at the point.
std::vector<std::pair<NodeIndex, double>> nodalWeights(const Mesh& mesh, const TetMesh& tets, const Found& f) {
  std::vector<std::pair<NodeIndex, double>> w;
  const auto nodes = mesh.cellNodes(f.cell);
  if (f.method == ProbeMethod::Isoparametric) {
    const ShapeValues n = shapeFunctions(mesh.cellType(f.cell), f.natural);
    for (std::size_t k = 0; k < nodes.size(); ++k) w.emplace_back(nodes[k], n[k]);
    return w;
  }
  const int corners = topology(mesh.cellType(f.cell)).cornerCount;
  for (int k = 0; k < 4; ++k) {
    const NodeIndex node = f.tet->nodes[std::size_t(k)];
    const double weight = f.tet->weights[std::size_t(k)];
    if (node < tets.originalNodes) {
      w.emplace_back(node, weight);
    } else {  // a Steiner point: the mean of its cell's corners
      for (int c = 0; c < corners; ++c) w.emplace_back(nodes[std::size_t(c)], weight / corners);
    }
  }
  return w;
}

ProbedField probeField(const Field& field, std::size_t step, std::size_t cell,
                       const std::vector<std::pair<NodeIndex, double>>& weights, std::optional<NodeIndex> atNode) {
  ProbedField out;
  out.name = field.name();
  out.location = field.location();
  const int nc = field.components();
  const std::size_t at = std::min(step, field.stepCount() - 1);
  // A field kept in its file's type is read as it is: a probe must not make it hold doubles.
  const bool stored = field.storesSamples() && !field.isLoaded(at);
  const SampleArray* samples = stored ? &field.samples(at) : nullptr;
  const std::vector<double>* doubles = stored ? nullptr : &field.values(at);
  const auto v = [&](std::size_t i) { return samples ? (*samples)[i] : (*doubles)[i]; };
  out.components.assign(std::size_t(nc), 0.0);
  for (int c = 0; c < nc; ++c) {
    if (field.location() == FieldLocation::Cell) {
      out.components[std::size_t(c)] = v(cell * std::size_t(nc) + std::size_t(c));
    } else if (atNode) {  // exactly the node's own value, not a sum that rounds to it
      out.components[std::size_t(c)] = v(std::size_t(*atNode) * std::size_t(nc) + std::size_t(c));
    } else {
      double sum = 0.0;
      for (const auto& [node, weight] : weights)
        if (weight != 0.0) sum += weight * v(std::size_t(node) * std::size_t(nc) + std::size_t(c));
      out.components[std::size_t(c)] = sum;
    }
  }
  for (const Quantity& q : quantitiesOf(field)) out.quantities.push_back({q, evaluateComponents(q, out.components)});
  return out;
}

// A point in a regular grid: its cell and trilinear weights from its continuous index, with
// no cells or tetrahedra built (a probe of a 256^3 cube would otherwise split 16M
// hexahedra). Values equal the hexahedron's shape functions there (trilinear).
ProbeResult probeGrid(const ModelSession& session, const RegularGrid& grid, const glm::dvec3& point, std::size_t step) {
  ProbeResult r;
  r.point = point;
  r.step = step;
  const glm::dvec3 index = grid.indexOf(point);
  const double slack = kOnMeshTolerance;  // of a cell, along each axis: rounding on a face
  std::array<std::size_t, 3> base{};
  glm::dvec3 f(0.0);
  for (int a = 0; a < 3; ++a) {
    const double last = double(grid.dims[std::size_t(a)] - 1);
    if (!(index[a] >= -slack && index[a] <= last + slack)) return r;
    const double clamped = std::clamp(index[a], 0.0, last);
    base[std::size_t(a)] = std::min(std::size_t(clamped), grid.dims[std::size_t(a)] - 2);
    f[a] = clamped - double(base[std::size_t(a)]);
  }
  const std::size_t cx = grid.dims[0] - 1, cy = grid.dims[1] - 1;
  r.method = ProbeMethod::Isoparametric;
  r.cell = base[0] + cx * (base[1] + cy * base[2]);
  r.cellId = std::int64_t(r.cell) + 1;
  r.cellType = CellType::Hex8;
  const std::array<NodeIndex, 8> corners = gridHexahedron(grid, base[0], base[1], base[2]);
  std::vector<glm::dvec3> positions;
  std::vector<std::pair<NodeIndex, double>> weights;
  const double nodeTolerance = kOnMeshTolerance * grid.bounds().diagonal();
  const Model& model = session.model();
  std::optional<NodeIndex> atNode;
  double nearest = INFINITY;
  for (const NodeIndex n : corners) {
    const auto [i, j, k] = grid.pointIndices(n);  // each base or base + 1
    weights.emplace_back(n, (i > base[0] ? f.x : 1.0 - f.x) * (j > base[1] ? f.y : 1.0 - f.y) *
                                (k > base[2] ? f.z : 1.0 - f.z));
    const glm::dvec3 p = model.nodePosition(n);
    positions.push_back(p);
    r.nodeIds.push_back(std::int64_t(n) + 1);
    const double d = glm::length(p - point);
    if (!atNode && d <= nodeTolerance) atNode = n;
    if (d < nearest) nearest = d, r.nearestNode = n;
  }
  r.nearestNodeId = std::int64_t(r.nearestNode) + 1;
  if (atNode) r.nodeId = std::int64_t(*atNode) + 1;
  r.natural = naturalCoordinates(CellType::Hex8, positions, point, referenceCentre(CellType::Hex8)).value_or(glm::dvec3(0.0));
  for (int a = 0; a < 3; ++a) r.gridPosition.push_back({grid.axisNames[std::size_t(a)], grid.label(a, index[a])});
  for (const auto& field : model.fields)
    if (field->stepCount() > 0) r.fields.push_back(probeField(*field, step, r.cell, weights, atNode));
  return r;
}

}  // namespace

const char* describe(ProbeMethod method) {
  switch (method) {
    case ProbeMethod::Outside: return "outside the mesh";
    case ProbeMethod::Isoparametric: return "interpolated with the element's shape functions";
    case ProbeMethod::TetSplit: return "interpolated linearly in the element's tetrahedral split (distorted element)";
    case ProbeMethod::AtNode:
      return "the node's own values";
    case ProbeMethod::ElementCentre:
      return "at the element's centre, by its shape functions";
  }
  return "?";
}

std::optional<double> ProbeResult::value(const std::string& key) const {
  for (const ProbedField& f : fields)
    for (const ProbedQuantity& q : f.quantities)
      if (q.quantity.key() == key || (f.name == key && &q == &f.quantities.front())) return q.value;
  return std::nullopt;
}

std::string ProbeResult::gridPositionText() const {
  std::string text;
  for (const auto& [axis, label] : gridPosition) {
    char number[32];
    std::snprintf(number, sizeof number, "%.6g", label);
    text += (text.empty() ? "" : ", ") + axis + " " + number;
  }
  return text;
}

ProbeResult probeAt(const ModelSession& session, const glm::dvec3& point, std::size_t step) {
  ProbeResult r;
  r.point = point;
  r.step = step;
  if (!std::isfinite(point.x + point.y + point.z)) return r;
  if (const auto& grid = session.model().grid; grid && grid->defect().empty()) return probeGrid(session, *grid, point, step);
  const Found found = findElement(session, point);
  if (found.method == ProbeMethod::Outside) return r;
  const Mesh& mesh = session.model().mesh();
  r.method = found.method;
  r.cell = found.cell;
  r.cellId = mesh.cellId(found.cell);
  r.cellType = mesh.cellType(found.cell);
  r.natural = found.natural;
  std::optional<NodeIndex> atNode;
  const double nodeTolerance = kOnMeshTolerance * session.locator().modelSize();
  double nearest = INFINITY;
  for (NodeIndex n : mesh.cellNodes(found.cell)) {
    r.nodeIds.push_back(mesh.nodeId(n));
    const double d = glm::length(mesh.nodes[n] - point);
    if (!atNode && d <= nodeTolerance) atNode = n;
    if (d < nearest) nearest = d, r.nearestNode = n;
  }
  r.nearestNodeId = mesh.nodeId(r.nearestNode);
  if (atNode) r.nodeId = mesh.nodeId(*atNode);
  if (const auto& grid = session.model().grid) {
    const glm::dvec3 index = grid->indexOf(point);
    for (int a = 0; a < 3; ++a) r.gridPosition.push_back({grid->axisNames[std::size_t(a)], grid->label(a, index[a])});
  }
  const auto weights = nodalWeights(mesh, session.tetrahedra(), found);
  for (const auto& field : session.model().fields)
    if (field->stepCount() > 0) r.fields.push_back(probeField(*field, step, found.cell, weights, atNode));
  return r;
}

namespace {

std::size_t nodeIndexOf(const Model& model, std::int64_t id) {
  const std::size_t count = model.nodeCount();
  if (!model.meshBuilt() || model.mesh().nodeIds.empty()) {  // ids are 1-based indices
    if (id >= 1 && std::uint64_t(id) <= count) return std::size_t(id - 1);
  } else {
    const auto& ids = model.mesh().nodeIds;
    const auto at = std::find(ids.begin(), ids.end(), id);
    if (at != ids.end()) return std::size_t(at - ids.begin());
  }
  throw std::invalid_argument("the model has no node " + std::to_string(id) + " (its " + std::to_string(count) +
                              " nodes are numbered as the file numbers them)");
}

std::size_t cellIndexOf(const Model& model, std::int64_t id) {
  const std::size_t count = model.cellCount();
  if (!model.meshBuilt() || model.mesh().cellIds.empty()) {
    if (id >= 1 && std::uint64_t(id) <= count) return std::size_t(id - 1);
  } else {
    const auto& ids = model.mesh().cellIds;
    const auto at = std::find(ids.begin(), ids.end(), id);
    if (at != ids.end()) return std::size_t(at - ids.begin());
  }
  throw std::invalid_argument("the model has no element " + std::to_string(id) + " (its " + std::to_string(count) +
                              " elements are numbered as the file numbers them)");
}

// The element's fields and the report's element part, with node data from `weights`.
void fillFromCell(ProbeResult& r, const ModelSession& session, std::size_t cell,
                  const std::vector<std::pair<NodeIndex, double>>& weights, std::optional<NodeIndex> atNode) {
  const Mesh& mesh = session.model().mesh();
  r.cell = cell;
  r.cellId = mesh.cellId(cell);
  r.cellType = mesh.cellType(cell);
  for (NodeIndex n : mesh.cellNodes(cell)) r.nodeIds.push_back(mesh.nodeId(n));
  for (const auto& field : session.model().fields)
    if (field->stepCount() > 0) r.fields.push_back(probeField(*field, r.step, cell, weights, atNode));
}

}  // namespace

ProbeResult probeNode(const ModelSession& session, std::int64_t nodeId, std::size_t step) {
  const Model& model = session.model();
  const std::size_t node = nodeIndexOf(model, nodeId);
  if (model.grid && !model.meshBuilt()) {  // a grid's node: probed where it is, no cells built
    ProbeResult r = probeAt(session, model.nodePosition(node), step);
    r.method = ProbeMethod::AtNode;
    return r;
  }
  const Mesh& mesh = model.mesh();
  for (std::size_t cell = 0; cell < mesh.cellCount(); ++cell) {
    const auto nodes = mesh.cellNodes(cell);
    if (std::find(nodes.begin(), nodes.end(), NodeIndex(node)) == nodes.end()) continue;
    ProbeResult r;
    r.point = mesh.nodes[node];
    r.step = step;
    r.method = ProbeMethod::AtNode;
    r.nodeId = nodeId;
    r.nearestNode = node;
    r.nearestNodeId = nodeId;
    fillFromCell(r, session, cell, {{NodeIndex(node), 1.0}}, NodeIndex(node));
    return r;
  }
  throw std::invalid_argument("node " + std::to_string(nodeId) + " belongs to no element");
}

ProbeResult probeElement(const ModelSession& session, std::int64_t elementId, std::size_t step) {
  const Model& model = session.model();
  const std::size_t cell = cellIndexOf(model, elementId);
  const Mesh& mesh = model.mesh();
  const CellType type = mesh.cellType(cell);
  ProbeResult r;
  r.step = step;
  r.method = ProbeMethod::ElementCentre;
  r.natural = referenceCentre(type);
  const std::vector<glm::dvec3> positions = positionsOf(mesh, cell);
  r.point = positionAt(type, positions, r.natural);
  const auto nodes = mesh.cellNodes(cell);
  const ShapeValues n = shapeFunctions(type, r.natural);
  std::vector<std::pair<NodeIndex, double>> weights;
  double nearest = INFINITY;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    weights.emplace_back(nodes[k], n[k]);
    const double d = glm::length(positions[k] - r.point);
    if (d < nearest) nearest = d, r.nearestNode = nodes[k];
  }
  r.nearestNodeId = mesh.nodeId(r.nearestNode);
  fillFromCell(r, session, cell, weights, std::nullopt);
  return r;
}

std::optional<ProbeResult> probeById(const ModelSession& session, const std::string& text, std::size_t step) {
  std::string word;
  long long id = 0;
  char rest = 0;
  char buffer[16] = {};
  if (std::sscanf(text.c_str(), " %15[A-Za-z] %lld %c", buffer, &id, &rest) != 2) return std::nullopt;
  word = buffer;
  std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (word == "node" || word == "n") return probeNode(session, id, step);
  if (word == "element" || word == "elem" || word == "e" || word == "cell") return probeElement(session, id, step);
  return std::nullopt;
}

}  // namespace volpost::app
