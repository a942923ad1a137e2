// SPDX-License-Identifier: MIT
#include "vtkVolpostReader.h"

#include "ModelToVtk.h"
#include "ReaderPipeline.h"
#include "VolpostReading.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkUnstructuredGrid.h>

#include <exception>

vtkStandardNewMacro(vtkVolpostReader);

vtkVolpostReader::vtkVolpostReader() : Cache(new vtkVolpostModelCache) { this->SetNumberOfInputPorts(0); }

vtkVolpostReader::~vtkVolpostReader() {
  this->SetFileName(nullptr);
  delete this->Cache;
}

void vtkVolpostReader::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}

int vtkVolpostReader::CanReadFile(const char* fileName) {
  return fileName && volpost::paraview::canRead(fileName) ? 1 : 0;
}

int vtkVolpostReader::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs) {
  if (!this->FileName || !*this->FileName) {
    vtkErrorMacro("No file name was given.");
    return 0;
  }
  bool read = false;
  const std::string error =
      volpost::paraview::readOnFirstRank(*this->Cache, this->FileName, {}, volpost::paraview::progressOf(*this), read);
  if (!error.empty()) {
    // The first rank says what is wrong; the others fail without repeating it.
    vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
    if (!controller || controller->GetLocalProcessId() == 0) vtkErrorMacro(<< error);
    return 0;
  }
  if (read) volpost::paraview::reportFindings(*this, this->Cache->model(), this->FileName);
  vtkInformation* info = outputs->GetInformationObject(0);
  volpost::paraview::announceTimes(*info, this->Cache->announced.times);
  // The first rank reads the whole file and gives it as piece 0; the other pieces are empty
  // (ParaView's Redistribute DataSet filter spreads the cells over the ranks).
  info->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

int vtkVolpostReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs) {
  vtkInformation* info = outputs->GetInformationObject(0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(info);
  if (!output) return 0;
  if (info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0) return 1;
  if (!this->Cache->holds()) return 0;

  const volpost::paraview::TimeSteps& steps = this->Cache->steps();
  const double time = volpost::paraview::requestedTime(*info, steps);
  try {
    volpost::paraview::fillUnstructuredGrid(
        this->Cache->model(),
        [&](const volpost::Field& field) { return volpost::paraview::fieldStepAt(field, steps, time); }, *output);
  } catch (const std::exception& e) {
    output->Initialize();
    vtkErrorMacro(<< this->FileName << ": " << e.what());
    return 0;
  }
  if (!steps.times.empty()) output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
  return 1;
}
