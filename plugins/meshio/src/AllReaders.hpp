// SPDX-License-Identifier: MIT
// Every reader of this library, in the order the host tries them: one list for the plugin,
// the tests and the benchmarks.
#pragma once

#include "AbaqusInputReader.hpp"
#include "ExodusReader.hpp"
#include "FrdReader.hpp"
#include "GmshReader.hpp"
#include "NeutralFileReader.hpp"
#include "NrrdReader.hpp"
#include "VtiReader.hpp"
#include "VtkLegacyReader.hpp"
#include "VtuReader.hpp"

#include <volpost/core/ReaderRegistry.hpp>

#include <vector>

namespace volpost::meshio {

struct AllReaders {
  VtuReader vtu;
  VtiReader vti;
  VtkLegacyReader legacy;
  GmshReader gmsh;
  AbaqusInputReader inp;
  FrdReader frd;
  ExodusReader exodus;
  NeutralFileReader neutral;
  NrrdReader nrrd;

  std::vector<const MeshReader*> list() const { return {&vtu, &vti, &legacy, &gmsh, &inp, &frd, &exodus, &neutral, &nrrd}; }
};

/// A registry of one process-wide set of the readers, for programs that do not load the
/// plugin (tests, benchmarks).
const ReaderRegistry& allReadersRegistry();

}  // namespace volpost::meshio
