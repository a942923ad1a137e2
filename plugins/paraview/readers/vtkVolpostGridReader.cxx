// SPDX-License-Identifier: MIT
#include "vtkVolpostGridReader.h"

#include "ModelToVtk.h"
#include "ReaderPipeline.h"
#include "VolpostReading.h"

#include <vtkDataObject.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <exception>
#include <string>

vtkStandardNewMacro(vtkVolpostGridReader);

vtkVolpostGridReader::vtkVolpostGridReader() : Cache(new vtkVolpostModelCache) { this->SetNumberOfInputPorts(0); }

vtkVolpostGridReader::~vtkVolpostGridReader() {
  this->SetFileName(nullptr);
  this->SetOffset(nullptr);
  delete this->Cache;
}

void vtkVolpostGridReader::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}

int vtkVolpostGridReader::CanReadFile(const char* fileName) {
  return fileName && volpost::paraview::canRead(fileName) ? 1 : 0;
}

namespace {

/// The reader options the properties name: only those set, so a file that is not SEG-Y
/// reads as before and a SEG-Y setting on it is refused by name.
volpost::ReaderOptions optionsOf(const std::pair<const char*, int> (&bytes)[6], const char* offset) {
  volpost::ReaderOptions options;
  for (const auto& [name, value] : bytes)
    if (value != 0) options[name] = std::to_string(value);
  if (offset && *offset) options["offset"] = offset;
  return options;
}

}  // namespace

int vtkVolpostGridReader::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs) {
  if (!this->FileName || !*this->FileName) {
    vtkErrorMacro("No file name was given.");
    return 0;
  }
  const std::pair<const char*, int> bytes[6] = {
      {"inline-byte", this->InlineByte}, {"crossline-byte", this->CrosslineByte}, {"cdp-x-byte", this->CdpXByte},
      {"cdp-y-byte", this->CdpYByte},    {"scalar-byte", this->ScalarByte},       {"offset-byte", this->OffsetByte}};
  volpost::paraview::ImageGeometry geometry{};
  try {
    const bool read =
        this->Cache->load(this->FileName, optionsOf(bytes, this->Offset), volpost::paraview::progressOf(*this));
    if (read) volpost::paraview::reportFindings(*this, this->Cache->model(), this->FileName);
    const volpost::Model& model = this->Cache->model();
    if (!model.grid) {
      vtkErrorMacro(<< this->FileName << ": the file holds cells, not a regular grid of samples: open it with the "
                    << "volpost finite-element reader.");
      return 0;
    }
    geometry = volpost::paraview::imageGeometry(*model.grid);
    if (read && geometry.largestMove > 1e-9 * geometry.spacing[0])
      vtkWarningMacro(<< this->FileName << ": the grid's axes are not quite at right angles; squared for image data, "
                      << "which moves a point by at most " << geometry.largestMove << " model units.");
  } catch (const std::invalid_argument& e) {  // the grid's shape: the message names no file
    vtkErrorMacro(<< this->FileName << ": " << e.what());
    return 0;
  } catch (const std::exception& e) {  // the readers' messages name the file and byte
    vtkErrorMacro(<< e.what());
    return 0;
  }
  vtkInformation* info = outputs->GetInformationObject(0);
  const int extent[6] = {0, geometry.dims[0] - 1, 0, geometry.dims[1] - 1, 0, geometry.dims[2] - 1};
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  info->Set(vtkDataObject::ORIGIN(), geometry.origin, 3);
  info->Set(vtkDataObject::SPACING(), geometry.spacing, 3);
  info->Set(vtkDataObject::DIRECTION(), geometry.direction, 9);
  // Every rank reads the file and keeps the part of the grid ParaView gives it.
  info->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
  volpost::paraview::announceTimes(*info, this->Cache->steps().times);
  return 1;
}

int vtkVolpostGridReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs) {
  vtkInformation* info = outputs->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(info);
  if (!output || !this->Cache->holds()) return 0;
  const volpost::paraview::TimeSteps& steps = this->Cache->steps();
  const double time = volpost::paraview::requestedTime(*info, steps);
  try {
    volpost::paraview::fillImageData(
        this->Cache->model(),
        [&](const volpost::Field& field) { return volpost::paraview::fieldStepAt(field, steps, time); }, *output);
  } catch (const std::exception& e) {
    output->Initialize();
    vtkErrorMacro(<< this->FileName << ": " << e.what());
    return 0;
  }
  if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
    output->Crop(info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()));
  if (!steps.times.empty()) output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
  return 1;
}
