// SPDX-License-Identifier: MIT
// What each renderer of the volume plugin says of itself (traits) agrees with what it is:
// the host builds its menus and refusals from these alone, so a wrong trait is a wrong
// menu or a refusal of an option the renderer honours.
#include "CellProjector.hpp"
#include "CpuVolumeRenderer.hpp"
#include "GridRayMarcher.hpp"
#include "GridSlicer.hpp"
#include "RayCaster.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <set>
#include <vector>

using namespace volpost;
using namespace volpost::volume;

namespace {

std::vector<std::unique_ptr<VolumeRenderer>> everyRenderer() {
  std::vector<std::unique_ptr<VolumeRenderer>> out;
  out.push_back(std::make_unique<RayCaster>());
  out.push_back(std::make_unique<CellProjector>(OrderMethod::Mpvonc));
  out.push_back(std::make_unique<CellProjector>(OrderMethod::ImageSpace));
  out.push_back(std::make_unique<CpuVolumeRenderer>());
  out.push_back(std::make_unique<GridRayMarcher>());
  out.push_back(std::make_unique<GridSlicer>());
  return out;
}

}  // namespace

TEST(VolumeRendererTraits, EveryRendererSaysWhatItDrawsAsItsInterfaceAllows) {
  std::set<std::string> labels;
  for (const auto& r : everyRenderer()) {
    const VolumeRendererTraits t = r->traits();
    SCOPED_TRACE(r->name());
    EXPECT_FALSE(t.label.empty());
    EXPECT_TRUE(labels.insert(t.label).second) << "two renderers read the same in the menu";
    EXPECT_TRUE(t.drawsMeshes || t.drawsGrids) << "it draws something";
    EXPECT_EQ(t.drawsGrids, dynamic_cast<GridVolumeRenderer*>(r.get()) != nullptr);
    if (t.shading || t.transferFunction2D) EXPECT_TRUE(t.drawsGrids) << "both are settings of grid renderers";
    std::set<IntegrationMode> modes(t.modes.begin(), t.modes.end());
    EXPECT_EQ(modes.size(), t.modes.size()) << "a mode offered twice";
  }
}

TEST(VolumeRendererTraits, AGridOnlyRendererRefusesAMeshAsItSays) {
  for (const auto& r : everyRenderer()) {
    if (r->traits().drawsMeshes) continue;
    SCOPED_TRACE(r->name());
    Mesh mesh;
    mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.addCell(CellType::Tet4, std::vector<NodeIndex>{0, 1, 2, 3});
    const std::vector<double> values{0, 1, 2, 3};
    EXPECT_THROW(r->setVolume(mesh, FieldLocation::Node, values), std::invalid_argument);
  }
}

TEST(VolumeRendererTraits, TheCpuRayCasterIntegratesExactlyAndSaysSo) {
  const VolumeRendererTraits t = CpuVolumeRenderer().traits();
  EXPECT_TRUE(t.modes.empty());
  EXPECT_FALSE(t.samplingStepOnMeshes);
  EXPECT_TRUE(t.samplingStepOnGrids);
  EXPECT_TRUE(t.runsOnCpu);
  EXPECT_TRUE(t.drawsMeshes && t.drawsGrids);
  EXPECT_FALSE(RayCaster().traits().runsOnCpu);
  EXPECT_EQ(RayCaster().traits().modes, allIntegrationModes());
}
