// SPDX-License-Identifier: MIT
// A plugin of this SDK whose reader interface is of another version (its IID says 7): the
// host must refuse it from its metadata, naming the interface and both versions.
#pragma once

#include <volpost/plugin/PluginInterfaces.hpp>

#include <QObject>

class OldReaderPlugin : public QObject {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID "org.volpost.ReaderPlugin/7" FILE "oldreader.meta.json")

 public:
  OldReaderPlugin() { std::abort(); }  // never constructed: refused from its metadata
};
