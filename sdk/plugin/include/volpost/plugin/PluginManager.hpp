// SPDX-License-Identifier: MIT
// Finds, checks and loads plugins; keeps a record of every candidate and why it failed.
#pragma once

#include <volpost/core/ReaderRegistry.hpp>
#include <volpost/plugin/PluginInterfaces.hpp>

#include <QObject>
#include <QPluginLoader>
#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

namespace volpost {

struct PluginRecord {
  QString path;
  QString id, name, version, sdkVersion, description;
  QStringList provides;  ///< "reader", "renderer", "panel"
  bool loaded = false;
  QString error;         ///< why it was refused or failed to load (empty when loaded)
};

class PluginManager {
 public:
  PluginManager();
  ~PluginManager();
  PluginManager(const PluginManager&) = delete;
  PluginManager& operator=(const PluginManager&) = delete;

  /// The folders searched, in order: the install's plugin folder (next to the
  /// executable: ../lib/volpost/plugins), each folder of $VOLPOST_PLUGIN_PATH
  /// (':'-separated), and the user folders saved in the settings (plugins/userPaths).
  static QStringList defaultSearchPaths();
  static QStringList userPaths();
  static void setUserPaths(const QStringList& paths);

  /// Loads every plugin found in the folders. Safe to call once per process.
  void loadFrom(const QStringList& folders);

  const std::vector<PluginRecord>& records() const { return records_; }
  const ReaderRegistry& readers() const { return readers_; }
  std::vector<RendererPlugin*> rendererPlugins() const;
  std::vector<PanelPlugin*> panelPlugins() const;

 private:
  void tryLoad(const QString& path);
  std::vector<PluginRecord> records_;
  std::vector<std::unique_ptr<QPluginLoader>> loaders_;
  std::vector<QObject*> instances_;
  ReaderRegistry readers_;
};

}  // namespace volpost
