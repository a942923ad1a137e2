// SPDX-License-Identifier: MIT
// A scene of the bar pulled by 100 MPa for pixel tests: S.xx over 90..110 on `colorMap`,
// no edges, legend, axes or shading, seen square-on from -y (orthographic, zoom 2), so a
// pixel's color is the color map's at the value under it.
#pragma once

#include "support/BarSession.hpp"

#include "core/CameraSpec.hpp"
#include "core/PluginRenderers.hpp"
#include "core/SceneDrawing.hpp"

#include <memory>
#include <string>

namespace volpost::test {

inline std::unique_ptr<app::Scene> flatBarScene(const std::string& colorMap) {
  auto scene = std::make_unique<app::Scene>([](const std::string&) { return nullptr; });
  scene->setSession(app::ModelSession::load(meshioReaders(), dataFile("bar/bar_tet4.vtu")));
  scene->setResult("S.xx", 0);
  scene->setColorMap(colorMap);
  scene->setFixedRange(app::DisplayRange{90.0, 110.0});
  scene->setShowEdges(false);
  scene->setShowLegend(false);
  scene->setShowTriad(false);
  scene->setLighting(false);
  app::applyCameraSpec(scene->camera(), "-y,ortho,zoom=2");
  return scene;
}

}  // namespace volpost::test
