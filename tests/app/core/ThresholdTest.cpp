// SPDX-License-Identifier: MIT
// Threshold on the bar pulled by 100 MPa: the kept cells are exactly those whose values
// lie in the range (by the element's own value, or at all / any of its nodes), keep the
// file's numbers and their element results, and the scene draws, probes and saves them.
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

#include "core/PluginRenderers.hpp"
#include "core/Probe.hpp"
#include "core/SceneDrawing.hpp"
#include "core/SceneImage.hpp"
#include "core/Threshold.hpp"

#include "support/HeadlessGl.hpp"

using namespace volpost;
using namespace volpost::app;

namespace {

std::shared_ptr<ModelSession> bar() {
  return ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("bar/bar_tet4.vtu"));
}

// The cells of `whole` whose nodes' S11 lie in [lo, hi]: all of them or any.
std::vector<std::int64_t> expectedIds(const ModelSession& whole, double lo, double hi, bool all) {
  const std::vector<double>& s = whole.model().findField("S11")->values(0);
  const Mesh& mesh = whole.model().mesh();
  std::vector<std::int64_t> ids;
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) {
    int in = 0;
    for (const NodeIndex n : mesh.cellNodes(c)) in += s[n] >= lo && s[n] <= hi ? 1 : 0;
    if (all ? in == int(mesh.cellNodes(c).size()) : in > 0) ids.push_back(mesh.cellId(c));
  }
  return ids;
}

std::vector<std::int64_t> idsOf(const ModelSession& part) {
  std::vector<std::int64_t> ids;
  for (std::size_t c = 0; c < part.model().mesh().cellCount(); ++c) ids.push_back(part.model().mesh().cellId(c));
  return ids;
}

}  // namespace

TEST(Threshold, KeepsTheCellsWhoseNodesLieInTheRange) {
  const auto whole = bar();
  ThresholdLayer t{true, "S11", 99.0, 101.0, true};
  const auto all = thresholdedSession(*whole, t, 0);
  const std::vector<std::int64_t> expected = expectedIds(*whole, 99.0, 101.0, true);
  ASSERT_FALSE(expected.empty());
  ASSERT_LT(expected.size(), whole->model().cellCount());
  EXPECT_EQ(idsOf(*all), expected) << "the kept cells, with the file's numbers";
  t.allNodes = false;
  const auto any = thresholdedSession(*whole, t, 0);
  EXPECT_EQ(idsOf(*any), expectedIds(*whole, 99.0, 101.0, false));
  EXPECT_GT(any->model().cellCount(), all->model().cellCount());
  // The nodes are shared as they are; the element results are the kept cells'.
  EXPECT_EQ(all->model().nodeCount(), whole->model().nodeCount());
  const Field* region = all->model().findField("region");
  ASSERT_TRUE(region);
  EXPECT_EQ(region->values(0).size(), all->model().cellCount());
  // An element result thresholds by the element's own value: region is 1 everywhere.
  const auto byRegion = thresholdedSession(*whole, ThresholdLayer{true, "region", 0.5, 1.5, true}, 0);
  EXPECT_EQ(byRegion->model().cellCount(), whole->model().cellCount());
  EXPECT_EQ(thresholdedSession(*whole, ThresholdLayer{true, "region", 2.0, 3.0, true}, 0)->model().cellCount(), 0u);
  // The part's color range is that of the nodes its cells use, not of every node it shares.
  const ScalarView partView = all->evaluate(all->findQuantity("S11"), 0);
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t c = 0; c < all->model().cellCount(); ++c)
    for (const NodeIndex n : all->model().mesh().cellNodes(c)) {
      lo = std::min(lo, partView.values[n]);
      hi = std::max(hi, partView.values[n]);
    }
  EXPECT_EQ(partView.range.min, lo);
  EXPECT_EQ(partView.range.max, hi);
  EXPECT_LT(hi - lo, whole->evaluate(whole->findQuantity("S11"), 0).range.max -
                         whole->evaluate(whole->findQuantity("S11"), 0).range.min);
  EXPECT_THROW(checkThreshold(*whole, ThresholdLayer{true, "S11", 2.0, 1.0, true}), std::invalid_argument);
  EXPECT_THROW(checkThreshold(*whole, ThresholdLayer{true, "nothing", 0.0, 1.0, true}), std::invalid_argument);
}

