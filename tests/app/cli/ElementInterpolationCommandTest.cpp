// SPDX-License-Identifier: MIT
// `volpost render --interpolation element`: the cells' own field drawn by the reference and
// the CPU ray caster, by renderers that draw the tetrahedra only on refined pieces, kept in
// the state file.
#include "FloatPictures.hpp"
#include "ProcessRunner.hpp"
#include "support/TestSupport.hpp"

#include <QImage>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <string>

using volpost::test::dataFile;
using volpost::test::runVolpost;

namespace {

// A legacy VTK file of n^3 hex8 cells on [0,1]^3 with the point field T = f(x, y, z);
// `moveFirstCorner` pulls cell 0's corner at the origin through the cell (the map folds);
// `liftFirstCorner` raises it out of its faces' planes (the cell's faces warp).
std::string writeHexBlock(const std::string& path, int n, const std::function<double(double, double, double)>& f,
                          bool moveFirstCorner = false, double liftFirstCorner = 0.0) {
  const int m = n + 1;
  std::ostringstream points, values, cells;
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const double x = double(i) / n, y = double(j) / n, z = double(k) / n;
        const bool moved = moveFirstCorner && i == 0 && j == 0 && k == 0;
        const double lift = i == 0 && j == 0 && k == 0 ? liftFirstCorner : 0.0;
        points << (moved ? 0.9 : x) << ' ' << (moved ? 0.4 : y) << ' ' << (moved ? 0.45 : z + lift) << '\n';
        values << f(x, y, z) << '\n';
      }
  const auto id = [m](int i, int j, int k) { return (k * m + j) * m + i; };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        cells << "8 " << id(i, j, k) << ' ' << id(i + 1, j, k) << ' ' << id(i + 1, j + 1, k) << ' ' << id(i, j + 1, k)
              << ' ' << id(i, j, k + 1) << ' ' << id(i + 1, j, k + 1) << ' ' << id(i + 1, j + 1, k + 1) << ' '
              << id(i, j + 1, k + 1) << '\n';
  const int count = n * n * n;
  std::ofstream out(path);
  out << "# vtk DataFile Version 4.2\nhex8 block\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS " << m * m * m << " double\n"
      << points.str() << "CELLS " << count << ' ' << 9 * count << '\n'
      << cells.str() << "CELL_TYPES " << count << '\n';
  for (int c = 0; c < count; ++c) out << "12\n";
  out << "POINT_DATA " << m * m * m << "\nSCALARS T double 1\nLOOKUP_TABLE default\n" << values.str();
  return path;
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

// A hex8's trilinear field (x y z is its own trilinear interpolant) differs from the linear
// field of the tetrahedra the hex is split into; the reference draws either on request.
TEST(ElementInterpolationCommand, TheReferenceDrawsTheHexahedraTrilinearFieldNotTheirSplit) {
  const std::string dir = ::testing::TempDir();
  const std::string model =
      writeHexBlock(dir + "/hex_xyz.vtk", 2, [](double x, double y, double z) { return x * y * z; });
  const std::string common = "render " + model +
                             " --field T --size 48x40 --eye 2.2,-1.4,1.9 --target 0.5,0.5,0.5 "
                             "--up 0,0,1 --renderer reference -o " +
                             dir + "/hex.png";
  const std::string element = dir + "/hex_element.npy", split = dir + "/hex_split.npy";
  const auto a = runVolpost(common + " --interpolation element --float " + element);
  ASSERT_EQ(a.exitCode, 0) << a.output;
  EXPECT_EQ(a.output.find("note:"), std::string::npos) << "no cell is folded: " << a.output;
  ASSERT_EQ(runVolpost(common + " --interpolation tetrahedra --float " + split).exitCode, 0);
  const FloatPicturesApart apart = compareFloatPictures(element, split, 48u * 40u * 4u);
  EXPECT_GT(apart.alpha, 0.05f) << "the volume shows";
  EXPECT_GT(apart.worst, 2e-3f) << "the trilinear field is not the split's piecewise linear one";
  // The default is the split's field.
  const std::string plain = dir + "/hex_default.npy";
  ASSERT_EQ(runVolpost(common + " --float " + plain).exitCode, 0);
  EXPECT_EQ(compareFloatPictures(plain, split, 48u * 40u * 4u).worst, 0.0f);
}

// A linear field is reproduced exactly by every element (hex20, wedge15, tet10 here): both
// interpolations draw the same picture, up to the reference's fitting tolerance.
TEST(ElementInterpolationCommand, QuadraticCellsDrawALinearFieldAsTheirSplitDoes) {
  const std::string dir = ::testing::TempDir(), model = dataFile("formats/golden.frd");
  const std::string common =
      "render " + model + " --field T --size 40x32 --renderer reference -o " + dir + "/golden.png";
  const std::string element = dir + "/golden_element.npy", split = dir + "/golden_split.npy";
  const auto a = runVolpost(common + " --interpolation element --float " + element);
  ASSERT_EQ(a.exitCode, 0) << a.output;
  ASSERT_EQ(runVolpost(common + " --float " + split).exitCode, 0);
  const FloatPicturesApart apart = compareFloatPictures(element, split, 40u * 32u * 4u);
  EXPECT_GT(apart.alpha, 0.05f) << "the volume shows";
  EXPECT_LT(apart.worst, 1e-5f);
}

TEST(ElementInterpolationCommand, AFoldedCellIsDrawnLinearAndNamed) {
  const std::string dir = ::testing::TempDir();
  const std::string model = writeHexBlock(
      dir + "/hex_folded.vtk", 2, [](double x, double y, double z) { return x + y + z; }, true);
  const auto r =
      runVolpost("render " + model + " --field T --size 32x24 --renderer reference --interpolation element -o " + dir +
                 "/folded.png");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("note: 1 cell folded, inverted or collapsed (no inverse map): drawn linear on their "
                          "tetrahedra; cell id 1"),
            std::string::npos)
      << r.output;
}

