// SPDX-License-Identifier: MIT
#include "vtkVolpostVolumeRepresentation.h"

#include "vtkVolpostVolumeMapper.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPVRenderView.h>
#include <vtkPVView.h>
#include <vtkPlane.h>
#include <vtkRenderer.h>
#include <vtkUnstructuredGrid.h>

namespace {
constexpr const char* kMapper = "volpost exact ray caster";
}

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
  if (auto* mapper = vtkVolpostVolumeMapper::SafeDownCast(this->GetActiveVolumeMapper())) {
    vtkUnstructuredGrid* grid = nullptr;
    if (inputs[0]->GetNumberOfInformationObjects() > 0) grid = vtkUnstructuredGrid::GetData(inputs[0], 0);
    mapper->SetSourceGrid(grid);
  }
  return this->Superclass::RequestData(request, inputs, outputs);
}

int vtkVolpostVolumeRepresentation::ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* inInfo,
                                                       vtkInformation* outInfo) {
  if (request == vtkPVView::REQUEST_RENDER() && this->GetVisibility())
    if (auto* view = vtkPVRenderView::SafeDownCast(inInfo->Get(vtkPVView::VIEW())))
      if (vtkRenderer* renderer = view->GetRenderer()) renderer->SetUseDepthPeelingForVolumes(false);
  return this->Superclass::ProcessViewRequest(request, inInfo, outInfo);
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
