// SPDX-License-Identifier: MIT
// Meshes of hexahedra (hex8 or hex20) on a lattice carried to space by a function: boxes,
// bent boxes, quarter cylinders whose midside nodes sit on the arcs.
#pragma once

#include <volpost/core/CellShape.hpp>
#include <volpost/core/Field.hpp>
#include <volpost/core/Mesh.hpp>
#include <volpost/core/Model.hpp>

#include <glm/vec3.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <numbers>
#include <vector>

namespace volpost::test {

// n^3 cells of `type` (hex8 or hex20) on the lattice [0, n]^3 carried to space by `place`;
// nodes shared between cells.
inline Mesh hexLattice(CellType type, int n, const std::function<glm::dvec3(const glm::dvec3&)>& place) {
  Mesh mesh;
  std::map<std::array<int, 3>, NodeIndex> index;  // by position in half-cell steps
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        std::vector<NodeIndex> ids;
        for (int node = 0; node < topology(type).nodeCount; ++node) {
          const glm::dvec3 g = 2.0 * glm::dvec3(i, j, k) + naturalCoordinatesOfNode(type, node) + 1.0;
          const std::array<int, 3> key{int(g.x), int(g.y), int(g.z)};
          const auto [it, fresh] = index.emplace(key, NodeIndex(mesh.nodes.size()));
          if (fresh) mesh.nodes.push_back(place(0.5 * g));
          ids.push_back(it->second);
        }
        mesh.addCell(type, ids);
      }
  return mesh;
}

// n^3 hex20 cells of the quarter annulus r in [1, 2], theta in [0, 90 degrees], z in [0, 1],
// every node (the midside ones too) on its arc.
inline Mesh hex20QuarterAnnulus(int n) {
  return hexLattice(CellType::Hex20, n, [n](const glm::dvec3& g) {
    const double r = 1.0 + g.x / n, theta = std::numbers::pi / 2.0 * g.y / n;
    return glm::dvec3(r * std::cos(theta), r * std::sin(theta), g.z / n);
  });
}

// The quarter annulus of n^3 hex20 cells carrying the node field T, one step per function
// of the position.
inline std::shared_ptr<Model> quarterAnnulusModel(int n,
                                                  const std::vector<std::function<double(const glm::dvec3&)>>& steps) {
  auto model = std::make_shared<Model>();
  model->mesh() = hex20QuarterAnnulus(n);
  std::vector<std::vector<double>> values(steps.size());
  for (const glm::dvec3& p : model->mesh().nodes)
    for (std::size_t s = 0; s < steps.size(); ++s) values[s].push_back(steps[s](p));
  model->fields.push_back(Field::fromValues("T", FieldLocation::Node, 1, values));
  return model;
}

}  // namespace volpost::test
