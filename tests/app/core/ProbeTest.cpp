// SPDX-License-Identifier: MIT
// Probing: every node of a model found at its own coordinates (midside nodes on curved
// faces too, and coordinates rounded as files store them), values interpolated by the
// element's shape functions, points really outside refused, ids as the file numbers them.
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

#include <volpost/core/CellShape.hpp>
#include "core/Probe.hpp"
#include "core/ScenePick.hpp"
#include "host/ElementRefinement.hpp"
#include "host/IsoSurfaceExtraction.hpp"
#include "host/SectionCut.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

using namespace volpost;
using namespace volpost::app;

namespace {

// A quarter of a thick-walled cylinder (radii 1 and 2, height 1) in hex20 elements whose
// midside nodes lie on the true arcs, with a nodal field f = x^2 + y z and an element
// field of the element's number; element ids start at 101, node ids at 1001.
std::shared_ptr<ModelSession> quarterRing(int around, int through) {
  auto model = std::make_shared<Model>();
  Mesh& mesh = model->mesh();
  // Nodes on a (2 around + 1) x (2 through + 1) x 3 lattice of (theta, r, z); the hex20
  // uses the lattice points it needs, the rest stay unused.
  const int nt = 2 * around + 1, nr = 2 * through + 1, nz = 3;
  const auto index = [&](int t, int r, int z) { return NodeIndex((z * nr + r) * nt + t); };
  for (int z = 0; z < nz; ++z)
    for (int r = 0; r < nr; ++r)
      for (int t = 0; t < nt; ++t) {
        const double theta = 0.5 * std::numbers::pi * t / (nt - 1), radius = 1.0 + double(r) / (nr - 1);
        mesh.nodes.push_back({radius * std::cos(theta), radius * std::sin(theta), 0.5 * z});
        mesh.nodeIds.push_back(1001 + std::int64_t(mesh.nodes.size()) - 1);
      }
  for (int j = 0; j < through; ++j)
    for (int i = 0; i < around; ++i) {
      const int t = 2 * i, r = 2 * j;
      // VTK hex20: corners (t, r) counter-clockwise seen from +z at z = 0 then z = 2, then
      // the midside nodes of edges 01 12 23 30 (bottom), 45 56 67 74 (top), 04 15 26 37.
      const NodeIndex c[20] = {index(t, r, 0),     index(t, r + 2, 0),     index(t + 2, r + 2, 0), index(t + 2, r, 0),
                               index(t, r, 2),     index(t, r + 2, 2),     index(t + 2, r + 2, 2), index(t + 2, r, 2),
                               index(t, r + 1, 0), index(t + 1, r + 2, 0), index(t + 2, r + 1, 0), index(t + 1, r, 0),
                               index(t, r + 1, 2), index(t + 1, r + 2, 2), index(t + 2, r + 1, 2), index(t + 1, r, 2),
                               index(t, r, 1),     index(t, r + 2, 1),     index(t + 2, r + 2, 1), index(t + 2, r, 1)};
      mesh.addCell(CellType::Hex20, c);
      mesh.cellIds.push_back(101 + std::int64_t(mesh.cellCount()) - 1);
    }
  std::vector<double> f, e;
  for (const auto& p : mesh.nodes) f.push_back(p.x * p.x + p.y * p.z);
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) e.push_back(double(c));
  model->fields.push_back(Field::fromValues("f", FieldLocation::Node, 1, {f}));
  model->fields.push_back(Field::fromValues("element", FieldLocation::Cell, 1, {e}));
  return ModelSession::fromModel(model);
}

double roundTo(double v, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*e", digits - 1, v);
  return std::strtod(text, nullptr);
}

}  // namespace

