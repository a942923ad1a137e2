// SPDX-License-Identifier: MIT
#include "vtkVolpostVolumeRepresentation.h"

#include "vtkVolpostVolumeMapper.h"

#include <vtkNew.h>
#include <vtkObjectFactory.h>

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

void vtkVolpostVolumeRepresentation::SetEarlyTermination(double transmittance) {
  if (auto* mapper = vtkVolpostVolumeMapper::SafeDownCast(this->GetActiveVolumeMapper())) {
    mapper->SetEarlyTermination(transmittance);
    this->MarkModified();
  }
}
