// SPDX-License-Identifier: MIT
// Pieces the command-line verbs share: plugin loading, progress on stderr, messages.
#pragma once

#include "../core/ModelSession.hpp"

#include <volpost/plugin/PluginManager.hpp>

#include <QString>

#include <memory>

namespace volpost::app {

/// Loads the plugins from the default folders; warns on stderr about refused ones.
std::unique_ptr<PluginManager> loadPluginsForCli();

/// Progress that draws "label 42%" on stderr when it is a terminal, silent otherwise.
Progress terminalProgress(const std::string& label);

void printError(const QString& message);

}  // namespace volpost::app
