// SPDX-License-Identifier: MIT
// The plugin object the host loads: it hands over the reader.
#pragma once

#include "TetraReader.hpp"

#include <volpost/plugin/PluginInterfaces.hpp>

#include <QObject>

class HelloReaderPlugin : public QObject, public volpost::ReaderPlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID VOLPOST_READER_PLUGIN_IID FILE "hello_reader.meta.json")
  Q_INTERFACES(volpost::ReaderPlugin)

 public:
  QList<const volpost::MeshReader*> readers() const override { return {&reader_}; }

 private:
  TetraReader reader_;
};
