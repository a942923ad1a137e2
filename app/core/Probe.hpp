// SPDX-License-Identifier: MIT
// What a model holds at a point: the element there (its id as the file numbers it, its
// type and nodes) and every field's value, interpolated in that element with its own
// shape functions (trilinear in hex8, quadratic in tet10, serendipity in hex20 and
// wedge15) as the FE program and ParaView do; element data as stored. The window's Probe
// panel, `volpost probe` and the min/max markers all ask here.
#pragma once

#include "ModelSession.hpp"

#include <volpost/core/CellType.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace volpost::app {

/// How the values at a probed point were found.
enum class ProbeMethod {
  Outside,        ///< the point is not in the mesh
  Isoparametric,  ///< the element's shape functions at the point's natural coordinates
  TetSplit,       ///< linear in the tetrahedron of the element's split (the shape functions
                  ///< did not converge: a distorted element)
  AtNode,         ///< a node asked for by its id: its own values
  ElementCentre,  ///< an element asked for by its id: at its centre, by its shape functions
};
const char* describe(ProbeMethod method);

struct ProbedQuantity {
  Quantity quantity;
  double value = 0.0;
};

struct ProbedField {
  std::string name;
  FieldLocation location = FieldLocation::Node;
  std::vector<double> components;        ///< interpolated (node data) or as stored (element data)
  std::vector<ProbedQuantity> quantities;  ///< every quantity the field offers, from those components
};

struct ProbeResult {
  glm::dvec3 point{0.0};
  ProbeMethod method = ProbeMethod::Outside;
  std::size_t cell = 0;                 ///< 0-based element index in the model
  std::int64_t cellId = 0;              ///< the element's id as the file numbers it
  CellType cellType = CellType::Tet4;
  std::vector<std::int64_t> nodeIds;    ///< the element's nodes, file ids
  std::optional<std::int64_t> nodeId;   ///< the point is this node (within the tolerance)
  std::size_t nearestNode = 0;          ///< the element's node nearest the point (0-based index)
  std::int64_t nearestNodeId = 0;       ///< and its id
  glm::dvec3 natural{0.0};              ///< natural coordinates in the element (Isoparametric)
  std::size_t step = 0;
  /// On a regular grid, where the point is in the grid's own words: each axis's name and
  /// label there ("inline" 1005.25, "crossline" 2003, "time (ms)" 120).
  std::vector<std::pair<std::string, double>> gridPosition;
  std::vector<ProbedField> fields;
  bool inside() const { return method != ProbeMethod::Outside; }
  /// The value of a quantity by its written form ("S.mises"); nullopt when not probed.
  std::optional<double> value(const std::string& key) const;
  /// "inline 1005.25, crossline 2003, time (ms) 120"; empty off a grid.
  std::string gridPositionText() const;
};

/// Probes a point at a step (0-based; fields with fewer steps give their last). Thread-safe
/// (builds the session's locator on first use). Throws what a lazy read of a damaged file
/// throws (ReadError).
ProbeResult probeAt(const ModelSession& session, const glm::dvec3& point, std::size_t step);

/// The node with this id (as the file numbers it): its position, its own values, an
/// element it belongs to (whose element results are reported). Throws std::invalid_argument
/// when the model has no such node, or no element uses it.
ProbeResult probeNode(const ModelSession& session, std::int64_t nodeId, std::size_t step);
/// The element with this id: its centre (the point of the reference element's centre),
/// node results interpolated there by its shape functions, its element results as stored,
/// its nodes. Throws std::invalid_argument when the model has no such element.
ProbeResult probeElement(const ModelSession& session, std::int64_t elementId, std::size_t step);
/// "node 5484" or "element 15600" (also "n 5484", "e 15600", "elem"): what probeNode or
/// probeElement would report; nullopt for text of another form. Throws as they do.
std::optional<ProbeResult> probeById(const ModelSession& session, const std::string& text, std::size_t step);

}  // namespace volpost::app
