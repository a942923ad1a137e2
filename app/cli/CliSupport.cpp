// SPDX-License-Identifier: MIT
#include "CliSupport.hpp"

#include <cstdio>
#include <unistd.h>

namespace volpost::app {

std::unique_ptr<PluginManager> loadPluginsForCli() {
  auto plugins = std::make_unique<PluginManager>();
  plugins->loadFrom(PluginManager::defaultSearchPaths());
  for (const PluginRecord& r : plugins->records())
    if (!r.loaded)
      std::fprintf(stderr, "volpost: warning: plugin %s refused: %s\n", qPrintable(r.path), qPrintable(r.error));
  return plugins;
}

Progress terminalProgress(const std::string& label) {
  if (!isatty(STDERR_FILENO)) return Progress();
  auto last = std::make_shared<int>(-1);
  return Progress([label, last](double f, const std::string& stage) {
    const int percent = int(f * 100.0);
    if (percent != *last) {
      *last = percent;
      const std::string what = stage.empty() ? label : stage;
      std::fprintf(stderr, "\r%-24s %3d%%%s", what.c_str(), percent, percent >= 100 ? "\n" : "");
      std::fflush(stderr);
    }
    return true;
  });
}

void printError(const QString& message) { std::fprintf(stderr, "volpost: error: %s\n", qPrintable(message)); }

}  // namespace volpost::app
