// SPDX-License-Identifier: MIT
// How a part of the window changes the scene: it hands the window a change; the window
// runs it, says in the status bar why when the scene refuses it (false), and redraws.
#pragma once

#include <functional>

namespace volpost::app {

class Scene;

using ChangeScene = std::function<bool(const std::function<void(Scene&)>&)>;

}  // namespace volpost::app
