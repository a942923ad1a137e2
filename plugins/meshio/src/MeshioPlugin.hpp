// SPDX-License-Identifier: MIT
// The meshio plugin: hands the host its file readers.
#pragma once

#include "AbaqusInputReader.hpp"
#include "FrdReader.hpp"
#include "ExodusReader.hpp"
#include "GmshReader.hpp"
#include "NeutralFileReader.hpp"
#include "VtkLegacyReader.hpp"
#include "VtuReader.hpp"

#include <volpost/plugin/PluginInterfaces.hpp>

#include <QObject>

namespace volpost::meshio {

class MeshioPlugin : public QObject, public ReaderPlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID VOLPOST_READER_PLUGIN_IID FILE "meshio.meta.json")
  Q_INTERFACES(volpost::ReaderPlugin)

 public:
  QList<const MeshReader*> readers() const override { return {&vtu_, &legacy_, &gmsh_, &inp_, &frd_, &exodus_, &neutral_}; }

 private:
  VtuReader vtu_;
  VtkLegacyReader legacy_;
  GmshReader gmsh_;
  AbaqusInputReader inp_;
  FrdReader frd_;
  ExodusReader exodus_;
  NeutralFileReader neutral_;
};

}  // namespace volpost::meshio