// A cell whose faces warp away from its tetrahedra's flat faces: the reference follows its
// own faces and says so; the CPU ray caster says it draws the field within the flat faces.
TEST(ElementInterpolationCommand, EachRendererSaysHowItDrawsCellsThatBendFromTheirSplit) {
  const std::string dir = ::testing::TempDir();
  const std::string model = writeHexBlock(
      dir + "/hex_warped.vtk", 2, [](double x, double y, double z) { return x + y * z; }, false, 0.1);
  const std::string common = "render " + model + " --field T --size 32x24 --interpolation element -o " + dir + "/w.png";
  const auto reference = runVolpost(common + " --renderer reference");
  ASSERT_EQ(reference.exitCode, 0) << reference.output;
  EXPECT_NE(reference.output.find("note: 1 cell bends away from the flat faces of its tetrahedra (by up to 12% of a "
                                  "cell): drawn to its own curved faces"),
            std::string::npos)
      << reference.output;
  const auto cpu = runVolpost(common + " --renderer cpu");
  ASSERT_EQ(cpu.exitCode, 0) << cpu.output;
  EXPECT_NE(cpu.output.find("note: 1 cell bends away from the flat faces of its tetrahedra (by up to 12% of a cell): "
                            "this renderer draws the field within the tetrahedra's flat faces; the reference renderer "
                            "and the GPU renderers follow the curved faces"),
            std::string::npos)
      << cpu.output;
  const auto straight = runVolpost(
      "render " + writeHexBlock(dir + "/hex_straight.vtk", 2, [](double x, double y, double z) { return x + y * z; }) +
      " --field T --size 32x24 --interpolation element --renderer reference -o " + dir + "/s.png");
  ASSERT_EQ(straight.exitCode, 0) << straight.output;
  EXPECT_EQ(straight.output.find("bends away"), std::string::npos) << straight.output;
}

