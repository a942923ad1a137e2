// SPDX-License-Identifier: MIT
#include "AllReaders.hpp"

namespace volpost::meshio {

const ReaderRegistry& allReadersRegistry() {
  static const AllReaders readers;
  static const ReaderRegistry registry = [] {
    ReaderRegistry r;
    for (const MeshReader* reader : readers.list()) r.add(reader);
    return r;
  }();
  return registry;
}

}  // namespace volpost::meshio
