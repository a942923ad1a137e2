// SPDX-License-Identifier: MIT
// Sections and iso-surfaces of the cells' own field and shape from the command line: a
// quarter cylinder of hex20 cells whose midside nodes sit on the arcs, cut by a plane and
// drawn from above. The section of the cells' own (curved) shapes is the round quarter
// annulus; the split's is bounded by chords across each cell. `volpost surface
// --interpolation element` writes the level set of the cells' own field.
#include "ProcessRunner.hpp"

#include <QImage>
#include <QRect>

#include <glm/vec3.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

using volpost::test::runVolpost;

namespace {

// VTK's quadratic hexahedron: the natural coordinates of its 20 nodes, in its order.
constexpr int kHex20[20][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1},  {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1},
                               {-1, 1, 1},   {0, -1, -1}, {1, 0, -1},  {0, 1, -1},  {-1, 0, -1}, {0, -1, 1}, {1, 0, 1},
                               {0, 1, 1},    {-1, 0, 1},  {-1, -1, 0}, {1, -1, 0},  {1, 1, 0},   {-1, 1, 0}};

// r in [1, 2], theta in [0, 90 degrees], z in [0, 1], n cells each way; T = z (x + 2 y).
std::string writeQuarterCylinder(const std::string& path, int n) {
  std::map<std::array<int, 3>, int> index;  // by position in half-cell steps
  std::ostringstream points, values, cells;
  int pointCount = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        cells << 20;
        for (const auto& xi : kHex20) {
          const std::array<int, 3> g{2 * i + xi[0] + 1, 2 * j + xi[1] + 1, 2 * k + xi[2] + 1};
          const auto [it, fresh] = index.emplace(g, pointCount);
          if (fresh) {
            const double r = 1.0 + g[0] / (2.0 * n), theta = std::numbers::pi / 2.0 * g[1] / (2.0 * n);
            const double x = r * std::cos(theta), y = r * std::sin(theta), z = g[2] / (2.0 * n);
            points << x << ' ' << y << ' ' << z << '\n';
            values << z * (x + 2.0 * y) << '\n';
            ++pointCount;
          }
          cells << ' ' << it->second;
        }
        cells << '\n';
      }
  const int count = n * n * n;
  std::ofstream out(path);
  out.precision(17);
  out << "# vtk DataFile Version 4.2\nquarter cylinder\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS " << pointCount
      << " double\n"
      << points.str() << "CELLS " << count << ' ' << 21 * count << '\n'
      << cells.str() << "CELL_TYPES " << count << '\n';
  for (int c = 0; c < count; ++c) out << "25\n";
  out << "POINT_DATA " << pointCount << "\nSCALARS T double 1\nLOOKUP_TABLE default\n" << values.str();
  return path;
}

bool covered(const QImage& image, int x, int y) {
  const QRgb background = image.pixel(0, 0), p = image.pixel(x, y);
  return std::abs(qRed(p) - qRed(background)) + std::abs(qGreen(p) - qGreen(background)) +
             std::abs(qBlue(p) - qBlue(background)) >
         12;
}

// Pixels drawn inside the hole of the quarter annulus (radius below `radius`), the picture
// framed by `frame` (the pixel box the annulus [0, 2] x [0, 2] covers).
long drawnInsideRadius(const QImage& image, const QRect& frame, double radius) {
  long drawn = 0;
  for (int y = frame.top(); y <= frame.bottom(); ++y)
    for (int x = frame.left(); x <= frame.right(); ++x) {
      const double mx = 2.0 * (x + 0.5 - frame.left()) / frame.width();
      const double my = 2.0 * (frame.bottom() + 0.5 - y) / frame.height();
      drawn += std::hypot(mx, my) < radius && covered(image, x, y);
    }
  return drawn;
}

QRect coveredBox(const QImage& image) {
  QRect box;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (covered(image, x, y)) box |= QRect(x, y, 1, 1);
  return box;
}

}  // namespace

