// SPDX-License-Identifier: MIT
#include <volpost/core/ColorMap.hpp>
#include <volpost/core/Camera.hpp>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

using namespace volpost;

TEST(ColorMap, EndsAndMiddleOfEveryMap) {
  for (const auto& name : ColorMap::names()) {
    const ColorMap m = ColorMap::named(name);
    const auto texels = m.rgba8(256);
    EXPECT_EQ(texels.size(), 1024u);
    EXPECT_EQ(m.at(-5.0), m.at(0.0)) << name;
    EXPECT_EQ(m.at(7.0), m.at(1.0)) << name;
    EXPECT_EQ(m.at(std::nan("")), m.at(0.0)) << name;
  }
  EXPECT_EQ(ColorMap::named("grayscale").at(0.25), glm::dvec3(0.25));
  EXPECT_EQ(ColorMap::named("seismic").at(0.5), glm::dvec3(1.0));  // zero amplitude is white
  EXPECT_EQ(ColorMap::named("seismic").at(0.25), glm::dvec3(0, 0, 1));
  EXPECT_THROW(ColorMap::named("jet2"), std::invalid_argument);
}

TEST(Camera, FitCentersTheModelAndStandardViewsLookAlongAxes) {
  Camera c;
  Bounds b;
  b.extend({0, 0, 0});
  b.extend({10, 1, 1});
  c.setView(StandardView::PlusX);
  c.fit(b);
  EXPECT_EQ(c.target(), glm::dvec3(5, 0.5, 0.5));
  EXPECT_GT(c.eye().x, 10.0);
  EXPECT_NEAR(glm::length(c.viewDirection() - glm::dvec3(-1, 0, 0)), 0.0, 1e-12);
  // The target projects to the image center.
  const glm::dvec4 clip = c.projectionMatrix(1.5) * c.viewMatrix() * glm::dvec4(c.target(), 1.0);
  EXPECT_NEAR(clip.x / clip.w, 0.0, 1e-12);
  EXPECT_NEAR(clip.y / clip.w, 0.0, 1e-12);
  // Every corner of the box is inside the view after fit.
  for (double x : {0.0, 10.0})
    for (double y : {0.0, 1.0})
      for (double z : {0.0, 1.0}) {
        const glm::dvec4 p = c.projectionMatrix(1.0) * c.viewMatrix() * glm::dvec4(x, y, z, 1.0);
        for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(p[k] / p.w), 1.0);
      }
}

TEST(Camera, OrbitKeepsDistanceAndZoomMovesCloser) {
  Camera c;
  Bounds b;
  b.extend({-1, -1, -1});
  b.extend({1, 1, 1});
  c.fit(b);
  const double d = glm::length(c.eye() - c.target());
  c.orbit(37.0, -12.0);
  EXPECT_NEAR(glm::length(c.eye() - c.target()), d, 1e-9);
  c.zoom(2.0);
  EXPECT_NEAR(glm::length(c.eye() - c.target()), d / 2.0, 1e-9);
  c.pan(0.5, 0.0);
  EXPECT_GT(glm::length(c.target()), 0.0);
}

// A fitted model stays whole in a tall picture (the angle spans the narrower side) and
// keeps clear of a right margin (the legend's strip), in both projections.
namespace {

// A camera of `projection` fitted to the cube [-1, 1]^3.
Camera fittedToTheUnitCube(Camera::Projection projection) {
  Camera c;
  c.setProjection(projection);
  Bounds b;
  b.extend({-1, -1, -1});
  b.extend({1, 1, 1});
  c.fit(b);
  return c;
}

}  // namespace

TEST(Camera, FittedModelStaysInsideTallPicturesAndLeftOfTheMargin) {
  for (auto projection : {Camera::Projection::Perspective, Camera::Projection::Orthographic}) {
    Camera c = fittedToTheUnitCube(projection);
    for (double aspect : {0.25, 1.0, 3.0})
      for (double margin : {0.0, 0.3}) {
        c.setRightMargin(margin);
        const glm::dmat4 m = c.projectionMatrix(aspect) * c.viewMatrix();
        for (double x : {-1.0, 1.0})
          for (double y : {-1.0, 1.0})
            for (double z : {-1.0, 1.0}) {
              const glm::dvec4 p = m * glm::dvec4(x, y, z, 1.0);
              EXPECT_LE(p.x / p.w, 1.0 - 2.0 * margin) << "aspect " << aspect << " margin " << margin;
              EXPECT_GE(p.x / p.w, -1.0);
              EXPECT_LE(std::abs(p.y / p.w), 1.0);
            }
        // The target sits in the middle of the framed part.
        const glm::dvec4 t = m * glm::dvec4(c.target(), 1.0);
        EXPECT_NEAR(t.x / t.w, -margin, 1e-12);
      }
  }
  Camera c;
  c.setRightMargin(2.0);
  EXPECT_EQ(c.rightMargin(), 0.5);
  c.setRightMargin(std::nan(""));
  EXPECT_EQ(c.rightMargin(), 0.0);
}

