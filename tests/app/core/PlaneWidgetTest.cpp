// SPDX-License-Identifier: MIT
// The clip plane's widget without a window: the outline where the plane cuts the box, the
// hit test of the handle, and what dragging its knob and its shaft does to the plane.
#include "core/BoxWidget.hpp"
#include "core/FeatureEdges.hpp"
#include "core/PlaneWidget.hpp"
#include "core/SceneOverlay.hpp"
#include "core/VolumeSpecs.hpp"

#include "support/TetGrid.hpp"

#include "host/BoundarySurface.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

using namespace volpost;
using namespace volpost::app;

namespace {

Bounds unitCube() {
  Bounds b;
  b.extend({0.0, 0.0, 0.0});
  b.extend({1.0, 1.0, 1.0});
  return b;
}

// Twice the signed area of the polygon, in the plane with normal n (positive: counter-clockwise about n).
double signedArea(const std::vector<glm::dvec3>& p, const glm::dvec3& n) {
  glm::dvec3 sum(0.0);
  for (std::size_t i = 0; i < p.size(); ++i) sum += glm::cross(p[i], p[(i + 1) % p.size()]);
  return glm::dot(sum, glm::normalize(n));
}

bool convexInOrder(const std::vector<glm::dvec3>& p, const glm::dvec3& n) {
  int positive = 0, negative = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::dvec3 a = p[(i + 1) % p.size()] - p[i], b = p[(i + 2) % p.size()] - p[(i + 1) % p.size()];
    const double turn = glm::dot(glm::cross(a, b), n);
    (turn > 0.0 ? positive : negative)++;
  }
  return positive == 0 || negative == 0;
}

Camera lookingAt(const Bounds& b) {
  Camera c;
  c.setView(StandardView::Isometric);
  c.fit(b);
  c.orbit(20.0, 10.0);
  return c;
}

}  // namespace

