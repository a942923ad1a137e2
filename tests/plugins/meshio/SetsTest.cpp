// SPDX-License-Identifier: MIT
// The sets a file names (Abaqus/CalculiX ELSET and NSET, Gmsh physical groups, Exodus
// element blocks and node sets) become the model's sets of cell and node indices, the same
// members whichever format the model was written in.
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

#include <volpost/core/EntitySet.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

using namespace volpost;
using volpost::test::dataFile;
using volpost::test::meshioReaders;

namespace {

std::shared_ptr<Model> loadText(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return meshioReaders().load(path);
}

const EntitySet& setNamed(const Model& m, const std::string& name, SetKind kind) {
  for (const EntitySet& s : m.sets)
    if (s.name == name && s.kind == kind) return s;
  ADD_FAILURE() << "no " << setKindName(kind) << " set " << name;
  static const EntitySet none;
  return none;
}

// The file ids of a set's members.
std::set<std::int64_t> idsOf(const Model& m, const EntitySet& s) {
  std::set<std::int64_t> ids;
  const auto& fileIds = s.kind == SetKind::Nodes ? m.mesh().nodeIds : m.mesh().cellIds;
  for (const std::uint32_t i : s.members) ids.insert(fileIds.empty() ? std::int64_t(i + 1) : fileIds.at(i));
  return ids;
}

const Diagnostic* diagnostic(const Model& m, const std::string& code) {
  const auto it =
      std::find_if(m.diagnostics.begin(), m.diagnostics.end(), [&](const Diagnostic& d) { return d.code == code; });
  return it == m.diagnostics.end() ? nullptr : &*it;
}

// Two unit cubes of tets side by side (nodes 1..12), a shell on top (element 100).
const char* const kTwoBlocks =
    "*NODE, NSET=ALLNODES\n"
    "1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
    "9,2,0,0\n10,2,1,0\n11,2,0,1\n12,2,1,1\n"
    "*ELEMENT, TYPE=C3D4, ELSET=LEFT\n"
    "1,1,2,4,5\n2,2,3,4,7\n3,2,4,5,7\n"
    "*ELEMENT, TYPE=C3D4, ELSET=right\n"
    "11,2,9,3,6\n12,9,10,3,12\n"
    "*ELEMENT, TYPE=S3, ELSET=SKIN\n"
    "100,5,6,7\n";

}  // namespace

TEST(DeckSets, ElementAndNodeSetsByIdsRangesAndNames) {
  const auto model = loadText("sets.inp", std::string(kTwoBlocks) +
                                              "*ELSET, ELSET=Both\nLEFT, RIGHT\n"
                                              "*ELSET, ELSET=ODD, GENERATE\n1, 11, 2\n"
                                              "*NSET, NSET=BASE\n1, 2, 3,\n4, 9, 10\n"
                                              "*NSET, NSET=EDGE, GENERATE\n9, 12\n");
  ASSERT_EQ(model->mesh().cellCount(), 5u);
  EXPECT_EQ(idsOf(*model, setNamed(*model, "LEFT", SetKind::Cells)), (std::set<std::int64_t>{1, 2, 3}));
  EXPECT_EQ(idsOf(*model, setNamed(*model, "RIGHT", SetKind::Cells)), (std::set<std::int64_t>{11, 12}));
  EXPECT_EQ(idsOf(*model, setNamed(*model, "BOTH", SetKind::Cells)), (std::set<std::int64_t>{1, 2, 3, 11, 12}));
  // 1, 3, 5, 7, 9, 11: the ids no solid has (5, 7, 9) are reported, not guessed.
  EXPECT_EQ(idsOf(*model, setNamed(*model, "ODD", SetKind::Cells)), (std::set<std::int64_t>{1, 3, 11}));
  EXPECT_EQ(idsOf(*model, setNamed(*model, "BASE", SetKind::Nodes)), (std::set<std::int64_t>{1, 2, 3, 4, 9, 10}));
  EXPECT_EQ(idsOf(*model, setNamed(*model, "EDGE", SetKind::Nodes)), (std::set<std::int64_t>{9, 10, 11, 12}));
  EXPECT_EQ(setNamed(*model, "ALLNODES", SetKind::Nodes).members.size(), 12u);
  const Diagnostic* unknown = diagnostic(*model, "set-unknown-ids");
  ASSERT_NE(unknown, nullptr);
  EXPECT_NE(unknown->message.find("ODD"), std::string::npos) << unknown->message;
  // The shell's set is known to be empty for a reason the user is told.
  const Diagnostic* empty = diagnostic(*model, "set-empty");
  ASSERT_NE(empty, nullptr);
  EXPECT_NE(empty->message.find("SKIN"), std::string::npos) << empty->message;
  EXPECT_EQ(findSet(model->sets, "both"), &setNamed(*model, "BOTH", SetKind::Cells));
}