TEST(Probe, EveryNodeOfACurvedHex20MeshIsFoundWithItsOwnValue) {
  const auto ring = quarterRing(6, 2);
  ASSERT_GT(signedCellVolume(ring->model().mesh(), 0), 0.0) << "the test's hex20 must be positively oriented";
  const Mesh& mesh = ring->model().mesh();
  const std::vector<double>& f = ring->model().fields[0]->values(0);
  std::vector<bool> used(mesh.nodeCount(), false);
  for (NodeIndex n : mesh.connectivity()) used[n] = true;
  int probed = 0;
  for (std::size_t n = 0; n < mesh.nodeCount(); ++n) {
    if (!used[n]) continue;
    for (int digits : {17, 10, 6}) {  // full precision, and as .inp and .frd files write them
      const glm::dvec3 p(roundTo(mesh.nodes[n].x, digits), roundTo(mesh.nodes[n].y, digits), roundTo(mesh.nodes[n].z, digits));
      const ProbeResult r = probeAt(*ring, p, 0);
      ASSERT_TRUE(r.inside()) << "node " << mesh.nodeId(n) << " at " << digits << " digits";
      EXPECT_EQ(r.method, ProbeMethod::Isoparametric);
      EXPECT_NEAR(*r.value("f"), f[n], digits == 17 ? 1e-12 : 1e-4) << "node " << mesh.nodeId(n);
      if (digits == 17) EXPECT_EQ(r.nodeId, mesh.nodeId(n));
      ++probed;
    }
  }
  // Used lattice points: corners (all indices even) and edge midpoints (exactly one odd).
  EXPECT_EQ(probed, 3 * (7 * 3 * 2 + 6 * 3 * 2 + 7 * 2 * 2 + 7 * 3 * 1)) << "every used node, three ways";
}

TEST(Probe, NodesAndElementsByTheFilesIds) {
  const auto ring = quarterRing(6, 2);
  const Mesh& mesh = ring->model().mesh();
  const std::vector<double>& f = ring->model().fields[0]->values(0);
  // A node: exactly its own value, at its own position, in an element that uses it.
  const ProbeResult node = probeNode(*ring, 1001 + 32, 0);
  EXPECT_EQ(node.method, ProbeMethod::AtNode);
  EXPECT_EQ(node.point, mesh.nodes[32]);
  EXPECT_EQ(*node.value("f"), f[32]);
  EXPECT_NE(std::find(node.nodeIds.begin(), node.nodeIds.end(), 1001 + 32), node.nodeIds.end());
  EXPECT_EQ(*node.value("element"), double(node.cellId - 101));  // that element's result as stored
  // An element: its centre by its shape functions (on the true arcs of its curved faces),
  // node data interpolated there, its own result as stored, its 20 nodes.
  const ProbeResult element = probeElement(*ring, 101 + 4, 0);
  EXPECT_EQ(element.method, ProbeMethod::ElementCentre);
  EXPECT_EQ(element.cell, 4u);
  EXPECT_EQ(element.nodeIds.size(), 20u);
  EXPECT_EQ(*element.value("element"), 4.0);
  double expected = 0.0;
  const ShapeValues n = shapeFunctions(CellType::Hex20, referenceCentre(CellType::Hex20));
  const auto nodes = mesh.cellNodes(4);
  for (std::size_t k = 0; k < nodes.size(); ++k) expected += n[k] * f[nodes[k]];
  EXPECT_NEAR(*element.value("f"), expected, 1e-12);
  // The centre found by a click there gives the same element and values.
  const ProbeResult clicked = probeAt(*ring, element.point, 0);
  EXPECT_EQ(clicked.cellId, element.cellId);
  EXPECT_NEAR(*clicked.value("f"), expected, 1e-9);
  // Typed forms, and ids the file does not have.
  EXPECT_EQ(probeById(*ring, "node 1033", 0)->point, mesh.nodes[32]);
  EXPECT_EQ(probeById(*ring, "  Element 105", 0)->cell, 4u);
  EXPECT_EQ(probeById(*ring, "e 105", 0)->cell, 4u);
  EXPECT_FALSE(probeById(*ring, "1, 2, 3", 0));
  EXPECT_FALSE(probeById(*ring, "node 1033 x", 0));
  EXPECT_THROW(probeNode(*ring, 1000, 0), std::invalid_argument);
  EXPECT_THROW(probeElement(*ring, 1, 0), std::invalid_argument);
  EXPECT_THROW(probeById(*ring, "element -5", 0), std::invalid_argument);
}

