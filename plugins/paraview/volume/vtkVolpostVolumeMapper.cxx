// SPDX-License-Identifier: MIT
#include "vtkVolpostVolumeMapper.h"

#include "VtkToVolpost.h"

#include "CpuRayCaster.hpp"
#include "TetWalkMesh.hpp"

#include <volpost/core/Tetrahedralize.hpp>
#include <volpost/core/optics/ElementField.hpp>

#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkColorTransferFunction.h>
#include <vtkDataArray.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPlane.h>
#include <vtkPlaneCollection.h>
#include <vtkPointData.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>
#include <vtk_glew.h>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

/// What is kept between frames: the grid in volpost's terms and its walk mesh (rebuilt when
/// the grid, the array or the interpolation changes) and the part of it the transfer function
/// shows (found again when that changes).
class vtkVolpostVolumeState {
 public:
  vtkMTimeType gridTime = 0;
  std::string key;
  std::unique_ptr<volpost::Mesh> mesh;
  std::unique_ptr<volpost::TetMesh> tets;
  std::vector<double> nodeValues;
  std::shared_ptr<const volpost::volume::TetWalkMesh> walk;
  std::shared_ptr<const volpost::optics::ElementField> field;
  std::shared_ptr<const volpost::volume::CpuElementField> element;
  volpost::Bounds bounds;
  std::size_t skippedCells = 0;
  volpost::TransferFunction tf;
  std::optional<volpost::volume::VisiblePart> visible;
  double msPerPixel = 0.0;  ///< the last picture's wall time per pixel (for interactive renders)
  std::vector<volpost::ClipPlane> region;  ///< this rank's cuts in parallel (SetRankRegion)
};

vtkStandardNewMacro(vtkVolpostVolumeMapper);

vtkVolpostVolumeMapper::vtkVolpostVolumeMapper() : State(new vtkVolpostVolumeState) {}

vtkVolpostVolumeMapper::~vtkVolpostVolumeMapper() { delete this->State; }

void vtkVolpostVolumeMapper::SetRankRegion(const double bounds[6], int innerFaces) {
  std::vector<volpost::ClipPlane> region;
  for (int face = 0; face < 6; ++face) {
    if (!(innerFaces & (1 << face))) continue;
    const int axis = face / 2;
    glm::dvec3 point(0.0), normal(0.0);
    point[axis] = bounds[face];
    normal[axis] = face % 2 == 0 ? 1.0 : -1.0;  // keeps the inside of the box
    region.push_back({point, normal});
  }
  if (region == this->State->region) return;
  this->State->region = std::move(region);
  this->Modified();
}

void vtkVolpostVolumeMapper::ClearRankRegion() {
  if (this->State->region.empty()) return;
  this->State->region.clear();
  this->Modified();
}

void vtkVolpostVolumeMapper::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "EarlyTermination: " << this->EarlyTermination << "\n";
  os << indent << "Interpolation: " << (this->Interpolation ? "cells' own field" : "tetrahedra") << "\n";
  os << indent << "ElementTolerance: " << this->ElementTolerance << "\n";
  os << indent << "InteractiveUpdateRate: " << this->InteractiveUpdateRate << "\n";
  os << indent << "LastReduction: " << this->LastReduction << "\n";
}

