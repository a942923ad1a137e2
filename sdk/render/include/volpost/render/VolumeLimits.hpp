// SPDX-License-Identifier: MIT
// How many clip planes and iso-surfaces a volume takes, and the one check of each that
// the scene, the state files and every renderer share. Shaders receive the same numbers as
// MAX_CLIP_PLANES / MAX_ISO_SURFACES (volumeLimitDefines()), so C++ and GLSL cannot differ.
#pragma once

#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/optics/IsoTables.hpp>

#include <span>
#include <string>

namespace volpost {

/// At most this many clip planes (a clip box is six, plus two free planes) and
/// iso-surfaces per volume.
inline constexpr int kMaxClipPlanes = 8;
inline constexpr int kMaxIsoSurfaces = 8;

/// "#define MAX_CLIP_PLANES 8\n#define MAX_ISO_SURFACES 8\n", for gl::buildProgram.
std::string volumeLimitDefines();

/// Throws std::invalid_argument, in a user's words, for more than kMaxClipPlanes planes or
/// a plane without a finite point and a finite, non-zero normal.
void checkClipPlanes(std::span<const ClipPlane> planes);
/// Throws std::invalid_argument for more than kMaxIsoSurfaces surfaces, a value that is not
/// finite or an opacity outside 0..1.
void checkIsoSurfaces(std::span<const optics::IsoSurface> surfaces);

}  // namespace volpost