TEST(ElementSurfacesCommand, TheSectionOfCurvedCellsIsRoundWithTheirOwnShapes) {
  const std::string dir = ::testing::TempDir();
  const std::string model = writeQuarterCylinder(dir + "/quarter.vtk", 3);
  // From above, parallel projection, the part below z = 0.4 kept: only the section shows.
  const std::string common = "render " + model +
                             " --field T --size 400x400 --eye 1,1,5 --target 1,1,0.4 --up 0,1,0 --camera ortho "
                             "--clip 0,0,0.4,0,0,-1 --no-edges --no-legend --no-triad --flat";
  const auto ownRun = runVolpost(common + " --interpolation element -o " + dir + "/own.png");
  ASSERT_EQ(ownRun.exitCode, 0) << ownRun.output;
  const auto splitRun = runVolpost(common + " --interpolation tetrahedra -o " + dir + "/split.png");
  ASSERT_EQ(splitRun.exitCode, 0) << splitRun.output;
  const QImage ownPicture(QString::fromStdString(dir + "/own.png"));
  const QImage splitPicture(QString::fromStdString(dir + "/split.png"));
  ASSERT_FALSE(ownPicture.isNull());
  ASSERT_FALSE(splitPicture.isNull());
  const QRect frame = coveredBox(ownPicture);
  ASSERT_GT(frame.width(), 200);
  EXPECT_LE(std::abs(frame.width() - frame.height()), 2) << "the annulus is as wide as it is high";
  // The hole is round: the split's chords across 30 degrees cut into it (their middles at
  // radius cos 15 degrees = 0.966); the cells' own shapes keep to radius 1.
  const long own = drawnInsideRadius(ownPicture, frame, 0.985), split = drawnInsideRadius(splitPicture, frame, 0.985);
  EXPECT_LT(own, 15) << "pixels of the cells' own section inside radius 0.985";
  EXPECT_GT(split, 150) << "pixels of the split's section inside radius 0.985";
  // Without the cut, the top face's inner outline: the boundary in the cells' own shapes
  // is round as well, the flat faces through the nodes are not.
  const std::string top = "render " + model +
                          " --field T --size 400x400 --eye 1,1,5 --target 1,1,0.4 --up 0,1,0 --camera ortho "
                          "--no-edges --no-legend --no-triad --flat";
  ASSERT_EQ(runVolpost(top + " --interpolation element -o " + dir + "/top_own.png").exitCode, 0);
  ASSERT_EQ(runVolpost(top + " -o " + dir + "/top_split.png").exitCode, 0);
  const QImage topOwn(QString::fromStdString(dir + "/top_own.png"));
  const QImage topSplit(QString::fromStdString(dir + "/top_split.png"));
  ASSERT_FALSE(topOwn.isNull());
  ASSERT_FALSE(topSplit.isNull());
  EXPECT_LT(drawnInsideRadius(topOwn, coveredBox(topOwn), 0.995), 15) << "the own boundary inside radius 0.995";
  EXPECT_GT(drawnInsideRadius(topSplit, coveredBox(topSplit), 0.995), 60) << "the flat one inside radius 0.995";
}

namespace {

// The vertices and triangles (0-based corners) of an .obj file as `volpost surface` writes it.
struct ObjSurface {
  std::vector<glm::dvec3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

ObjSurface readObj(const std::string& path) {
  ObjSurface out;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line.size() > 2 ? line.substr(2) : std::string());
    if (line.rfind("v ", 0) == 0) {
      glm::dvec3 p(0.0);
      fields >> p.x >> p.y >> p.z;
      out.points.push_back(p);
    } else if (line.rfind("f ", 0) == 0) {
      std::array<std::size_t, 3> t{};
      std::string corner;
      for (std::size_t k = 0; k < 3 && fields >> corner; ++k) t[k] = std::size_t(std::stoul(corner) - 1);
      out.triangles.push_back(t);
    }
  }
  return out;
}

}  // namespace

TEST(ElementSurfacesCommand, SurfaceWritesTheLevelSetOfTheCellsOwnField) {
  const std::string dir = ::testing::TempDir();
  const std::string model = writeQuarterCylinder(dir + "/quarter_iso.vtk", 2);
  const auto own = runVolpost("surface " + model + " " + dir + "/own.obj --field T --iso 0.8 --interpolation element");
  ASSERT_EQ(own.exitCode, 0) << own.output;
  EXPECT_NE(own.output.find("the cells' own field"), std::string::npos) << own.output;
  // Every vertex of the written surface on T = z (x + 2 y) = 0.8: the field is quadratic in
  // the hex20's natural coordinates, only near z (x + 2 y), so within a few hundredths.
  const std::vector<glm::dvec3> vertices = readObj(dir + "/own.obj").points;
  double worst = 0.0;
  for (const glm::dvec3& p : vertices) worst = std::max(worst, std::abs(p.z * (p.x + 2.0 * p.y) - 0.8));
  EXPECT_GT(vertices.size(), 100u);
  EXPECT_LT(worst, 0.03);
  // Refused, with the reason: an unknown choice.
  const auto unknown = runVolpost("surface " + model + " " + dir + "/x.obj --field T --iso 0.8 --interpolation cubic");
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.output.find("--interpolation cubic is not one of: element, tetrahedra"), std::string::npos)
      << unknown.output;
  EXPECT_FALSE(std::ifstream(dir + "/x.obj").good());
}

