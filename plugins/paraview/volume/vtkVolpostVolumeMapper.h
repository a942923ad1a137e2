// SPDX-License-Identifier: MIT
// A volume mapper for unstructured grids that draws with volpost's CPU ray caster: each
// pixel's ray walked tet to tet, the transfer function integrated exactly along it (no
// sampling step), on the tetrahedra of volpost's split of the grid's cells, or through the
// cells' own shape functions. ParaView's color map and opacity function become volpost's
// transfer function (docs/user/paraview.md states the rule).
#ifndef vtkVolpostVolumeMapper_h
#define vtkVolpostVolumeMapper_h

#include "VolpostParaViewVolumeModule.h"

#include <vtkUnstructuredGridVolumeMapper.h>

class vtkUnstructuredGrid;
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

  /// How node values vary inside a cell: 0, linear on the tetrahedra each cell is split into;
  /// 1, the cell's own shape functions (trilinear in a hex8, quadratic in a tet10 or hex20),
  /// within ElementTolerance per channel. Needs the grid's own cells, as the representation
  /// delivers them (ParaView's own Volume delivers tetrahedra of its split).
  vtkSetClampMacro(Interpolation, int, 0, 1);
  vtkGetMacro(Interpolation, int);
  /// The most a pixel's channel may differ from the exact picture of the cells' own field
  /// (0: to rounding). Default 0.01, as volpost's.
  vtkSetClampMacro(ElementTolerance, double, 0.0, 0.1);
  vtkGetMacro(ElementTolerance, double);

  /// In parallel, the box of space this rank draws (ParaView's ordered compositing gives each
  /// rank one, and its piece holds every cell that meets the box): each ray is cut exactly at
  /// the box's faces that it shares with another rank's box, so that the ranks' pictures,
  /// composited in view order, add up to the one-process picture. `innerFaces` has bit
  /// 2 * axis + (0 low, 1 high) set for each such face; the others (the outside of the whole
  /// grid) cut nothing. ClearRankRegion: one process, nothing cut.
  void SetRankRegion(const double bounds[6], int innerFaces);
  void ClearRankRegion();

  /// While the view turns (the render window's desired update rate at least this, as VTK's
  /// interactor sets it during a drag) the picture is drawn with one ray per n x n pixels,
  /// n chosen from the last pictures' cost per pixel so that a frame keeps up with that
  /// rate; the still render that ends the drag draws every pixel. 0: every pixel always.
  /// Default 1 frame per second, as vtkSmartVolumeMapper's.
  vtkSetClampMacro(InteractiveUpdateRate, double, 0.0, 1e6);
  vtkGetMacro(InteractiveUpdateRate, double);
  /// n of the last picture drawn (1: a ray per pixel).
  vtkGetMacro(LastReduction, int);
  /// The clipping planes (vtkAbstractMapper::AddClippingPlane, in the data's coordinates)
  /// cut each ray's stretch exactly: the side a plane's normal points away from is cut away,
  /// as VTK's mappers do. A plane with a zero normal is refused with an error.

  void Render(vtkRenderer* renderer, vtkVolume* volume) override;
  void ReleaseGraphicsResources(vtkWindow*) override {}

 protected:
  vtkVolpostVolumeMapper();
  ~vtkVolpostVolumeMapper() override;

 private:
  vtkVolpostVolumeMapper(const vtkVolpostVolumeMapper&) = delete;
  void operator=(const vtkVolpostVolumeMapper&) = delete;

  double EarlyTermination = 0.002;
  int Interpolation = 0;
  double ElementTolerance = 0.01;
  double InteractiveUpdateRate = 1.0;
  int LastReduction = 1;
  vtkVolpostVolumeState* State;
};

#endif