TEST(Probe, PointsBetweenChordAndArcAreInsideAndInterpolatedByTheShapeFunctions) {
  const auto ring = quarterRing(6, 2);
  // On the outer surface r = 2, halfway between two corner nodes in angle: the linear
  // split's chord passes inside, the hex20's arc through the midside node is the surface.
  const double theta = 0.5 * std::numbers::pi * 1.0 / 12.0, z = 0.3;
  for (double r : {2.0, 1.9995}) {
    const glm::dvec3 p(r * std::cos(theta), r * std::sin(theta), z);
    const ProbeResult at = probeAt(*ring, p, 0);
    ASSERT_TRUE(at.inside()) << r;
    EXPECT_EQ(at.method, ProbeMethod::Isoparametric);
    // f = x^2 + y z is quadratic; the arc's parametrization is not, so it is close, not exact.
    EXPECT_NEAR(*at.value("f"), p.x * p.x + p.y * p.z, 2e-3) << r;
    EXPECT_EQ(at.cellId, 107);  // the outer layer's first element: theta in [0, 15] degrees, r in [1.5, 2]
  }
  // Beyond the arc by a ten-thousandth of the model: outside.
  const double size = ring->locator().modelSize();
  const double out = 2.0 + 1e-4 * size;
  EXPECT_FALSE(probeAt(*ring, glm::dvec3(out * std::cos(theta), out * std::sin(theta), z), 0).inside());
  EXPECT_FALSE(probeAt(*ring, glm::dvec3(0.5, 0.5, 0.5), 0).inside()) << "in the bore";
  EXPECT_FALSE(probeAt(*ring, glm::dvec3(1.5, 0.1, 1.0 + 1e-3), 0).inside()) << "above the top";
  EXPECT_FALSE(probeAt(*ring, glm::dvec3(NAN, 0.1, 0.5), 0).inside());
}

TEST(Probe, ReportsTheElementItsNodesAndElementDataAsStored) {
  const auto ring = quarterRing(6, 2);
  const double theta = 0.5 * std::numbers::pi * 5.5 / 6.0;  // in the sixth element around
  const ProbeResult r = probeAt(*ring, glm::dvec3(1.25 * std::cos(theta), 1.25 * std::sin(theta), 0.5), 0);
  ASSERT_TRUE(r.inside());
  EXPECT_EQ(r.cellId, 106);
  EXPECT_EQ(r.cellType, CellType::Hex20);
  ASSERT_EQ(r.nodeIds.size(), 20u);
  for (std::int64_t id : r.nodeIds) EXPECT_GE(id, 1001);
  EXPECT_EQ(*r.value("element"), 5.0) << "element data as stored";
  EXPECT_FALSE(r.nodeId) << "not at a node";
}

TEST(Probe, BarStressAndIdsFromAFileWithoutIds) {
  const auto bar = ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("bar/bar_tet4.vtu"));
  const ProbeResult r = probeAt(*bar, glm::dvec3(5.0, 0.5, 0.5), 0);
  ASSERT_TRUE(r.inside());
  EXPECT_NEAR(*r.value("S.xx"), 100.0, 0.05);
  EXPECT_EQ(r.cellId, std::int64_t(r.cell) + 1) << "a VTU without ids numbers elements from 1";
  EXPECT_EQ(r.cellType, CellType::Tet4);
  ASSERT_TRUE(r.value("S.mises"));
  EXPECT_NEAR(*r.value("S.mises"), 100.0, 0.5) << "derived from the interpolated tensor";
}

// The real quadratic models: every node found at the coordinates its own file stores
// (the .frd keeps six digits) with the value the file gives it.
TEST(Probe, EveryNodeOfTheRealQuadraticModelsIsFound) {
  for (const char* file : {"bracket/tet10/bracket_tet10.frd", "bracket/tet10/bracket_tet10.inp", "wheel/mixed/wheel_mixed.frd"}) {
    VOLPOST_SHARED_OR_SKIP(path, file);
    const auto session = ModelSession::load(volpost::test::meshioReaders(), path);
    const Mesh& mesh = session->model().mesh();
    std::vector<bool> used(mesh.nodeCount(), false);
    for (NodeIndex n : mesh.connectivity()) used[n] = true;
    const Field* u = session->model().findField("U");
    std::size_t missed = 0, probed = 0;
    double worst = 0.0;
    for (std::size_t n = 0; n < mesh.nodeCount(); ++n) {
      if (!used[n]) continue;
      const ProbeResult r = probeAt(*session, mesh.nodes[n], 0);
      ++probed;
      if (!r.inside()) {
        ++missed;
        continue;
      }
      if (u) worst = std::max(worst, std::abs(*r.value("U.x") - u->values(0)[3 * n]));
    }
    EXPECT_EQ(missed, 0u) << file << ": " << missed << " of " << probed << " nodes not found";
    EXPECT_EQ(worst, 0.0) << file << ": a node's probed U.x differs from its own";
  }
}

