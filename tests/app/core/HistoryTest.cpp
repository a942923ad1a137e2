// SPDX-License-Identifier: MIT
// History plots: values against the step at nodes, elements and points, checked against
// the stored values; the time axis only for increasing times; steps a field lacks and
// points outside are gaps, never a repeated value.
#include "core/History.hpp"
#include "core/Measure.hpp"
#include "core/Scene.hpp"

#include <volpost/render/VolumeRenderer.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace volpost;
using namespace volpost::app;

namespace {

// One tet; T = (node + 1) * step at three steps (times 0.5, 1, 2), "mode" with two steps,
// a per-element "E" = 10 * step.
std::shared_ptr<ModelSession> tetWithSteps(std::vector<double> times) {
  auto model = std::make_shared<Model>();
  Mesh& mesh = model->mesh();
  mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.nodeIds = {11, 12, 13, 14};
  const NodeIndex tet[4] = {0, 1, 2, 3};
  mesh.addCell(CellType::Tet4, tet);
  mesh.cellIds = {7};
  std::vector<std::vector<double>> t, e;
  std::vector<Step> steps;
  for (std::size_t s = 0; s < times.size(); ++s) {
    t.push_back({1.0 * double(s + 1), 2.0 * double(s + 1), 3.0 * double(s + 1), 4.0 * double(s + 1)});
    e.push_back({10.0 * double(s + 1)});
    steps.push_back({"step " + std::to_string(s + 1), times[s]});
  }
  model->fields.push_back(Field::fromValues("T", FieldLocation::Node, 1, t, steps));
  model->fields.push_back(Field::fromValues("E", FieldLocation::Cell, 1, e, steps));
  model->fields.push_back(Field::fromValues("mode", FieldLocation::Node, 1, {t[0], t[0]}, {steps[0], steps[1]}));
  std::vector<std::vector<double>> u;  // every node moved 0.1 x step along x
  for (std::size_t s = 0; s < times.size(); ++s)
    u.push_back(std::vector<double>(12, 0.0)),
        u.back()[0] = u.back()[3] = u.back()[6] = u.back()[9] = 0.1 * double(s + 1);
  model->fields.push_back(Field::fromValues("U", FieldLocation::Node, 3, u, steps));
  return ModelSession::fromModel(model);
}

}  // namespace

TEST(History, ValuesAtANodeAnElementAndAPointAtEveryStep) {
  const auto session = tetWithSteps({0.5, 1.0, 2.0});
  const History h = sampleHistory(*session,
                                  {{HistoryPlace::Kind::Node, 12, {}},
                                   {HistoryPlace::Kind::Element, 7, {}},
                                   {HistoryPlace::Kind::Point, 0, {0.25, 0.25, 0.25}},
                                   {HistoryPlace::Kind::Point, 0, {5, 5, 5}}},
                                  {"T", "E"});
  ASSERT_EQ(h.curves.size(), 8u);
  EXPECT_TRUE(h.byTime);
  EXPECT_EQ(h.curves[0].name, "T at node 12");
  EXPECT_EQ(h.curves[0].values, (std::vector<double>{2, 4, 6}));
  EXPECT_EQ(h.curves[1].values, (std::vector<double>{10, 20, 30}));  // E, as stored, at the node's element
  EXPECT_NEAR(h.curves[2].values[2], 3.0 * 2.5, 1e-12);              // the centre: the mean of 1..4, times 3
  EXPECT_NEAR(h.curves[4].values[1], 2.0 * (0.25 * 1 + 0.25 * 2 + 0.25 * 3 + 0.25 * 4), 1e-12);
  EXPECT_TRUE(std::isnan(h.curves[6].values[0]));  // outside
  const Chart chart = historyChart(h);
  EXPECT_EQ(chart.xTitle, "time");
  EXPECT_EQ(chart.curves[0].x, (std::vector<double>{0.5, 1.0, 2.0}));
  const std::string table = historyTable(h);
  EXPECT_EQ(table.substr(0, table.find('\n')),
            "step,label,time,T at node 12,E at node 12,T at element 7,E at element 7,\"T at (0.25, 0.25, 0.25)\","
            "\"E at (0.25, 0.25, 0.25)\",\"T at (5, 5, 5)\",\"E at (5, 5, 5)\"");
  EXPECT_NE(table.find("\n3,step 3,2,6,30,"), std::string::npos) << table;
}

