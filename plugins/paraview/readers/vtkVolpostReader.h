// SPDX-License-Identifier: MIT
// ParaView's reader of the finite-element formats volpost reads (CalculiX .frd and .inp, Gmsh,
// the Tecgraf neutral file, and the rest of volpost's formats): an unstructured grid whose
// quadratic cells are VTK's quadratic cells, every field at the chosen time step.
#ifndef vtkVolpostReader_h
#define vtkVolpostReader_h

#include "VolpostParaViewReadersModule.h"

#include <vtkUnstructuredGridAlgorithm.h>

class vtkVolpostModelCache;

class VOLPOSTPARAVIEWREADERS_EXPORT vtkVolpostReader : public vtkUnstructuredGridAlgorithm {
 public:
  static vtkVolpostReader* New();
  vtkTypeMacro(vtkVolpostReader, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);

  /// Whether volpost's readers can read the file (ParaView asks before choosing a reader).
  int CanReadFile(const char* fileName);

 protected:
  vtkVolpostReader();
  ~vtkVolpostReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

 private:
  vtkVolpostReader(const vtkVolpostReader&) = delete;
  void operator=(const vtkVolpostReader&) = delete;

  char* FileName = nullptr;
  vtkVolpostModelCache* Cache;
};

#endif
