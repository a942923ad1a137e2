// SPDX-License-Identifier: MIT
// A streamline layer's lines traced on a model at a step, with the values they are colored
// by (the speed or a quantity at each point): no GL, so the window traces on a worker
// thread and the command line in place.
#pragma once

#include "ModelSession.hpp"
#include "SceneState.hpp"

#include "host/Streamlines.hpp"

#include <volpost/core/Progress.hpp>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace volpost::app {

/// Streamlines traced for a StreamlineLayer, and the values they are colored by.
struct StreamlineResult {
  StreamlineLayer layer;                                              ///< what they were traced for
  const ModelSession* session = nullptr;                              ///< on which model
  std::size_t step = 0;                                               ///< and step
  FieldInterpolation interpolation = FieldInterpolation::Tetrahedra;  ///< and field inside the cells
  std::vector<Streamline> lines;
  std::vector<std::vector<double>> values;  ///< per point of each line
  std::string valueName;                    ///< "velocity speed", or the quantity's name
  double min = 0.0, max = 1.0;              ///< range of the values
  std::size_t seeds = 0, outside = 0;       ///< seeds given, and those outside the mesh
  double milliseconds = 0.0;                ///< tracing time
};

/// Traces a streamline layer's lines on a model at a step (no GL; any thread), the velocity
/// and the values they are colored by interpolated inside the cells as `interpolation`
/// says (the cells' own shape functions, or linear on their split). Throws
/// std::invalid_argument for a field or seeds that do not fit; Cancelled on request.
std::shared_ptr<const StreamlineResult> traceStreamlineLayer(const ModelSession& session, const StreamlineLayer& layer,
                                                             std::size_t step, FieldInterpolation interpolation,
                                                             const Progress& progress = {});

}  // namespace volpost::app
