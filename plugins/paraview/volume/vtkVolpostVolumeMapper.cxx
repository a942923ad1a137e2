// SPDX-License-Identifier: MIT
#include "vtkVolpostVolumeMapper.h"

#include "VtkToVolpost.h"

#include "CpuRayCaster.hpp"
#include "TetWalkMesh.hpp"

#include <volpost/core/Tetrahedralize.hpp>

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
#include <vtkPointData.h>
#include <vtkRenderer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>
#include <vtk_glew.h>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <exception>
#include <memory>
#include <optional>
#include <string>

/// What is kept between frames: the walk mesh (rebuilt when the grid or the array changes)
/// and the part of it the transfer function shows (found again when that changes).
class vtkVolpostVolumeState {
 public:
  vtkMTimeType gridTime = 0;
  std::string arrayKey;
  std::shared_ptr<const volpost::volume::TetWalkMesh> walk;
  volpost::Bounds bounds;
  std::size_t skippedCells = 0;
  volpost::TransferFunction tf;
  std::optional<volpost::volume::VisiblePart> visible;
};

vtkStandardNewMacro(vtkVolpostVolumeMapper);

vtkVolpostVolumeMapper::vtkVolpostVolumeMapper() : State(new vtkVolpostVolumeState) {}

vtkVolpostVolumeMapper::~vtkVolpostVolumeMapper() { delete this->State; }

void vtkVolpostVolumeMapper::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "EarlyTermination: " << this->EarlyTermination << "\n";
}

namespace {

/// The grid as volpost's walk mesh: cells split into tets as volpost splits them, the
/// array's values carried over (node values to the split's extra points by its rule).
std::shared_ptr<const volpost::volume::TetWalkMesh> walkMeshOf(vtkUnstructuredGrid& grid, vtkDataArray& array,
                                                               bool perCell, volpost::Bounds& bounds,
                                                               std::size_t& skipped) {
  std::vector<std::size_t> kept;
  const volpost::Mesh mesh = volpost::paraview::meshOf(grid, skipped, kept);
  const std::vector<double> all = volpost::paraview::valuesOf(array, -1);
  const volpost::TetMesh tets = volpost::tetrahedralize(mesh);
  bounds = mesh.bounds();
  if (perCell) {
    std::vector<double> values(kept.size());
    for (std::size_t c = 0; c < kept.size(); ++c) values[c] = all[kept[c]];
    const std::vector<double> tetValues = tets.cellValues(values);
    return std::make_shared<volpost::volume::TetWalkMesh>(tets.mesh, volpost::FieldLocation::Cell, tetValues);
  }
  const std::vector<double> nodeValues = tets.nodeValues(mesh, all);
  return std::make_shared<volpost::volume::TetWalkMesh>(tets.mesh, volpost::FieldLocation::Node, nodeValues);
}

/// Where the view's opaque geometry lies, as volpost's window depth for `camera` (0..1,
/// bottom row first): rays end there, so a surface in front hides the volume behind it.
/// Empty when nothing opaque was drawn.
std::vector<float> sceneDepthOf(vtkRenderer& renderer, const volpost::Camera& camera, int width, int height) {
  const int* origin = renderer.GetOrigin();
  std::vector<float> depth(std::size_t(width) * std::size_t(height), 1.0f);
  if (!renderer.GetRenderWindow()->GetZbufferData(origin[0], origin[1], origin[0] + width - 1, origin[1] + height - 1,
                                                  depth.data()))
    return {};
  vtkNew<vtkMatrix4x4> toWorld;
  toWorld->DeepCopy(
      renderer.GetActiveCamera()->GetCompositeProjectionTransformMatrix(renderer.GetTiledAspectRatio(), -1, 1));
  toWorld->Invert();
  const glm::dmat4 toVolpost = camera.projectionMatrix(double(width) / double(height)) * camera.viewMatrix();
  bool any = false;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float& d = depth[std::size_t(y) * std::size_t(width) + std::size_t(x)];
      if (!(d < 1.0f)) {
        d = 1.0f;
        continue;
      }
      const double ndc[4] = {(x + 0.5) / width * 2.0 - 1.0, (y + 0.5) / height * 2.0 - 1.0, 2.0 * d - 1.0, 1.0};
      double world[4];
      toWorld->MultiplyPoint(ndc, world);
      const glm::dvec4 clip =
          toVolpost * glm::dvec4(world[0] / world[3], world[1] / world[3], world[2] / world[3], 1.0);
      d = float(std::clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0));
      any = true;
    }
  return any ? depth : std::vector<float>{};
}

/// Premultiplied RGBA over what the view holds, bottom row first as OpenGL draws.
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
  window->DrawPixels(origin[0], origin[1], origin[0] + image.width - 1, origin[1] + image.height - 1, 0, 0,
                     image.width - 1, image.height - 1, image.width, image.height, 4, VTK_FLOAT, bottomFirst.data());
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
    const std::string key =
        std::string(scalars->GetName() ? scalars->GetName() : "") + (perCell ? " cells" : " points");
    if (!s.walk || s.gridTime != grid->GetMTime() || s.arrayKey != key) {
      s.walk = walkMeshOf(*grid, *scalars, perCell != 0, s.bounds, s.skippedCells);
      if (s.skippedCells > 0)
        vtkWarningMacro(<< s.skippedCells << " cells are not drawn: volpost draws tetrahedra, hexahedra, wedges, "
                        << "pyramids and their quadratic forms.");
      s.gridTime = grid->GetMTime();
      s.arrayKey = key;
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
      s.visible = volpost::volume::findVisiblePart(*s.walk, tf, {});
      s.tf = tf;
    }
    const int* size = renderer->GetSize();
    if (size[0] <= 0 || size[1] <= 0) return;
    const volpost::Camera camera =
        volpost::paraview::cameraOf(*renderer->GetActiveCamera(), s.bounds, size[0], size[1]);
    volpost::volume::CpuRaySettings settings;
    settings.terminationTransmittance = this->EarlyTermination;
    settings.sceneDepth = sceneDepthOf(*renderer, camera, size[0], size[1]);
    const volpost::volume::CpuImage image =
        volpost::volume::renderCpu(*s.walk, *s.visible, tf, camera, size[0], size[1], settings);
    drawOver(*renderer, image);
  } catch (const std::exception& e) {
    vtkErrorMacro(<< "volpost Volume: " << e.what());
  }
}
