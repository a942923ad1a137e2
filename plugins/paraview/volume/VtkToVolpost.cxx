// SPDX-License-Identifier: MIT
#include "VtkToVolpost.h"

#include <volpost/core/CellType.hpp>

#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkColorTransferFunction.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <span>

namespace volpost::paraview {

Mesh meshOf(vtkUnstructuredGrid& grid, std::size_t& skipped, std::vector<std::size_t>& keptCells) {
  Mesh mesh;
  const vtkIdType points = grid.GetNumberOfPoints();
  mesh.nodes.resize(std::size_t(points));
  for (vtkIdType p = 0; p < points; ++p) {
    double x[3];
    grid.GetPoint(p, x);
    mesh.nodes[std::size_t(p)] = glm::dvec3(x[0], x[1], x[2]);
  }
  skipped = 0;
  keptCells.clear();
  vtkNew<vtkIdList> ids;
  std::vector<NodeIndex> nodes;
  for (vtkIdType c = 0; c < grid.GetNumberOfCells(); ++c) {
    const auto type = cellTypeFromVtk(grid.GetCellType(c));
    grid.GetCellPoints(c, ids);
    if (!type || ids->GetNumberOfIds() != topology(*type).nodeCount) {
      ++skipped;
      continue;
    }
    nodes.assign(std::size_t(ids->GetNumberOfIds()), 0);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) nodes[std::size_t(k)] = NodeIndex(ids->GetId(k));
    mesh.addCell(*type, nodes);
    keptCells.push_back(std::size_t(c));
  }
  return mesh;
}

std::vector<double> valuesOf(vtkDataArray& array) {
  const int components = array.GetNumberOfComponents();
  std::vector<double> values(std::size_t(array.GetNumberOfTuples()));
  for (vtkIdType t = 0; t < array.GetNumberOfTuples(); ++t) {
    double sum = 0.0;
    for (int k = 0; k < components; ++k) sum += array.GetComponent(t, k) * array.GetComponent(t, k);
    values[std::size_t(t)] = components == 1 ? array.GetComponent(t, 0) : std::sqrt(sum);
  }
  return values;
}

TransferFunction transferFunctionOf(vtkColorTransferFunction& colors, vtkPiecewiseFunction& opacity,
                                    double unitDistance, double low, double high) {
  std::vector<double> at;
  for (int i = 0; i < colors.GetSize(); ++i) {
    double node[6];
    colors.GetNodeValue(i, node);
    at.push_back(node[0]);
  }
  for (int i = 0; i < opacity.GetSize(); ++i) {
    double node[4];
    opacity.GetNodeValue(i, node);
    at.push_back(node[0]);
  }
  if (!(high > low)) high = low + 1.0;
  constexpr int kSamples = 256;
  for (int i = 0; i <= kSamples; ++i) at.push_back(low + (high - low) * double(i) / kSamples);
  std::sort(at.begin(), at.end());
  at.erase(std::unique(at.begin(), at.end()), at.end());
  const double d = unitDistance > 0.0 ? unitDistance : 1.0;
  std::vector<ControlPoint> points;
  points.reserve(at.size());
  for (const double v : at) {
    double rgb[3];
    colors.GetColor(v, rgb);
    const double o = std::clamp(opacity.GetValue(v), 0.0, 1.0);
    const double extinction = o >= 1.0 ? kMaxFloatExtinction : std::min(-std::log1p(-o) / d, kMaxFloatExtinction);
    points.push_back({v, glm::dvec3(rgb[0], rgb[1], rgb[2]), extinction});
  }
  return TransferFunction(std::move(points));
}

Camera cameraOf(vtkCamera& vtk, const Bounds& bounds, int width, int height) {
  Camera camera;
  if (bounds.valid) camera.fit(bounds);  // the depth range
  const double* eye = vtk.GetPosition();
  const double* focal = vtk.GetFocalPoint();
  const double* up = vtk.GetViewUp();
  camera.lookAt(glm::dvec3(eye[0], eye[1], eye[2]), glm::dvec3(focal[0], focal[1], focal[2]),
                glm::dvec3(up[0], up[1], up[2]));
  // ParaView's angle spans the height; volpost's the narrower side.
  const double narrowOverHeight = width < height ? double(width) / double(height) : 1.0;
  if (vtk.GetParallelProjection()) {
    camera.setProjection(Camera::Projection::Orthographic);
    const double halfNarrow = vtk.GetParallelScale() * narrowOverHeight;
    camera.setFieldOfView(2.0 * glm::degrees(std::atan(halfNarrow / camera.distance())));
  } else {
    const double half = glm::radians(vtk.GetViewAngle()) * 0.5;
    camera.setFieldOfView(2.0 * glm::degrees(std::atan(std::tan(half) * narrowOverHeight)));
  }
  return camera;
}

}  // namespace volpost::paraview