TEST(DeckSets, UnknownSetNamesAreReported) {
  const auto model = loadText("unknown_names.inp", std::string(kTwoBlocks) + "*ELSET, ELSET=MORE\nLEFT, NOSUCH\n");
  EXPECT_EQ(idsOf(*model, setNamed(*model, "MORE", SetKind::Cells)), (std::set<std::int64_t>{1, 2, 3}));
  const Diagnostic* d = diagnostic(*model, "set-unknown-names");
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("NOSUCH"), std::string::npos) << d->message;
}

TEST(DeckSets, BadSetLinesNameTheLine) {
  const auto error = [](const std::string& name, const std::string& tail) {
    try {
      loadText(name, std::string(kTwoBlocks) + tail);
    } catch (const ReadError& e) {
      return std::string(e.what());
    }
    return std::string("loaded");
  };
  EXPECT_NE(error("g1.inp", "*ELSET, ELSET=G, GENERATE\n5, 1\n").find("g1.inp:24: a GENERATE line needs first <= last"),
            std::string::npos);
  EXPECT_NE(error("g2.inp", "*ELSET, ELSET=G, GENERATE\n1, 2000000000\n").find("more than 100000000 ids"),
            std::string::npos);
  EXPECT_NE(error("g3.inp", "*NSET, NSET=N, GENERATE\n1\n").find("'first, last[, step]'"), std::string::npos);
  EXPECT_NE(error("g4.inp", "*ELSET\n1\n").find("g4.inp:23: *ELSET without ELSET="), std::string::npos);
  EXPECT_NE(error("g5.inp", "*NSET, NSET=N\n1, 2x\n").find("g5.inp:24"), std::string::npos);
  // Ids at the integer limits give a clear error, not an overflow.
  EXPECT_NE(error("g6.inp", "*NSET, NSET=N, GENERATE\n-9223372036854775807, 9223372036854775807, 1\n")
                .find("more than 100000000 ids"),
            std::string::npos);
  EXPECT_EQ(error("g7.inp", "*NSET, NSET=N, GENERATE\n9223372036854775806, 9223372036854775807, 5\n"), "loaded");
}

TEST(GmshSets, PhysicalGroupsByNameOrByDimensionAndTag) {
  const auto named = meshioReaders().load(dataFile("bad/ref_small_tets.msh"));
  EXPECT_EQ(setNamed(*named, "box", SetKind::Cells).members.size(), named->mesh().cellCount());
  // golden_22: group 5 holds a triangle and the three tets; a surface and a volume share the tag.
  const auto unnamed = meshioReaders().load(dataFile("formats/golden_22.msh"));
  EXPECT_EQ(setNamed(*unnamed, "physical volume 5", SetKind::Cells).members.size(), 3u);
  EXPECT_EQ(setNamed(*unnamed, "physical surface 5", SetKind::Nodes).members.size(), 3u);
}

TEST(ExodusSets, BlocksAndNodeSetsMatchTheDeck) {
  const auto exo = meshioReaders().load(dataFile("bad/ref_small_tets.exo"));
  const auto inp = meshioReaders().load(dataFile("bad/ref_small_tets.inp"));
  EXPECT_EQ(setNamed(*exo, "tetra", SetKind::Cells).members.size(), exo->mesh().cellCount());
  const std::set<std::int64_t> fixed = idsOf(*inp, setNamed(*inp, "FIXED", SetKind::Nodes));
  EXPECT_EQ(fixed.size(), 20u);
  EXPECT_EQ(idsOf(*exo, setNamed(*exo, "FIXED", SetKind::Nodes)), fixed);
}

