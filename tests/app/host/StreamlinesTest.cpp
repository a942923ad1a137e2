// SPDX-License-Identifier: MIT
// Streamlines against fields whose trajectories are known: a solid-body rotation (circles
// must close), a linear field (an invariant of the exact solution), the ABC flow and the
// analytic flow around the post of ../shared/data (against the exact field integrated
// with a tight tolerance), plus the ways a line ends: leaving the mesh (on the boundary
// face), stagnation, a seed outside the mesh.
#include "support/HexLattice.hpp"
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"
#include "support/TetGrid.hpp"

#include "host/Streamlines.hpp"

#include <volpost/core/Quantity.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <functional>

using namespace volpost;

namespace {

struct GridField {
  TetMesh tets;
  std::vector<glm::dvec3> vectors;
};

GridField onGrid(int nx, int ny, int nz, glm::dvec3 origin, double cell, const std::function<glm::dvec3(glm::dvec3)>& field) {
  GridField s;
  s.tets = tetrahedralize(test::tetGrid(nx, ny, nz, origin, cell));
  for (const glm::dvec3& p : s.tets.mesh.nodes) s.vectors.push_back(field(p));
  return s;
}

// A reference trajectory of the exact (analytic) field: Dormand-Prince with a tight
// tolerance, by arc length, to the given length.
glm::dvec3 exactAfterLength(const std::function<glm::dvec3(glm::dvec3)>& field, glm::dvec3 x, double length) {
  const auto unit = [&](glm::dvec3 p) { return glm::normalize(field(p)); };
  const int steps = 20000;
  const double h = length / steps;
  for (int i = 0; i < steps; ++i) {  // classical RK4 on the unit field: error ~ h^4
    const glm::dvec3 k1 = unit(x), k2 = unit(x + 0.5 * h * k1), k3 = unit(x + 0.5 * h * k2), k4 = unit(x + h * k3);
    x += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return x;
}

// The point of a polyline at the given arc length from its start.
glm::dvec3 atLength(const std::vector<glm::dvec3>& points, std::size_t first, double length) {
  double walked = 0.0;
  for (std::size_t i = first; i + 1 < points.size(); ++i) {
    const double d = glm::length(points[i + 1] - points[i]);
    if (walked + d >= length) return points[i] + (length - walked) / d * (points[i + 1] - points[i]);
    walked += d;
  }
  return points.back();
}

}  // namespace

TEST(Streamlines, SolidBodyRotationClosesItsCircles) {
  // v = (-y, x, 0) about the box's axis: linear, so the tets carry it exactly and every
  // error is the integrator's.
  const GridField s = onGrid(8, 8, 1, {-1, -1, 0}, 0.25, [](glm::dvec3 p) { return glm::dvec3(-p.y, p.x, 0.0); });
  const StreamlineTracer tracer(s.tets, s.vectors);
  for (StreamlineMethod method : {StreamlineMethod::RK2, StreamlineMethod::RK4, StreamlineMethod::RK45}) {
    StreamlineSettings settings;
    settings.method = method;
    settings.direction = StreamlineDirection::Forward;
    settings.tolerance = 1e-6;
    const Streamline line = tracer.trace({0.6, 0.0, 0.1}, settings);
    EXPECT_EQ(line.forwardStop, StreamlineStop::ClosedOrbit) << toString(method) << ": " << describe(line.forwardStop);
    double worstRadius = 0.0;
    for (const glm::dvec3& p : line.points) worstRadius = std::max(worstRadius, std::abs(std::hypot(p.x, p.y) - 0.6));
    std::printf("solid-body rotation, %s, tolerance 1e-6 x size: closure error %.3g, radius error %.3g, %zu steps "
                "(%zu rejected)\n",
                toString(method), line.closureError, worstRadius, line.steps, line.rejected);
    EXPECT_LT(line.closureError, 1e-3);
    EXPECT_LT(worstRadius, 1e-3);
    EXPECT_NEAR(line.length, 2.0 * M_PI * 0.6, 0.05);
  }
}

TEST(Streamlines, EveryWrittenPointLiesOnTheIntegratedCircle) {
  // The written line is the step ends, each within the tolerance of the exact line through
  // the previous one: the exact flow keeps the radius, so the radius changes by at most
  // the tolerance from point to point. Points on a cubic through the ends of rk4's and
  // rk45's long steps strayed 1.5e-4 off the circle between them (five times the
  // tolerance); the closure point is an integrated step too.
  const GridField s = onGrid(8, 8, 1, {-1, -1, 0}, 0.25, [](glm::dvec3 p) { return glm::dvec3(-p.y, p.x, 0.0); });
  const StreamlineTracer tracer(s.tets, s.vectors);
  for (StreamlineMethod method : {StreamlineMethod::RK2, StreamlineMethod::RK4, StreamlineMethod::RK45}) {
    StreamlineSettings settings;  // the default tolerance, 1e-5 of the model's size
    settings.method = method;
    settings.direction = StreamlineDirection::Forward;
    const double eps = settings.tolerance * tracer.modelSize();
    const Streamline line = tracer.trace({0.6, 0.0, 0.1}, settings);
    ASSERT_EQ(line.forwardStop, StreamlineStop::ClosedOrbit) << toString(method);
    EXPECT_EQ(line.points.size(), line.steps + 1) << "the seed and one point per step";
    for (std::size_t i = 1; i < line.points.size(); ++i) {
      const double before = std::hypot(line.points[i - 1].x, line.points[i - 1].y);
      const double after = std::hypot(line.points[i].x, line.points[i].y);
      EXPECT_LE(std::abs(after - before), eps) << toString(method) << ", point " << i;
    }
    EXPECT_LT(line.closureError, double(line.steps) * eps) << toString(method);
  }
}

TEST(Streamlines, PointsInsideTheStepsAreAsAccurateAsTheEnds) {
  // Asked for points every 0.05 model units, rk45's long steps (about 0.25 here) are
  // written through inner points, each a step of its own from the step's start.
  const GridField s = onGrid(8, 8, 1, {-1, -1, 0}, 0.25, [](glm::dvec3 p) { return glm::dvec3(-p.y, p.x, 0.0); });
  const StreamlineTracer tracer(s.tets, s.vectors);
  StreamlineSettings settings;
  settings.method = StreamlineMethod::RK45;
  settings.direction = StreamlineDirection::Forward;
  settings.pointSpacing = 0.05;
  const double eps = settings.tolerance * tracer.modelSize();
  const Streamline line = tracer.trace({0.6, 0.0, 0.1}, settings);
  ASSERT_EQ(line.forwardStop, StreamlineStop::ClosedOrbit);
  EXPECT_GT(line.points.size(), 4 * line.steps) << "2 pi 0.6 / 0.05: about 75 points";
  double worst = 0.0, longest = 0.0;
  for (std::size_t i = 0; i < line.points.size(); ++i) {
    worst = std::max(worst, std::abs(std::hypot(line.points[i].x, line.points[i].y) - 0.6));
    if (i > 0) longest = std::max(longest, glm::length(line.points[i] - line.points[i - 1]));
  }
  EXPECT_LT(worst, double(line.steps + 1) * eps);
  EXPECT_LE(longest, 0.05 * 1.0001);
}

TEST(Streamlines, TheLengthLimitIsNotExceeded) {
  // The last step was sized by the speed at its start and ran past the limit (1.0162 for
  // a limit of 1 on the ABC flow): it now ends where the integrated step reaches it.
  const double A = 1.0, B = std::sqrt(2.0 / 3.0), C = std::sqrt(1.0 / 3.0);
  const auto abc = [&](glm::dvec3 p) {
    return glm::dvec3(A * std::sin(p.z) + C * std::cos(p.y), B * std::sin(p.x) + A * std::cos(p.z),
                      C * std::sin(p.y) + B * std::cos(p.x));
  };
  const GridField s = onGrid(12, 12, 12, {0, 0, 0}, 2.0 * M_PI / 12, abc);
  const StreamlineTracer tracer(s.tets, s.vectors);
  for (StreamlineMethod method : {StreamlineMethod::RK2, StreamlineMethod::RK4, StreamlineMethod::RK45})
    for (double limit : {0.3, 1.0, 2.5}) {
      StreamlineSettings settings;
      settings.method = method;
      settings.maxLength = limit;
      const Streamline line = tracer.trace({M_PI, 2.0, 3.0}, settings);
      // Each direction on its own (the forward one used to start with the backward one's
      // length and stop at once).
      double forward = 0.0, backward = 0.0;
      for (std::size_t i = 0; i + 1 < line.points.size(); ++i)
        (i < line.seedIndex ? backward : forward) += glm::length(line.points[i + 1] - line.points[i]);
      for (const auto& [stop, walked] :
           {std::pair{line.forwardStop, forward}, std::pair{line.backwardStop, backward}}) {
        EXPECT_LE(walked, limit * (1.0 + 1e-9)) << toString(method) << " " << limit;
        if (limit < 2.0) EXPECT_EQ(stop, StreamlineStop::MaxLength) << toString(method) << " " << limit;
        if (stop == StreamlineStop::MaxLength) EXPECT_NEAR(walked, limit, 1e-9 * limit) << toString(method);
      }
      EXPECT_NEAR(line.length, forward + backward, 1e-9 * limit) << toString(method);
    }
}

TEST(Streamlines, LinearFieldKeepsTheInvariantOfItsExactSolution) {
  // v = (-x, y/2, 0): x = x0 e^-t, y = y0 e^(t/2), so y^2 x stays y0^2 x0.
  const GridField s = onGrid(6, 6, 1, {0.5, 0.5, 0}, 0.25, [](glm::dvec3 p) { return glm::dvec3(-p.x, 0.5 * p.y, 0.0); });
  const StreamlineTracer tracer(s.tets, s.vectors);
  for (StreamlineMethod method : {StreamlineMethod::RK2, StreamlineMethod::RK4, StreamlineMethod::RK45}) {
    StreamlineSettings settings;
    settings.method = method;
    settings.tolerance = 1e-7;
    const glm::dvec3 seed(1.5, 0.8, 0.1);
    const Streamline line = tracer.trace(seed, settings);
    const double invariant = seed.y * seed.y * seed.x;
    double worst = 0.0;
    for (const glm::dvec3& p : line.points) worst = std::max(worst, std::abs(p.y * p.y * p.x - invariant) / invariant);
    std::printf("linear field, %s: largest relative drift of y^2 x %.3g over %zu points\n", toString(method), worst,
                line.points.size());
    EXPECT_LT(worst, 1e-4) << toString(method);
    EXPECT_EQ(line.forwardStop, StreamlineStop::LeftMesh);
    EXPECT_EQ(line.backwardStop, StreamlineStop::LeftMesh);
  }
}

TEST(Streamlines, InHexahedraTheCellsOwnTrilinearVelocityIsFollowed) {
  // v = (1, 0, y z) is its own trilinear interpolant in hex8 cells: z = z0 e^(y0 x) along the
  // line from x = 0. The split's linear pieces of y z bend the line off it; the cells' own
  // field keeps it to the integration tolerance. Straight and bent cells alike.
  for (const bool bent : {false, true}) {
    SCOPED_TRACE(bent ? "bent cells" : "straight cells");
    const Mesh mesh = test::hexLattice(CellType::Hex8, 4, [bent](const glm::dvec3& g) {
      const glm::dvec3 p = g / 4.0;
      return bent ? p + 0.04 * glm::dvec3(0.0, std::sin(3.0 * p.x), std::sin(3.0 * p.y)) * (p.x * (1.0 - p.x)) : p;
    });
    std::vector<double> nodal;
    for (const glm::dvec3& p : mesh.nodes) nodal.insert(nodal.end(), {1.0, 0.0, p.y * p.z});
    const TetMesh tets = tetrahedralize(mesh);
    const StreamlineTracer own(tets, tetNodeVectors(tets, mesh, nodal), &mesh);
    const StreamlineTracer split(tets, tetNodeVectors(tets, mesh, nodal));
    StreamlineSettings settings;
    settings.direction = StreamlineDirection::Forward;
    settings.tolerance = 1e-8;
    const glm::dvec3 seed(0.0, 0.7, 0.3);
    const auto miss = [&](const Streamline& line) {
      double worst = 0.0;
      for (const glm::dvec3& p : line.points) worst = std::max(worst, std::abs(p.z - seed.z * std::exp(seed.y * p.x)));
      return worst;
    };
    const Streamline a = own.trace(seed, settings), b = split.trace(seed, settings);
    EXPECT_NEAR(a.points.back().x, 1.0, 1e-9);
    if (!bent) {  // bent cells carry another field (the nodes moved, the values at them not)
      EXPECT_LT(miss(a), 1e-6);
      EXPECT_GT(miss(b), 1e-4);
    } else {
      EXPECT_GT(std::abs(a.points.back().z - b.points.back().z), 1e-5);
    }
    // The line's own velocities are the trilinear field at its points.
    for (std::size_t k = 0; k < a.points.size() && !bent; ++k)
      EXPECT_NEAR(a.velocity[k].z, a.points[k].y * a.points[k].z, 1e-9);
  }
}

TEST(Streamlines, ALineThatLeavesEndsOnTheBoundaryFace) {
  const GridField s = onGrid(4, 4, 4, {0, 0, 0}, 0.5, [](glm::dvec3) { return glm::dvec3(1.0, 0.3, 0.0); });
  const StreamlineTracer tracer(s.tets, s.vectors);
  StreamlineSettings settings;
  const Streamline line = tracer.trace({1.0, 0.7, 1.1}, settings);
  EXPECT_EQ(line.forwardStop, StreamlineStop::LeftMesh);
  EXPECT_EQ(line.backwardStop, StreamlineStop::LeftMesh);
  EXPECT_NEAR(line.points.back().x, 2.0, 1e-12) << "the forward end lies on the face x = 2";
  EXPECT_NEAR(line.points.front().x, 0.0, 1e-12) << "the backward end on x = 0";
  EXPECT_NEAR(line.points.back().y, 0.7 + 0.3, 1e-9);
  for (const glm::dvec3& p : line.points) EXPECT_NEAR(p.y - 0.3 * p.x, 0.7 - 0.3, 1e-9) << "a straight line";
}

TEST(Streamlines, StagnationAndSeedsOutsideAreReported) {
  // A source at the box's centre: backward, the line runs into it and stops there.
  const GridField s = onGrid(4, 4, 4, {0, 0, 0}, 0.25, [](glm::dvec3 p) { return p - glm::dvec3(0.5); });
  const StreamlineTracer tracer(s.tets, s.vectors);
  StreamlineSettings settings;
  settings.direction = StreamlineDirection::Backward;
  const Streamline line = tracer.trace({0.8, 0.6, 0.55}, settings);
  EXPECT_EQ(line.backwardStop, StreamlineStop::Stagnation) << describe(line.backwardStop);
  EXPECT_LT(glm::length(line.points.front() - glm::dvec3(0.5)), 1e-3);
  try {
    (void)tracer.trace({2.0, 0.5, 0.5}, settings);
    FAIL() << "a seed outside the mesh must be refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("(2, 0.5, 0.5) is outside the mesh"), std::string::npos) << e.what();
  }
  std::size_t outside = 0;
  const auto lines = tracer.traceAll({{0.8, 0.6, 0.55}, {5, 5, 5}, {0.2, 0.3, 0.4}}, settings, &outside);
  EXPECT_EQ(lines.size(), 2u);
  EXPECT_EQ(outside, 1u);
}

TEST(Streamlines, AbcFlowFollowsTheExactFieldToTheInterpolationError) {
  // Arnold-Beltrami-Childress flow on a tetrahedralized box: not linear, so the lines
  // carry the error of the linear interpolation (second order in the cell size).
  const double A = 1.0, B = std::sqrt(2.0 / 3.0), C = std::sqrt(1.0 / 3.0);
  const auto abc = [&](glm::dvec3 p) {
    return glm::dvec3(A * std::sin(p.z) + C * std::cos(p.y), B * std::sin(p.x) + A * std::cos(p.z),
                      C * std::sin(p.y) + B * std::cos(p.x));
  };
  double previous = 0.0;
  for (int n : {8, 16}) {
    const double cell = 2.0 * M_PI / n;
    const GridField s = onGrid(n, n, n, {0, 0, 0}, cell, abc);
    const StreamlineTracer tracer(s.tets, s.vectors);
    StreamlineSettings settings;
    settings.method = StreamlineMethod::RK45;
    settings.direction = StreamlineDirection::Forward;
    settings.tolerance = 1e-8;
    const glm::dvec3 seed(M_PI, 2.0, 3.0);
    const Streamline line = tracer.trace(seed, settings);
    const double length = 2.0;
    ASSERT_GT(line.length, length);
    const double error = glm::length(atLength(line.points, 0, length) - exactAfterLength(abc, seed, length));
    std::printf("ABC flow, %d^3 cubes (cell %.3f): error after length %.1f = %.3g\n", n, cell, length, error);
    EXPECT_LT(error, 0.5 * cell * cell);
    if (previous > 0.0) EXPECT_LT(error, 0.5 * previous) << "halving the cells must shrink the error";
    previous = error;
  }
}

TEST(Streamlines, ThePostFlowFollowsItsAnalyticField) {
  VOLPOST_SHARED_OR_SKIP(path, "post/coarse/post_coarse.vtu");
  const auto model = test::meshioReaders().load(path);
  const Field* velocity = model->findField("velocity");
  ASSERT_TRUE(velocity);
  const TetMesh tets = tetrahedralize(model->mesh());
  const StreamlineTracer tracer(tets, tetNodeVectors(tets, model->mesh(), velocity->values(0)));
  // ../shared/data/README.md: potential flow past a cylinder with circulation, faded at the
  // walls, plus a small vertical part.
  const double U = 1.0, a = 1.0, G = 2.0 * M_PI * 0.8, H = 4.0, d = 0.25;
  const auto exact = [&](glm::dvec3 p) {
    const double r = std::hypot(p.x, p.y), t = std::atan2(p.y, p.x);
    const double ur = U * (1 - a * a / (r * r)) * std::cos(t), ut = -U * (1 + a * a / (r * r)) * std::sin(t) + G / (2 * M_PI * r);
    const double f = std::tanh(p.z / d) * std::tanh((H - p.z) / d);
    return glm::dvec3(f * (ur * std::cos(t) - ut * std::sin(t)), f * (ur * std::sin(t) + ut * std::cos(t)),
                      0.2 * U * (a / r) * (a / r) * std::sin(2 * t) * std::sin(M_PI * p.z / H));
  };
  StreamlineSettings settings;
  settings.method = StreamlineMethod::RK45;
  settings.direction = StreamlineDirection::Forward;
  settings.tolerance = 1e-8;
  for (const glm::dvec3 seed : {glm::dvec3(-6, 1.5, 2.0), glm::dvec3(-6, -2.5, 1.5), glm::dvec3(-5, 0.4, 2.5)}) {
    const Streamline line = tracer.trace(seed, settings);
    const double length = std::min(6.0, 0.9 * line.length);
    const double error = glm::length(atLength(line.points, 0, length) - exactAfterLength(exact, seed, length));
    std::printf("post flow from (%g, %g, %g): error after length %.1f = %.3g\n", seed.x, seed.y, seed.z, length, error);
    EXPECT_LT(error, 0.15) << "the coarse post's cells are about 0.5 across";
  }
}