namespace {

/// The grid as volpost's walk mesh: cells split into tets as volpost splits them, the
/// array's values carried over (node values to the split's extra points by its rule); with
/// `element`, the cells' own field over it.
void buildWalk(vtkVolpostVolumeState& s, vtkUnstructuredGrid& grid, vtkDataArray& array, bool perCell, bool element) {
  std::vector<std::size_t> kept;
  s.mesh = std::make_unique<volpost::Mesh>(volpost::paraview::meshOf(grid, s.skippedCells, kept));
  s.tets = std::make_unique<volpost::TetMesh>(volpost::tetrahedralize(*s.mesh));
  s.bounds = s.mesh->bounds();
  s.field.reset();
  s.element.reset();
  const std::vector<double> all = volpost::paraview::valuesOf(array);
  if (perCell) {
    std::vector<double> values(kept.size());
    for (std::size_t c = 0; c < kept.size(); ++c) values[c] = all[kept[c]];
    s.walk = std::make_shared<volpost::volume::TetWalkMesh>(s.tets->mesh, volpost::FieldLocation::Cell,
                                                            s.tets->cellValues(values));
    return;
  }
  s.nodeValues = all;
  s.walk = std::make_shared<volpost::volume::TetWalkMesh>(s.tets->mesh, volpost::FieldLocation::Node,
                                                          s.tets->nodeValues(*s.mesh, s.nodeValues));
  if (!element) return;
  s.field = std::make_shared<volpost::optics::ElementField>(*s.mesh, s.nodeValues, *s.tets, s.walk->origin());
  auto cells = std::make_shared<volpost::volume::CpuElementField>();
  cells->field = s.field;
  cells->cellOfTet.resize(s.walk->tetCount());  // the walk leaves degenerate tets out
  for (std::size_t t = 0; t < cells->cellOfTet.size(); ++t)
    cells->cellOfTet[t] = s.tets->sourceCell(s.walk->meshTet(t));
  s.element = std::move(cells);
}

/// Where the view's opaque geometry lies, as volpost's window depth for `camera` (0..1,
/// bottom row first) at width x height: rays end there, so a surface in front hides the
/// volume behind it. The view is `reduction` times larger each way (at most; its last
/// row and column may be cut); each picture pixel takes the view pixel under its centre.
/// Empty when nothing opaque was drawn.
std::vector<float> sceneDepthOf(vtkRenderer& renderer, const volpost::Camera& camera, int width, int height,
                                int reduction) {
  const int* origin = renderer.GetOrigin();
  const int* view = renderer.GetSize();
  std::vector<float> drawn(std::size_t(view[0]) * std::size_t(view[1]), 1.0f);
  if (!renderer.GetRenderWindow()->GetZbufferData(origin[0], origin[1], origin[0] + view[0] - 1,
                                                  origin[1] + view[1] - 1, drawn.data()))
    return {};
  vtkNew<vtkMatrix4x4> toWorld;
  toWorld->DeepCopy(
      renderer.GetActiveCamera()->GetCompositeProjectionTransformMatrix(renderer.GetTiledAspectRatio(), -1, 1));
  toWorld->Invert();
  const glm::dmat4 toVolpost = camera.projectionMatrix(double(width) / double(height)) * camera.viewMatrix();
  std::vector<float> depth(std::size_t(width) * std::size_t(height), 1.0f);
  bool any = false;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int vx = std::min(int((x + 0.5) * reduction), view[0] - 1);
      const int vy = std::min(int((y + 0.5) * reduction), view[1] - 1);
      const float d = drawn[std::size_t(vy) * std::size_t(view[0]) + std::size_t(vx)];
      if (!(d < 1.0f)) continue;
      const double ndc[4] = {(vx + 0.5) / view[0] * 2.0 - 1.0, (vy + 0.5) / view[1] * 2.0 - 1.0, 2.0 * d - 1.0, 1.0};
      double world[4];
      toWorld->MultiplyPoint(ndc, world);
      const glm::dvec4 clip =
          toVolpost * glm::dvec4(world[0] / world[3], world[1] / world[3], world[2] / world[3], 1.0);
      depth[std::size_t(y) * std::size_t(width) + std::size_t(x)] = float(std::clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0));
      any = true;
    }
  return any ? depth : std::vector<float>{};
}

/// Premultiplied RGBA over what the view holds, bottom row first as OpenGL draws, stretched
/// over the whole view (a reduced picture: its pixels cover about n x n of the view's; never
/// beyond the view, where another view of the layout may lie).
void drawOver(vtkRenderer& renderer, const volpost::volume::CpuImage& image) {
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer.GetRenderWindow());
  if (!window || image.width <= 0 || image.height <= 0) return;
  const std::size_t row = std::size_t(image.width) * 4;
  std::vector<float> bottomFirst(image.rgba.size());
  for (int y = 0; y < image.height; ++y)
    std::copy_n(image.rgba.begin() + std::ptrdiff_t(std::size_t(image.height - 1 - y) * row), row,
                bottomFirst.begin() + std::ptrdiff_t(std::size_t(y) * row));

  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunction(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  state->vtkglEnable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  const int* origin = renderer.GetOrigin();
  const int* view = renderer.GetSize();
  window->DrawPixels(origin[0], origin[1], origin[0] + view[0] - 1, origin[1] + view[1] - 1, 0, 0, image.width - 1,
                     image.height - 1, image.width, image.height, 4, VTK_FLOAT, bottomFirst.data());
}

// VTK's clipping planes as volpost's: both keep the side the normal points to.
std::vector<volpost::ClipPlane> clipPlanesOf(vtkPlaneCollection* planes) {
  std::vector<volpost::ClipPlane> out;
  if (!planes) return out;
  planes->InitTraversal();
  while (vtkPlane* plane = planes->GetNextItem()) {
    double origin[3], normal[3];
    plane->GetOrigin(origin);
    plane->GetNormal(normal);
    const glm::dvec3 n(normal[0], normal[1], normal[2]);
    if (!(glm::length(n) > 0.0) || !std::isfinite(glm::length(n)) || !std::isfinite(origin[0] + origin[1] + origin[2]))
      throw std::invalid_argument("a clip plane needs a finite origin and a nonzero normal");
    out.push_back({glm::dvec3(origin[0], origin[1], origin[2]), glm::normalize(n)});
  }
  return out;
}

}  // namespace

