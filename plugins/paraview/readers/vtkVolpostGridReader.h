// SPDX-License-Identifier: MIT
// ParaView's reader of the regular grids volpost reads (SEG-Y seismic volumes, NRRD): image
// data with the grid's origin, spacing and axis directions, the SEG-Y reader's settings as
// properties.
#ifndef vtkVolpostGridReader_h
#define vtkVolpostGridReader_h

#include "VolpostParaViewReadersModule.h"

#include <vtkImageAlgorithm.h>

class vtkVolpostModelCache;

class VOLPOSTPARAVIEWREADERS_EXPORT vtkVolpostGridReader : public vtkImageAlgorithm {
 public:
  static vtkVolpostGridReader* New();
  vtkTypeMacro(vtkVolpostGridReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);

  /// SEG-Y trace header positions (first byte, 1-based); 0 keeps the standard position.
  vtkSetMacro(InlineByte, int);
  vtkGetMacro(InlineByte, int);
  vtkSetMacro(CrosslineByte, int);
  vtkGetMacro(CrosslineByte, int);
  vtkSetMacro(CdpXByte, int);
  vtkGetMacro(CdpXByte, int);
  vtkSetMacro(CdpYByte, int);
  vtkGetMacro(CdpYByte, int);
  vtkSetMacro(ScalarByte, int);
  vtkGetMacro(ScalarByte, int);
  vtkSetMacro(OffsetByte, int);
  vtkGetMacro(OffsetByte, int);
  /// Pre-stack SEG-Y: the offset whose traces make the volume (empty: a file with several
  /// offsets is refused, naming them).
  vtkSetStringMacro(Offset);
  vtkGetStringMacro(Offset);

  int CanReadFile(const char* fileName);

 protected:
  vtkVolpostGridReader();
  ~vtkVolpostGridReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

 private:
  vtkVolpostGridReader(const vtkVolpostGridReader&) = delete;
  void operator=(const vtkVolpostGridReader&) = delete;

  char* FileName = nullptr;
  int InlineByte = 0;
  int CrosslineByte = 0;
  int CdpXByte = 0;
  int CdpYByte = 0;
  int ScalarByte = 0;
  int OffsetByte = 0;
  char* Offset = nullptr;
  vtkVolpostModelCache* Cache;
};

#endif
