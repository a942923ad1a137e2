// SPDX-License-Identifier: MIT
// The command-line verbs: `volpost info`, `volpost render`, `volpost plugins`.
#pragma once

#include <QStringList>

namespace volpost::app {

/// Each takes the arguments after the verb and returns the process exit code:
/// 0 success, 1 the work failed (bad file, rendering error), 2 bad usage.
int runInfo(const QStringList& args);
int runRender(const QStringList& args);
int runPlugins(const QStringList& args);

}  // namespace volpost::app
