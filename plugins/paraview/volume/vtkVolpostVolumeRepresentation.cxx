// SPDX-License-Identifier: MIT
#include "vtkVolpostVolumeRepresentation.h"

#include "vtkVolpostVolumeMapper.h"

#include <vtkBoundingBox.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkPVRenderView.h>
#include <vtkPVRenderViewDataDeliveryManager.h>
#include <vtkPVView.h>
#include <vtkPlane.h>
#include <vtkRenderer.h>
#include <vtkVolumeRepresentationPreprocessor.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace {
constexpr const char* kMapper = "volpost exact ray caster";

// The faces of box `rank` that another box lies against (bit 2 * axis + side): the cuts
// between ranks. The others are the outside of the whole (a ray cut there would lose the
// part of a cell the box was drawn tight around).
int sharedFaces(const std::vector<vtkBoundingBox>& boxes, int rank) {
  double own[6];
  boxes[std::size_t(rank)].GetBounds(own);
  int shared = 0;
  for (std::size_t other = 0; other < boxes.size(); ++other) {
    if (int(other) == rank || !boxes[other].IsValid()) continue;
    double b[6];
    boxes[other].GetBounds(b);
    for (int axis = 0; axis < 3; ++axis) {
      bool overlaps = true;  // in the other two axes, by a positive extent
      for (int a = 0; a < 3; ++a)
        if (a != axis) overlaps = overlaps && std::min(own[2 * a + 1], b[2 * a + 1]) > std::max(own[2 * a], b[2 * a]);
      if (!overlaps) continue;
      if (b[2 * axis + 1] == own[2 * axis]) shared |= 1 << (2 * axis);
      if (b[2 * axis] == own[2 * axis + 1]) shared |= 1 << (2 * axis + 1);
    }
  }
  return shared;
}
}  // namespace

vtkStandardNewMacro(vtkVolpostVolumeRepresentation);

vtkVolpostVolumeRepresentation::vtkVolpostVolumeRepresentation() {
  vtkNew<vtkVolpostVolumeMapper> mapper;
  this->AddVolumeMapper(kMapper, mapper);
  this->Superclass::SetActiveVolumeMapper(kMapper);
}

vtkVolpostVolumeRepresentation::~vtkVolpostVolumeRepresentation() = default;

void vtkVolpostVolumeRepresentation::SetActiveVolumeMapper(const char*) {
  this->Superclass::SetActiveVolumeMapper(kMapper);
}

int vtkVolpostVolumeRepresentation::RequestData(vtkInformation* request, vtkInformationVector** inputs,
                                                vtkInformationVector* outputs) {
  vtkUnstructuredGrid* grid =
      inputs[0]->GetNumberOfInformationObjects() == 1 ? vtkUnstructuredGrid::GetData(inputs[0], 0) : nullptr;
  // What the view delivers (and in parallel redistributes) is the preprocessor's output.
  auto* delivered = vtkUnstructuredGrid::SafeDownCast(this->Preprocessor->GetOutputDataObject(0));
  if (!grid || !delivered || this->UseSeparateOpacityArray)  // ParaView's tetrahedra, as its Volume has them
    return this->Superclass::RequestData(request, inputs, outputs);
  // The grid's own cells instead of ParaView's tetrahedra of them (not made at all).
  delivered->ShallowCopy(grid);
  vtkMath::UninitializeBounds(this->DataBounds);
  delivered->GetBounds(this->DataBounds);
  return this->vtkVolumeRepresentation::RequestData(request, inputs, outputs);
}

int vtkVolpostVolumeRepresentation::ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* inInfo,
                                                       vtkInformation* outInfo) {
  auto* view = vtkPVRenderView::SafeDownCast(inInfo->Get(vtkPVView::VIEW()));
  if (request == vtkPVView::REQUEST_RENDER() && this->GetVisibility() && view)
    if (vtkRenderer* renderer = view->GetRenderer()) renderer->SetUseDepthPeelingForVolumes(false);
  if (!this->Superclass::ProcessViewRequest(request, inInfo, outInfo)) return 0;
  if (request == vtkPVView::REQUEST_UPDATE()) {
    // In parallel every rank gets each cell that meets its box whole (a cell on a cut goes
    // to both sides), and the ray caster cuts its rays at the box (UpdateRankRegion).
    vtkPVRenderView::SetRedistributionModeToDuplicateBoundaryCells(inInfo, this);
  } else if (request == vtkPVView::REQUEST_RENDER() && view) {
    this->UpdateRankRegion(*view);
  }
  return 1;
}

void vtkVolpostVolumeRepresentation::UpdateRankRegion(vtkPVRenderView& view) {
  auto* mapper = vtkVolpostVolumeMapper::SafeDownCast(this->GetActiveVolumeMapper());
  if (!mapper) return;
  auto* delivery = vtkPVRenderViewDataDeliveryManager::SafeDownCast(view.GetDeliveryManager());
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  if (!delivery || ranks < 2 || !view.GetUseOrderedCompositing() ||
      delivery->GetCuts().size() != std::size_t(ranks)) {
    mapper->ClearRankRegion();
    return;
  }
  const std::vector<vtkBoundingBox>& cuts = delivery->GetCuts();
  const int rank = controller->GetLocalProcessId();
  double own[6];
  cuts[std::size_t(rank)].GetBounds(own);
  mapper->SetRankRegion(own, sharedFaces(cuts, rank));
}

void vtkVolpostVolumeRepresentation::SetInterpolation(int interpolation) {
  if (auto* mapper = vtkVolpostVolumeMapper::SafeDownCast(this->GetActiveVolumeMapper())) {
    mapper->SetInterpolation(interpolation);
    this->MarkModified();
  }
}

void vtkVolpostVolumeRepresentation::SetElementTolerance(double tolerance) {
  if (auto* mapper = vtkVolpostVolumeMapper::SafeDownCast(this->GetActiveVolumeMapper())) {
    mapper->SetElementTolerance(tolerance);
    this->MarkModified();
  }
}

void vtkVolpostVolumeRepresentation::SetClipping(int on) {
  this->Clipping = on != 0;
  this->UpdateClipping();
}

void vtkVolpostVolumeRepresentation::SetClipOrigin(double x, double y, double z) {
  this->ClipOrigin[0] = x, this->ClipOrigin[1] = y, this->ClipOrigin[2] = z;
  this->UpdateClipping();
}

void vtkVolpostVolumeRepresentation::SetClipNormal(double x, double y, double z) {
  this->ClipNormal[0] = x, this->ClipNormal[1] = y, this->ClipNormal[2] = z;
  this->UpdateClipping();
}

void vtkVolpostVolumeRepresentation::UpdateClipping() {
  auto* mapper = vtkVolpostVolumeMapper::SafeDownCast(this->GetActiveVolumeMapper());
  if (!mapper) return;
  mapper->RemoveAllClippingPlanes();
  if (this->Clipping) {
    vtkNew<vtkPlane> plane;
    plane->SetOrigin(this->ClipOrigin);
    plane->SetNormal(this->ClipNormal);
    mapper->AddClippingPlane(plane);
  }
  this->MarkModified();
}

void vtkVolpostVolumeRepresentation::SetEarlyTermination(double transmittance) {
  if (auto* mapper = vtkVolpostVolumeMapper::SafeDownCast(this->GetActiveVolumeMapper())) {
    mapper->SetEarlyTermination(transmittance);
    this->MarkModified();
  }
}
