// SPDX-License-Identifier: MIT
// Pieces the command-line verbs share: plugin loading, progress on stderr, messages.
#pragma once

#include "../core/ModelSession.hpp"

#include <volpost/plugin/PluginManager.hpp>

#include <QString>

#include <exception>
#include <memory>

namespace volpost::app {

/// Loads the plugins from the default folders; warns on stderr about refused ones.
std::unique_ptr<PluginManager> loadPluginsForCli();

/// Progress that draws "label 42%" on stderr when it is a terminal, silent otherwise.
Progress terminalProgress(const std::string& label);

void printError(const QString& message);

/// Runs a verb's work and returns its exit code; a cancel (Ctrl+C on the progress) is 1,
/// an error is printed and is 1.
template <typename Work>
int exitCodeOf(Work&& work) {
  try {
    return work();
  } catch (const Cancelled&) {
    return 1;
  } catch (const std::exception& e) {
    printError(e.what());
    return 1;
  }
}

}  // namespace volpost::app
