// SPDX-License-Identifier: MIT
// A plugin that claims an older SDK in its metadata: the host must refuse it before
// running any of its code.
#pragma once

#include <volpost/plugin/PluginInterfaces.hpp>

#include <QObject>

class OldSdkPlugin : public QObject, public volpost::ReaderPlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID VOLPOST_READER_PLUGIN_IID FILE "oldsdk.json")
  Q_INTERFACES(volpost::ReaderPlugin)

 public:
  OldSdkPlugin() { std::abort(); }  // never constructed: refused from its metadata
  QList<const volpost::MeshReader*> readers() const override { return {}; }
};
