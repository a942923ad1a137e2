// SPDX-License-Identifier: MIT
// The seismic plugin: hands the host its SEG-Y reader.
#pragma once

#include "SegyReader.hpp"

#include <volpost/plugin/PluginInterfaces.hpp>

#include <QObject>

namespace volpost::seismic {

class SeismicPlugin : public QObject, public ReaderPlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID VOLPOST_READER_PLUGIN_IID FILE "seismic.meta.json")
  Q_INTERFACES(volpost::ReaderPlugin)

 public:
  QList<const MeshReader*> readers() const override { return {&segy_}; }

 private:
  SegyReader segy_;
};

}  // namespace volpost::seismic
