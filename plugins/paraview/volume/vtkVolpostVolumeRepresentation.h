// SPDX-License-Identifier: MIT
// "volpost Volume": ParaView's volume representation of unstructured grids (its data
// delivery, redistribution and ordered compositing in parallel, color map and opacity
// function) with volpost's ray caster as the only mapper. ParaView hands its own volume
// mappers tetrahedra of its split; this representation delivers the grid's own cells, so that
// the ray caster walks volpost's split of them or draws their own field, in one process and
// in parallel alike.
#ifndef vtkVolpostVolumeRepresentation_h
#define vtkVolpostVolumeRepresentation_h

#include "VolpostParaViewVolumeModule.h"

#include <vtkUnstructuredGridVolumeRepresentation.h>
class vtkPVRenderView;

class VOLPOSTPARAVIEWVOLUME_EXPORT vtkVolpostVolumeRepresentation : public vtkUnstructuredGridVolumeRepresentation {
 public:
  static vtkVolpostVolumeRepresentation* New();
  vtkTypeMacro(vtkVolpostVolumeRepresentation, vtkUnstructuredGridVolumeRepresentation);

  /// Always volpost's ray caster, whatever ParaView's Volume representation was set to.
  void SetActiveVolumeMapper(const char*) override;

  /// Forwarded to the ray caster (vtkVolpostVolumeMapper::SetEarlyTermination,
  /// SetInterpolation, SetElementTolerance).
  void SetEarlyTermination(double transmittance);
  void SetInterpolation(int interpolation);
  void SetElementTolerance(double tolerance);
  /// A clip plane: the volume on the side the normal points away from is cut away, each
  /// ray's stretch through the rest integrated exactly. Off by default.
  void SetClipping(int on);
  void SetClipOrigin(double x, double y, double z);
  void SetClipNormal(double x, double y, double z);

  /// Before each render: turns the view's depth peeling of volumes off. The ray caster
  /// draws its finished picture over the view; inside the peeling pass (the window's
  /// default) that picture would be blended once per peel into buffers it cannot write,
  /// and the window showed garbage around the volume. Volumes are then drawn after the
  /// translucent surfaces, as without depth peeling. In parallel, asks the view to move
  /// whole cells to every rank whose box they meet, and hands the ray caster this rank's box.
  int ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo) override;

 protected:
  vtkVolpostVolumeRepresentation();
  ~vtkVolpostVolumeRepresentation() override;

  /// Delivers an unstructured grid's own cells rather than ParaView's tetrahedra of them (a
  /// multiblock input, or one with a separate opacity array, gets ParaView's tetrahedra).
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// In parallel with ordered compositing: this rank's box of the view's cuts to the ray
  /// caster (vtkVolpostVolumeMapper::SetRankRegion); otherwise none.
  void UpdateRankRegion(vtkPVRenderView& view);
  /// Hands the mapper the plane, or none.
  void UpdateClipping();

 private:
  vtkVolpostVolumeRepresentation(const vtkVolpostVolumeRepresentation&) = delete;
  void operator=(const vtkVolpostVolumeRepresentation&) = delete;
  bool Clipping = false;
  double ClipOrigin[3] = {0.0, 0.0, 0.0};
  double ClipNormal[3] = {1.0, 0.0, 0.0};
};

#endif
