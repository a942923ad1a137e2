// SPDX-License-Identifier: MIT
// The tfeditor plugin: the transfer-function editor as a dock panel of the host window.
#pragma once

#include "TfEditorPanel.hpp"

#include <volpost/plugin/PluginInterfaces.hpp>

#include <QObject>
#include <QPointer>

namespace volpost::tfeditor {

class TfEditorPlugin : public QObject, public PanelPlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID VOLPOST_PANEL_PLUGIN_IID FILE "tfeditor.meta.json")
  Q_INTERFACES(volpost::PanelPlugin)

 public:
  QString panelTitle() const override { return "Transfer Function"; }
  QWidget* createPanel(PanelHost& host, QWidget* parent) override {
    panel_ = new TfEditorPanel(host, parent);
    return panel_;
  }
  void hostChanged() override {
    if (panel_) panel_->hostChanged();
  }

 private:
  QPointer<TfEditorPanel> panel_;
};

}  // namespace volpost::tfeditor
