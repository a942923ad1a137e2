// SPDX-License-Identifier: MIT
// The surface renderer in a headless EGL context, checked pixel by pixel against the
// exact colors a field must produce (no stored reference images).
#include <volpost/render/HeadlessContext.hpp>
#include <volpost/render/OffscreenTarget.hpp>
#include <volpost/render/ShaderLibrary.hpp>
#include <volpost/render/VolumeLimits.hpp>

#include "host/BoundarySurface.hpp"
#include "host/render/HostShaders.hpp"
#include "host/render/SurfaceRenderer.hpp"

#include <glm/gtc/matrix_inverse.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace volpost;

namespace {

constexpr int kSize = 96;
constexpr double kPlate = 4.0;  // plate of 4 x 4 x 1 unit hexahedra

Mesh plate() {
  Mesh m;
  const int n = int(kPlate);
  auto id = [n](int i, int j, int k) { return NodeIndex((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) m.nodes.push_back({double(i), double(j), double(k)});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const NodeIndex c[8] = {id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0),
                              id(i, j, 1), id(i + 1, j, 1), id(i + 1, j + 1, 1), id(i, j + 1, 1)};
      m.addCell(CellType::Hex8, c);
    }
  return m;
}

class HeadlessRender : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      context_ = std::make_unique<HeadlessContext>();
    } catch (const std::exception& e) {
      GTEST_SKIP() << "not run: no headless OpenGL 4.5 context: " << e.what();
    }
    mesh_ = plate();
    surface_ = extractBoundary(mesh_);
    target_ = std::make_unique<OffscreenTarget>(kSize, kSize);
    renderer_.initialize();
    renderer_.setSurface(surface_);
    renderer_.setColorMap(ColorMap::named("grayscale"));
    renderer_.setLighting(false);
    renderer_.setShowEdges(false);
    camera_.setProjection(Camera::Projection::Orthographic);
    camera_.setView(StandardView::PlusZ);
    camera_.fit(mesh_.bounds());
  }
  void TearDown() override {
    if (context_) renderer_.release();
  }

  std::vector<std::uint8_t> draw() {
    RenderContext ctx;
    ctx.camera = camera_;
    ctx.width = ctx.height = kSize;
    ctx.framebuffer = target_->framebuffer();
    ctx.origin = surface_.origin;
    glBindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer);
    glViewport(0, 0, kSize, kSize);
    glClearColor(1.0f, 0.0f, 1.0f, 1.0f);  // magenta: never a grayscale color
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    renderer_.render(ctx);
    gl::check("draw");
    return target_->readPixels();
  }

  /// Model (x, y) under the centre of pixel (px, py), py counted from the top.
  glm::dvec2 modelPointAt(int px, int py) const {
    const glm::dmat4 inv = glm::inverse(camera_.projectionMatrix(1.0) * camera_.viewMatrix());
    const glm::dvec4 ndc(2.0 * (px + 0.5) / kSize - 1.0, 1.0 - 2.0 * (py + 0.5) / kSize, 0.0, 1.0);
    const glm::dvec4 p = inv * ndc;
    return {p.x / p.w, p.y / p.w};
  }

  std::unique_ptr<HeadlessContext> context_;
  Mesh mesh_;
  BoundarySurface surface_;
  std::unique_ptr<OffscreenTarget> target_;
  SurfaceRenderer renderer_;
  Camera camera_;
};

bool isBackground(const std::uint8_t* p) { return p[0] == 255 && p[1] == 0 && p[2] == 255; }

}  // namespace

TEST_F(HeadlessRender, EveryHostShaderCompiles) {
  registerHostShaders();
  int programs = 0;
  for (const std::string& name : gl::shaderNames()) {
    if (!name.starts_with("host/") || !name.ends_with(".vert")) continue;
    const std::string base = name.substr(0, name.rfind('.'));
    const auto names = gl::shaderNames();
    std::vector<std::string> stages = {name};
    if (std::find(names.begin(), names.end(), base + ".geom") != names.end()) stages.push_back(base + ".geom");
    stages.push_back(base + ".frag");
    // As the host builds them: the volume limits defined (clip_planes.glsl sizes its array).
    EXPECT_NO_THROW(gl::buildProgram(stages, volumeLimitDefines())) << name;
    ++programs;
  }
  EXPECT_GE(programs, 5);  // surface, edges, overlay, streamline, tube
}

TEST_F(HeadlessRender, NodalFieldIsInterpolatedLinearly) {
  // f = x: every pixel over the plate shows gray level x / 4, to 8-bit precision.
  std::vector<double> f(mesh_.nodeCount());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = mesh_.nodes[i].x;
  renderer_.setScalars(FieldLocation::Node, f, 0.0, kPlate);
  const auto pixels = draw();
  int covered = 0;
  double worst = 0.0;
  for (int py = 0; py < kSize; ++py)
    for (int px = 0; px < kSize; ++px) {
      const std::uint8_t* p = &pixels[std::size_t(py * kSize + px) * 4];
      const glm::dvec2 m = modelPointAt(px, py);
      const bool inside = m.x > 0.02 && m.x < kPlate - 0.02 && m.y > 0.02 && m.y < kPlate - 0.02;
      const bool outside = m.x < -0.02 || m.x > kPlate + 0.02 || m.y < -0.02 || m.y > kPlate + 0.02;
      if (outside) EXPECT_TRUE(isBackground(p)) << px << "," << py;
      if (!inside) continue;
      ++covered;
      ASSERT_FALSE(isBackground(p)) << "hole at pixel " << px << "," << py;
      worst = std::max(worst, std::abs(p[0] / 255.0 - m.x / kPlate));
      EXPECT_EQ(p[0], p[1]);
    }
  EXPECT_GT(covered, kSize * kSize / 4);
  EXPECT_LE(worst, 2.5 / 255.0) << "largest gray-level error";
}

