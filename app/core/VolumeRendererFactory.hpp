// SPDX-License-Identifier: MIT
// How a scene gets its volume renderer: by name, from whatever offers them (the loaded
// plugins in the app, a single renderer in a test), with the names it knows for messages
// that point to another renderer.
#pragma once

#include <volpost/render/VolumeRenderer.hpp>

#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace volpost::app {

class VolumeRendererFactory {
 public:
  using Create = std::function<std::unique_ptr<VolumeRenderer>(const std::string& name)>;

  VolumeRendererFactory() = default;
  /// `create` returns nullptr for a name it does not know; `names` are those it knows, in
  /// menu order (empty: messages name no alternative).
  template <typename F>
  requires std::is_constructible_v<Create, F> VolumeRendererFactory(
      F create, std::vector<std::string> names = {})  // NOLINT: converts
      : create_(std::move(create)), names_(std::move(names)) {}

  std::unique_ptr<VolumeRenderer> operator()(const std::string& name) const {
    return create_ ? create_(name) : nullptr;
  }
  /// The names of the renderers whose traits satisfy `has`, in menu order: "raycast, vicp,
  /// cpu".
  std::string namesWhere(bool (*has)(const VolumeRendererTraits&)) const {
    std::string out;
    for (const std::string& name : names_)
      if (const auto renderer = (*this)(name); renderer && has(renderer->traits()))
        out += (out.empty() ? "" : ", ") + name;
    return out;
  }

 private:
  Create create_;
  std::vector<std::string> names_;
};

}  // namespace volpost::app