TEST(ModelSets, AnIntegerCellFieldOffersGroupsWhereTheFileHasNoSets) {
  const auto model = loadText("regions.vtk",
                              "# vtk DataFile Version 3.0\nregions\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                              "POINTS 5 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n"
                              "CELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n10\n10\n"
                              "CELL_DATA 2\nSCALARS region int 1\nLOOKUP_TABLE default\n7\n9\n"
                              "SCALARS stress double 1\nLOOKUP_TABLE default\n0.5\n1.5\n");
  const std::vector<EntitySet> sets = modelSets(*model);
  ASSERT_EQ(sets.size(), 2u);
  EXPECT_EQ(sets[0].name, "region 7");
  EXPECT_EQ(sets[0].members, std::vector<std::uint32_t>{0});
  EXPECT_EQ(sets[1].name, "region 9");
  EXPECT_EQ(sets[1].origin, "cell field");
  // A deck's own sets come first and stop the offer.
  const auto deck = loadText("deck_sets.inp", kTwoBlocks);
  for (const EntitySet& s : modelSets(*deck)) EXPECT_NE(s.origin, "cell field") << s.name;
}

TEST(FrdSets, TheDeckBesideTheResultsGivesItsSets) {
  const auto frd = meshioReaders().load(dataFile("bad/ref_small_tets.frd"));
  const auto inp = meshioReaders().load(dataFile("bad/ref_small_tets.inp"));
  const EntitySet& fixed = setNamed(*frd, "FIXED", SetKind::Nodes);
  EXPECT_EQ(idsOf(*frd, fixed), idsOf(*inp, setNamed(*inp, "FIXED", SetKind::Nodes)));
  EXPECT_EQ(fixed.origin, "NSET of ref_small_tets.inp");
  EXPECT_EQ(setNamed(*frd, "EALL", SetKind::Cells).members.size(), frd->mesh().cellCount());
  EXPECT_NE(diagnostic(*frd, "deck-sets"), nullptr);
}

TEST(FrdSets, ADeckOfAnotherMeshOrAnUnreadableOneIsSaid) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "frd_beside";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(dataFile("bad/ref_small_tets.frd"), dir / "model.frd",
                             std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "model.inp") << std::string(kTwoBlocks) +
                                          "*NODE\n9999, 5, 5, 5\n*NSET, NSET=FAR\n1, 2, 9999, 5000\n";
  const auto other = meshioReaders().load((dir / "model.frd").string());
  EXPECT_EQ(other->mesh().cellCount(), 266u) << "the results are loaded all the same";
  const Diagnostic* mismatch = diagnostic(*other, "deck-sets-mismatch");
  ASSERT_NE(mismatch, nullptr);
  EXPECT_NE(mismatch->message.find("model.inp"), std::string::npos) << mismatch->message;
  EXPECT_EQ(idsOf(*other, setNamed(*other, "FAR", SetKind::Nodes)), (std::set<std::int64_t>{1, 2}));
  const Diagnostic* unknown = diagnostic(*other, "set-unknown-ids");  // the deck's own word on its sets
  ASSERT_NE(unknown, nullptr);
  EXPECT_NE(unknown->message.find("model.inp: *NSET FAR names 1 node id"), std::string::npos) << unknown->message;

  std::ofstream(dir / "model.inp") << "*NODE\n1, 0, zero, 0\n";
  const auto unreadable = meshioReaders().load((dir / "model.frd").string());
  EXPECT_EQ(unreadable->mesh().cellCount(), 266u);
  const Diagnostic* notRead = diagnostic(*unreadable, "deck-sets-not-read");
  ASSERT_NE(notRead, nullptr);
  EXPECT_NE(notRead->message.find("model.inp:2: expected a node coordinate"), std::string::npos) << notRead->message;
  EXPECT_TRUE(unreadable->sets.empty());
}

TEST(DeckSurfaces, FacesBecomeTheNodeSetsOfTheirNodes) {
  const auto model = loadText("surfaces.inp", std::string(kTwoBlocks) +
                                                  "*SURFACE, NAME=BOTTOM\n1, S1\n"
                                                  "*SURFACE, NAME=Side, TYPE=ELEMENT\n1, S2\n"
                                                  "*SURFACE, NAME=OUTSIDE\nRIGHT\n"
                                                  "*SURFACE, NAME=BYNODES, TYPE=NODE\nALLNODES\n"
                                                  "*SURFACE, NAME=SHELL\nSKIN, SPOS\n"
                                                  "*SURFACE, NAME=ODD\n1, S1\n77, S2\n");
  const auto origin = [&](const char* name) { return setNamed(*model, name, SetKind::Nodes).origin; };
  EXPECT_EQ(idsOf(*model, setNamed(*model, "BOTTOM", SetKind::Nodes)), (std::set<std::int64_t>{1, 2, 4}));
  EXPECT_EQ(idsOf(*model, setNamed(*model, "SIDE", SetKind::Nodes)), (std::set<std::int64_t>{1, 2, 5}));
  EXPECT_EQ(origin("BOTTOM"), "SURFACE");
  // Without a face: the faces of RIGHT's two tets that they do not share, every node here.
  EXPECT_EQ(idsOf(*model, setNamed(*model, "OUTSIDE", SetKind::Nodes)), (std::set<std::int64_t>{2, 3, 6, 9, 10, 12}));
  EXPECT_EQ(setNamed(*model, "BYNODES", SetKind::Nodes).members.size(), 12u);
  EXPECT_EQ(findSet(model->sets, "SHELL"), nullptr) << "a shell's side is not loaded";
  const Diagnostic* unknown = diagnostic(*model, "set-unknown-ids");
  ASSERT_NE(unknown, nullptr);
  EXPECT_NE(unknown->message.find("*SURFACE ODD names 1 id"), std::string::npos) << unknown->message;
}

