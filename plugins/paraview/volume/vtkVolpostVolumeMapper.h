// SPDX-License-Identifier: MIT
// A volume mapper for unstructured grids that draws with volpost's CPU ray caster: each
// pixel's ray walked tet to tet, the transfer function integrated exactly along it (no
// sampling step). Cells other than tetrahedra are split as volpost splits them. ParaView's
// color map and opacity function become volpost's transfer function (docs/user/paraview.md
// states the rule).
#ifndef vtkVolpostVolumeMapper_h
#define vtkVolpostVolumeMapper_h

#include "VolpostParaViewVolumeModule.h"

#include <vtkUnstructuredGridVolumeMapper.h>

class vtkVolpostVolumeState;

class VOLPOSTPARAVIEWVOLUME_EXPORT vtkVolpostVolumeMapper : public vtkUnstructuredGridVolumeMapper {
 public:
  static vtkVolpostVolumeMapper* New();
  vtkTypeMacro(vtkVolpostVolumeMapper, vtkUnstructuredGridVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// A ray stops once what lies behind would count less than this, which bounds the error
  /// per channel (0: never, the exact picture). Default 0.002, as volpost's.
  vtkSetClampMacro(EarlyTermination, double, 0.0, 0.1);
  vtkGetMacro(EarlyTermination, double);

  void Render(vtkRenderer* renderer, vtkVolume* volume) override;
  void ReleaseGraphicsResources(vtkWindow*) override {}

 protected:
  vtkVolpostVolumeMapper();
  ~vtkVolpostVolumeMapper() override;

 private:
  vtkVolpostVolumeMapper(const vtkVolpostVolumeMapper&) = delete;
  void operator=(const vtkVolpostVolumeMapper&) = delete;

  double EarlyTermination = 0.002;
  vtkVolpostVolumeState* State;
};

#endif
