// SPDX-License-Identifier: MIT
// The FE formats beyond VTK: Gmsh 2.2/4.1 (ASCII, binary), Abaqus/CalculiX decks,
// CalculiX .frd and Exodus II. The same model read from every format must give the same
// mesh (by node id) and the same values; quadratic node orders are checked by geometry
// (each midside node at the middle of its own edge).
#include "support/TestSupport.hpp"
#include "support/ReaderSupport.hpp"

#include <volpost/core/Quantity.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <fstream>
#include <set>
#include <tuple>

using namespace volpost;
using volpost::test::dataFile;
using volpost::test::meshioReaders;

namespace {

// Node position by file id (0-based VTK files number nodes 1.. in ascending id order).
glm::dvec3 nodeById(const Model& m, std::int64_t id) {
  if (m.mesh().nodeIds.empty()) return m.mesh().nodes.at(std::size_t(id - 1));
  const auto it = std::find(m.mesh().nodeIds.begin(), m.mesh().nodeIds.end(), id);
  EXPECT_NE(it, m.mesh().nodeIds.end()) << "no node " << id;
  return it == m.mesh().nodeIds.end() ? glm::dvec3(NAN) : m.mesh().nodes[std::size_t(it - m.mesh().nodeIds.begin())];
}

std::int64_t idOf(const Model& m, std::size_t node) {
  return m.mesh().nodeIds.empty() ? std::int64_t(node + 1) : m.mesh().nodeIds[node];
}

// Every cell as (type, its node ids in VTK order); order-independent comparison.
std::multiset<std::vector<std::int64_t>> cellsById(const Model& m) {
  std::multiset<std::vector<std::int64_t>> out;
  for (std::size_t c = 0; c < m.mesh().cellCount(); ++c) {
    std::vector<std::int64_t> ids{std::int64_t(m.mesh().cellType(c))};
    for (NodeIndex n : m.mesh().cellNodes(c)) ids.push_back(idOf(m, n));
    out.insert(ids);
  }
  return out;
}

// Largest distance of a midside node from the middle of its edge, over all cells.
double worstMidsideOffset(const Model& m) {
  double worst = 0.0;
  for (std::size_t c = 0; c < m.mesh().cellCount(); ++c) {
    const auto& t = topology(m.mesh().cellType(c));
    if (!t.quadratic) continue;
    const auto nodes = m.mesh().cellNodes(c);
    for (const CellEdge& e : t.edges) {
      const glm::dvec3 mid = 0.5 * (m.mesh().nodes[nodes[e.a]] + m.mesh().nodes[nodes[e.b]]);
      worst = std::max(worst, glm::length(m.mesh().nodes[nodes[std::size_t(e.mid)]] - mid));
    }
  }
  return worst;
}

bool hasDiagnostic(const Model& m, const std::string& code) {
  return std::any_of(m.diagnostics.begin(), m.diagnostics.end(), [&](const Diagnostic& d) { return d.code == code; });
}

}  // namespace

// --- the small reference model of bad/, written by gmsh/ccx/VTK/netCDF ---------------

class SmallModelInEveryFormat : public ::testing::TestWithParam<const char*> {};

