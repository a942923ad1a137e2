// SPDX-License-Identifier: MIT
// Scenes for tests: a renderer factory that offers the GPU ray caster alone (as "raycast",
// its name in the plugin), the way a scene gets its renderers from the loaded plugins.
#pragma once

#include "RayCaster.hpp"

#include "core/VolumeRendererFactory.hpp"

#include <memory>
#include <string>

namespace volpost::test {

inline app::VolumeRendererFactory rayCasterOnly() {
  return {[](const std::string& name) -> std::unique_ptr<VolumeRenderer> {
            if (name == "raycast") return std::make_unique<volume::RayCaster>();
            return nullptr;
          },
          {"raycast"}};
}

}  // namespace volpost::test
