// SPDX-License-Identifier: MIT
#include "host/render/HostShaders.hpp"

#include <volpost/render/ShaderLibrary.hpp>

#include <map>
#include <mutex>
#include <string>
#include <string_view>

namespace volpost {
namespace host {
const std::map<std::string, std::string_view>& embeddedShaders();  // generated (volpost_embed_shaders)
}

void registerHostShaders() {
  static std::once_flag once;
  std::call_once(once, [] { gl::registerShaders("host", host::embeddedShaders()); });
}

}  // namespace volpost