TEST_P(SmallModelInEveryFormat, GivesTheMeshAndValuesOfTheVtuFile) {
  static const auto reference = meshioReaders().load(dataFile("bad/ref_small_tets.vtu"));
  const auto model = meshioReaders().load(dataFile(std::string("bad/") + GetParam()));
  ASSERT_EQ(model->mesh().nodeCount(), 108u);
  ASSERT_EQ(model->mesh().cellCount(), 266u);
  EXPECT_FALSE(hasDiagnostic(*model, "inverted-cells"));
  // .frd keeps 6 significant digits of the coordinates, the .inp about 10, the others all.
  const std::string file = GetParam();
  const double tolerance = file.ends_with(".frd") ? 5e-5 : file.ends_with(".inp") ? 1e-9 : 1e-12;
  for (std::size_t n = 0; n < model->mesh().nodeCount(); ++n)
    ASSERT_NEAR(glm::length(model->mesh().nodes[n] - nodeById(*reference, idOf(*model, n))), 0.0, tolerance) << n;
  EXPECT_EQ(cellsById(*model), cellsById(*reference));
  for (const char* name : {"U", "S"}) {
    const Field* f = model->findField(name);
    if (std::string(GetParam()).ends_with(".msh") || std::string(GetParam()).ends_with(".inp")) {
      EXPECT_FALSE(f) << "mesh-only format";
      continue;
    }
    ASSERT_TRUE(f) << name;
    const Field& r = *reference->findField(name);
    ASSERT_EQ(f->components(), r.components());
    const std::size_t nc = std::size_t(r.components());
    for (std::size_t n = 0; n < model->mesh().nodeCount(); ++n)
      for (std::size_t k = 0; k < nc; ++k)
        ASSERT_EQ(f->values(0)[n * nc + k], r.values(0)[std::size_t(idOf(*model, n) - 1) * nc + k]) << name << " node " << n;
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, SmallModelInEveryFormat,
                         ::testing::Values("ref_small_tets.msh", "ref_small_tets_v22.msh", "ref_small_tets.inp",
                                           "ref_small_tets.frd", "ref_small_tets.vtk", "ref_small_tets.exo"),
                         [](const auto& p) {
                           std::string n = p.param;
                           for (char& c : n) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

// --- hand-made golden files: quadratic cells, sparse ids, steps, element data ----------

class GoldenModel : public ::testing::TestWithParam<const char*> {};

TEST_P(GoldenModel, PutsEveryMidsideNodeOnItsEdge) {
  const auto model = meshioReaders().load(dataFile(std::string("formats/") + GetParam()));
  ASSERT_EQ(model->mesh().cellCount(), 3u) << "the surface triangle is skipped";
  ASSERT_EQ(model->mesh().nodeCount(), 37u);
  const auto counts = model->mesh().countsByType();
  EXPECT_EQ(counts.at(CellType::Hex20), 1u);
  EXPECT_EQ(counts.at(CellType::Wedge15), 1u);
  EXPECT_EQ(counts.at(CellType::Tet10), 1u);
  EXPECT_EQ(worstMidsideOffset(*model), 0.0);
  for (std::size_t c = 0; c < 3; ++c) EXPECT_GT(signedCellVolume(model->mesh(), c), 0.0) << c;
  EXPECT_NEAR(signedCellVolume(model->mesh(), 0) + signedCellVolume(model->mesh(), 1) + signedCellVolume(model->mesh(), 2),
              1.0 + 0.5 + 1.0 / 6.0, 1e-12);
  EXPECT_EQ(model->mesh().cellIds, (std::vector<std::int64_t>{101, 102, 103}));
}

class GoldenResults : public ::testing::TestWithParam<const char*> {};

TEST_P(GoldenResults, ReadsEveryStepOfTheNodalResult) {
  const auto model = meshioReaders().load(dataFile(std::string("formats/") + GetParam()));
  const Field* t = model->findField("T");
  ASSERT_TRUE(t);
  ASSERT_EQ(t->stepCount(), 2u);
  EXPECT_EQ(t->steps()[1].time, 2.0);
  for (std::size_t step = 0; step < 2; ++step)
    for (std::size_t n = 0; n < model->mesh().nodeCount(); ++n) {
      const glm::dvec3 p = model->mesh().nodes[n];
      EXPECT_NEAR(t->values(step)[n], double(step + 1) * (p.x + 10 * p.y + 100 * p.z), 1e-9);
    }
}

std::string paramName(const ::testing::TestParamInfo<const char*>& p) {
  std::string n = p.param;
  for (char& c : n) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Formats, GoldenModel,
                         ::testing::Values("golden_41.msh", "golden_41_binary.msh", "golden_22.msh",
                                           "golden_22_binary.msh", "golden.inp", "golden.frd"),
                         paramName);
INSTANTIATE_TEST_SUITE_P(Formats, GoldenResults,
                         ::testing::Values("golden_41.msh", "golden_41_binary.msh", "golden_22.msh",
                                           "golden_22_binary.msh", "golden.frd"),
                         paramName);

TEST(AbaqusDeck, ReadsTheHeadingIncludesAndElementSets) {
  const auto model = meshioReaders().load(dataFile("formats/golden.inp"));
  EXPECT_EQ(model->title, "golden model");
  const Field* sets = model->findField("element set");
  ASSERT_TRUE(sets);
  EXPECT_EQ(sets->values(0), (std::vector<double>{1.0, 2.0, 3.0}));
  EXPECT_TRUE(hasDiagnostic(*model, "skipped-non-solid-elements"));
}

TEST(GmshData, ElementAndElementNodeViewsAreKept) {
  for (const char* file : {"formats/golden_41.msh", "formats/golden_22_binary.msh"}) {
    SCOPED_TRACE(file);
    const auto model = meshioReaders().load(dataFile(file));
    const Field* e = model->findField("E");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->location(), FieldLocation::Cell);
    EXPECT_EQ(e->values(0), (std::vector<double>{1.0, 2.0, 3.0}));
    const Field* region = model->findField("region");
    ASSERT_TRUE(region);
    EXPECT_EQ(region->values(0), (std::vector<double>{5.0, 5.0, 5.0}));
    // Element-nodal values 7 + (gmsh local index) on the tet: averaged at its nodes. Only
    // the tet has them, so each of its 10 nodes shows its own corner value.
    const Field* en = model->findField("EN");
    ASSERT_TRUE(en);
    EXPECT_EQ(en->location(), FieldLocation::Node);
    const auto tet = model->mesh().cellNodes(2);
    const int gmshOfVtk[10] = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8};  // gmsh swaps tet10 nodes 8 and 9
    for (std::size_t k = 0; k < 10; ++k) EXPECT_EQ(en->values(0)[tet[k]], 7.0 + gmshOfVtk[k]) << k;
    EXPECT_TRUE(hasDiagnostic(*model, "element-nodal-averaged"));
  }
}

TEST(AbaqusDeck, CollapsedHexahedraBecomePyramidsAndWedges) {
  const std::string dir = ::testing::TempDir();
  const std::string path = dir + "/collapsed.inp";
  {
    std::ofstream out(path);
    out << "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0.5,0.5,1\n6,0,0,1\n7,1,0,1\n8,0,1,1\n";
    out << "*ELEMENT, TYPE=C3D8\n1, 1,2,3,4,5,5,5,5\n2, 1,2,4,4,6,7,8,8\n";
  }
  const auto model = meshioReaders().load(path);
  ASSERT_EQ(model->mesh().cellCount(), 2u);
  EXPECT_EQ(model->mesh().cellType(0), CellType::Pyramid5);
  EXPECT_EQ(model->mesh().cellType(1), CellType::Wedge6);
  EXPECT_NEAR(signedCellVolume(model->mesh(), 0), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(signedCellVolume(model->mesh(), 1), 0.5, 1e-12);
  EXPECT_FALSE(hasDiagnostic(*model, "repeated-node-cells"));
}

TEST(ReaderErrors, NameTheLineAndTheDefect) {
  const std::string dir = ::testing::TempDir();
  const auto attempt = [&](const std::string& name, const std::string& text) {
    const std::string path = dir + "/" + name;
    std::ofstream(path) << text;
    try {
      meshioReaders().load(path);
    } catch (const ReadError& e) {
      return std::string(e.what());
    }
    return std::string("loaded");
  };
  EXPECT_NE(attempt("a.inp", "*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n*ELEMENT,TYPE=C3D4\n1,1,2,3\n")
                .find("a.inp:7: file ends inside an element record"), std::string::npos);
  EXPECT_NE(attempt("b.inp", "*NODE\n1,0,zero,0\n").find("b.inp:2: expected a node coordinate"), std::string::npos);
  EXPECT_NE(attempt("c.msh", "$MeshFormat\n4.0 0 8\n$EndMeshFormat\n").find("c.msh:2: MSH version 4.0 is not supported"),
            std::string::npos);
  EXPECT_NE(attempt("d.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n$EndNodes\n")
                .find("d.msh:7: expected a node tag"), std::string::npos);
  EXPECT_NE(attempt("e.frd", "    1C\n    2C     1      0\n -1    1 0.00000E+00 0.00000E+00 0.00000E+00\n -3\n 9999\n")
                .find("no element block"), std::string::npos);
  EXPECT_NE(attempt("f.exo", "CDF\x01 this is not netCDF").find("f.exo: cannot read as netCDF"), std::string::npos);
}

// --- the real cases of ../shared/data: every format of a case agrees ------------------

struct RealCase {
  const char* stem;      // "bar/tet10/bar_tet10"
  std::size_t nodes, cells;
};

class RealCaseInEveryFormat : public ::testing::TestWithParam<RealCase> {};

TEST_P(RealCaseInEveryFormat, CountsTypesAndResultsAgree) {
  const RealCase& c = GetParam();
  VOLPOST_SHARED_OR_SKIP(vtu, std::string(c.stem) + ".vtu");
  const auto reference = meshioReaders().load(vtu);
  EXPECT_EQ(reference->mesh().nodeCount(), c.nodes);
  EXPECT_EQ(reference->mesh().cellCount(), c.cells);
  const auto referenceCells = cellsById(*reference);
  for (const char* ext : {".msh", "_v22.msh", ".inp", ".frd", ".exo", ".vtk"}) {
    const std::string path = test::sharedFile(std::string(c.stem) + ext);
    if (path.empty()) continue;  // post has no .inp/.frd (no solver run)
    SCOPED_TRACE(path);
    const auto model = meshioReaders().load(path);
    EXPECT_EQ(model->mesh().nodeCount(), c.nodes);
    EXPECT_EQ(model->mesh().countsByType(), reference->mesh().countsByType());
    EXPECT_FALSE(hasDiagnostic(*model, "inverted-cells"));
    EXPECT_EQ(cellsById(*model), referenceCells);
    const bool straight = std::string(c.stem).starts_with("bar/");
    if (straight) EXPECT_LT(worstMidsideOffset(*model), std::string(ext) == ".frd" ? 1e-4 : std::string(ext) == ".inp" ? 1e-9 : 1e-12);
    const Field* u = model->findField("U");
    if (!u) continue;
    const Field& r = *reference->findField("U");
    double worst = 0.0;
    for (std::size_t n = 0; n < model->mesh().nodeCount(); ++n)
      for (std::size_t k = 0; k < 3; ++k)
        worst = std::max(worst, std::abs(u->values(0)[n * 3 + k] - r.values(0)[std::size_t(idOf(*model, n) - 1) * 3 + k]));
    EXPECT_EQ(worst, 0.0) << "U differs from the .vtu (the same .frd values)";
  }
}

INSTANTIATE_TEST_SUITE_P(Shared, RealCaseInEveryFormat,
                         ::testing::Values(RealCase{"bar/tet4/bar_tet4", 3091, 12431},
                                           RealCase{"bar/tet10/bar_tet10", 9555, 5360},
                                           RealCase{"bar/hex8/bar_hex8", 6561, 5120},
                                           RealCase{"bar/wedge6/bar_wedge6", 6018, 9900},
                                           RealCase{"wheel/tet4/wheel_tet4", 8012, 30632},
                                           RealCase{"wheel/mixed/wheel_mixed", 12746, 32482},
                                           RealCase{"bracket/tet10/bracket_tet10", 11433, 6109},
                                           RealCase{"post/coarse/post_coarse", 7342, 35246}),
                         [](const auto& p) {
                           std::string n = p.param.stem;
                           n = n.substr(n.rfind('/') + 1);
                           return n;
                         });

// --- Tecgraf neutral file -----------------------------------------------------------

TEST(NeutralFile, ReadsTheQuadraticCellsInTheirAlternatingOrder) {
  const auto model = meshioReaders().load(dataFile("formats/golden.nf"));
  EXPECT_EQ(model->title, "golden neutral file");
  ASSERT_EQ(model->mesh().cellCount(), 2u) << "the T3 surface element is skipped";
  EXPECT_EQ(model->mesh().cellType(0), CellType::Hex20);
  EXPECT_EQ(model->mesh().cellType(1), CellType::Tet10);
  EXPECT_EQ(worstMidsideOffset(*model), 0.0);
  EXPECT_NEAR(signedCellVolume(model->mesh(), 0), 1.0, 1e-12);
  EXPECT_NEAR(signedCellVolume(model->mesh(), 1), 1.0 / 6.0, 1e-12);
  EXPECT_TRUE(hasDiagnostic(*model, "skipped-lower-dimensional-cells"));
}

TEST(NeutralFile, ReadsEveryResultBlockOfEveryStep) {
  const auto model = meshioReaders().load(dataFile("formats/golden.nf"));
  const auto& nodes = model->mesh().nodes;
  for (std::size_t step = 0; step < 2; ++step) {
    const double f = double(step + 1);
    const Field& u = *model->findField("U");
    const Field& t = *model->findField("T");
    const Field& v = *model->findField("V");
    const Field& sx = *model->findField("SX");
    EXPECT_EQ(u.steps()[step].time, f);
    for (std::size_t n = 0; n < nodes.size(); ++n) {
      EXPECT_EQ(u.values(step)[n * 3], f * nodes[n].x);
      EXPECT_EQ(t.values(step)[n], f * (nodes[n].x + 10 * nodes[n].y + 100 * nodes[n].z));
      EXPECT_EQ(v.values(step)[n * 3 + 1], f);
      EXPECT_DOUBLE_EQ(sx.values(step)[n], nodes[n].x) << "element-nodal values averaged at the node";
    }
    EXPECT_EQ(model->findField("P")->values(step)[0], f);
    const Field& gauss = *model->findField("SG");
    EXPECT_EQ(gauss.location(), FieldLocation::Cell);
    EXPECT_EQ(gauss.values(step), (std::vector<double>{2.0 * f, 6.0 * f})) << "mean of the Gauss points";
  }
}

TEST(NeutralFile, RejectsDamageWithTheLine) {
  const std::string dir = ::testing::TempDir();
  const auto attempt = [&](const std::string& text) {
    const std::string path = dir + "/bad.nf";
    std::ofstream(path) << text;
    try {
      meshioReaders().load(path);
    } catch (const ReadError& e) {
      return std::string(e.what());
    }
    return std::string("loaded");
  };
  const std::string nodes = "%NODE.COORD\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
  EXPECT_NE(attempt(nodes + "%ELEMENT.TETR4\n1\n1 1 1 1 2 3 4\n").find("without %END"), std::string::npos);
  EXPECT_NE(attempt(nodes + "%ELEMENT.TETR4\n1\n1 1 1 1 2 3 9\n%END\n").find("bad.nf:9: element 1 (cell 0) uses node 9"),
            std::string::npos);
  EXPECT_NE(attempt("%NODE.COORD\n5\n1 0 0 0\n2 1 0 0\n%END\n").find("bad.nf:5: expected a node id"), std::string::npos);
  EXPECT_NE(attempt("%NODE.COORD\n1\n1 0 0 0\n2 1 0 0\n%END\n").find("more records than its count"), std::string::npos);
  const std::string wedge = attempt(nodes + "%ELEMENT.TETR4\n1\n1 1 1 1 2 3 4\n%ELEMENT.WEDGE6\n1\n2 1 1 1 2 3 4 1 2\n%END\n");
  EXPECT_EQ(wedge, "loaded") << wedge;
  const auto model = meshioReaders().load(dir + "/bad.nf");
  EXPECT_TRUE(hasDiagnostic(*model, "unknown-element-type")) << "an unknown element block is skipped with a warning";
}

// --- writing VTU and probing -----------------------------------------------------------

#include "host/PointLocator.hpp"
#include "host/VtuWriter.hpp"

class VtuWriterLayout : public ::testing::TestWithParam<VtuLayout> {};

TEST_P(VtuWriterLayout, RoundTripKeepsMeshIdsAndEveryStep) {
  const auto model = meshioReaders().load(dataFile("formats/golden.nf"));
  const std::string path = ::testing::TempDir() + "/roundtrip.vtu";
  writeVtu(*model, path, {}, GetParam());
  {
    std::ifstream in(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const bool inline_ = GetParam() == VtuLayout::Inline;
    EXPECT_EQ(text.find("<AppendedData") == std::string::npos, inline_);
    EXPECT_EQ(text.find("format=\"binary\"") != std::string::npos, inline_);
  }
  const auto back = meshioReaders().load(path);
  EXPECT_EQ(back->mesh().nodes, model->mesh().nodes);
  EXPECT_EQ(back->mesh().nodeIds, model->mesh().nodeIds);
  EXPECT_EQ(back->mesh().cellIds, model->mesh().cellIds);
  EXPECT_EQ(cellsById(*back), cellsById(*model));
  // Each field comes back as itself, with every step, its time and its label.
  EXPECT_EQ(back->title, model->title);
  for (const auto& f : model->fields) {
    const Field* g = back->findField(f->name());
    ASSERT_TRUE(g) << f->name();
    EXPECT_EQ(g->location(), f->location());
    EXPECT_EQ(g->components(), f->components());
    ASSERT_EQ(g->stepCount(), f->stepCount()) << f->name();
    for (std::size_t s = 0; s < f->stepCount(); ++s) {
      EXPECT_EQ(g->steps()[s].label, f->steps()[s].label);
      EXPECT_EQ(g->steps()[s].time, f->steps()[s].time);
      const auto& a = f->values(s);
      const auto& b = g->values(s);
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(a[i] == b[i] || (std::isnan(a[i]) && std::isnan(b[i])));
    }
  }
  EXPECT_THROW(writeVtu(*model, "/no/such/folder/x.vtu", {}, GetParam()), WriteError);
}

INSTANTIATE_TEST_SUITE_P(BothLayouts, VtuWriterLayout, ::testing::Values(VtuLayout::Appended, VtuLayout::Inline));

TEST(Probe, BarAxialStressIsForceOverAreaInEveryElementType) {
  // S11 = F/A = 100 away from the clamp (FE: 99.996..100.000 for 3 < x < 7).
  for (const char* variant : {"tet4", "tet10", "hex8", "wedge6"}) {
    VOLPOST_SHARED_OR_SKIP(path, std::string("bar/") + variant + "/bar_" + variant + ".frd");
    const auto model = meshioReaders().load(path);
    const TetMesh tets = tetrahedralize(model->mesh());
    const Field& s = *model->findField("S");
    const auto sxx = tets.nodeValues(model->mesh(), evaluate(s, *parseQuantity("S.xx", s), 0));
    const PointLocator locator(tets);
    for (const glm::dvec3 p : {glm::dvec3(3.5, 0.5, 0.5), glm::dvec3(5.0, 0.1, 0.9), glm::dvec3(6.9, 0.77, 0.23)}) {
      const auto at = locator.locate(p);
      ASSERT_TRUE(at) << variant;
      EXPECT_NEAR(PointLocator::interpolateNodal(*at, sxx), 100.0, 0.01) << variant << " at x = " << p.x;
    }
  }
}

// --- the solver's own checks (../shared/data/<case>/checks.json) -----------------------

#include <nlohmann/json.hpp>

namespace {

double maxOf(const Model& m, const std::string& quantity) {
  const std::string fieldName = quantity.substr(0, quantity.find('.'));
  const Field* f = m.findField(fieldName);
  EXPECT_TRUE(f) << fieldName;
  if (!f) return NAN;
  return rangeOf(evaluate(*f, *parseQuantity(quantity, *f), 0)).max;
}

nlohmann::json checksOf(const std::string& path, const std::string& variant) {
  std::ifstream in(path);
  const auto j = nlohmann::json::parse(in);
  if (!j.is_array()) return j;
  for (const auto& v : j)
    if (v.value("variant", "") == variant) return v;
  return {};
}

}  // namespace

TEST(SolverChecks, ResultsOfEveryFormatMatchWhatTheSolverRunReported) {
  struct Check {
    const char* checks;
    const char* variant;
    const char* stem;
  };
  for (const Check& c : {Check{"bracket/checks.json", "", "bracket/tet10/bracket_tet10"},
                         Check{"wheel/checks.json", "tet4", "wheel/tet4/wheel_tet4"},
                         Check{"wheel/checks.json", "mixed", "wheel/mixed/wheel_mixed"}}) {
    VOLPOST_SHARED_OR_SKIP(checksPath, c.checks);
    const auto expected = checksOf(checksPath, c.variant);
    for (const char* ext : {".frd", ".exo", ".vtu", ".vtk"}) {
      const std::string path = test::sharedFile(std::string(c.stem) + ext);
      SCOPED_TRACE(path);
      const auto model = meshioReaders().load(path);
      EXPECT_EQ(model->mesh().nodeCount(), expected["nodes"].get<std::size_t>());
      EXPECT_NEAR(maxOf(*model, "U.magnitude"), expected["U_max"].get<double>(), 1e-5 * expected["U_max"].get<double>());
      // von Mises from the stored components (6 significant digits) against ccx's own.
      EXPECT_NEAR(maxOf(*model, "S.mises"), expected["S_Mises_max"].get<double>(), 1e-4 * expected["S_Mises_max"].get<double>());
      if (expected.contains("T_min")) {
        const Field& t = *model->findField("T");
        const ValueRange r = rangeOf(t.values(0));
        EXPECT_EQ(r.min, expected["T_min"].get<double>());
        EXPECT_EQ(r.max, expected["T_max"].get<double>());
      }
    }
  }
}

TEST(SolverChecks, PostFlowFieldIsTheAnalyticOneAtProbedPoints) {
  // pressure = 0.5 (U^2 - u_x^2 - u_y^2) of the potential flow around the post (a = 1,
  // G = 2 pi 0.8): linear tets interpolate it to O(h^2).
  VOLPOST_SHARED_OR_SKIP(path, "post/fine/post_fine.exo");
  const auto model = meshioReaders().load(path);
  const TetMesh tets = tetrahedralize(model->mesh());
  const auto pressure = tets.nodeValues(model->mesh(), model->findField("pressure")->values(0));
  const PointLocator locator(tets);
  const double G = 2.0 * M_PI * 0.8;
  for (const auto& [r, theta, z] : {std::tuple{2.0, 0.3, 1.0}, std::tuple{5.0, 2.0, 2.0}, std::tuple{8.0, -1.2, 3.5}}) {
    const double ur = (1.0 - 1.0 / (r * r)) * std::cos(theta), ut = -(1.0 + 1.0 / (r * r)) * std::sin(theta) + G / (2.0 * M_PI * r);
    const double ux = ur * std::cos(theta) - ut * std::sin(theta), uy = ur * std::sin(theta) + ut * std::cos(theta);
    const double exact = 0.5 * (1.0 - ux * ux - uy * uy);
    const auto at = locator.locate(glm::dvec3(r * std::cos(theta), r * std::sin(theta), z));
    ASSERT_TRUE(at);
    EXPECT_NEAR(PointLocator::interpolateNodal(*at, pressure), exact, 0.02) << "r = " << r;
  }
}

// convert -> read: every real model of ../shared/data in every format comes back the same
// (nodes, cells by type, ids, every field with every step, its label, time and values).
TEST(VtuWriter, EveryRealModelRoundTrips) {
  const std::string root = volpost::test::sharedFile("bar");
  if (root.empty()) GTEST_SKIP() << "not run: ../shared/data is absent";
  const auto shared = std::filesystem::path(root).parent_path();
  std::size_t checked = 0;
  for (const char* folder : {"bar", "bracket", "post", "wheel"})
    for (const auto& entry : std::filesystem::recursive_directory_iterator(shared / folder)) {
      const std::string ext = entry.path().extension().string();
      if (!entry.is_regular_file() || (ext != ".vtu" && ext != ".vtk" && ext != ".msh" && ext != ".inp" && ext != ".frd" &&
                                       ext != ".exo" && ext != ".nf"))
        continue;
      if (entry.file_size() > (8u << 20)) continue;  // the fine post: the same readers, more time
      SCOPED_TRACE(entry.path().string());
      const auto model = meshioReaders().load(entry.path().string());
      const std::string out = ::testing::TempDir() + "/every_real_model.vtu";
      writeVtu(*model, out);
      const auto back = meshioReaders().load(out);
      EXPECT_EQ(back->mesh().nodes, model->mesh().nodes);
      EXPECT_EQ(back->mesh().countsByType(), model->mesh().countsByType());
      EXPECT_EQ(back->mesh().nodeIds, model->mesh().nodeIds);
      EXPECT_EQ(back->mesh().cellIds, model->mesh().cellIds);
      EXPECT_EQ(back->title, model->title);
      ASSERT_EQ(back->fields.size(), model->fields.size());
      for (const auto& f : model->fields) {
        const Field* g = back->findField(f->name());
        ASSERT_TRUE(g) << f->name();
        EXPECT_EQ(g->components(), f->components());
        EXPECT_EQ(g->location(), f->location());
        ASSERT_EQ(g->stepCount(), f->stepCount()) << f->name();
        for (std::size_t s = 0; s < f->stepCount(); ++s) {
          EXPECT_EQ(g->steps()[s].label, f->steps()[s].label);
          EXPECT_EQ(g->steps()[s].time, f->steps()[s].time);
          const auto& a = f->values(s);
          const auto& b = g->values(s);
          ASSERT_EQ(a.size(), b.size());
          std::size_t differ = 0;
          for (std::size_t i = 0; i < a.size(); ++i) differ += !(a[i] == b[i] || (std::isnan(a[i]) && std::isnan(b[i])));
          EXPECT_EQ(differ, 0u) << f->name() << " step " << s + 1;
        }
      }
      ++checked;
    }
  EXPECT_GT(checked, 30u);
}
