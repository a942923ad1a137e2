// SPDX-License-Identifier: MIT
// Writes a model as a VTK XML unstructured grid (.vtu) so that any model volpost opens can
// go on to ParaView or VTK: appended raw binary (UInt64 headers, Float64 points, Int64
// connectivity), every field at every step, the file's node and element ids.
#pragma once

#include <volpost/core/Model.hpp>
#include <volpost/core/Progress.hpp>

#include <string>

namespace volpost {

/// Fields with several steps are written as one array per step, "NAME step K". Writes to
/// a temporary file and renames it, so a failed write never leaves half a file behind.
/// Throws WriteError (naming the file) when the file cannot be written.
void writeVtu(const Model& model, const std::string& path, const Progress& progress = {});

}  // namespace volpost
