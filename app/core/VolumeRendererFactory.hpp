// SPDX-License-Identifier: MIT
// How a scene gets its volume renderer: by name, from whatever offers them (the loaded
// plugins in the app, a single renderer in a test), with the names it knows for messages
// that point to another renderer. A renderer may also draw apart from the scene's GL
// layers (the exact reference: `volpost render` runs it on the CPU): the factory names
// and describes it, so scenes and state files take it, but does not create it. The
// renderer itself stays behind a declaration, so the scene's state compiles without GL.
#pragma once

#include <volpost/render/VolumeRendererTraits.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace volpost {
class VolumeRenderer;
}

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

  /// A renderer that draws apart from the scene (its pictures made another way), known by
  /// name and traits; it comes last in the names.
  void describeApart(const std::string& name, const VolumeRendererTraits& traits);
  bool drawsApart(const std::string& name) const;
  /// "raycast, vicp, cpu": the renderers it creates, in menu order.
  std::string namesDrawnHere() const;

  /// A new renderer (GL objects not yet made), or nullptr for a name it does not know or
  /// one that draws apart.
  std::unique_ptr<VolumeRenderer> operator()(const std::string& name) const;
  /// What the renderer of that name says of itself (nullopt: no such renderer).
  std::optional<VolumeRendererTraits> traitsOf(const std::string& name) const;
  /// The names of the renderers whose traits satisfy `has`, in menu order: "raycast, vicp,
  /// cpu".
  std::string namesWhere(bool (*has)(const VolumeRendererTraits&)) const;

 private:
  Create create_;
  std::vector<std::string> names_;
  std::vector<std::pair<std::string, VolumeRendererTraits>> apart_;
};

/// " (raycast, vicp)" after a message's advice, or nothing where no renderer is listed.
inline std::string inParentheses(const std::string& names) {
  return names.empty() ? std::string() : " (" + names + ")";
}

}  // namespace volpost::app