// A click in the view: the pixel's ray meets the model's surface where the picture shows it.
TEST(ScenePick, TheCentreOfAnAxisViewHitsTheNearFaceAndAMissIsNothing) {
  const auto bar = ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("bar/bar_tet4.vtu"));
  Camera camera;
  camera.setView(StandardView::PlusX);  // from +x: the loaded end face x = 10 is in front
  camera.fit(bar->model().mesh().bounds());
  const auto hit = pickSurface(*bar, pixelRay(camera, 50.0, 40.0, 100.0, 80.0));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.x, 10.0, 1e-9);
  EXPECT_NEAR(hit->point.y, 0.5, 1e-9);
  EXPECT_NEAR(hit->point.z, 0.5, 1e-9);
  const ProbeResult r = probeAt(*bar, hit->point, 0);
  ASSERT_TRUE(r.inside()) << "a picked surface point probes";
  EXPECT_EQ(r.cell, hit->cell) << "in the element whose face was hit";
  // The corner of the picture looks past the bar.
  EXPECT_FALSE(pickSurface(*bar, pixelRay(camera, 1.0, 1.0, 100.0, 80.0)));
  // Orthographic too, from below.
  camera.setView(StandardView::MinusZ);
  camera.setProjection(Camera::Projection::Orthographic);
  camera.fit(bar->model().mesh().bounds());
  const auto below = pickSurface(*bar, pixelRay(camera, 50.0, 40.0, 100.0, 80.0));
  ASSERT_TRUE(below);
  EXPECT_NEAR(below->point.z, 0.0, 1e-9);
  EXPECT_NEAR(below->point.x, 5.0, 1e-6);
}

// A regular grid is probed from its indices, without building its cells or tetrahedra: on a
// left-handed rotated grid the value is the trilinear interpolation of the stored samples
// (16-bit integers), the cell is the one holding the point, a grid point gives its own
// sample, cell data its cell's value, and a point past the grid is outside.
TEST(Probe, AGridIsProbedTrilinearlyWithoutBuildingItsCells) {
  auto model = std::make_shared<Model>();
  RegularGrid g;
  g.dims = {6, 5, 4};
  g.origin = {500.0, -20.0, 0.0};
  const double c = std::cos(0.3), s = std::sin(0.3);
  g.axes = {glm::dvec3(2 * c, 2 * s, 0), glm::dvec3(-1.5 * s, 1.5 * c, 0), glm::dvec3(0, 0, -0.5)};
  g.axisNames = {"inline", "crossline", "time (ms)"};
  g.firstLabel = {100, 7, 0};
  g.labelStep = {1, 1, 4};
  model->grid = g;
  SampleArray amplitude(SampleType::Int16, g.pointCount());
  std::vector<double> asDoubles(g.pointCount());
  for (std::size_t n = 0; n < g.pointCount(); ++n) {
    asDoubles[n] = double(int(n * 37 % 201) - 100);
    amplitude.set(n, asDoubles[n]);
  }
  model->fields.push_back(Field::fromSamples("amplitude", FieldLocation::Node, 1, std::move(amplitude)));
  std::vector<double> perCell(g.cellCount());
  for (std::size_t k = 0; k < perCell.size(); ++k) perCell[k] = double(k) * 0.5;
  model->fields.push_back(Field::fromValues("cell number", FieldLocation::Cell, 1, {perCell}));
  const auto session = ModelSession::fromModel(model);
  for (const glm::dvec3 index : {glm::dvec3(2.3, 1.7, 0.4), glm::dvec3(0.0, 0.0, 0.0), glm::dvec3(5.0, 4.0, 3.0),
                                 glm::dvec3(4.99, 0.01, 2.5)}) {
    const ProbeResult r = probeAt(*session, g.position(index.x, index.y, index.z), 0);
    ASSERT_TRUE(r.inside());
    EXPECT_NEAR(*r.value("amplitude"), trilinear(g, asDoubles.data(), index), 1e-9);
    const std::size_t ci = std::min<std::size_t>(std::size_t(index.x), 4), cj = std::min<std::size_t>(std::size_t(index.y), 3),
                      ck = std::min<std::size_t>(std::size_t(index.z), 2);
    EXPECT_EQ(r.cell, ci + 5 * (cj + 4 * ck));
    EXPECT_EQ(*r.value("cell number"), perCell[r.cell]);
    EXPECT_EQ(r.cellType, CellType::Hex8);
    ASSERT_EQ(r.gridPosition.size(), 3u);
    EXPECT_NEAR(r.gridPosition[0].second, 100 + index.x, 1e-9);
    EXPECT_NEAR(r.gridPosition[2].second, 4 * index.z, 1e-9);
  }
  const ProbeResult corner = probeAt(*session, g.position(3, 2, 1), 0);
  ASSERT_TRUE(corner.nodeId);
  EXPECT_EQ(*corner.value("amplitude"), asDoubles[g.pointIndex(3, 2, 1)]);
  EXPECT_FALSE(probeAt(*session, g.position(-0.1, 2, 1), 0).inside());
  EXPECT_FALSE(probeAt(*session, g.position(2, 2, 3.2), 0).inside());
  EXPECT_FALSE(model->meshBuilt()) << "the probe needed no cells";
  EXPECT_FALSE(model->fields[0]->isLoaded(0)) << "nor a double copy of the samples";
}

