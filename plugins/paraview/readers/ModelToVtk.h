// SPDX-License-Identifier: MIT
// A volpost model as VTK data: cells in VTK's own types (quadratic cells as VTK's quadratic
// cells: volpost keeps VTK's node order), every field at one step as an array of its name.
#pragma once

#include <volpost/core/Model.hpp>

#include <cstddef>
#include <functional>

class vtkDataSetAttributes;
class vtkImageData;
class vtkUnstructuredGrid;

namespace volpost::paraview {

/// Which step of each field to show (see VolpostReading.h).
using StepOfField = std::function<std::size_t(const Field&)>;

/// The model's nodes, cells, file ids ("node_id", "element_id", as `volpost convert` names
/// them) and fields at their chosen steps.
void fillUnstructuredGrid(const Model& model, const StepOfField& stepOf, vtkUnstructuredGrid& out);

/// Where image data puts a regular grid: origin, spacing and each index axis's direction
/// (the columns of `direction`), the axes made exactly orthogonal. Throws
/// std::invalid_argument when that would move a point by more than a thousandth of the
/// smallest spacing (image data cannot hold a sheared grid; the mesh reader then gives its
/// cells).
struct ImageGeometry {
  int dims[3];
  double origin[3];
  double spacing[3];
  double direction[9];       ///< row-major 3x3, as vtkImageData::SetDirectionMatrix takes it
  double largestMove = 0.0;  ///< how far making the axes orthogonal moved a point, model units
};
ImageGeometry imageGeometry(const RegularGrid& grid);

/// A regular-grid model as image data: origin, spacing and the direction of each index axis.
/// Throws as imageGeometry, or std::invalid_argument when the model is not a grid.
void fillImageData(const Model& model, const StepOfField& stepOf, vtkImageData& out);

}  // namespace volpost::paraview
