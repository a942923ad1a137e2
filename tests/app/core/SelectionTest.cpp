// SPDX-License-Identifier: MIT
// Picking elements and nodes: the ids the user names or a box holds become the sets
// "selected elements" and "selected nodes", usable as any set and kept in state files. The
// box takes what is seen (surface, cut faces) or everything through the depth, checked on
// a block of unit cubes where each answer can be counted by hand.
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

#include <volpost/render/VolumeRenderer.hpp>

#include "core/BoxSelection.hpp"
#include "core/Scene.hpp"
#include "core/Selection.hpp"
#include "core/SetVisibility.hpp"

#include <fstream>

using namespace volpost;
using namespace volpost::app;

namespace {

std::string refusalOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

// n x n x n unit hexahedra filling [0, n]^3; element ids start at 1001, node ids at 1.
std::shared_ptr<ModelSession> hexBlock(int n) {
  auto model = std::make_shared<Model>();
  Mesh mesh;
  const auto id = [&](int i, int j, int k) { return NodeIndex((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) mesh.nodes.push_back(glm::dvec3(i, j, k));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const NodeIndex hex[8] = {id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
                                  id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        mesh.addCell(CellType::Hex8, hex);
        mesh.cellIds.push_back(1001 + std::int64_t(mesh.cellCount()) - 1);
      }
  model->setMesh(std::move(mesh));
  return ModelSession::fromModel(model);
}

// The box between two model points' places in a picture.
PictureBox boxBetween(const Camera& camera, glm::dvec3 a, glm::dvec3 b, double w, double h) {
  const glm::dvec2 pa = *camera.projectToPicture(a, w, h), pb = *camera.projectToPicture(b, w, h);
  return {pa.x, pa.y, pb.x, pb.y};
}

std::vector<std::int64_t> cellIds(const ModelSession& s, const std::vector<std::uint32_t>& cells) {
  std::vector<std::int64_t> out;
  for (const std::uint32_t c : cells) out.push_back(s.model().mesh().cellId(c));
  return out;
}

}  // namespace

TEST(Selection, IdListsReadAndWriteRanges) {
  EXPECT_EQ(parseIdList("101,105-107, 3"), (std::vector<std::int64_t>{3, 101, 105, 106, 107}));
  EXPECT_EQ(parseIdList("-3--1"), (std::vector<std::int64_t>{-3, -2, -1}));
  EXPECT_EQ(idListText({3, 101, 105, 106, 107}), "3,101,105-107");
  EXPECT_EQ(parseIdList(idListText({1, 2, 3, 9})), (std::vector<std::int64_t>{1, 2, 3, 9}));
  EXPECT_NE(refusalOf([] { parseIdList("1,,2"); }).find("empty id"), std::string::npos);
  EXPECT_NE(refusalOf([] { parseIdList("7,x9"); }).find("'x9' in '7,x9' is not an id"), std::string::npos);
  EXPECT_NE(refusalOf([] { parseIdList("9-3"); }).find("the range 9-3 runs backwards"), std::string::npos);
  EXPECT_NE(refusalOf([] { parseIdList("1-9000000000"); }).find("names more than"), std::string::npos);
  EXPECT_NE(refusalOf([] { parseIdList("1-600000,700000-1200000"); }).find("names more than"), std::string::npos);
}

TEST(Selection, IdsInTheModelTakeWhatARangeHolds) {
  const auto golden = ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("formats/golden.inp"));
  EXPECT_EQ(idsInModel("1-102, 103", *golden, SetKind::Cells), (std::vector<std::int64_t>{101, 102, 103}))
      << "a range takes the ids it holds";
  EXPECT_NE(refusalOf([&] { idsInModel("101,104", *golden, SetKind::Cells); }).find("no element 104"),
            std::string::npos);
  EXPECT_NE(refusalOf([&] { idsInModel("1-50", *golden, SetKind::Cells); }).find("no element numbered 1 to 50"),
            std::string::npos);
  const std::int64_t node = golden->model().mesh().nodeId(0);
  EXPECT_EQ(idsInModel(std::to_string(node), *golden, SetKind::Nodes), (std::vector<std::int64_t>{node}));
}

TEST(Selection, BecomesSetsOfTheModelKeptInTheState) {
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("formats/golden.inp")));
  const std::string unknown = refusalOf([&] { scene.setSelection({{101, 999}, {}}); });
  EXPECT_NE(unknown.find("the model has no element 999 to select"), std::string::npos) << unknown;
  EXPECT_TRUE(scene.selection().empty()) << "refused: nothing changed";

  const std::int64_t node = scene.baseSession()->model().mesh().nodeId(0);
  scene.setSelection({{103, 101, 103}, {node}});
  EXPECT_EQ(scene.selection().elements, (std::vector<std::int64_t>{101, 103})) << "sorted, each once";
  const std::vector<EntitySet> sets = modelSets(scene.baseSession()->model());
  const EntitySet* picked = findSet(sets, kSelectedElements);
  ASSERT_NE(picked, nullptr);
  EXPECT_EQ(picked->members, (std::vector<std::uint32_t>{0, 2}));
  EXPECT_EQ(sets.back().name, kSelectedNodes) << "the selection comes after the file's sets";
  ASSERT_NE(findSet(sets, "E_HEX"), nullptr) << "the file's sets stay";

  // Shown alone like any set; the state keeps both.
  scene.setSetVisibility({{kSelectedElements}, {}, {}});
  EXPECT_EQ(scene.session()->model().cellCount(), 2u);
  const SceneState back = SceneState::fromJson(scene.state().toJson(), "/data/view.json");
  EXPECT_EQ(back.selection, scene.selection());
  EXPECT_NE(scene.state().toJson().find("\"elements\": \"101,103\""), std::string::npos) << scene.state().toJson();

  // Cleared, the choices that named its sets forget them: every element is drawn again.
  scene.setSelection({});
  EXPECT_FALSE(scene.setVisibility().active());
  EXPECT_EQ(scene.session()->model().cellCount(), 3u);
  EXPECT_EQ(findSet(modelSets(scene.baseSession()->model()), kSelectedElements), nullptr);
  scene.applyState(back);
  EXPECT_EQ(scene.session()->model().cellCount(), 2u) << "the state's selection and its choice come back";

  // A state naming an element the model lacks is refused with the key.
  std::string text = back.toJson();
  text.replace(text.find("101,103"), 7, "101,104");
  const SceneState bad = SceneState::fromJson(text, "/data/view.json");
  EXPECT_NE(refusalOf([&] { scene.applyState(bad); }).find("no element 104"), std::string::npos);
  EXPECT_EQ(scene.session()->model().cellCount(), 2u);
  try {
    text.replace(text.find("101,104"), 7, "101,,4");
    (void)SceneState::fromJson(text, "/data/view.json");
    ADD_FAILURE() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("\"selection.elements\""), std::string::npos) << e.what();
  }
}