// The cells' own field is one field: the boundary surface, a section and an iso-surface
// drawn with it carry, at their points, what the probe (and plot over line, which probes)
// reads there. A quarter ring of curved hex20, f = x^2 + y z (quadratic in space, so the
// hex20's serendipity field differs from it only slightly, and from its split by more).
TEST(Probe, TheCellsOwnSurfacesCarryWhatTheProbeReads) {
  const auto ring = quarterRing(6, 2);
  const Mesh& mesh = ring->model().mesh();
  const std::vector<double>& f = ring->model().fields[0]->values(0);
  const optics::ElementField field(mesh, f, ring->tetrahedra(), glm::dvec3(0.0));
  const double range = field.valueScale();
  const auto probed = [&](const glm::dvec3& p) {
    const ProbeResult r = probeAt(*ring, p, 0);
    EXPECT_TRUE(r.inside()) << p.x << " " << p.y << " " << p.z;
    return r.value("f").value_or(NAN);
  };
  // The boundary in the cells' own shapes: its points are on the model and carry the probe's value.
  const RefinedSurface boundary = refineBoundary(field, ring->surface());
  const BoundarySurface& s = boundary.surface;
  ASSERT_GT(boundary.level, 1);
  int checked = 0;
  for (const auto v : s.mesh.vertices()) {
    if (v.idx() % 13 != 0) continue;
    const auto q = s.mesh.point(v);
    const glm::dvec3 p = s.origin + glm::dvec3(q[0], q[1], q[2]);
    EXPECT_NEAR(probed(p), boundary.values[s.mesh.property(s.nodeOfVertex, v)], 1e-5 * range);  // float positions
    ++checked;
  }
  EXPECT_GT(checked, 100);
  // A section's colors: linear between the refined pieces' points, so to the refinement's
  // tolerance (1/1000 of the range).
  const SectionTriangles section = cutCells(field, {}, ClipPlane{{0.0, 0.0, 0.3}, {0.0, 0.0, 1.0}});
  ASSERT_GT(section.positions.size(), 100u);
  for (std::size_t k = 0; k < section.positions.size(); k += 11)
    EXPECT_NEAR(probed(section.positions[k]), section.values[k], 1e-3 * range);
  // An iso-surface's vertices lie where the probe reads the iso-value, to the same tolerance.
  const double iso = 1.2;
  const ExtractedSurface shell = extractIsoSurface(field, iso);
  ASSERT_GT(shell.mesh.n_vertices(), 100u);
  for (const auto v : shell.mesh.vertices()) {
    if (v.idx() % 7 != 0) continue;
    const auto q = shell.mesh.point(v);
    EXPECT_NEAR(probed(shell.origin + glm::dvec3(q[0], q[1], q[2])), iso, 1e-3 * range);
  }
}
