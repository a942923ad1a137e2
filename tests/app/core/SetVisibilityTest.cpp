// SPDX-License-Identifier: MIT
// Showing and hiding element sets: the kept cells are exactly the chosen sets' members,
// keep their file numbers and their sets, and the choice is refused (changing nothing)
// where it names no element set or leaves nothing to draw; it lives in the saved state.
#include "support/HeadlessGl.hpp"
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

#include <volpost/render/VolumeRenderer.hpp>

#include "core/PluginRenderers.hpp"
#include "core/Scene.hpp"
#include "core/SceneImage.hpp"
#include "core/SetColors.hpp"
#include "core/SetMembership.hpp"
#include "core/SetVisibility.hpp"

#include <QImage>

#include <cmath>
#include <fstream>
#include <set>

using namespace volpost;
using namespace volpost::app;

namespace {

// Three quadratic cells, one per ELSET: E_HEX (element 101), E_WEDGE (102), E_TET (103).
std::shared_ptr<ModelSession> golden() {
  return ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("formats/golden.inp"));
}

std::vector<std::int64_t> idsOf(const ModelSession& part) {
  std::vector<std::int64_t> ids;
  for (std::size_t c = 0; c < part.model().mesh().cellCount(); ++c) ids.push_back(part.model().mesh().cellId(c));
  return ids;
}

