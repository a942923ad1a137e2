// SPDX-License-Identifier: MIT
// Gathers result blocks as a reader meets them (one block = one field at one step) and
// turns them into the model's fields, one Field per name with all its steps in order.
#pragma once

#include <volpost/core/Model.hpp>

#include <map>
#include <string>
#include <vector>

namespace volpost::meshio {

class ResultCollector {
 public:
  /// `values` holds entityCount x components doubles. A block whose name was seen with a
  /// different location or component count becomes its own field ("name (cells)", ...).
  void add(const std::string& name, FieldLocation location, int components, Step step,
           std::vector<double> values);
  /// Empty, or what is wrong when a block's size does not fit the final mesh (a result
  /// block read before the mesh was complete, in a file that interleaves them).
  std::string mismatch(const Mesh& mesh) const;
  /// Moves the fields into `model` (in the order their names first appeared).
  void moveInto(Model& model);
  /// Bytes the blocks gathered so far hold.
  std::size_t bytes() const { return bytes_; }
  /// The bytes with `doubles` more values: what to check against the memory budget before
  /// allocating them (a small file can declare results that expand to gigabytes).
  double bytesWith(std::size_t doubles) const { return double(bytes_) + 8.0 * double(doubles); }

 private:
  struct Pending {
    std::string name;
    FieldLocation location;
    int components;
    std::vector<Step> steps;
    std::vector<std::vector<double>> values;
  };
  std::vector<Pending> fields_;
  std::size_t bytes_ = 0;
};

/// Values given per element corner (element-nodal or extrapolated Gauss points) averaged
/// at each node over the cells that share it. `cellCornerValues[c]` holds the nodes of
/// cell c in mesh order, `components` values each. Nodes no cell touches get NaN.
std::vector<double> averageToNodes(const Mesh& mesh, const std::vector<std::vector<double>>& cellCornerValues,
                                   int components);

}  // namespace volpost::meshio
