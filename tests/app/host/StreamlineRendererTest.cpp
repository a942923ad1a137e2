// SPDX-License-Identifier: MIT
// Lit lines against the closed form of their shading: a straight line of constant value
// seen head-on has one tangent T, so every pixel along it must show
// base (ambient + kd sqrt(1 - (L.T)^2)^p) + ks (sqrt(1-(L.T)^2) sqrt(1-(V.T)^2) - (L.T)(V.T))^n.
#include "host/render/StreamlineRenderer.hpp"

#include <volpost/render/HeadlessContext.hpp>
#include <volpost/render/OffscreenTarget.hpp>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace volpost;

namespace {

class LitLines : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      context_ = std::make_unique<HeadlessContext>();
    } catch (const std::exception& e) {
      GTEST_SKIP() << "not run: no headless OpenGL 4.5 context: " << e.what();
    }
    renderer_.initialize();
    renderer_.setColorMap(ColorMap::named("grayscale"));
    renderer_.setRange(0.0, 1.0);
  }
  void TearDown() override {
    if (context_) renderer_.release();
  }

  // Draws one straight line through the origin along `direction` (in the view plane of a
  // camera looking down -z) and returns the picture.
  std::vector<std::uint8_t> draw(glm::dvec3 direction, float width) {
    StreamlineStyle style;
    style.width = width;
    renderer_.setLines({{-direction, glm::dvec3(0.0), direction}}, {{0.5, 0.5, 0.5}}, glm::dvec3(0.0), style);
    Camera camera;
    camera.setProjection(Camera::Projection::Orthographic);
    camera.setView(StandardView::PlusZ);
    Bounds b;
    b.valid = true;
    b.min = glm::dvec3(-1.0);
    b.max = glm::dvec3(1.0);
    camera.fit(b);
    target_ = std::make_unique<OffscreenTarget>(kSize, kSize);
    RenderContext ctx;
    ctx.camera = camera;
    ctx.width = ctx.height = kSize;
    ctx.framebuffer = target_->framebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer);
    glViewport(0, 0, kSize, kSize);
    glClearColor(1.0f, 0.0f, 1.0f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    renderer_.render(ctx);
    glFinish();
    return target_->readPixels();
  }

  double expected(glm::dvec3 viewTangent) const {
    const glm::dvec3 L = glm::normalize(glm::dvec3(renderer_.lightDirection)), V(0, 0, 1), T = glm::normalize(viewTangent);
    const double LT = glm::dot(L, T), VT = glm::dot(V, T);
    const double sinL = std::sqrt(1 - LT * LT), sinV = std::sqrt(1 - VT * VT);
    const double d = std::pow(sinL, renderer_.diffuseExponent);
    const double s = std::pow(std::max(sinL * sinV - LT * VT, 0.0), renderer_.shininess);
    return std::min(1.0, 0.5 * (renderer_.ambient + renderer_.diffuse * d) + renderer_.specular * s);
  }

  static constexpr int kSize = 64;
  std::unique_ptr<HeadlessContext> context_;
  std::unique_ptr<OffscreenTarget> target_;
  StreamlineRenderer renderer_;
};

}  // namespace

TEST_F(LitLines, ShadingFollowsTheClosedFormAlongTheLine) {
  // Three directions in the view plane give three values of L.T.
  for (const glm::dvec3 direction : {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(1, 1, 0) / std::sqrt(2.0)}) {
    const auto pixels = draw(direction, 5.0f);
    const double want = expected(direction);
    int checked = 0;
    for (int k = -20; k <= 20; ++k) {  // along the line, away from its ends
      const int x = kSize / 2 + int(std::lround(k * direction.x)), y = kSize / 2 - int(std::lround(k * direction.y));
      const std::uint8_t* p = &pixels[(std::size_t(y) * kSize + std::size_t(x)) * 4];
      if (p[0] == 255 && p[1] == 0 && p[2] == 255) continue;  // background: not on the line
      ++checked;
      EXPECT_NEAR(p[0] / 255.0, want, 2.5 / 255.0) << "direction (" << direction.x << ", " << direction.y << ") at " << k;
      EXPECT_EQ(p[0], p[1]);
    }
    EXPECT_GT(checked, 30) << "the line covers its pixels";
  }
}

TEST_F(LitLines, WidthIsInPixels) {
  const auto pixels = draw({1, 0, 0}, 7.0f);
  int covered = 0;  // across the horizontal line, at its middle
  for (int y = 0; y < kSize; ++y) {
    const std::uint8_t* p = &pixels[(std::size_t(y) * kSize + kSize / 2) * 4];
    covered += !(p[0] == 255 && p[1] == 0 && p[2] == 255);
  }
  EXPECT_NEAR(covered, 7, 1);
}
