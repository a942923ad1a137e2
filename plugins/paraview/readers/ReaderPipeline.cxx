// SPDX-License-Identifier: MIT
#include "ReaderPipeline.h"

#include <vtkAlgorithm.h>
#include <vtkInformation.h>
#include <vtkStreamingDemandDrivenPipeline.h>

namespace volpost::paraview {

void announceTimes(vtkInformation& output, const std::vector<double>& times) {
  if (times.empty()) {
    output.Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    output.Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
    return;
  }
  output.Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), int(times.size()));
  const double range[2] = {times.front(), times.back()};
  output.Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
}

double requestedTime(vtkInformation& output, const TimeSteps& steps) {
  if (steps.times.empty()) return 0.0;
  if (output.Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
    return output.Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
  return steps.times.front();
}

Progress progressOf(vtkAlgorithm& reader) {
  return Progress([&reader](double fraction, const std::string&) {
    reader.UpdateProgress(fraction);
    return !reader.GetAbortExecute();
  });
}

void reportFindings(vtkAlgorithm& reader, const Model& model, const char* fileName) {
  for (const Diagnostic& d : model.diagnostics)
    if (d.severity == Severity::Warning) vtkWarningWithObjectMacro(&reader, << fileName << ": " << d.message);
}

}  // namespace volpost::paraview