TEST(History, TheExtremesOverASetAtEveryStep) {
  auto session = tetWithSteps({0.5, 1.0, 2.0});
  // A node set of nodes 11 and 13 and an element set of the tet (indices, as readers keep them).
  auto model = std::make_shared<Model>(session->model());
  model->sets.push_back({"CORNERS", SetKind::Nodes, "NSET", {0, 2}});
  model->sets.push_back({"SOLID", SetKind::Cells, "ELSET", {0}});
  session = ModelSession::fromModel(model);
  const History h = sampleHistory(*session,
                                  {{HistoryPlace::Kind::SetMax, 0, {}, "corners"},
                                   {HistoryPlace::Kind::SetMin, 0, {}, "CORNERS"},
                                   {HistoryPlace::Kind::SetMax, 0, {}, "SOLID"}},
                                  {"T"});
  ASSERT_EQ(h.curves.size(), 3u);
  EXPECT_EQ(h.curves[0].name, "T at max over corners");
  EXPECT_EQ(h.curves[0].values, (std::vector<double>{3, 6, 9})) << "node 13's T = 3 x step";
  EXPECT_EQ(h.curves[1].values, (std::vector<double>{1, 2, 3})) << "node 11's";
  EXPECT_EQ(h.curves[2].values, (std::vector<double>{4, 8, 12})) << "an element set: its elements' nodes";
  const History e = sampleHistory(*session, {{HistoryPlace::Kind::SetMin, 0, {}, "SOLID"}}, {"E"});
  EXPECT_EQ(e.curves[0].values, (std::vector<double>{10, 20, 30})) << "per element: the elements' own values";
  try {
    (void)sampleHistory(*session, {{HistoryPlace::Kind::SetMax, 0, {}, "CORNERS"}}, {"E"});
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& x) {
    EXPECT_NE(std::string(x.what()).find("needs an element set"), std::string::npos) << x.what();
  }
  try {
    (void)sampleHistory(*session, {{HistoryPlace::Kind::SetMax, 0, {}, "NOPE"}}, {"T"});
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& x) {
    EXPECT_NE(std::string(x.what()).find("its sets: CORNERS, SOLID"), std::string::npos) << x.what();
  }
}

TEST(StepBlend, AnInBetweenFrameInterpolatesTheValuesAndTheShape) {
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(tetWithSteps({0.5, 1.0, 2.0}));
  scene.setResult("T", 0);
  scene.setDeformation({true, "U", 1.0, false});
  EXPECT_DOUBLE_EQ(scene.session()->model().nodePosition(1).x, 1.1);
  scene.setStepBlend(0.25);
  ASSERT_TRUE(scene.view());
  EXPECT_DOUBLE_EQ(scene.view()->values[3], 4.0 * 1.25) << "node 14's T a quarter of the way from 4 to 8";
  EXPECT_EQ(scene.view()->stepLabel, "step 1 to step 2 (25 %)");
  EXPECT_DOUBLE_EQ(scene.session()->model().nodePosition(1).x, 1.0 + 0.125) << "the shape moves with it";
  scene.setResult("T", 1);  // a step of its own again
  EXPECT_EQ(scene.stepBlend(), 0.0);
  EXPECT_DOUBLE_EQ(scene.view()->values[3], 8.0);
  EXPECT_DOUBLE_EQ(scene.session()->model().nodePosition(1).x, 1.2);
  scene.setResult("T", 2);
  scene.setStepBlend(0.5);  // the last step has no next: it stays
  EXPECT_DOUBLE_EQ(scene.view()->values[3], 12.0);
  EXPECT_THROW(scene.setStepBlend(1.0), std::invalid_argument);
  EXPECT_THROW(scene.setStepBlend(-0.1), std::invalid_argument);
  EXPECT_FALSE(scene.state().toJson().find("blend") != std::string::npos) << "not kept in the state";
}

