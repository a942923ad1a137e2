// SPDX-License-Identifier: MIT
// A grid model answers from its grid until something needs its cells, then builds them once.
#include <volpost/core/MeshChecks.hpp>
#include <volpost/core/Model.hpp>
#include <volpost/core/ResourceLimits.hpp>
#include <volpost/core/Error.hpp>

#include <gtest/gtest.h>

#include <thread>
#include <vector>

using namespace volpost;

namespace {

RegularGrid rotatedGrid() {
  RegularGrid g;
  g.dims = {5, 4, 3};
  g.origin = {100.0, -20.0, 3.0};
  g.axes = {glm::dvec3(0.6, 0.8, 0.0), glm::dvec3(-1.6, 1.2, 0.0), glm::dvec3(0.0, 0.0, -0.5)};  // left-handed
  return g;
}

}  // namespace

TEST(Model, AGridModelAnswersCountsAndBoundsWithoutBuildingItsCells) {
  Model m;
  m.grid = rotatedGrid();
  EXPECT_FALSE(m.meshBuilt());
  EXPECT_EQ(m.nodeCount(), 60u);
  EXPECT_EQ(m.cellCount(), 24u);
  EXPECT_EQ(m.countsByType().at(CellType::Hex8), 24u);
  const Bounds fromGrid = m.bounds();
  checkModel(m);  // the checks leave an unbuilt grid alone
  EXPECT_FALSE(m.meshBuilt());
  EXPECT_TRUE(m.diagnostics.empty());

  const Mesh& mesh = m.mesh();  // first use builds the hexahedra
  EXPECT_TRUE(m.meshBuilt());
  EXPECT_EQ(mesh.nodeCount(), 60u);
  EXPECT_EQ(mesh.cellCount(), 24u);
  EXPECT_EQ(&m.mesh(), &mesh) << "built once";
  const Mesh expected = hexahedraOfGrid(*m.grid);
  EXPECT_EQ(std::vector<NodeIndex>(mesh.connectivity().begin(), mesh.connectivity().end()),
            std::vector<NodeIndex>(expected.connectivity().begin(), expected.connectivity().end()));
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) EXPECT_GT(signedCellVolume(mesh, c), 0.0) << "cell " << c;
  const Bounds built = mesh.bounds();
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(fromGrid.min[a], built.min[a], 1e-12);
    EXPECT_NEAR(fromGrid.max[a], built.max[a], 1e-12);
  }
  checkModel(m);  // and a built grid has nothing to report
  EXPECT_TRUE(m.diagnostics.empty());
}

TEST(Model, ThreadsAskingAtOnceGetOneMesh) {
  Model m;
  m.grid = rotatedGrid();
  std::vector<const Mesh*> seen(8, nullptr);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < seen.size(); ++t) threads.emplace_back([&, t] { seen[t] = &m.mesh(); });
  for (std::thread& t : threads) t.join();
  for (const Mesh* s : seen) {
    EXPECT_EQ(s, seen[0]);
    EXPECT_EQ(s->cellCount(), 24u);
  }
}

TEST(Model, ACopyAndAGivenMeshKeepTheirOwnCells) {
  Model m;
  m.grid = rotatedGrid();
  const Model unbuilt(m);
  EXPECT_FALSE(unbuilt.meshBuilt());
  EXPECT_EQ(unbuilt.mesh().cellCount(), 24u);
  EXPECT_FALSE(m.meshBuilt()) << "the copy built its own";

  Model given;
  given.grid = rotatedGrid();
  Mesh one;
  one.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const NodeIndex tet[4] = {0, 1, 2, 3};
  one.addCell(CellType::Tet4, tet);
  given.setMesh(one);
  EXPECT_TRUE(given.meshBuilt());
  EXPECT_EQ(given.mesh().cellCount(), 1u) << "a given mesh is not replaced by the grid's";
  Model copy;
  copy = given;
  EXPECT_EQ(copy.mesh().cellCount(), 1u);
  copy.mesh().nodes[0].x = 7.0;
  EXPECT_EQ(given.mesh().nodes[0].x, 0.0) << "the copy's nodes are its own";
}