// A point's pixel: the target lands in the middle of the framed part (left of the margin),
// a point on the screen's right lands right of it, one behind the eye and an empty picture
// have none.
TEST(Camera, ProjectToPictureFindsThePixelOfAPoint) {
  for (auto projection : {Camera::Projection::Perspective, Camera::Projection::Orthographic}) {
    Camera c = fittedToTheUnitCube(projection);
    c.setRightMargin(0.25);
    const auto target = c.projectToPicture(c.target(), 400, 300);
    ASSERT_TRUE(target);
    EXPECT_NEAR(target->x, 0.5 * 400 * 0.75, 1e-9);
    EXPECT_NEAR(target->y, 150.0, 1e-9);
    const glm::dvec3 right = glm::normalize(glm::cross(c.viewDirection(), c.up()));
    const auto beside = c.projectToPicture(c.target() + 0.5 * right + 0.5 * c.up(), 400, 300);
    ASSERT_TRUE(beside);
    EXPECT_GT(beside->x, target->x);
    EXPECT_LT(beside->y, target->y) << "up in the model is up in the picture (rows go down)";
    EXPECT_FALSE(c.projectToPicture(c.target(), 0, 300));
    if (projection == Camera::Projection::Perspective)
      EXPECT_FALSE(c.projectToPicture(c.eye() - c.viewDirection(), 400, 300)) << "behind the eye";
  }
}

// A turntable keeps the model upright: after any drags the screen's x axis stays level
// (no roll), and the elevation stops short of looking straight down the axis. The
// trackball, by contrast, rolls after a loop of drags.
TEST(Camera, TurntableKeepsTheModelUprightWhereTheTrackballRolls) {
  Camera table, ball;
  table.setView(StandardView::Isometric);
  ball.setView(StandardView::Isometric);
  const glm::dvec3 z(0, 0, 1);
  for (int i = 0; i < 40; ++i) {  // a loop: right, up, left, down
    const double az = i % 4 == 0 ? 30.0 : i % 4 == 2 ? -30.0 : 0.0;
    const double el = i % 4 == 1 ? 25.0 : i % 4 == 3 ? -25.0 : 0.0;
    table.turntable(az, el, z);
    ball.orbit(az, el);
  }
  const glm::dvec3 tableRight = glm::cross(table.viewDirection(), table.up());
  EXPECT_NEAR(glm::dot(tableRight, z), 0.0, 1e-9) << "no roll";
  EXPECT_GT(glm::dot(table.up(), z), 0.0);
  const glm::dvec3 ballRight = glm::cross(ball.viewDirection(), ball.up());
  EXPECT_GT(std::abs(glm::dot(ballRight, z)), 1e-3) << "the trackball rolled (the reason for the turntable)";
  for (int i = 0; i < 100; ++i) table.turntable(0.0, -10.0, z);  // far past the pole
  EXPECT_LT(std::abs(glm::dot(table.viewDirection(), z)), std::cos(glm::radians(0.99))) << "a degree short of the pole";
  EXPECT_GT(glm::dot(table.up(), z), -1e-9) << "not flipped over the pole";
}

TEST(ColorMap, EveryMapRunsReversedUnderItsNameWithASuffix) {
  for (const std::string& name : ColorMap::names()) {
    const std::string reversed = ColorMap::reversedName(name);
    EXPECT_EQ(reversed, name + "-reversed");
    EXPECT_TRUE(ColorMap::isReversed(reversed));
    EXPECT_EQ(ColorMap::reversedName(reversed), name);
    EXPECT_EQ(ColorMap::label(reversed), ColorMap::label(name) + ", reversed");
    const ColorMap forward = ColorMap::named(name), backward = ColorMap::named(reversed);
    for (double t : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
      const glm::dvec3 a = forward.at(1.0 - t), b = backward.at(t);
      EXPECT_NEAR(a.r, b.r, 1e-12) << name << " at " << t;
      EXPECT_NEAR(a.g, b.g, 1e-12) << name << " at " << t;
      EXPECT_NEAR(a.b, b.b, 1e-12) << name << " at " << t;
    }
  }
  EXPECT_THROW(ColorMap::named("-reversed"), std::invalid_argument);
  EXPECT_THROW(ColorMap::named("nothing-reversed"), std::invalid_argument);
}
