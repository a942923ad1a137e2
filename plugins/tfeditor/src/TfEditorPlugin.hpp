// SPDX-License-Identifier: MIT
// The tfeditor plugin: the transfer-function editors as a dock panel of the host window, the
// 1D one (value) and the 2D one (value x gradient magnitude, regular grids) on two tabs.
#pragma once

#include "Tf2dEditorPanel.hpp"
#include "TfEditorPanel.hpp"

#include <volpost/plugin/PluginInterfaces.hpp>

#include <QObject>
#include <QPointer>
#include <QTabWidget>

namespace volpost::tfeditor {

class TfEditorPlugin : public QObject, public PanelPlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID VOLPOST_PANEL_PLUGIN_IID FILE "tfeditor.meta.json")
  Q_INTERFACES(volpost::PanelPlugin)

 public:
  QString panelTitle() const override { return "Transfer Function"; }
  QWidget* createPanel(PanelHost& host, QWidget* parent) override {
    auto* tabs = new QTabWidget(parent);
    tabs->setObjectName("tfEditorTabs");
    panel_ = new TfEditorPanel(host, tabs);
    panel2d_ = new Tf2dEditorPanel(host, tabs);
    panel2d_->setObjectName("tf2dEditor");
    tabs->addTab(panel_, "Value");
    tabs->addTab(panel2d_, "Value x gradient");
    tabs->setTabToolTip(1, "A 2D transfer function over the value and its gradient magnitude (regular grids)");
    return tabs;
  }
  void hostChanged() override {
    if (panel_) panel_->hostChanged();
    if (panel2d_) panel2d_->hostChanged();
  }

 private:
  QPointer<TfEditorPanel> panel_;
  QPointer<Tf2dEditorPanel> panel2d_;
};

}  // namespace volpost::tfeditor