void vtkVolpostVolumeMapper::Render(vtkRenderer* renderer, vtkVolume* volume) {
  auto* grid = vtkUnstructuredGrid::SafeDownCast(this->GetInput());
  if (!renderer || !volume || !grid || grid->GetNumberOfCells() == 0) return;
  int perCell = 0;
  vtkDataArray* scalars =
      this->GetScalars(grid, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, perCell);
  if (!scalars) {
    vtkErrorMacro("volpost Volume draws a point or cell array: color by one.");
    return;
  }
  vtkVolpostVolumeState& s = *this->State;
  try {
    const bool element = this->Interpolation == 1;
    const std::string key = std::string(scalars->GetName() ? scalars->GetName() : "") +
                            (perCell ? " cells" : " points") + (element ? " element" : " tets") +
                            std::to_string(reinterpret_cast<std::uintptr_t>(grid));
    if (!s.walk || s.gridTime != grid->GetMTime() || s.key != key) {
      buildWalk(s, *grid, *scalars, perCell != 0, element && !perCell);
      if (element && perCell)
        vtkWarningMacro("The cells' own field needs values at the nodes: a cell array is drawn constant per cell.");
      if (s.skippedCells > 0)
        vtkWarningMacro(<< s.skippedCells << " cells are not drawn: volpost draws tetrahedra, hexahedra, wedges, "
                        << "pyramids and their quadratic forms.");
      if (s.field && !s.field->uninvertibleCells().empty())
        vtkWarningMacro(<< s.field->uninvertibleCells().size() << " cells are folded or inverted (the first is cell "
                        << s.field->uninvertibleCells().front()
                        << "): drawn by the tetrahedra of their split, not their own field.");
      s.gridTime = grid->GetMTime();
      s.key = key;
      s.visible.reset();
    }
    vtkVolumeProperty* property = volume->GetProperty();
    vtkColorTransferFunction* colors = property->GetRGBTransferFunction(0);
    vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
    double colorRange[2], opacityRange[2];
    colors->GetRange(colorRange);
    opacity->GetRange(opacityRange);
    const volpost::TransferFunction tf = volpost::paraview::transferFunctionOf(
        *colors, *opacity, property->GetScalarOpacityUnitDistance(0), std::min(colorRange[0], opacityRange[0]),
        std::max(colorRange[1], opacityRange[1]));
    if (!s.visible || !(tf == s.tf)) {
      s.visible = volpost::volume::findVisiblePart(*s.walk, tf, {}, 0, s.element.get());
      s.tf = tf;
    }
    const int* size = renderer->GetSize();
    if (size[0] <= 0 || size[1] <= 0) return;
    // While the view turns: fewer rays, as many as keep up with the rate asked for.
    int reduction = 1;
    const double rate = renderer->GetRenderWindow() ? renderer->GetRenderWindow()->GetDesiredUpdateRate() : 0.0;
    if (this->InteractiveUpdateRate > 0.0 && rate >= this->InteractiveUpdateRate && s.msPerPixel > 0.0) {
      const double fullMs = s.msPerPixel * double(size[0]) * double(size[1]);
      reduction = std::clamp(int(std::ceil(std::sqrt(fullMs * rate / 1000.0))), 1, 16);
    }
    const int width = (size[0] + reduction - 1) / reduction, height = (size[1] + reduction - 1) / reduction;
    const volpost::Camera camera = volpost::paraview::cameraOf(*renderer->GetActiveCamera(), s.bounds, width, height);
    volpost::volume::CpuRaySettings settings;
    settings.terminationTransmittance = this->EarlyTermination;
    settings.sceneDepth = sceneDepthOf(*renderer, camera, width, height, reduction);
    settings.element = s.element;
    settings.elementTolerance = s.element ? this->ElementTolerance : 0.0;
    settings.clipPlanes = clipPlanesOf(this->ClippingPlanes);
    settings.clipPlanes.insert(settings.clipPlanes.end(), s.region.begin(), s.region.end());
    const auto start = std::chrono::steady_clock::now();
    const volpost::volume::CpuImage image =
        volpost::volume::renderCpu(*s.walk, *s.visible, tf, camera, width, height, settings);
    s.msPerPixel = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() /
                   (double(width) * double(height));
    this->LastReduction = reduction;
    drawOver(*renderer, image);
  } catch (const std::exception& e) {
    vtkErrorMacro(<< "volpost Volume: " << e.what());
  }
}
