// SPDX-License-Identifier: MIT
// The command-line verbs: info, render, plugins, convert, surface, probe, streamlines.
#pragma once

#include <QStringList>

namespace volpost::app {

/// Each takes the arguments after the verb and returns the process exit code:
/// 0 success, 1 the work failed (bad file, rendering error), 2 bad usage.
int runInfo(const QStringList& args);
int runRender(const QStringList& args);
int runPlugins(const QStringList& args);
int runConvert(const QStringList& args);
int runSurface(const QStringList& args);
int runProbe(const QStringList& args);
int runStreamlines(const QStringList& args);
int runPlot(const QStringList& args);

}  // namespace volpost::app
