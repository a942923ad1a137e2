// SPDX-License-Identifier: MIT
// The CPU ray caster drawing the cells' own field (trilinear hex8, quadratic hex20 and
// tet10) against the reference with the same field, which is checked against closed forms
// in tests/app/host/ElementReferenceTest.cpp. The split's field is drawn too, to show that
// the bounds could not be met by it.
#include "VolumeImageFixture.hpp"

#include "CpuRayCaster.hpp"
#include "support/HexLattice.hpp"
#include "support/ReferenceCells.hpp"

#include <volpost/core/CellShape.hpp>
#include <volpost/core/Tetrahedralize.hpp>

#include <array>
#include <functional>
#include <map>
#include <memory>

using namespace volpost;
using namespace volpost::test;

namespace {

using ClosedForm = std::function<double(const glm::dvec3&)>;

// [0,1]^3 cut into n^3 cells of `type` (hex8 or hex20), nodes shared, straight edges.
Mesh boxOf(CellType type, int n) {
  return hexLattice(type, n, [n](const glm::dvec3& g) { return g / double(n); });
}

std::vector<double> sampled(const Mesh& mesh, const ClosedForm& f) {
  std::vector<double> v;
  for (const glm::dvec3& p : mesh.nodes) v.push_back(f(p));
  return v;
}

TransferFunction peak(double at, double width) {
  return TransferFunction({{at - 3.0 * width, {0.1, 0.2, 0.9}, 0.2},
                           {at - width, {0.9, 0.1, 0.1}, 0.4},
                           {at, {1.0, 0.9, 0.2}, 14.0},
                           {at + width, {0.2, 0.8, 0.3}, 0.4},
                           {at + 3.0 * width, {1.0, 1.0, 1.0}, 0.2}});
}

// One model drawn three ways: the CPU ray caster with the element field, the reference with
// it, the reference with the split's field.
struct ThreeImages {
  ImageError cpu;    ///< CPU (element) against the reference (element)
  ImageError split;  ///< reference (split) against the reference (element)
  double alpha = 0;  ///< the largest opacity of the reference (element): something shows
};

ThreeImages draw(const Mesh& mesh, const std::vector<double>& values, const TransferFunction& tf, const Camera& camera,
                 int size, std::vector<optics::IsoSurface> iso = {}, std::vector<ClipPlane> planes = {},
                 double tolerance = 0.0) {
  const TetMesh split = tetrahedralize(mesh);
  const std::vector<double> tetValues = split.nodeValues(mesh, values);
  const volume::TetWalkMesh walk(split.mesh, FieldLocation::Node, tetValues);
  auto element = std::make_shared<volume::CpuElementField>();
  element->field = std::make_shared<const optics::ElementField>(mesh, values, split, walk.origin() + glm::dvec3(0.25));
  for (std::size_t t = 0; t < walk.tetCount(); ++t) element->cellOfTet.push_back(split.sourceCell(walk.meshTet(t)));
  volume::CpuRaySettings settings;
  settings.terminationTransmittance = 0.0;
  settings.isoSurfaces = iso;
  settings.clipPlanes = planes;
  settings.element = element;
  settings.elementTolerance = tolerance;
  const volume::CpuImage cpu = volume::renderCpu(walk, tf, camera, size, size, settings);

  const optics::TetVolume volume(split.mesh, FieldLocation::Node, tetValues);
  const optics::ElementField field(mesh, values, split, volume.origin());
  optics::RaySettings ref;
  ref.isoSurfaces = iso;
  ref.clipPlanes = planes;
  const optics::ReferenceImage linear = optics::renderReference(volume, tf, camera, size, size, ref);
  ref.elementField = &field;
  const optics::ReferenceImage exact = optics::renderReference(volume, tf, camera, size, size, ref);
  std::vector<float> linearRgba;
  for (const glm::dvec4& p : linear.pixels)
    for (int k = 0; k < 4; ++k) linearRgba.push_back(float(p[k]));
  ThreeImages out{RayCast::compare(cpu.rgba, exact), RayCast::compare(linearRgba, exact), 0.0};
  for (const glm::dvec4& p : exact.pixels) out.alpha = std::max(out.alpha, p.a);
  return out;
}

}  // namespace

