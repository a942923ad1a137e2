// SPDX-License-Identifier: MIT
// The volume plugin's GLSL (plugins/volume/shaders, embedded at build time) in the SDK's
// shader registry under "volume/".
#pragma once

namespace volpost::volume {

/// Registers the shaders once per process; safe to call from every initialize().
void registerVolumeShaders();

}  // namespace volpost::volume