TEST(History, StepNumbersWithoutIncreasingTimesAndGapsWhereAFieldHasNoStep) {
  const auto session = tetWithSteps({0.0, 0.0, 0.0});
  const History h = sampleHistory(*session, {{HistoryPlace::Kind::Node, 14, {}}}, {"mode", "T"});
  EXPECT_FALSE(h.byTime);
  EXPECT_EQ(historyChart(h).xTitle, "step");
  EXPECT_EQ(historyChart(h).curves[0].x, (std::vector<double>{1, 2, 3}));
  ASSERT_EQ(h.curves[0].values.size(), 3u);
  EXPECT_EQ(h.curves[0].values[1], 4.0);
  EXPECT_TRUE(std::isnan(h.curves[0].values[2]));  // "mode" has two steps: no repeat of the last
}

TEST(History, RefusalsNameWhatIsWrong) {
  const auto session = tetWithSteps({1, 2});
  EXPECT_THROW(sampleHistory(*session, {{HistoryPlace::Kind::Node, 99, {}}}, {"T"}), std::invalid_argument);
  EXPECT_THROW(sampleHistory(*session, {{HistoryPlace::Kind::Element, 8, {}}}, {"T"}), std::invalid_argument);
  EXPECT_THROW(sampleHistory(*session, {{HistoryPlace::Kind::Node, 11, {}}}, {"nope"}), std::invalid_argument);
  EXPECT_THROW(sampleHistory(*session, {}, {"T"}), std::invalid_argument);
  std::vector<HistoryPlace> many(kMaxHistoryCurves + 1, {HistoryPlace::Kind::Node, 11, {}});
  EXPECT_THROW(sampleHistory(*session, many, {"T"}), std::invalid_argument);
}

TEST(Measure, DistancesAndAnglesBetweenPoints) {
  EXPECT_DOUBLE_EQ(distanceBetween({0, 0, 0}, {3, 4, 12}), 13.0);
  EXPECT_NEAR(*angleAt({1, 0, 0}, {0, 0, 0}, {0, 2, 0}), 90.0, 1e-12);
  EXPECT_NEAR(*angleAt({1, 0, 0}, {0, 0, 0}, {1, 1, 0}), 45.0, 1e-12);
  EXPECT_NEAR(*angleAt({1, 0, 0}, {0, 0, 0}, {-1, 1e-9, 0}), 180.0, 1e-6);  // nearly straight: no acos rounding
  EXPECT_NEAR(*angleAt({1, 0, 0}, {0, 0, 0}, {1, 1e-9, 0}), 0.0, 1e-6);
  EXPECT_FALSE(angleAt({0, 0, 0}, {0, 0, 0}, {1, 0, 0}));
}

TEST(Measure, TheSceneMeasuresProbesAndTheStateKeepsIt) {
  Scene scene([](const std::string&) { return nullptr; });
  scene.setProbes({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
  scene.setMeasure({0, 1, 2});
  const SceneState back = SceneState::fromJson(scene.state().toJson(), "/data/view.json");
  EXPECT_EQ(back.measure, (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_NE(scene.state().toJson().find("\"measure\": [\n      1,\n      2,\n      3"), std::string::npos)
      << "probes are counted from 1 in the file, as the picture numbers them";
  const auto refused = [&](std::vector<std::size_t> m) {
    try {
      scene.setMeasure(std::move(m));
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refused({0}).find("names two probes, or three"), std::string::npos);
  EXPECT_NE(refused({0, 3}).find("probe 4 is not there to measure (3 probes)"), std::string::npos);
  EXPECT_NE(refused({1, 1}).find("probe 2 is named twice"), std::string::npos);
  EXPECT_EQ(scene.measure(), (std::vector<std::size_t>{0, 1, 2})) << "a refused measure changes nothing";
  scene.setProbes({{0, 0, 0}, {1, 0, 0}});  // the third probe removed: no angle to draw
  EXPECT_TRUE(scene.measure().empty());
  EXPECT_THROW(SceneState::fromJson(R"({"markers": {"probes": [[0,0,0],[1,0,0]], "measure": [1, 5]}})", "v.json"),
               std::exception);
}