std::string refusal(const ModelSession& session, const SetVisibility& v) {
  try {
    checkSetVisibility(session, v);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace

TEST(SetVisibility, KeepsTheShownSetsLessTheHiddenOnes) {
  const auto whole = golden();
  EXPECT_EQ(idsOf(*setVisibleSession(whole, {{"E_HEX"}, {}, {}})), (std::vector<std::int64_t>{101}));
  EXPECT_EQ(idsOf(*setVisibleSession(whole, {{}, {"E_HEX"}, {}})), (std::vector<std::int64_t>{102, 103}));
  EXPECT_EQ(idsOf(*setVisibleSession(whole, {{"e_hex", "E_TET"}, {"E_TET"}, {}})), (std::vector<std::int64_t>{101}))
      << "names are matched regardless of case, hidden wins";
  EXPECT_EQ(setVisibleSession(whole, {}), whole) << "no choice: the model itself";
  // The part keeps its sets, renumbered to its own cells.
  const auto part = setVisibleSession(whole, {{"E_WEDGE", "E_TET"}, {}, {}});
  const EntitySet* tet = findSet(part->model().sets, "E_TET");
  ASSERT_NE(tet, nullptr);
  ASSERT_EQ(tet->members.size(), 1u);
  EXPECT_EQ(part->model().mesh().cellId(tet->members[0]), 103);
  EXPECT_EQ(part->model().mesh().cellType(tet->members[0]), CellType::Tet10);
}

TEST(SetVisibility, RefusesNamesThatAreNoElementSetAndEmptyChoices) {
  const auto whole = golden();
  const std::string unknown = refusal(*whole, {{"E_BEAM"}, {}, {}});
  EXPECT_NE(unknown.find("no set is named 'E_BEAM'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("E_HEX, E_WEDGE, E_TET"), std::string::npos) << unknown;
  const std::string nodes = refusal(*whole, {{"NALL"}, {}, {}});
  EXPECT_NE(nodes.find("'NALL' is a set of 37 nodes"), std::string::npos) << nodes;
  const std::string nothing = refusal(*whole, {{}, {"E_HEX", "E_WEDGE", "E_TET"}, {}});
  EXPECT_NE(nothing.find("leaves no element"), std::string::npos) << nothing;
  EXPECT_EQ(refusal(*whole, {{"E_HEX"}, {"E_TET"}, {}}), "accepted");
}

TEST(SetVisibility, TheSceneDrawsThePartAndSavesTheChoice) {
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(golden());
  scene.setResult("element set", 0);
  scene.setSetVisibility({{"E_WEDGE"}, {}, {}});
  EXPECT_EQ(idsOf(*scene.session()), (std::vector<std::int64_t>{102}));
  ASSERT_TRUE(scene.view());
  ASSERT_EQ(scene.view()->values.size(), 1u);
  EXPECT_EQ(scene.view()->values[0], 2.0) << "the shown element result is the part's";
  EXPECT_THROW(scene.setSetVisibility({{"NOSUCH"}, {}, {}}), std::invalid_argument);
  EXPECT_EQ(scene.setVisibility().shown, (std::vector<std::string>{"E_WEDGE"})) << "a refused choice changes nothing";
  EXPECT_EQ(idsOf(*scene.session()), (std::vector<std::int64_t>{102}));

  const SceneState back = SceneState::fromJson(scene.state().toJson(), "/data/view.json");
  EXPECT_EQ(back.sets, scene.setVisibility());
  scene.setSetVisibility({});
  EXPECT_EQ(scene.session(), scene.baseSession());
  scene.applyState(back);
  EXPECT_EQ(idsOf(*scene.session()), (std::vector<std::int64_t>{102}));

  // A threshold applies to the part the sets leave.
  scene.setThreshold(ThresholdLayer{true, "element set", 1.5, 3.5, true});
  EXPECT_EQ(idsOf(*scene.session()), (std::vector<std::int64_t>{102}));
  scene.setSetVisibility({{}, {"E_WEDGE"}, {}});
  EXPECT_EQ(idsOf(*scene.session()), (std::vector<std::int64_t>{103}));
  // Together they must leave a cell; a refused change keeps what was drawn.
  EXPECT_THROW(scene.setThreshold(ThresholdLayer{true, "element set", 1.5, 2.5, true}), std::invalid_argument);
  EXPECT_THROW(scene.setSetVisibility({{"E_HEX"}, {}, {}}), std::invalid_argument);
  EXPECT_EQ(idsOf(*scene.session()), (std::vector<std::int64_t>{103}));

  // Another model starts with every cell drawn.
  scene.setSession(golden());
  EXPECT_FALSE(scene.setVisibility().active());
  EXPECT_EQ(scene.session()->model().cellCount(), 3u);
}

TEST(SetVisibility, TheColorRangeAndExtremesAreThoseOfTheDrawnSets) {
  // Two tets, region 7 and region 9 (groups offered by the integer field), sharing three
  // nodes; T is 100 at the node only region 9 uses.
  const std::string path = ::testing::TempDir() + "/two_regions.vtk";
  std::ofstream(path) << "# vtk DataFile Version 3.0\nregions\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                         "POINTS 5 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n"
                         "CELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n10\n10\n"
                         "CELL_DATA 2\nSCALARS region int 1\nLOOKUP_TABLE default\n7\n9\n"
                         "POINT_DATA 5\nSCALARS T double 1\nLOOKUP_TABLE default\n1\n2\n3\n4\n100\n";
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(ModelSession::load(volpost::test::meshioReaders(), path));
  scene.setResult("T", 0);
  EXPECT_EQ(scene.view()->range.max, 100.0);
  scene.setSetVisibility({{"region 7"}, {}, {}});
  ASSERT_TRUE(scene.view());
  EXPECT_EQ(scene.view()->range.min, 1.0);
  EXPECT_EQ(scene.view()->range.max, 4.0) << "the node only the hidden set uses is not in the range";
  const auto extremes = scene.extremes();
  ASSERT_TRUE(extremes);
  EXPECT_EQ(extremes->maxId, 4);
  scene.setSetVisibility({{}, {"region 7"}, {}});
  EXPECT_EQ(scene.view()->range.min, 2.0);
  EXPECT_EQ(scene.view()->range.max, 100.0);
}

TEST(SetVisibility, AMarkedSetGivesTheNodesOfWhatIsDrawn) {
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(golden());
  scene.setSetVisibility({{"E_TET"}, {}, {}});
  const auto part = scene.session();
  SetVisibility marked = scene.setVisibility();
  marked.marked = "nall";  // a node set: its nodes the drawn tet10 uses
  scene.setSetVisibility(marked);
  EXPECT_EQ(scene.session(), part) << "marking draws the same cells";
  EXPECT_EQ(scene.markedSet().nodeCount, 10u);
  marked.shown.clear();
  marked.marked = "E_WEDGE";  // an element set: its wedge15's nodes
  scene.setSetVisibility(marked);
  EXPECT_EQ(scene.markedSet().nodeCount, 15u);
  for (const glm::dvec3& p : scene.markedSet().nodes) EXPECT_GE(p.x, 0.0);
  EXPECT_TRUE(scene.markedSet().numbers.empty()) << "numbers only when asked";
  marked.numbers = true;  // an element set's numbers: its element's, at its centre
  scene.setSetVisibility(marked);
  ASSERT_EQ(scene.markedSet().numbers.size(), 1u);
  EXPECT_EQ(scene.markedSet().numbers[0].id, 102);
  glm::dvec3 centre(0.0);
  const auto wedge = scene.session()->model().mesh().cellNodes(1);
  for (int k = 0; k < 6; ++k) centre += scene.session()->model().nodePosition(wedge[std::size_t(k)]) / 6.0;
  EXPECT_LT(glm::length(scene.markedSet().numbers[0].at - centre), 1e-12);
  marked.marked = "NALL";  // a node set's numbers: the file's node ids
  scene.setSetVisibility(marked);
  ASSERT_EQ(scene.markedSet().numbers.size(), 37u);
  std::set<std::int64_t> ids;
  for (const auto& n : scene.markedSet().numbers) ids.insert(n.id);
  std::set<std::int64_t> expected;
  for (std::size_t n = 0; n < 37; ++n) expected.insert(scene.session()->model().mesh().nodeId(n));
  EXPECT_EQ(ids, expected);
  marked.marked = "E_WEDGE";
  marked.numbers = false;
  scene.setSetVisibility(marked);
  marked.marked = "NOSUCH";
  EXPECT_THROW(scene.setSetVisibility(marked), std::invalid_argument);
  EXPECT_EQ(scene.setVisibility().marked, "E_WEDGE");
  const SceneState back = SceneState::fromJson(scene.state().toJson(), "/data/view.json");
  EXPECT_EQ(back.sets.marked, "E_WEDGE");
  scene.setSession(golden());
  EXPECT_TRUE(scene.markedSet().nodes.empty()) << "another model marks nothing";
}

TEST(SetMembership, TheSetsHoldingAnElementOrANode) {
  const auto whole = golden();
  const std::vector<EntitySet> sets = modelSets(whole->model());
  EXPECT_EQ(setsHolding(sets, SetKind::Cells, 2), (std::vector<std::string>{"E_TET"}));
  EXPECT_EQ(setsHolding(sets, SetKind::Nodes, 0), (std::vector<std::string>{"NALL"}));
  EXPECT_TRUE(setsHolding(sets, SetKind::Cells, 99).empty());
  EXPECT_EQ(setNameList({"EALL", "region 7"}), "EALL, \"region 7\"");
}

namespace {

// Pixels within 3/255 per channel of `rgb`.
int pixelsOf(const QImage& image, const glm::dvec3& rgb) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      n += std::abs(c.red() - int(std::lround(rgb.r * 255))) <= 3 &&
                   std::abs(c.green() - int(std::lround(rgb.g * 255))) <= 3 &&
                   std::abs(c.blue() - int(std::lround(rgb.b * 255))) <= 3
               ? 1
               : 0;
    }
  return n;
}

// Three tets: ALL holds the first two, SMALL the second, the third is in no set.
std::shared_ptr<ModelSession> overlappingSets() {
  const std::string path = ::testing::TempDir() + "/overlapping_sets.inp";
  std::ofstream(path) << "*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n5,1,1,1\n6,2,1,1\n"
                         "*ELEMENT, TYPE=C3D4, ELSET=ALL\n1,1,2,3,4\n2,2,3,4,5\n"
                         "*ELEMENT, TYPE=C3D4\n3,2,3,5,6\n"
                         "*ELSET, ELSET=SMALL\n2\n";
  return ModelSession::load(volpost::test::meshioReaders(), path);
}

}  // namespace

TEST(SetColors, EachCellTakesTheSmallestSetHoldingItAndASetKeepsItsColor) {
  const auto whole = overlappingSets();
  const SetColoring c = setColoring(*whole, *whole);
  ASSERT_EQ(c.view.values.size(), 3u);
  EXPECT_EQ(c.view.location, FieldLocation::Cell);
  EXPECT_EQ(c.view.values[0], 0.5) << "ALL, the first element set: the palette's first color";
  EXPECT_EQ(c.view.values[1], 1.5) << "SMALL inside ALL: the smaller set's color";
  EXPECT_TRUE(std::isnan(c.view.values[2])) << "in no set: drawn gray";
  ASSERT_EQ(c.entries.size(), 2u);
  EXPECT_EQ(c.entries[0].name, "ALL");
  EXPECT_EQ(c.entries[0].cells, 1u);
  EXPECT_EQ(c.entries[1].name, "SMALL");
  EXPECT_EQ(c.entries[1].rgb, setPaletteColor(1));
  EXPECT_EQ(c.cellsInNoSet, 1u);
  EXPECT_EQ(c.view.range.nanCount, 1u);

  // Hiding a set leaves the others their colors; a set that colors no drawn cell is not keyed.
  const auto golden3 = golden();
  const auto part = setVisibleSession(golden3, {{}, {"E_HEX"}, {}});
  const SetColoring p = setColoring(*part, *golden3);
  ASSERT_EQ(p.view.values.size(), 2u);
  EXPECT_EQ(p.view.values[0], 1.5) << "E_WEDGE keeps the second color";
  EXPECT_EQ(p.view.values[1], 2.5) << "E_TET the third";
  ASSERT_EQ(p.entries.size(), 2u);
  EXPECT_EQ(p.entries[0].name, "E_WEDGE");
  EXPECT_EQ(p.cellsInNoSet, 0u);
  // The palette map is flat over each band: its middle is the set's color.
  const ColorMap map = setPaletteMap();
  for (int i = 0; i < kSetPaletteSize; ++i) {
    EXPECT_EQ(map.at((i + 0.5) / kSetPaletteSize), setPaletteColor(std::size_t(i))) << i;
    EXPECT_EQ(map.at((i + 0.02) / kSetPaletteSize), setPaletteColor(std::size_t(i))) << i;
  }
  EXPECT_EQ(setPaletteColor(kSetPaletteSize + 3), setPaletteColor(3)) << "more sets than colors: they cycle";
}

TEST(SetColors, TheSceneColorsBySetsKeysThemAndSavesTheChoice) {
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(golden());
  scene.setResult("element set", 0);
  EXPECT_EQ(scene.setColoring(), nullptr) << "off until asked";
  EXPECT_EQ(scene.surfaceValues().view, scene.shownValues().view);
  const std::uint64_t before = scene.surfaceValues().version;
  SetVisibility v;
  v.colors = true;
  scene.setSetVisibility(v);
  ASSERT_NE(scene.setColoring(), nullptr);
  EXPECT_EQ(scene.surfaceValues().view, &scene.setColoring()->view);
  EXPECT_NE(scene.surfaceValues().version, before) << "cached sections are cut again";
  EXPECT_EQ(scene.surfaceRange().max, double(kSetPaletteSize));
  EXPECT_EQ(scene.view()->quantity.key(), "element set") << "the result stays for probing and the volume";
  const auto key = scene.legends();
  ASSERT_FALSE(key.empty());
  EXPECT_EQ(key.front().content.title, "Element sets");
  ASSERT_EQ(key.front().content.swatches.size(), 3u);
  EXPECT_EQ(key.front().content.swatches[2].name, "E_TET");
  EXPECT_EQ(key.front().content.swatches[2].rgb, setPaletteColor(2));

  const SceneState back = SceneState::fromJson(scene.state().toJson(), "/data/view.json");
  EXPECT_TRUE(back.sets.colors);
  v.colors = false;
  scene.setSetVisibility(v);
  EXPECT_EQ(scene.setColoring(), nullptr);
  EXPECT_TRUE(scene.legends().front().content.swatches.empty()) << "the result's bar again";
  scene.applyState(back);
  EXPECT_NE(scene.setColoring(), nullptr);

  // A model with no element set has nothing to color by: refused, nothing changed.
  const std::string path = ::testing::TempDir() + "/no_sets.vtk";
  std::ofstream(path) << "# vtk DataFile Version 3.0\nno sets\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                         "POINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
  scene.setSession(ModelSession::load(volpost::test::meshioReaders(), path));
  SetVisibility colors;
  colors.colors = true;
  try {
    scene.setSetVisibility(colors);
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no element sets to color by"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(scene.setVisibility().colors);
}

TEST(SetColors, ThePictureShowsEachSetInItsColor) {
  VOLPOST_SKIP_WITHOUT_GL();
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(golden());
  scene.setResult("element set", 0);
  scene.setShowEdges(false);
  scene.setLighting(false);  // the colors as they are
  scene.setShowTriad(false);
  SetVisibility v;
  v.colors = true;
  scene.setSetVisibility(v);
  const QImage all = renderSceneImage(scene, 200, 120).picture;
  for (std::size_t i = 0; i < 3; ++i) EXPECT_GT(pixelsOf(all, setPaletteColor(i)), 60) << "set " << i;
  v.hidden = {"E_HEX"};
  scene.setSetVisibility(v);
  const QImage part = renderSceneImage(scene, 200, 120).picture;
  EXPECT_LT(pixelsOf(part, setPaletteColor(0)), 8) << "the hidden set's color is gone (but in the key)";
  EXPECT_GT(pixelsOf(part, setPaletteColor(1)), 60) << "the others keep theirs";
  EXPECT_GT(pixelsOf(part, setPaletteColor(2)), 60);
  v = {};
  scene.setSetVisibility(v);
  const QImage result = renderSceneImage(scene, 200, 120).picture;
  EXPECT_LT(pixelsOf(result, setPaletteColor(1)), 8) << "the result's colors again";
}
