// SPDX-License-Identifier: MIT
#include "VolumeRendererFactory.hpp"

#include <volpost/render/VolumeRenderer.hpp>

namespace volpost::app {

void VolumeRendererFactory::describeApart(const std::string& name, const VolumeRendererTraits& traits) {
  apart_.emplace_back(name, traits);
  names_.push_back(name);
}

bool VolumeRendererFactory::drawsApart(const std::string& name) const {
  for (const auto& [apart, traits] : apart_)
    if (apart == name) return true;
  return false;
}

std::string VolumeRendererFactory::namesDrawnHere() const {
  std::string out;
  for (const std::string& name : names_)
    if (!drawsApart(name)) out += (out.empty() ? "" : ", ") + name;
  return out;
}

std::unique_ptr<VolumeRenderer> VolumeRendererFactory::operator()(const std::string& name) const {
  return create_ && !drawsApart(name) ? create_(name) : nullptr;
}

// Creating a renderer makes no GL objects (initialize() does), so asking one is cheap.
std::optional<VolumeRendererTraits> VolumeRendererFactory::traitsOf(const std::string& name) const {
  for (const auto& [apart, traits] : apart_)
    if (apart == name) return traits;
  const std::unique_ptr<VolumeRenderer> renderer = (*this)(name);
  if (!renderer) return std::nullopt;
  return renderer->traits();
}

std::string VolumeRendererFactory::namesWhere(bool (*has)(const VolumeRendererTraits&)) const {
  std::string out;
  for (const std::string& name : names_)
    if (const auto traits = traitsOf(name); traits && has(*traits)) out += (out.empty() ? "" : ", ") + name;
  return out;
}

}  // namespace volpost::app