namespace {

// The smallest distance from the z axis of a triangle's middle in an .obj file.
double innermostMiddle(const std::string& path) {
  const ObjSurface surface = readObj(path);
  double innermost = INFINITY;
  for (const auto& t : surface.triangles) {
    const glm::dvec3 middle = (surface.points.at(t[0]) + surface.points.at(t[1]) + surface.points.at(t[2])) / 3.0;
    innermost = std::min(innermost, std::hypot(middle.x, middle.y));
  }
  return innermost;
}

}  // namespace

TEST(ElementSurfacesCommand, SurfaceWritesTheBoundaryInTheCellsOwnShapes) {
  const std::string dir = ::testing::TempDir();
  const std::string model = writeQuarterCylinder(dir + "/quarter_boundary.vtk", 2);
  const auto own = runVolpost("surface " + model + " " + dir + "/own_boundary.obj --interpolation element");
  ASSERT_EQ(own.exitCode, 0) << own.output;
  EXPECT_NE(own.output.find("boundary in the cells' own shapes"), std::string::npos) << own.output;
  const auto flat = runVolpost("surface " + model + " " + dir + "/flat_boundary.obj");
  ASSERT_EQ(flat.exitCode, 0) << flat.output;
  // The inner cylinder (radius 1): the flat faces' triangles, across 22.5 degrees between
  // nodes, sag inside it; the cells' own faces follow it (each triangle cut as finely as
  // the tolerance, 1/1000 estimated at its sides' middles, asks: 0.99895 measured).
  EXPECT_GT(innermostMiddle(dir + "/own_boundary.obj"), 0.998);
  EXPECT_LT(innermostMiddle(dir + "/flat_boundary.obj"), 0.995);
}

// `volpost surface` follows the element tolerance as pictures do: a coarser one gives fewer
// pieces; it needs the cells' own field and a valid value.
TEST(ElementSurfacesCommand, TheElementToleranceSetsHowFinelyTheSurfaceFollowsTheCells) {
  const std::string dir = ::testing::TempDir();
  const std::string model = writeQuarterCylinder(dir + "/quarter_tolerance.vtk", 2);
  const auto triangles = [](const std::string& output) {
    const auto at = output.find("own shapes, ");
    return at == std::string::npos ? 0L : std::stol(output.substr(at + 12));
  };
  const auto fine = runVolpost("surface " + model + " " + dir + "/fine.obj --interpolation element");
  ASSERT_EQ(fine.exitCode, 0) << fine.output;
  const auto coarse =
      runVolpost("surface " + model + " " + dir + "/coarse.obj --interpolation element --element-tolerance 0.1");
  ASSERT_EQ(coarse.exitCode, 0) << coarse.output;
  EXPECT_GT(triangles(coarse.output), 0);
  EXPECT_LT(4 * triangles(coarse.output), triangles(fine.output)) << coarse.output << fine.output;
  EXPECT_LT(innermostMiddle(dir + "/fine.obj"), 1.0);
  const auto flat = runVolpost("surface " + model + " " + dir + "/flat.obj --element-tolerance 0.1");
  EXPECT_EQ(flat.exitCode, 2);
  EXPECT_NE(flat.output.find("add --interpolation element"), std::string::npos) << flat.output;
  const auto big =
      runVolpost("surface " + model + " " + dir + "/big.obj --interpolation element --element-tolerance 2");
  EXPECT_EQ(big.exitCode, 2);
  EXPECT_NE(big.output.find("must be 0 (exact) or lie in [1e-05, 0.1]"), std::string::npos) << big.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/big.obj"));
  const auto word =
      runVolpost("surface " + model + " " + dir + "/word.obj --interpolation element --element-tolerance fine");
  EXPECT_EQ(word.exitCode, 2);
  EXPECT_NE(word.output.find("--element-tolerance fine is not a number"), std::string::npos) << word.output;
}