// Renderers that draw tetrahedra only (the GPU ray caster, cell projection) are given the
// split cut where the transfer function shows the cells' field: their picture of a hex8
// block carrying x y z comes within the tolerance of the exact one at every pixel, where the
// split's is off by a tenth; they say how finely they drew it, and refuse an exact
// tolerance they cannot reach.
TEST(ElementInterpolationCommand, RenderersOfTetrahedraDrawItOnRefinedPieces) {
  const std::string dir = ::testing::TempDir();
  const std::string model =
      writeHexBlock(dir + "/hex_refined.vtk", 3, [](double x, double y, double z) { return x * y * z; });
  const std::string common =
      "render " + model + " --field T --size 64x56 --interpolation element -o " + dir + "/refined.png";
  const std::string reference = dir + "/refined_reference.npy", split = dir + "/refined_split.npy";
  ASSERT_EQ(runVolpost(common + " --renderer reference --float " + reference).exitCode, 0);
  ASSERT_EQ(runVolpost(common + " --renderer raycast --interpolation tetrahedra --float " + split).exitCode, 0);
  const FloatPicturesApart splitApart = compareFloatPictures(split, reference, 64u * 56u * 4u);
  EXPECT_GT(splitApart.alpha, 0.05f) << "the volume shows";
  EXPECT_GT(splitApart.worst, 0.05f) << "the split's field is another picture";
  for (const std::string renderer : {"raycast", "vicp"})
    for (const double tolerance : {0.01, 0.002}) {
      SCOPED_TRACE(renderer + " " + std::to_string(tolerance));
      const std::string own = dir + "/refined_" + renderer + ".npy";
      const auto r = runVolpost(common + " --renderer " + renderer + " --element-tolerance " +
                                std::to_string(tolerance) + " --float " + own);
      ASSERT_EQ(r.exitCode, 0) << r.output;
      EXPECT_NE(r.output.find("tetrahedra (the split's 162, halved up to "), std::string::npos) << r.output;
      EXPECT_NE(r.output.find("times where the transfer function shows the field), a pixel's channel within 0.00"),
                std::string::npos)
          << r.output;
      const FloatPicturesApart apart = compareFloatPictures(own, reference, 64u * 56u * 4u);
      // Measured: 0.0053 and 0.0013 (raycast), the same for vicp.
      EXPECT_LE(apart.worst, float(tolerance)) << "within the tolerance at every pixel";
    }
  const auto exact =
      runVolpost(common + " --renderer raycast --element-tolerance 0 --float " + dir + "/refined_exact.npy");
  EXPECT_EQ(exact.exitCode, 2);
  EXPECT_NE(exact.output.find("--element-tolerance 0 (exact): raycast draws the cells' own field on tetrahedra "
                              "refined to a tolerance above 0; the exact field is drawn by cpu, reference"),
            std::string::npos)
      << exact.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/refined_exact.npy"));
  // A mesh of tet4 cells is its own split: drawn exactly, so 0 is taken.
  const auto tets = runVolpost("render " + dataFile("bar/bar_tet4.vtu") +
                               " --field S11 --size 32x24 --renderer raycast --interpolation element "
                               "--element-tolerance 0 -o " +
                               dir + "/refined_tet4.png");
  EXPECT_EQ(tets.exitCode, 0) << tets.output;
  EXPECT_EQ(tets.output.find("note:"), std::string::npos) << "nothing refined: " << tets.output;
}

