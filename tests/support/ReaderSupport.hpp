// SPDX-License-Identifier: MIT
// The meshio readers in a registry, as the host assembles them from the plugin.
#pragma once

#include "AllReaders.hpp"

namespace volpost::test {

inline const ReaderRegistry& meshioReaders() { return meshio::allReadersRegistry(); }

}  // namespace volpost::test
