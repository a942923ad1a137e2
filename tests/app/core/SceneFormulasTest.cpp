// SPDX-License-Identifier: MIT
// The calculator's formulas in the scene: shown like any result, kept in the state file,
// refused without changing what is shown, and what showed a removed formula falls back.
#include "support/BarSession.hpp"
#include "support/RayCasterScene.hpp"
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

#include "core/Scene.hpp"

#include <stdexcept>

using namespace volpost;
using namespace volpost::app;
using volpost::test::barSession;

TEST(SceneFormulas, AFormulaIsShownAndComesBackThroughTheStateFile) {
  Scene scene{VolumeRendererFactory{}};
  scene.setSession(barSession());
  scene.setFormulas({{"ratio", "S.mises / 250"}, {"twice", "S * 2"}});
  scene.setResult("twice.mises", 0);
  ASSERT_TRUE(scene.view());
  const ValueRange mises = barSession()->evaluate(barSession()->findQuantity("S.mises"), 0).range;
  EXPECT_NEAR(scene.view()->range.max, 2.0 * mises.max, 1e-9 * mises.max);
  // The model as read is left alone: the formulas live in the scene's own copy.
  EXPECT_EQ(barSession()->model().findField("ratio"), nullptr);

  const SceneState back = SceneState::fromJson(scene.state().toJson(), "/data/view.json");
  ASSERT_EQ(back.formulas.size(), 2u);
  EXPECT_EQ(back.formulas[0], (FormulaSpec{"ratio", "S.mises / 250"}));
  EXPECT_EQ(back.quantity, "twice.mises");
  Scene other{VolumeRendererFactory{}};
  other.setSession(barSession());
  other.applyState(back);
  ASSERT_TRUE(other.view());
  EXPECT_EQ(other.view()->range.max, scene.view()->range.max);
  EXPECT_EQ(other.formulas(), scene.formulas());
}

TEST(SceneFormulas, ABadFormulaChangesNothingAndARemovedOneFallsBack) {
  Scene scene{VolumeRendererFactory{}};
  scene.setSession(barSession());
  scene.setFormulas({{"ratio", "S.mises / 250"}});
  scene.setResult("ratio", 0);
  EXPECT_THROW(scene.setFormulas({{"ratio", "S.mises / "}}), FormulaError);
  EXPECT_EQ(scene.state().quantity, "ratio");
  EXPECT_EQ(scene.formulas().size(), 1u);
  // A state naming a quantity its formulas do not make is refused whole.
  SceneState s = scene.state();
  s.formulas = {{"other", "T"}};
  EXPECT_THROW(scene.applyState(s), std::invalid_argument);
  EXPECT_EQ(scene.state().quantity, "ratio");
  // Removed: the result falls back to the model's default (von Mises).
  scene.setFormulas({});
  EXPECT_EQ(scene.state().quantity, "S.mises");
  EXPECT_EQ(scene.session()->model().findField("ratio"), nullptr);
  // Another model drops them.
  scene.setFormulas({{"ratio", "S.mises / 250"}});
  scene.setSession(barSession());
  EXPECT_TRUE(scene.formulas().empty());
}

// Values that are not numbers are counted in the legend with what becomes of them: gray on
// the surface, left out of the volume (which draws no gray).
TEST(SceneFormulas, TheLegendSaysWhereValuesThatAreNotNumbersGo) {
  Scene scene{volpost::test::rayCasterOnly()};
  scene.setSession(barSession());
  scene.setFormulas({{"root", "sqrt(S11 - 100)"}});
  scene.setResult("root", 0);
  ASSERT_TRUE(scene.view());
  const std::size_t notNumbers = scene.view()->range.nanCount;
  EXPECT_GT(notNumbers, 0u);
  EXPECT_EQ(scene.legends().front().content.noValueCount, notNumbers);
  EXPECT_EQ(scene.legends().front().content.noValueShown, QString("gray"));
  scene.setVolumeShown(true);
  EXPECT_EQ(scene.legends().front().content.noValueShown, QString("left out of the volume"));
}
