// SPDX-License-Identifier: MIT
// What ParaView hands a volume mapper, in volpost's terms: the grid's cells and one value per
// node or cell, the color map and opacity function as a transfer function of extinction, and
// the view's camera.
#pragma once

#include <volpost/core/Camera.hpp>
#include <volpost/core/Field.hpp>
#include <volpost/core/Mesh.hpp>
#include <volpost/core/TransferFunction.hpp>

#include <cstddef>
#include <string>
#include <vector>

class vtkCamera;
class vtkColorTransferFunction;
class vtkDataArray;
class vtkPiecewiseFunction;
class vtkUnstructuredGrid;

namespace volpost::paraview {

/// The grid's 3D cells of the types volpost knows (tet4/10, hex8/20, wedge6/15, pyramid5);
/// `skipped` counts the others (polyhedra, 2D cells, ...), which are not drawn.
Mesh meshOf(vtkUnstructuredGrid& grid, std::size_t& skipped, std::vector<std::size_t>& keptCells);

/// One value per tuple: the array's value, or its magnitude when it has several components
/// (as ParaView's Volume draws vectors by default).
std::vector<double> valuesOf(vtkDataArray& array);

/// ParaView's color map and opacity function as volpost's transfer function. The opacity o
/// given for ParaView's unit distance d becomes the extinction -ln(1 - o) / d (a slab of
/// thickness d absorbs o), o = 1 the largest extinction volpost's float path takes.
/// Control points: every node of both functions, and 256 evenly spaced values across their
/// range so that the color map's own interpolation (Lab, diverging) is followed; between
/// them color and extinction are linear.
TransferFunction transferFunctionOf(vtkColorTransferFunction& colors, vtkPiecewiseFunction& opacity,
                                    double unitDistance, double low, double high);

/// The view's camera for a picture of `width` x `height`: eye, focal point, up, angle of
/// view (ParaView's is across the height, volpost's across the narrower side) or parallel
/// scale. `bounds` sets the depth range (volpost starts rays at its near plane).
Camera cameraOf(vtkCamera& camera, const Bounds& bounds, int width, int height);

}  // namespace volpost::paraview
