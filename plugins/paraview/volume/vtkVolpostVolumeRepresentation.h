// SPDX-License-Identifier: MIT
// "volpost Volume": ParaView's volume representation of unstructured grids (its data
// delivery, redistribution and ordered compositing in parallel, color map and opacity
// function) with volpost's ray caster as the only mapper. ParaView hands every volume mapper
// tetrahedra (its preprocessor splits hexahedra, wedges and pyramids its own way).
#ifndef vtkVolpostVolumeRepresentation_h
#define vtkVolpostVolumeRepresentation_h

#include "VolpostParaViewVolumeModule.h"

#include <vtkUnstructuredGridVolumeRepresentation.h>

class VOLPOSTPARAVIEWVOLUME_EXPORT vtkVolpostVolumeRepresentation : public vtkUnstructuredGridVolumeRepresentation {
 public:
  static vtkVolpostVolumeRepresentation* New();
  vtkTypeMacro(vtkVolpostVolumeRepresentation, vtkUnstructuredGridVolumeRepresentation);

  /// Always volpost's ray caster, whatever ParaView's Volume representation was set to.
  void SetActiveVolumeMapper(const char*) override;

  /// Forwarded to the ray caster (vtkVolpostVolumeMapper::SetEarlyTermination).
  void SetEarlyTermination(double transmittance);

 protected:
  vtkVolpostVolumeRepresentation();
  ~vtkVolpostVolumeRepresentation() override;

 private:
  vtkVolpostVolumeRepresentation(const vtkVolpostVolumeRepresentation&) = delete;
  void operator=(const vtkVolpostVolumeRepresentation&) = delete;
};

#endif