TEST(DeckSurfaces, FaceNumbersOfWedgesHexahedraAndQuadraticTets) {
  const auto model = loadText("faces.inp",
                              "*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n5,1,0,1\n6,0,1,1\n"
                              "11,2,0,0\n12,3,0,0\n13,3,1,0\n14,2,1,0\n15,2,0,1\n16,3,0,1\n17,3,1,1\n18,2,1,1\n"
                              "21,5,0,0\n22,6,0,0\n23,5,1,0\n24,5,0,1\n25,5.5,0,0\n26,5.5,0.5,0\n27,5,0.5,0\n"
                              "28,5,0,0.5\n29,5.5,0,0.5\n30,5,0.5,0.5\n"
                              "*ELEMENT, TYPE=C3D6\n1, 1,2,3,4,5,6\n"
                              "*ELEMENT, TYPE=C3D8\n2, 11,12,13,14,15,16,17,18\n"
                              "*ELEMENT, TYPE=C3D10\n3, 21,22,23,24,25,26,27,28,29,30\n"
                              "*SURFACE, NAME=W1\n1, S1\n*SURFACE, NAME=W2\n1, S2\n*SURFACE, NAME=W3\n1, S3\n"
                              "*SURFACE, NAME=H2\n2, S2\n*SURFACE, NAME=H6\n2, S6\n"
                              "*SURFACE, NAME=T1\n3, S1\n*SURFACE, NAME=T3\n3, S3\n");
  const auto ids = [&](const char* name) { return idsOf(*model, setNamed(*model, name, SetKind::Nodes)); };
  EXPECT_EQ(ids("W1"), (std::set<std::int64_t>{1, 2, 3}));
  EXPECT_EQ(ids("W2"), (std::set<std::int64_t>{4, 5, 6}));
  EXPECT_EQ(ids("W3"), (std::set<std::int64_t>{1, 2, 4, 5}));
  EXPECT_EQ(ids("H2"), (std::set<std::int64_t>{15, 16, 17, 18}));
  EXPECT_EQ(ids("H6"), (std::set<std::int64_t>{11, 14, 15, 18}));
  EXPECT_EQ(ids("T1"), (std::set<std::int64_t>{21, 22, 23, 25, 26, 27}));
  EXPECT_EQ(ids("T3"), (std::set<std::int64_t>{22, 23, 24, 26, 29, 30}));
}

TEST(DeckSets, LongGenerateRangesCostWhatTheModelsIdsCost) {
  std::string lines;
  for (int k = 0; k < 100; ++k) lines += "1, 99999999\n";  // 1e10 ids written, 5 elements to look up
  const auto model = loadText("ranges.inp", std::string(kTwoBlocks) + "*ELSET, ELSET=ALL, GENERATE\n" + lines +
                                                "*NSET, NSET=WIDE, GENERATE\n"
                                                "-9223372036854775807, 9223372036854775807, 9223372036854775807\n");
  EXPECT_EQ(idsOf(*model, setNamed(*model, "ALL", SetKind::Cells)), (std::set<std::int64_t>{1, 2, 3, 11, 12}));
  const Diagnostic* unknown = diagnostic(*model, "set-unknown-ids");
  ASSERT_NE(unknown, nullptr);
  // 100 lines of 99999999 ids, less the 5 elements and the shell 100 on each.
  EXPECT_NE(unknown->message.find("*ELSET ALL names 9999999300 element ids"), std::string::npos) << unknown->message;
  EXPECT_EQ(findSet(model->sets, "WIDE"), nullptr) << "-max, 0 and max: no node has those ids";
}
