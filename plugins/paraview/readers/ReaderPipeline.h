// SPDX-License-Identifier: MIT
// What both ParaView readers tell the pipeline the same way: the time steps they offer, the
// step a request asks for, their progress and the findings of a file just read.
#pragma once

#include "VolpostReading.h"

#include <volpost/core/Progress.hpp>

class vtkAlgorithm;
class vtkInformation;

namespace volpost::paraview {

/// TIME_STEPS and TIME_RANGE on the output's information, or neither for a file of one step.
void announceTimes(vtkInformation& output, const std::vector<double>& times);

/// The time the request asks for (UPDATE_TIME_STEP), else the first step's; 0 without steps.
double requestedTime(vtkInformation& output, const TimeSteps& steps);

/// The reader's progress bar and its abort flag, as volpost's Progress.
Progress progressOf(vtkAlgorithm& reader);

/// The model's warnings (inverted cells, NaN values, ...) in ParaView's output messages.
void reportFindings(vtkAlgorithm& reader, const Model& model, const char* fileName);

}  // namespace volpost::paraview
