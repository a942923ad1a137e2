// SPDX-License-Identifier: MIT
// The netCDF library reads data past the end of a truncated classic file as zeros, without
// an error: a cut-off Exodus file would load with garbage values. The classic header (CDF-1,
// CDF-2, CDF-5) states where every variable lies, so the file's size can be checked
// against it before anything is read.
#pragma once

#include <string>

namespace volpost::meshio {

/// Throws ReadError naming the first variable (and its record count) that the file is too
/// short to hold, or a damaged header. netCDF-4/HDF5 files pass (HDF5 checks its own).
void checkClassicNetcdfExtent(const std::string& path);

}  // namespace volpost::meshio
