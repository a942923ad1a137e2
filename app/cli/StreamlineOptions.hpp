// SPDX-License-Identifier: MIT
// The command-line options of streamlines, shared by `render` and `streamlines`.
#pragma once

#include "../core/SceneState.hpp"

#include <QCommandLineOption>
#include <QCommandLineParser>

#include <vector>

namespace volpost::app {

struct StreamlineOptions {
  QCommandLineOption seeds{"seeds", "Where lines start (repeatable): point:X,Y,Z | line:X0,Y0,Z0:X1,Y1,Z1:N | "
                                    "disk:CX,CY,CZ:NX,NY,NZ:R:N | box:XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX:N[:SEED] | "
                                    "boundary:CX,CY,CZ:R:N.", "SPEC"};
  QCommandLineOption integrator{"integrator", "rk2 (default: adaptive second order), rk4 or rk45.", "NAME"};
  QCommandLineOption direction{"direction", "forward, backward or both (default).", "WAY"};
  QCommandLineOption tolerance{"tolerance", "Largest position error per step, as a fraction of the model's size "
                                            "(default 1e-5).", "T"};
  QCommandLineOption maxSteps{"max-steps", "Most steps per direction (default 20000).", "N"};
  QCommandLineOption maxLength{"max-length", "Longest line per direction, model units (default 20 x the model).", "L"};
  QCommandLineOption pointSpacing{"point-spacing",
                                  "Model units between written points inside a step, each "
                                  "integrated as accurately as the step ends (default 0: the "
                                  "step ends only).",
                                  "D"};
  QCommandLineOption colorBy{"color-lines-by", "Quantity the lines are colored by (default: the speed).", "Q"};
  QCommandLineOption averageCells{"average-cell-vectors", "Trace a field given per element by averaging it at the "
                                                          "nodes (an approximation)."};
  std::vector<QCommandLineOption> all() const {
    return {seeds, integrator, direction, tolerance, maxSteps, maxLength, pointSpacing, colorBy, averageCells};
  }
  /// Fills `layer` from the options that are set. Throws std::invalid_argument naming
  /// the option when a value is wrong.
  void apply(const QCommandLineParser& parser, StreamlineLayer& layer) const;
};

}  // namespace volpost::app