TEST(Model, AGridTooLargeForExplicitCellsOrWithInfiniteCornersIsRefused) {
  RegularGrid huge;
  huge.dims = {65536, 65536, 2};  // 2^33 points: node indices are 32-bit
  EXPECT_THROW((void)hexahedraOfGrid(huge), std::length_error);
  Model m;
  m.grid = huge;
  EXPECT_EQ(m.nodeCount(), std::size_t(1) << 33) << "the grid itself is fine without cells";
  RegularGrid far = rotatedGrid();
  far.origin = {1.7e308, 0.0, 0.0};
  far.axes[0] = {1e308, 0.0, 0.0};
  EXPECT_NE(far.defect().find("far corners"), std::string::npos) << far.defect();
}

// Readers check a grid's samples only; the hexahedra (57 bytes a point) are checked against
// the memory budget when something first needs them, with a message naming them, and the
// model stays usable without them.
TEST(Model, AGridsHexahedraOverTheMemoryBudgetAreRefusedWhenFirstNeeded) {
  Model model;
  model.sourcePath = "cube.sgy";
  RegularGrid g;
  g.dims = {40, 40, 40};
  model.grid = g;
  const std::size_t budget = memoryBudget();
  setMemoryBudget(64000 * 40);  // 2.56 MB: less than 64,000 points x 57 bytes
  try {
    (void)model.mesh();
    ADD_FAILURE() << "the hexahedra were built over the budget";
  } catch (const ReadError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("cube.sgy"), std::string::npos) << m;
    EXPECT_NE(m.find("59319 hexahedra"), std::string::npos) << m;
    EXPECT_NE(m.find("memory budget"), std::string::npos) << m;
  }
  EXPECT_FALSE(model.meshBuilt());
  EXPECT_EQ(model.nodeCount(), 64000u);
  setMemoryBudget(budget);
  EXPECT_EQ(model.mesh().cellCount(), 59319u);
  EXPECT_TRUE(model.meshBuilt());
}

TEST(Model, FieldsCountTogetherAgainstTheMemoryBudget) {
  // Forty arrays each within the budget, not together, took 2.5 GB: each step loaded must
  // fit beside what the fields already hold.
  const std::size_t before = Field::bytesHeldByAllFields();
  const std::size_t entities = 1000;
  std::vector<std::shared_ptr<Field>> fields;
  for (int i = 0; i < 5; ++i)
    fields.push_back(std::make_shared<Field>("f" + std::to_string(i), FieldLocation::Node, 1, entities,
                                             std::vector<Step>{{"", 0.0}},
                                             [](std::size_t) { return std::vector<double>(1000, 1.0); }));
  setMemoryBudget(before + 3 * entities * sizeof(double) + 100);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(fields[std::size_t(i)]->values(0).size(), entities);
  EXPECT_EQ(Field::bytesHeldByAllFields(), before + 3 * entities * sizeof(double));
  try {
    (void)fields[3]->values(0);
    ADD_FAILURE() << "a fourth array beyond the budget was loaded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("field f3: step 1 needs 7.81 KB, and the fields read so far hold"),
              std::string::npos)
        << e.what();
  }
  fields.resize(1);  // a released field gives its memory back
  EXPECT_EQ(Field::bytesHeldByAllFields(), before + entities * sizeof(double));
  fields.push_back(std::make_shared<Field>("g", FieldLocation::Node, 1, entities, std::vector<Step>{{"", 0.0}},
                                           [](std::size_t) { return std::vector<double>(1000, 2.0); }));
  EXPECT_EQ(fields.back()->values(0).front(), 2.0);
  setMemoryBudget(0);
}

TEST(Model, FieldsSharingANameAreGivenNamesOfTheirOwn) {
  Model m;
  m.fields.push_back(Field::fromValues("T", FieldLocation::Node, 1, {{1.0, 2.0}}));
  m.fields.push_back(Field::fromValues("T", FieldLocation::Cell, 1, {{3.0}}));
  m.fields.push_back(Field::fromValues("T", FieldLocation::Cell, 1, {{4.0}}));
  m.makeFieldNamesUnique();
  EXPECT_EQ(m.fields[0]->name(), "T");
  EXPECT_EQ(m.fields[1]->name(), "T (cells)");
  EXPECT_EQ(m.fields[2]->name(), "T (2)");
  ASSERT_EQ(m.diagnostics.size(), 2u);
  EXPECT_EQ(m.diagnostics[0].code, "field-renamed");
}
