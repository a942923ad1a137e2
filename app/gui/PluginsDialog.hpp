// SPDX-License-Identifier: MIT
// Tools > Plugins: every plugin found, loaded or refused with the reason, and the user's
// own plugin folders.
#pragma once

#include <volpost/plugin/PluginManager.hpp>

#include <QDialog>

class QListWidget;

namespace volpost::app {

class PluginsDialog : public QDialog {
  Q_OBJECT
 public:
  PluginsDialog(const PluginManager& plugins, QWidget* parent = nullptr);

 private:
  void saveFolders();
  QListWidget* folders_ = nullptr;
};

}  // namespace volpost::app
