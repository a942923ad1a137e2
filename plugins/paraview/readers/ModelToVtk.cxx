// SPDX-License-Identifier: MIT
#include "ModelToVtk.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace volpost::paraview {

namespace {

/// ParaView's component names for the kinds volpost knows (CalculiX's tensor order xx yy zz
/// xy yz zx is VTK's).
void nameComponents(vtkDoubleArray& array, FieldKind kind) {
  if (kind == FieldKind::Vector) {
    const char* names[] = {"X", "Y", "Z"};
    for (int c = 0; c < 3; ++c) array.SetComponentName(c, names[c]);
  } else if (kind == FieldKind::SymTensor) {
    const char* names[] = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};
    for (int c = 0; c < 6; ++c) array.SetComponentName(c, names[c]);
  }
}

void addFieldArray(const Field& field, std::size_t step, vtkDataSetAttributes& to) {
  const std::vector<double> values = field.valuesCopy(step);
  vtkNew<vtkDoubleArray> array;
  array->SetName(field.name().c_str());
  array->SetNumberOfComponents(field.components());
  array->SetNumberOfTuples(vtkIdType(field.entityCount()));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  nameComponents(*array, field.kind());
  to.AddArray(array);
}

void addIds(const std::vector<std::int64_t>& ids, const char* name, vtkDataSetAttributes& to) {
  if (ids.empty()) return;
  vtkNew<vtkTypeInt64Array> array;
  array->SetName(name);
  array->SetNumberOfTuples(vtkIdType(ids.size()));
  std::copy(ids.begin(), ids.end(), array->GetPointer(0));
  to.AddArray(array);
}

void addFields(const Model& model, const StepOfField& stepOf, vtkDataSetAttributes& points,
               vtkDataSetAttributes& cells) {
  for (const auto& field : model.fields)
    addFieldArray(*field, stepOf(*field), field->location() == FieldLocation::Node ? points : cells);
}

}  // namespace

void fillUnstructuredGrid(const Model& model, const StepOfField& stepOf, vtkUnstructuredGrid& out) {
  const Mesh& mesh = model.mesh();
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(vtkIdType(mesh.nodeCount()));
  for (std::size_t n = 0; n < mesh.nodeCount(); ++n) coordinates->SetTypedTuple(vtkIdType(n), &mesh.nodes[n].x);
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);

  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  vtkNew<vtkUnsignedCharArray> types;
  offsets->SetNumberOfTuples(vtkIdType(mesh.cellCount() + 1));
  connectivity->SetNumberOfTuples(vtkIdType(mesh.connectivity().size()));
  types->SetNumberOfTuples(vtkIdType(mesh.cellCount()));
  vtkIdType at = 0;
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) {
    offsets->SetValue(vtkIdType(c), at);
    types->SetValue(vtkIdType(c), static_cast<unsigned char>(vtkCellType(mesh.cellType(c))));
    for (const NodeIndex n : mesh.cellNodes(c)) connectivity->SetValue(at++, vtkIdType(n));
  }
  offsets->SetValue(vtkIdType(mesh.cellCount()), at);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);

  out.SetPoints(points);
  out.SetCells(types, cells);
  addIds(mesh.nodeIds, "node_id", *out.GetPointData());
  addIds(mesh.cellIds, "element_id", *out.GetCellData());
  addFields(model, stepOf, *out.GetPointData(), *out.GetCellData());
}

ImageGeometry imageGeometry(const RegularGrid& grid) {
  // Surveys store coordinates rounded, so their axes meet a hair off a right angle (90.0002
  // degrees): the axes are made orthogonal (the first kept, the others turned by the least)
  // when no point then moves by more than a thousandth of the smallest spacing.
  std::array<glm::dvec3, 3> direction{};
  direction[0] = glm::normalize(grid.axes[0]);
  direction[1] = glm::normalize(grid.axes[1] - glm::dot(grid.axes[1], direction[0]) * direction[0]);
  direction[2] = glm::cross(direction[0], direction[1]);
  if (glm::dot(direction[2], grid.axes[2]) < 0.0) direction[2] = -direction[2];
  ImageGeometry g{};
  for (int a = 0; a < 3; ++a) {
    g.dims[a] = int(grid.dims[a]);
    g.origin[a] = grid.origin[a];
    g.spacing[a] = glm::length(grid.axes[a]);
    for (int row = 0; row < 3; ++row) g.direction[row * 3 + a] = direction[a][row];
  }
  // The largest move is at a corner of the grid (positions are linear in the indices).
  for (int corner = 0; corner < 8; ++corner) {
    glm::dvec3 move(0.0);
    for (int a = 0; a < 3; ++a)
      if (corner & (1 << a)) move += double(grid.dims[a] - 1) * (grid.axes[a] - g.spacing[a] * direction[a]);
    g.largestMove = std::max(g.largestMove, glm::length(move));
  }
  const double smallest = std::min({g.spacing[0], g.spacing[1], g.spacing[2]});
  if (!(g.largestMove <= 1e-3 * smallest)) {
    std::ostringstream why;
    why << "the grid's axes are not at right angles (";
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3;
      const double cosine = glm::dot(glm::normalize(grid.axes[a]), glm::normalize(grid.axes[b]));
      why << (a ? ", " : "") << grid.axisNames[a] << " to " << grid.axisNames[b] << " "
          << std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / M_PI << " degrees";
    }
    why << ") and image data needs them square: open the file with the volpost finite-element reader, "
           "which gives its cells where they are";
    throw std::invalid_argument(why.str());
  }
  return g;
}

void fillImageData(const Model& model, const StepOfField& stepOf, vtkImageData& out) {
  if (!model.grid) throw std::invalid_argument("the file holds cells, not a regular grid of samples");
  const ImageGeometry g = imageGeometry(*model.grid);
  out.SetDimensions(g.dims);
  out.SetOrigin(g.origin);
  out.SetSpacing(g.spacing);
  out.SetDirectionMatrix(g.direction);
  addFields(model, stepOf, *out.GetPointData(), *out.GetCellData());
}

}  // namespace volpost::paraview
