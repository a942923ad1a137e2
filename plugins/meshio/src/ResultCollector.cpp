// SPDX-License-Identifier: MIT
#include "ResultCollector.hpp"

#include <cmath>
#include <limits>

namespace volpost::meshio {

void ResultCollector::add(const std::string& name, FieldLocation location, int components, Step step,
                          std::vector<double> values) {
  bytes_ += values.size() * sizeof(double);
  for (Pending& f : fields_) {
    if (f.name == name && f.location == location && f.components == components) {
      f.steps.push_back(std::move(step));
      f.values.push_back(std::move(values));
      return;
    }
  }
  std::string unique = name;
  for (const Pending& f : fields_)
    if (f.name == unique) unique = name + (location == FieldLocation::Cell ? " (cells)" : " (nodes)");
  for (int k = 2; ; ++k) {  // still taken: number it
    bool taken = false;
    for (const Pending& f : fields_) taken = taken || f.name == unique;
    if (!taken) break;
    unique = name + " (" + std::to_string(k) + ")";
  }
  fields_.push_back({unique, location, components, {std::move(step)}, {}});
  fields_.back().values.push_back(std::move(values));
}

std::string ResultCollector::mismatch(const Mesh& mesh) const {
  for (const Pending& f : fields_) {
    const std::size_t entities = f.location == FieldLocation::Node ? mesh.nodeCount() : mesh.cellCount();
    for (std::size_t s = 0; s < f.values.size(); ++s)
      if (f.values[s].size() != entities * std::size_t(f.components))
        return "result '" + f.name + "' (step " + std::to_string(s + 1) + ") was given for " +
               std::to_string(f.values[s].size() / std::size_t(f.components)) + " " +
               (f.location == FieldLocation::Node ? "nodes" : "cells") + " but the mesh has " + std::to_string(entities) +
               ": its block came before the mesh was complete";
  }
  return {};
}

void ResultCollector::moveInto(Model& model) {
  for (Pending& f : fields_)
    model.fields.push_back(Field::fromValues(f.name, f.location, f.components, std::move(f.values), std::move(f.steps)));
  fields_.clear();
}

std::vector<double> averageToNodes(const Mesh& mesh, const std::vector<std::vector<double>>& cellCornerValues,
                                   int components) {
  const std::size_t nc = std::size_t(components);
  std::vector<double> sum(mesh.nodeCount() * nc, 0.0);
  std::vector<std::uint32_t> count(mesh.nodeCount(), 0);
  for (std::size_t c = 0; c < cellCornerValues.size() && c < mesh.cellCount(); ++c) {
    const auto nodes = mesh.cellNodes(c);
    const auto& v = cellCornerValues[c];
    if (v.size() < nodes.size() * nc) continue;  // no values for this cell
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      for (std::size_t i = 0; i < nc; ++i) sum[nodes[k] * nc + i] += v[k * nc + i];
      ++count[nodes[k]];
    }
  }
  for (std::size_t n = 0; n < count.size(); ++n)
    for (std::size_t i = 0; i < nc; ++i)
      sum[n * nc + i] = count[n] ? sum[n * nc + i] / count[n] : std::numeric_limits<double>::quiet_NaN();
  return sum;
}

}  // namespace volpost::meshio