TEST(Threshold, TheSceneDrawsProbesAndKeepsTheKeptCells) {
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(bar());
  scene.setResult("region", 0);
  const std::size_t cells = scene.session()->model().cellCount();
  try {
    scene.setThreshold(ThresholdLayer{true, "S11", 1000.0, 2000.0, true});
    ADD_FAILURE() << "no cell kept was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("its values: 90.546"), std::string::npos) << e.what();
  }
  EXPECT_EQ(scene.session()->model().cellCount(), cells) << "a refused threshold changes nothing";
  scene.setThreshold(ThresholdLayer{true, "S11", 99.0, 101.0, true});
  const std::size_t kept = scene.session()->model().cellCount();
  EXPECT_LT(kept, cells);
  ASSERT_TRUE(scene.view());
  EXPECT_EQ(scene.view()->values.size(), kept) << "the shown element result is the kept cells'";
  // A point outside the kept cells is outside the drawn model.
  const glm::dvec3 end{0.2, 0.5, 0.5};  // near the loaded end, where S11 is far from 100
  EXPECT_TRUE(probeAt(*scene.baseSession(), end, 0).inside());
  EXPECT_FALSE(probeAt(*scene.session(), end, 0).inside());
  const SceneState back = SceneState::fromJson(scene.state().toJson(), "/data/view.json");
  EXPECT_EQ(back.threshold, scene.threshold());
  scene.setThreshold(ThresholdLayer{});
  EXPECT_EQ(scene.session()->model().cellCount(), cells);
  EXPECT_EQ(scene.session(), scene.baseSession());
  // Through a state: the same cells again.
  SceneState s = scene.state();
  s.threshold = back.threshold;
  scene.applyState(s);
  EXPECT_EQ(scene.session()->model().cellCount(), kept);
}

TEST(Threshold, OnlyTheKeptCellsAreDrawn) {
  VOLPOST_SKIP_WITHOUT_GL();
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(bar());
  scene.setResult("S11", 0);
  scene.setShowLegend(false);
  scene.setShowTriad(false);
  const auto covered = [&] {
    const QImage image = renderSceneImage(scene, 128, 96).picture;
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) n += image.pixel(x, y) != image.pixel(0, 0) ? 1 : 0;
    return n;
  };
  const int whole = covered();
  scene.setThreshold(ThresholdLayer{true, "S11", 110.0, 200.0, false});  // near the ends only
  const int part = covered();
  EXPECT_GT(part, 0);
  EXPECT_LT(part, whole * 9 / 10);
}

// The element the hover names is outlined over the picture in yellow; the outline is of
// the drawn model and goes when that changes.
TEST(Highlight, TheHoveredElementIsOutlinedUntilTheDrawnModelChanges) {
  VOLPOST_SKIP_WITHOUT_GL();
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(bar());
  scene.setResult("S11", 0);
  const auto yellow = [&] {
    const QImage image = renderSceneImage(scene, 160, 120).picture;
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) {
        const QColor c = image.pixelColor(x, y);
        n += c.red() > 200 && c.green() > 150 && c.blue() < 80 ? 1 : 0;
      }
    return n;
  };
  const int before = yellow();
  scene.setHighlight(Scene::Highlight{0, scene.session()->model().mesh().cellNodes(0)[0]});
  ASSERT_TRUE(scene.highlight());
  EXPECT_GT(yellow(), before + 10);
  scene.setHighlight(Scene::Highlight{scene.session()->model().cellCount(), std::nullopt});
  EXPECT_FALSE(scene.highlight()) << "no such element: nothing outlined";
  scene.setHighlight(Scene::Highlight{0, std::nullopt});
  scene.setThreshold(ThresholdLayer{true, "S11", 110.0, 200.0, false});
  EXPECT_FALSE(scene.highlight()) << "cell 0 of the whole model is not cell 0 of the part";
}
