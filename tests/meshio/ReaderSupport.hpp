// SPDX-License-Identifier: MIT
// The meshio readers in a registry, as the host assembles them from the plugin.
#pragma once

#include "AbaqusInputReader.hpp"
#include "FrdReader.hpp"
#include "ExodusReader.hpp"
#include "GmshReader.hpp"
#include "NeutralFileReader.hpp"
#include "VtkLegacyReader.hpp"
#include "VtuReader.hpp"

#include <volpost/core/ReaderRegistry.hpp>

namespace volpost::test {

inline const ReaderRegistry& meshioReaders() {
  static const meshio::VtuReader vtu;
  static const meshio::VtkLegacyReader legacy;
  static const meshio::GmshReader gmsh;
  static const meshio::AbaqusInputReader inp;
  static const meshio::FrdReader frd;
  static const meshio::ExodusReader exodus;
  static const meshio::NeutralFileReader neutral;
  static const ReaderRegistry registry = [] {
    ReaderRegistry r;
    r.add(&vtu);
    r.add(&legacy);
    r.add(&gmsh);
    r.add(&inp);
    r.add(&frd);
    r.add(&exodus);
    r.add(&neutral);
    return r;
  }();
  return registry;
}

}  // namespace volpost::test