TEST(ElementInterpolationCommand, SurfacesTakeItAndTheStateKeepsIt) {
  const std::string dir = ::testing::TempDir();
  const std::string model =
      writeHexBlock(dir + "/hex_state.vtk", 2, [](double x, double y, double z) { return x * y * z; });
  const std::string png = dir + "/state.png";
  const auto bad =
      runVolpost("render " + model + " --field T --renderer reference --interpolation quadratic -o " + png);
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.output.find("--interpolation quadratic is not one of: element, tetrahedra"), std::string::npos)
      << bad.output;
  // A surface picture takes it: the hex8 faces colored by their bilinear field, not by the
  // two triangles each face is otherwise drawn as.
  const std::string ownSurface = dir + "/own_surface.png", splitSurface = dir + "/split_surface.png";
  const std::string picture = "render " + model + " --field T --size 200x150 --no-edges --no-legend --no-triad --flat ";
  const auto surface = runVolpost(picture + "--interpolation element -o " + ownSurface);
  ASSERT_EQ(surface.exitCode, 0) << surface.output;
  ASSERT_EQ(runVolpost(picture + "-o " + splitSurface).exitCode, 0);
  EXPECT_NE(QImage(QString::fromStdString(ownSurface)), QImage(QString::fromStdString(splitSurface)));
  EXPECT_FALSE(QImage(QString::fromStdString(ownSurface)).isNull());
  // A regular grid's surface picture has nothing it changes: refused, no picture written.
  const std::string gridPicture = dir + "/grid_surface.png";
  const auto grid = runVolpost("render " + std::string(VOLPOST_TEST_DATA) +
                               "/formats/image_ascii.vti --interpolation element -o " + gridPicture);
  EXPECT_EQ(grid.exitCode, 2) << grid.output;
  EXPECT_NE(grid.output.find("this model is a regular grid"), std::string::npos) << grid.output;
  EXPECT_FALSE(std::filesystem::exists(gridPicture));
  // Nor does the element tolerance, where a section makes the interpolation count.
  const auto gridTolerance = runVolpost("render " + std::string(VOLPOST_TEST_DATA) +
                                        "/formats/image_ascii.vti --interpolation element --clip 0.5,0.5,0.5,1,0,0 "
                                        "--element-tolerance 0.05 -o " +
                                        gridPicture);
  EXPECT_EQ(gridTolerance.exitCode, 2) << gridTolerance.output;
  EXPECT_NE(gridTolerance.output.find("draws its cells as they are"), std::string::npos) << gridTolerance.output;
  EXPECT_FALSE(std::filesystem::exists(gridPicture));

  const std::string state = dir + "/element.json", first = dir + "/state_first.npy", again = dir + "/state_again.npy";
  const auto saved = runVolpost("render " + model +
                                " --field T --size 32x24 --renderer reference --interpolation element "
                                "-o " +
                                png + " --float " + first + " --save-state " + state);
  ASSERT_EQ(saved.exitCode, 0) << saved.output;
  EXPECT_NE(readText(state).find("\"interpolation\": \"element\""), std::string::npos) << readText(state);
  ASSERT_EQ(runVolpost("render --state " + state + " --size 32x24 -o " + png + " --float " + again).exitCode, 0);
  EXPECT_EQ(compareFloatPictures(first, again, 32u * 24u * 4u).worst, 0.0f);
  const std::string onGpu = dir + "/state_vicp.npy";
  const auto stateOnGpu =
      runVolpost("render --state " + state + " --size 32x24 --renderer vicp -o " + png + " --float " + onGpu);
  ASSERT_EQ(stateOnGpu.exitCode, 0) << stateOnGpu.output;
  EXPECT_NE(stateOnGpu.output.find("the cells' own field drawn on"), std::string::npos) << stateOnGpu.output;
  EXPECT_LE(compareFloatPictures(first, onGpu, 32u * 24u * 4u).worst, 5e-3f);
}

// The CPU ray caster draws the cells' own field as the reference does, up to its float walk
// (with no tolerance: to rounding); a folded cell is named by it too.
TEST(ElementInterpolationCommand, TheCpuRayCasterDrawsItAsTheReferenceDoes) {
  const std::string dir = ::testing::TempDir();
  const std::string model =
      writeHexBlock(dir + "/hex_cpu.vtk", 3, [](double x, double y, double z) { return x * y * z; });
  const std::string common =
      "render " + model + " --field T --size 48x40 --interpolation element -o " + dir + "/cpu.png";
  const std::string cpu = dir + "/hex_cpu.npy", reference = dir + "/hex_cpu_reference.npy",
                    split = dir + "/hex_cpu_split.npy";
  const auto a = runVolpost(common + " --renderer cpu --termination 0 --element-tolerance 0 --float " + cpu);
  ASSERT_EQ(a.exitCode, 0) << a.output;
  ASSERT_EQ(runVolpost(common + " --renderer reference --float " + reference).exitCode, 0);
  ASSERT_EQ(runVolpost(common + " --renderer cpu --termination 0 --interpolation tetrahedra --float " + split).exitCode,
            0);
  const FloatPicturesApart apart = compareFloatPictures(cpu, reference, 48u * 40u * 4u);
  EXPECT_GT(apart.alpha, 0.05f) << "the volume shows";
  EXPECT_LE(apart.worst, 2e-4f);
  EXPECT_GT(compareFloatPictures(split, reference, 48u * 40u * 4u).worst, 2e-3f);
  // A clip box: the CPU renderer holds only the tetrahedra it can show, each still named by its cell.
  const std::string boxed = " --clip-box 0.1,0.8,0.05,0.9,0.2,1 --float ";
  ASSERT_EQ(runVolpost(common + " --renderer cpu --termination 0 --element-tolerance 0" + boxed + cpu).exitCode, 0);
  ASSERT_EQ(runVolpost(common + " --renderer reference" + boxed + reference).exitCode, 0);
  const FloatPicturesApart clipped = compareFloatPictures(cpu, reference, 48u * 40u * 4u);
  EXPECT_GT(clipped.alpha, 0.05f);
  EXPECT_LE(clipped.worst, 2e-4f);

  const std::string folded = writeHexBlock(
      dir + "/hex_cpu_folded.vtk", 2, [](double x, double y, double z) { return x + y + z; }, true);
  const auto f = runVolpost("render " + folded + " --field T --size 32x24 --renderer cpu --interpolation element -o " +
                            dir + "/cpu_folded.png");
  ASSERT_EQ(f.exitCode, 0) << f.output;
  EXPECT_NE(f.output.find("note: 1 cell folded, inverted or collapsed"), std::string::npos) << f.output;
}