TEST(PlaneWidget, AnAxisPlaneCutsTheCubeInASquareAndADiagonalOneInAHexagon) {
  const auto square = planeInBox({{0.5, 0.5, 0.5}, {1.0, 0.0, 0.0}}, unitCube());
  ASSERT_EQ(square.size(), 4u);
  EXPECT_NEAR(std::abs(signedArea(square, {1, 0, 0})), 2.0, 1e-12);  // twice the unit area
  EXPECT_TRUE(convexInOrder(square, {1, 0, 0}));
  for (const auto& p : square) EXPECT_DOUBLE_EQ(p.x, 0.5);
  const auto hexagon = planeInBox({{0.5, 0.5, 0.5}, {1.0, 1.0, 1.0}}, unitCube());
  ASSERT_EQ(hexagon.size(), 6u);
  EXPECT_TRUE(convexInOrder(hexagon, {1, 1, 1}));
  // Through a corner and the opposite edge's ends: a triangle, the corner listed once.
  const auto triangle = planeInBox({{1.0, 0.0, 0.0}, {1.0, 1.0, 1.0}}, unitCube());
  EXPECT_EQ(triangle.size(), 3u);
  EXPECT_TRUE(planeInBox({{2.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}, unitCube()).empty()) << "misses the box";
  EXPECT_TRUE(planeInBox({{0.5, 0.5, 0.5}, {0.0, 0.0, 0.0}}, unitCube()).empty()) << "no normal";
  EXPECT_TRUE(planeInBox({{0.5, 0.5, 0.5}, {1.0, 0.0, 0.0}}, Bounds{}).empty()) << "no box";
}

TEST(PlaneWidget, TheHandleStandsOnTheOutlinesCentreAlongTheNormal) {
  const PlaneWidget w = planeWidget({{0.3, 0.0, 0.0}, {2.0, 0.0, 0.0}}, unitCube());
  ASSERT_EQ(w.outline.size(), 4u);
  EXPECT_NEAR(w.center.x, 0.3, 1e-12);
  EXPECT_NEAR(w.center.y, 0.5, 1e-12);
  EXPECT_NEAR(w.center.z, 0.5, 1e-12);
  EXPECT_NEAR(glm::length(w.knob - w.center), 0.25 * std::sqrt(3.0), 1e-12);
  EXPECT_GT(w.knob.x, w.center.x);
  for (const glm::dvec3& p : w.outline)  // 2 % of the diagonal outside the model's box
    EXPECT_TRUE((p.y < 0.0 || p.y > 1.0) && (p.z < 0.0 || p.z > 1.0));
}

TEST(PlaneWidget, TheKnobAndTheShaftAreHitWhereTheyAreDrawn) {
  const Bounds b = unitCube();
  const Camera camera = lookingAt(b);
  const PlaneWidget w = planeWidget({{0.5, 0.5, 0.5}, {1.0, 0.0, 0.0}}, b);
  const auto knob = camera.projectToPicture(w.knob, 400, 300);
  const auto center = camera.projectToPicture(w.center, 400, 300);
  ASSERT_TRUE(knob && center);
  EXPECT_EQ(hitPlaneWidget(w, camera, 400, 300, *knob + glm::dvec2(3, -2), 6.0), PlaneWidgetPart::Knob);
  EXPECT_EQ(hitPlaneWidget(w, camera, 400, 300, 0.5 * (*knob + *center), 6.0), PlaneWidgetPart::Shaft);
  EXPECT_EQ(hitPlaneWidget(w, camera, 400, 300, *knob + glm::dvec2(40, 40), 6.0), PlaneWidgetPart::None);
}

TEST(PlaneWidget, DraggingTheKnobTurnsThePlaneTowardTheMouse) {
  const Bounds b = unitCube();
  const Camera camera = lookingAt(b);
  const ClipPlane plane{{0.5, 0.5, 0.5}, {1.0, 0.0, 0.0}};
  const PlaneWidget w = planeWidget(plane, b);
  // Where the knob goes: a point in the plane through the knob that faces the camera.
  const glm::dvec3 up = camera.up();
  const glm::dvec3 target = w.knob + 0.3 * up;
  const auto pixel = camera.projectToPicture(target, 400, 300);
  ASSERT_TRUE(pixel);
  const ClipPlane turned = turnedPlane(plane, w, camera, 400, 300, *pixel);
  const glm::dvec3 expected = glm::normalize(target - w.center);
  EXPECT_NEAR(glm::length(turned.normal - expected), 0.0, 1e-9);
  EXPECT_NEAR(glm::length(turned.point - w.center), 0.0, 1e-12) << "it turns about the outline's centre";
  EXPECT_NEAR(glm::length(turned.normal), 1.0, 1e-12);
}

TEST(PlaneWidget, DraggingTheShaftSlidesThePlaneByWhatTheMouseMovedAlongIt) {
  const Bounds b = unitCube();
  const Camera camera = lookingAt(b);
  const ClipPlane plane{{0.5, 0.5, 0.5}, {1.0, 0.0, 0.0}};
  const PlaneWidget w = planeWidget(plane, b);
  const auto knob = camera.projectToPicture(w.knob, 400, 300);
  const auto center = camera.projectToPicture(w.center, 400, 300);
  ASSERT_TRUE(knob && center);
  // From the centre's pixel to the knob's: the plane moves by the handle's length.
  const ClipPlane moved = slidPlane(plane, w, camera, 400, 300, *center, *knob);
  EXPECT_NEAR(moved.point.x - plane.point.x, glm::length(w.knob - w.center), 1e-9);
  EXPECT_EQ(moved.normal, plane.normal);
  // Across the handle: nothing.
  const glm::dvec2 along = *knob - *center, across(-along.y, along.x);
  const ClipPlane still = slidPlane(plane, w, camera, 400, 300, *center, *center + across);
  EXPECT_NEAR(still.point.x, plane.point.x, 1e-9);
  // A normal pointing at the viewer: up the screen is toward the viewer.
  Camera facing;
  facing.setView(StandardView::PlusX);
  facing.fit(b);
  const ClipPlane towardEye{{0.5, 0.5, 0.5}, -facing.viewDirection()};
  const PlaneWidget fw = planeWidget(towardEye, b);
  const ClipPlane up = slidPlane(towardEye, fw, facing, 400, 300, {200, 150}, {200, 100});
  EXPECT_GT(glm::dot(up.point - towardEye.point, -facing.viewDirection()), 0.0);
}

TEST(PlaneWidget, ATypedPlaneReadsBackExactly) {
  const ClipPlane p{{0.1, -2.5e-7, 3.0}, {0.0, 0.6, -0.8}};
  const auto back = parseClipPlane(clipPlaneText(p));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->point, p.point);
  EXPECT_NEAR(glm::length(glm::normalize(back->normal) - p.normal), 0.0, 1e-12);
  EXPECT_FALSE(parseClipPlane("1,2,3,0,0,0")) << "no normal";
  EXPECT_FALSE(parseClipPlane("1,2,3,0,0")) << "five numbers";
}