TEST(CpuElementField, Hex8TrilinearFieldAsTheReferenceDrawsIt) {
  const Mesh mesh = boxOf(CellType::Hex8, 3);
  const auto values = sampled(mesh, [](const glm::dvec3& x) { return x.x * x.y * x.z; });
  const ThreeImages d = draw(mesh, values, peak(0.2, 0.04), isoCamera(mesh), 40);
  EXPECT_GT(d.alpha, 0.2);
  EXPECT_LE(d.cpu.max, 2e-4) << "float walk, double fit";
  EXPECT_GT(d.split.max, 1e-2) << "the split's field is another picture";
}

TEST(CpuElementField, Hex20QuadraticFieldWithIsoSurfaceAndClipPlane) {
  const Mesh mesh = boxOf(CellType::Hex20, 2);
  const auto values = sampled(mesh, [](const glm::dvec3& x) { return x.x * x.x + x.y * x.z - 0.5 * x.z * x.z; });
  const std::vector<optics::IsoSurface> iso{{0.45, {0.9, 0.9, 0.2}, 0.6}};
  const std::vector<ClipPlane> planes{{glm::dvec3(0.6, 0.5, 0.5), glm::dvec3(-1.0, 0.2, 0.0)}};
  const ThreeImages d = draw(mesh, values, peak(0.3, 0.05), isoCamera(mesh), 40, iso, planes);
  EXPECT_GT(d.alpha, 0.2);
  EXPECT_LE(d.cpu.max, 5e-4) << "iso-surface positions from float entry points";
  EXPECT_GT(d.split.max, 1e-2);
}

// A tet10 whose quadratic field peaks inside, above every node value (1 - |x - centroid|^2:
// 0.8125 at the nodes, 1 at the centroid): a transfer function that sees only that peak must
// not skip the cell as transparent by its node values.
TEST(CpuElementField, ATet10SeenOnlyWhereItsFieldRisesAboveItsNodesIsNotSkipped) {
  const Mesh mesh = volpost::test::referenceCell(CellType::Tet10).first;  // the unit tet, straight edges
  const auto values = sampled(mesh, [](const glm::dvec3& x) {
    const glm::dvec3 d = x - glm::dvec3(0.25);
    return 1.0 - glm::dot(d, d);
  });
  const TransferFunction above({{0.85, {0, 0, 0}, 0.0}, {0.93, {1, 0.5, 0}, 30.0}, {1.0, {1, 1, 0}, 30.0}});
  const ThreeImages d = draw(mesh, values, above, isoCamera(mesh), 40);
  EXPECT_GT(d.alpha, 0.05) << "the element field reaches the peak";
  EXPECT_LE(d.cpu.max, 2e-4);
  EXPECT_GT(d.split.max, 0.05) << "the split's field stays below it";
}

// Within a tolerance the CPU ray caster lights each stretch by chords where the transfer
// function allows: each pixel stays within it of the exact picture (plus the float walk's
// own 2e-4), on the trilinear hex8 and the quadratic hex20 with their sharp peaks.
TEST(CpuElementField, WithinItsToleranceEveryPixelStaysThatCloseToTheExactPicture) {
  const Mesh hex8 = boxOf(CellType::Hex8, 3), hex20 = boxOf(CellType::Hex20, 2);
  const auto trilinear = sampled(hex8, [](const glm::dvec3& x) { return x.x * x.y * x.z; });
  const auto quadratic = sampled(hex20, [](const glm::dvec3& x) { return x.x * x.x + x.y * x.z - 0.5 * x.z * x.z; });
  for (double tolerance : {1e-2, 1e-3}) {
    const ThreeImages a = draw(hex8, trilinear, peak(0.2, 0.04), isoCamera(hex8), 40, {}, {}, tolerance);
    EXPECT_LE(a.cpu.max, tolerance + 2e-4) << tolerance;
    EXPECT_LE(a.cpu.rmse, 1e-4) << tolerance;
    const ThreeImages b = draw(hex20, quadratic, peak(0.3, 0.05), isoCamera(hex20), 40, {}, {}, tolerance);
    EXPECT_LE(b.cpu.max, tolerance + 2e-4) << tolerance;
    EXPECT_LE(b.cpu.rmse, 1e-4) << tolerance;
  }
}