TEST_F(HeadlessRender, CellFieldIsConstantInEachCell) {
  std::vector<double> f(mesh_.cellCount());
  for (std::size_t c = 0; c < f.size(); ++c) f[c] = double(c);
  renderer_.setScalars(FieldLocation::Cell, f, 0.0, double(f.size() - 1));
  const auto pixels = draw();
  for (int py = 0; py < kSize; ++py)
    for (int px = 0; px < kSize; ++px) {
      const glm::dvec2 m = modelPointAt(px, py);
      const double fx = m.x - std::floor(m.x), fy = m.y - std::floor(m.y);
      if (m.x < 0 || m.y < 0 || m.x >= kPlate || m.y >= kPlate || fx < 0.05 || fx > 0.95 || fy < 0.05 || fy > 0.95)
        continue;  // away from cell borders
      const int cell = int(std::floor(m.y)) * int(kPlate) + int(std::floor(m.x));
      const double expected = double(cell) / double(f.size() - 1);
      EXPECT_NEAR(pixels[std::size_t(py * kSize + px) * 4] / 255.0, expected, 1.5 / 255.0) << "cell " << cell;
    }
}

TEST_F(HeadlessRender, NonFiniteValuesGetTheNoValueColorAndNothingElseChanges) {
  std::vector<double> f(mesh_.nodeCount(), 0.0);
  f[0] = std::nan("");                      // corner (0, 0, 0): on the hidden bottom face
  f[mesh_.nodeCount() - 1] = std::nan("");  // corner (4, 4, 1): on the top face, seen from +z
  renderer_.noValueColor = {0.0f, 0.0f, 1.0f};
  renderer_.setScalars(FieldLocation::Node, f, -1.0, 1.0);
  const auto pixels = draw();
  int blue = 0;
  for (int py = 0; py < kSize; ++py)
    for (int px = 0; px < kSize; ++px) {
      const std::uint8_t* p = &pixels[std::size_t(py * kSize + px) * 4];
      const glm::dvec2 m = modelPointAt(px, py);
      if (isBackground(p)) continue;
      const bool nearNaN = m.x > 3.0 && m.y > 3.0;  // the top quad that uses the NaN node
      const bool isBlue = p[2] == 255 && p[0] == 0;
      blue += isBlue;
      if (isBlue) EXPECT_TRUE(nearNaN) << px << "," << py;
      if (m.x > 3.05 && m.y > 3.05 && m.x < 3.95 && m.y < 3.95) EXPECT_TRUE(isBlue) << px << "," << py;
      if (!nearNaN) EXPECT_NEAR(p[0], 128, 1);
    }
  EXPECT_GT(blue, 10);
}

TEST_F(HeadlessRender, FarFromOriginModelRendersLikeTheOriginalOne) {
  // Coordinates near 1e6 with cells of 1e-3: GPU data is relative to the model center.
  std::vector<double> f(mesh_.nodeCount());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = mesh_.nodes[i].x;
  renderer_.setScalars(FieldLocation::Node, f, 0.0, kPlate);
  const auto reference = draw();
  for (auto& p : mesh_.nodes) p = p * 1e-3 + glm::dvec3(1e6, 2e6, -3e6);
  surface_ = extractBoundary(mesh_);
  renderer_.setSurface(surface_);
  camera_.fit(mesh_.bounds());
  const auto moved = draw();
  int differ = 0;
  for (std::size_t i = 0; i < reference.size(); i += 4) differ += std::abs(int(reference[i]) - int(moved[i])) > 2;
  EXPECT_LE(differ, kSize);  // a few edge pixels may round differently
}

// Element edges closer than a few pixels fade out instead of painting the faces over, and
// are drawn in full when the view is close enough to tell them apart.
TEST_F(HeadlessRender, DenseElementEdgesFadeWhenTheViewMovesAway) {
  renderer_.setShowEdges(true);
  renderer_.edgeColor = glm::vec3(0.0f);  // black edges on the default gray faces
  int shaded = 0;  // pixels between the faces' gray and black: a faded edge
  const auto darkPixels = [&] {
    const std::vector<std::uint8_t> image = draw();
    int dark = 0;
    shaded = 0;
    for (std::size_t i = 0; i < image.size(); i += 4) {
      if (isBackground(&image[i])) continue;
      dark += image[i] < 40;
      shaded += image[i] >= 40 && image[i] < 180;
    }
    return dark;
  };
  const int apart = darkPixels();  // unit edges about 19 pixels long
  EXPECT_GT(apart, 3 * kSize) << "the 5 x 5 grid lines are drawn";
  camera_.zoom(1.0 / 5.0);  // about 4 pixels an edge: fading
  EXPECT_EQ(darkPixels(), 0) << "faded edges are gray over the faces, not black";
  EXPECT_GT(shaded, 10) << "but still drawn";
  camera_.zoom(1.0 / 3.0);  // about 1.3 pixels an edge
  EXPECT_EQ(darkPixels(), 0) << "the faces show, not a black blot";
  std::vector<std::uint8_t> image = draw();
  int face = 0;
  for (std::size_t i = 0; i < image.size(); i += 4) face += !isBackground(&image[i]);
  EXPECT_GT(face, 10) << "the plate is still drawn";
}
