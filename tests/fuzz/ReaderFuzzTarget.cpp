// SPDX-License-Identifier: MIT
// libFuzzer target for one file reader (chosen at compile time by VOLPOST_FUZZ_READER).
// Every input must either load or be refused with ReadError: any other exception, a
// crash, a sanitizer report or a hang is a bug. Inputs go through a file, as in use.
#include "AbaqusInputReader.hpp"
#include "FrdReader.hpp"
#include "GmshReader.hpp"
#include "NeutralFileReader.hpp"
#include "VtkLegacyReader.hpp"
#include "VtuReader.hpp"

#include <volpost/core/MeshChecks.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

const std::string& inputPath() {
  static const std::string path = "/dev/shm/volpost_fuzz_" + std::to_string(getpid()) + "." VOLPOST_FUZZ_EXTENSION;
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream out(inputPath(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  static const volpost::meshio::VOLPOST_FUZZ_READER reader;
  try {
    auto model = reader.read(inputPath(), {});
    volpost::checkModel(*model);  // what loading does next: must survive whatever loaded
    for (const auto& f : model->fields)
      for (std::size_t s = 0; s < f->stepCount(); ++s) (void)f->values(s);
  } catch (const volpost::ReadError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "not a ReadError: %s\n", e.what());
    std::abort();
  }
  return 0;
}