// ---- the clip box's handles ----------------------------------------------------------

TEST(BoxWidget, CornersFacesAndEdgesFollowTheBox) {
  const ClipBox box{0.0, 2.0, -1.0, 1.0, 5.0, 6.0};
  const BoxWidget w = boxWidget(box);
  EXPECT_EQ(w.corners[0], glm::dvec3(0, -1, 5));
  EXPECT_EQ(w.corners[7], glm::dvec3(2, 1, 6));
  EXPECT_EQ(w.corners[5], glm::dvec3(2, -1, 6));
  EXPECT_EQ(w.faceCenters[0], glm::dvec3(0, 0, 5.5));
  EXPECT_EQ(w.faceCenters[3], glm::dvec3(1, 1, 5.5));
  EXPECT_EQ(w.faceCenters[5], glm::dvec3(1, 0, 6));
  for (const auto& e : boxEdges())  // every edge joins corners that differ along one axis
    EXPECT_EQ(glm::length(glm::sign(w.corners[std::size_t(e[0])] - w.corners[std::size_t(e[1])])), 1.0);
}

TEST(BoxWidget, DraggingAFaceKnobMovesThatFaceOnlyAndNeverPastTheOpposite) {
  const ClipBox box{0.0, 1.0, 0.0, 1.0, 0.0, 1.0};
  Camera camera = lookingAt(unitCube());
  camera.setProjection(Camera::Projection::Orthographic);  // screen moves linear in model ones: exact figures
  const BoxWidget w = boxWidget(box);
  const auto xmax = camera.projectToPicture(w.faceCenters[1], 400, 300);
  ASSERT_TRUE(xmax);
  EXPECT_EQ(hitBoxWidget(w, camera, 400, 300, *xmax + glm::dvec2(2, 1), 7.0), 1);
  EXPECT_FALSE(hitBoxWidget(w, camera, 400, 300, *xmax + glm::dvec2(30, 30), 7.0).has_value());
  // Toward the screen image of +x by what +0.1 in x spans there: xmax grows by 0.1.
  const auto further = camera.projectToPicture(w.faceCenters[1] + glm::dvec3(0.1, 0, 0), 400, 300);
  const ClipBox out = draggedBox(box, 1, camera, 400, 300, *xmax, *further);
  EXPECT_NEAR(out[1], 1.1, 1e-9);
  for (std::size_t i : {0u, 2u, 3u, 4u, 5u}) EXPECT_EQ(out[i], box[i]);
  // Far past the opposite face: it stops just short of it.
  const auto beyond = camera.projectToPicture(w.faceCenters[1] - glm::dvec3(5.0, 0, 0), 400, 300);
  const ClipBox flat = draggedBox(box, 1, camera, 400, 300, *xmax, *beyond);
  EXPECT_GT(flat[1], flat[0]);
  EXPECT_LT(flat[1] - flat[0], 0.01);
}

// ---- the undeformed outline's edges ----------------------------------------------------

TEST(FeatureEdges, ABoxOutlineIsItsTwelveEdgesNotTheFacesDiagonals) {
  const Mesh grid = test::tetGrid(3, 2, 2);
  const auto ends = featureEdges(extractBoundary(grid));
  EXPECT_EQ(ends.size(), 2u * 4u * (3u + 2u + 2u)) << "each box edge in its grid segments";
  for (std::size_t i = 0; i + 1 < ends.size(); i += 2) {  // along one axis, on two faces of the box
    const glm::dvec3 d = glm::abs(ends[i + 1] - ends[i]);
    EXPECT_EQ(int(d.x > 0) + int(d.y > 0) + int(d.z > 0), 1);
    const glm::dvec3 p = ends[i];
    const int onFaces = int(p.x == 0 || p.x == 3) + int(p.y == 0 || p.y == 2) + int(p.z == 0 || p.z == 2);
    EXPECT_GE(onFaces, 2);
  }
  EXPECT_TRUE(featureEdges(extractBoundary(Mesh())).empty());
}