// The CPU ray caster within --element-tolerance of the reference's exact picture (early
// termination off: its own bound would add to it); the tolerance kept in the state file;
// values it cannot honour, renderers that draw exactly and a split field refuse it.
TEST(ElementInterpolationCommand, TheCpuRayCasterKeepsItsToleranceAndTheStateKeepsIt) {
  const std::string dir = ::testing::TempDir();
  const std::string model =
      writeHexBlock(dir + "/hex_tolerance.vtk", 2, [](double x, double y, double z) { return x * y * z; });
  const std::string png = dir + "/tolerance.png";
  const std::string common = "render " + model +
                             " --field T --size 40x32 --eye 2.2,-1.4,1.9 --target 0.5,0.5,0.5 --up 0,0,1 "
                             "--interpolation element -o " +
                             png;
  const std::string exact = dir + "/tolerance_exact.npy", cpu = dir + "/tolerance_cpu.npy";
  ASSERT_EQ(runVolpost(common + " --renderer reference --float " + exact).exitCode, 0);
  const std::string state = dir + "/tolerance.json";
  const auto r = runVolpost(common + " --renderer cpu --termination 0 --element-tolerance 0.002 --float " + cpu +
                            " --save-state " + state);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const FloatPicturesApart apart = compareFloatPictures(exact, cpu, 40u * 32u * 4u);
  EXPECT_GT(apart.alpha, 0.05f) << "the volume shows";
  EXPECT_LE(apart.worst, 0.002f + 2e-4f) << "the tolerance and the float walk's own error";
  EXPECT_NE(readText(state).find("\"elementTolerance\": 0.002"), std::string::npos) << readText(state);

  const auto big = runVolpost(common + " --renderer cpu --element-tolerance 0.5");
  EXPECT_EQ(big.exitCode, 2);
  EXPECT_NE(big.output.find("must be 0 (exact) or lie in [1e-05, 0.1]; not 0.5"), std::string::npos) << big.output;
  const auto word = runVolpost(common + " --renderer cpu --element-tolerance fine");
  EXPECT_EQ(word.exitCode, 2);
  EXPECT_NE(word.output.find("--element-tolerance fine is not a number"), std::string::npos) << word.output;
  const auto reference = runVolpost(common + " --renderer reference --element-tolerance 0.01");
  EXPECT_EQ(reference.exitCode, 2);
  EXPECT_NE(reference.output.find("--element-tolerance is not used by reference"), std::string::npos)
      << reference.output;
  const auto split = runVolpost("render " + model + " --field T --renderer cpu --element-tolerance 0.01 -o " + png);
  EXPECT_EQ(split.exitCode, 2);
  EXPECT_NE(split.output.find("add --interpolation element"), std::string::npos) << split.output;
  const auto surface = runVolpost("render " + model + " --field T --element-tolerance 0.01 -o " + png);
  EXPECT_EQ(surface.exitCode, 2) << surface.output;
  // A surface picture with the cells' own field takes it too: its boundary follows the field
  // more coarsely with a larger one.
  const std::string fine = dir + "/tolerance_fine.png", coarse = dir + "/tolerance_coarse.png";
  const std::string surfacePicture = "render " + model + " --field T --size 80x64 --interpolation element -o ";
  ASSERT_EQ(runVolpost(surfacePicture + fine).exitCode, 0);
  ASSERT_EQ(runVolpost(surfacePicture + coarse + " --element-tolerance 0.1").exitCode, 0);
  EXPECT_NE(readText(fine), readText(coarse)) << "the tolerance is honoured, not ignored";
}
