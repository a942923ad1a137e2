// SPDX-License-Identifier: MIT
#include "VolumeShaders.hpp"

#include <volpost/render/ShaderLibrary.hpp>

#include <map>
#include <mutex>
#include <string>
#include <string_view>

namespace volpost::volume {

const std::map<std::string, std::string_view>& embeddedShaders();  // generated (volpost_embed_shaders)

void registerVolumeShaders() {
  static std::once_flag once;
  std::call_once(once, [] { gl::registerShaders("volume", embeddedShaders()); });
}

}  // namespace volpost::volume
