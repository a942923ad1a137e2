// SPDX-License-Identifier: MIT
// The host's GLSL (the top-level shaders/ folder, embedded at build time) in the SDK's
// shader registry under "host/".
#pragma once

namespace volpost {

/// Registers the shaders once per process; safe to call from every initialize().
void registerHostShaders();

}  // namespace volpost