TEST(Selection, ARegionFieldStillOffersItsGroupsBesideASelection) {
  const std::string path = ::testing::TempDir() + "/regions_selected.vtk";
  std::ofstream(path) << "# vtk DataFile Version 3.0\nregions\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                         "POINTS 5 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n"
                         "CELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n10\n10\n"
                         "CELL_DATA 2\nSCALARS region int 1\nLOOKUP_TABLE default\n7\n9\n";
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(ModelSession::load(volpost::test::meshioReaders(), path));
  scene.setSelection({{2}, {}});
  const std::vector<EntitySet> sets = modelSets(scene.baseSession()->model());
  EXPECT_NE(findSet(sets, "region 7"), nullptr);
  EXPECT_NE(findSet(sets, kSelectedElements), nullptr);
}

TEST(BoxSelection, TakesWhatIsSeenOrEverythingThroughTheDepth) {
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(hexBlock(4));
  const double w = 400, h = 300;
  for (const auto projection : {Camera::Projection::Orthographic, Camera::Projection::Perspective}) {
    SCOPED_TRACE(projection == Camera::Projection::Perspective ? "perspective" : "orthographic");
    scene.camera().setProjection(projection);
    scene.camera().lookAt({2.0, 2.0, 20.0}, {2.0, 2.0, 2.0}, {0.0, 1.0, 0.0});  // down onto z = 4
    scene.setClipPlanes({});
    Camera camera = scene.pictureCamera(w, h);
    // The four columns under x, y in (0.1, 1.9): seen, the top layer's cells (ids 1049..);
    // through, all four layers.
    const PictureBox cells = boxBetween(camera, {0.1, 0.1, 4.0}, {1.9, 1.9, 4.0}, w, h);
    EXPECT_EQ(cellIds(*scene.session(), elementsInBox(scene, camera, w, h, cells, SelectionDepth::Surface)),
              (std::vector<std::int64_t>{1049, 1050, 1053, 1054}));
    EXPECT_EQ(elementsInBox(scene, camera, w, h, cells, SelectionDepth::Through).size(), 16u);
    // Nodes with x, y in {1, 2}: four on top seen, twenty through the five layers of nodes.
    const PictureBox nodes = boxBetween(camera, {0.9, 0.9, 4.0}, {2.1, 2.1, 4.0}, w, h);
    const auto seenNodes = nodesInBox(scene, camera, w, h, nodes, SelectionDepth::Surface);
    ASSERT_EQ(seenNodes.size(), 4u);
    for (const std::uint32_t n : seenNodes) EXPECT_EQ(scene.session()->model().nodePosition(n).z, 4.0);
    EXPECT_EQ(nodesInBox(scene, camera, w, h, nodes, SelectionDepth::Through).size(), 20u);
    // A click takes the element under it.
    const glm::dvec2 at = *camera.projectToPicture({3.5, 0.5, 4.0}, w, h);
    EXPECT_EQ(cellIds(*scene.session(),
                      elementsInBox(scene, camera, w, h, {at.x, at.y, at.x, at.y}, SelectionDepth::Surface)),
              (std::vector<std::int64_t>{1052}));

    // Cut at z = 2.5 (the top kept below): the cut face shows the middle layer's cells; the
    // cut-away cells and nodes are not there to take.
    scene.setClipPlanes({ClipPlane{{0.0, 0.0, 2.5}, {0.0, 0.0, -1.0}}});
    camera = scene.pictureCamera(w, h);
    EXPECT_EQ(cellIds(*scene.session(), elementsInBox(scene, camera, w, h, cells, SelectionDepth::Surface)),
              (std::vector<std::int64_t>{1033, 1034, 1037, 1038}));
    EXPECT_EQ(elementsInBox(scene, camera, w, h, cells, SelectionDepth::Through).size(), 12u);
    EXPECT_TRUE(nodesInBox(scene, camera, w, h, nodes, SelectionDepth::Surface).empty())
        << "no node lies on a cut face";
    EXPECT_EQ(nodesInBox(scene, camera, w, h, nodes, SelectionDepth::Through).size(), 12u);
  }
  // Off the model: nothing.
  scene.setClipPlanes({});
  const Camera camera = scene.pictureCamera(w, h);
  EXPECT_TRUE(elementsInBox(scene, camera, w, h, {0, 0, 3, 3}, SelectionDepth::Surface).empty());
  EXPECT_TRUE(elementsInBox(scene, camera, w, h, {-50, -50, -10, -10}, SelectionDepth::Through).empty());
}
