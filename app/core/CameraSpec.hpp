// SPDX-License-Identifier: MIT
#pragma once

#include <volpost/core/Camera.hpp>

#include <string>

namespace volpost::app {

/// Applies a camera description to a camera already fitted to the model. The description
/// is a comma-separated list: a standard view (iso, +x, -x, +y, -y, +z, -z), az=DEG and
/// el=DEG (orbit from there), zoom=FACTOR, ortho or persp. Example: "iso,az=30,zoom=1.5".
/// Throws std::invalid_argument naming the item it does not understand.
void applyCameraSpec(Camera& camera, const std::string& spec);

}  // namespace volpost::app
