// SPDX-License-Identifier: MIT
// A GPU volume renderer (from a renderer plugin) drawing a model headless (EGL).
#pragma once

#include "VolumeImage.hpp"

#include <volpost/core/ColorMap.hpp>
#include <volpost/render/VolumeRenderer.hpp>

#include <QImage>

namespace volpost::app {

/// The transfer function's colors as a color map over its range (for the legend).
ColorMap colorMapOf(const TransferFunction& tf);

/// Renders the request with `renderer` (not yet initialized; it is initialized and
/// released here, inside a headless context). Background (0.96, 0.96, 0.97), legend of
/// the transfer function's colors unless `legend` is false.
QImage renderGpuVolume(const ModelSession& session, const VolumeRequest& request, VolumeRenderer& renderer,
                       IntegrationMode mode, bool legend);

}  // namespace volpost::app
