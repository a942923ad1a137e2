// SPDX-License-Identifier: MIT
// Writes a model as a VTK XML unstructured grid (.vtu) so that any model volpost opens can
// go on to ParaView or VTK: raw binary appended or base64 inline (UInt64 headers, Float64 points, Int64
// connectivity), every field at every step, the file's node and element ids.
#pragma once

#include <volpost/core/Model.hpp>
#include <volpost/core/Progress.hpp>

#include <string>

namespace volpost {

/// Where the arrays' bytes go. Appended: one raw block after the XML, the smallest and
/// quickest to read. Inline: base64 inside each array's element, a third larger; what VTK
/// 9.2 (ParaView 5.11) reads on systems whose XML parser (expat 2.5 with Debian 12's
/// security fixes, 2.6 and later) defers parsing: there it stops reading appended files whose
/// XML part passes about 1.4 KB.
enum class VtuLayout { Appended, Inline };

/// Fields with several steps are written as one array per step, "NAME step K". Writes to
/// a temporary file and renames it, so a failed write never leaves half a file behind.
/// Throws WriteError (naming the file) when the file cannot be written.
void writeVtu(const Model& model, const std::string& path, const Progress& progress = {},
              VtuLayout layout = VtuLayout::Appended);

}  // namespace volpost
