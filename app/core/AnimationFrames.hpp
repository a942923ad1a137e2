// SPDX-License-Identifier: MIT
// Numbered pictures of an animation over the steps of a result, for the window's export
// and `volpost render --all-steps`.
#pragma once

#include <QString>

#include <cstddef>

namespace volpost::app {

/// The path of frame `index` (0-based) of `count`: the number, from 1 and zero-padded to
/// the digits of `count` (at least 3), inserted before the extension of `path`:
/// frames/wheel.png -> frames/wheel_001.png.
QString framePath(const QString& path, std::size_t index, std::size_t count);

}  // namespace volpost::app
