// SPDX-License-Identifier: MIT
// The meshio plugin: hands the host its file readers.
#pragma once

#include "AllReaders.hpp"

#include <volpost/plugin/PluginInterfaces.hpp>

#include <QObject>

namespace volpost::meshio {

class MeshioPlugin : public QObject, public ReaderPlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID VOLPOST_READER_PLUGIN_IID FILE "meshio.meta.json")
  Q_INTERFACES(volpost::ReaderPlugin)

 public:
  QList<const MeshReader*> readers() const override {
    const auto list = readers_.list();
    return QList<const MeshReader*>(list.begin(), list.end());
  }

 private:
  AllReaders readers_;
};

}  // namespace volpost::meshio
