// SPDX-License-Identifier: MIT
#include "GridSlicer.hpp"

#include "VolumeBindings.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace volpost::volume {

namespace {

// The box's corners and their depths along the view direction.
struct Box {
  std::array<glm::dvec3, 8> p;
  std::array<double, 8> depth;
  glm::dvec3 e1, e2;  // a basis of the planes, to order a cut's points round its centre
  Box(const glm::dvec3& corner, const glm::dvec3& u, const glm::dvec3& v, const glm::dvec3& w, const glm::dvec3& eye,
      const glm::dvec3& viewDir) {
    for (int c = 0; c < 8; ++c)
      p[std::size_t(c)] = corner + double(c & 1) * u + double((c >> 1) & 1) * v + double((c >> 2) & 1) * w;
    for (std::size_t c = 0; c < 8; ++c) depth[c] = glm::dot(p[c] - eye, viewDir);
    const glm::dvec3 side = std::abs(viewDir.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    e1 = glm::normalize(glm::cross(viewDir, side));
    e2 = glm::cross(viewDir, e1);
  }
  double nearest() const { return *std::min_element(depth.begin(), depth.end()); }
  double farthest() const { return *std::max_element(depth.begin(), depth.end()); }

  // The polygon where the plane at depth d cuts the box, its corners moved `grow` further
  // from its centre, as a triangle fan; false if none.
  bool cut(double d, double grow, std::vector<glm::vec3>& triangles) const {
    static constexpr int kEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                          {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    std::vector<glm::dvec3> points;
    for (const auto& e : kEdges) {
      const double a = depth[std::size_t(e[0])] - d, b = depth[std::size_t(e[1])] - d;
      if ((a < 0.0) == (b < 0.0) || a == b) continue;
      points.push_back(p[std::size_t(e[0])] + (a / (a - b)) * (p[std::size_t(e[1])] - p[std::size_t(e[0])]));
    }
    if (points.size() < 3) return false;
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& q : points) centre += q;
    centre /= double(points.size());
    for (glm::dvec3& q : points)
      if (const double r = glm::length(q - centre); r > 0.0) q += (grow / r) * (q - centre);
    std::sort(points.begin(), points.end(), [&](const glm::dvec3& a, const glm::dvec3& b) {
      return std::atan2(glm::dot(a - centre, e2), glm::dot(a - centre, e1)) <
             std::atan2(glm::dot(b - centre, e2), glm::dot(b - centre, e1));
    });
    for (std::size_t i = 1; i + 1 < points.size(); ++i)
      for (const glm::dvec3& q : {points[0], points[i], points[i + 1]}) triangles.push_back(glm::vec3(q));
    return true;
  }
};

}  // namespace

std::vector<glm::vec3> slicePolygons(const glm::dvec3& corner, const glm::dvec3& u, const glm::dvec3& v,
                                     const glm::dvec3& w, const glm::dvec3& eye, const glm::dvec3& viewDir,
                                     double spacing, double nearest, std::size_t* slices,
                                     const std::function<double(double)>& grow) {
  const Box box(corner, u, v, w, eye, viewDir);
  const double lo = std::max(box.nearest(), nearest), hi = box.farthest();
  std::vector<glm::vec3> triangles;
  std::size_t count = 0;
  if (spacing > 0.0 && hi > lo && (hi - lo) / spacing <= 1e6)
    for (double k = std::floor(hi / spacing); k * spacing > lo; k -= 1.0)
      count += box.cut(k * spacing, grow ? grow(k * spacing) : 0.0, triangles);
  if (slices) *slices = count;
  return triangles;
}

namespace {

// The nearest and farthest distances from `eye` to the parallelepiped corner + a u + b v + c w
// (a, b, c in 0..1): the farthest is a corner's; the nearest 0 inside, else at most the
// distance to the eye's coordinates clamped into the box (exact for a rectangular box), and
// taken a twentieth of the farthest earlier for a sheared one (fragments outside the
// brick's part of a ray discard themselves).
std::pair<double, double> distanceRange(const glm::dvec3& eye, const glm::dvec3& corner, const glm::dvec3& u,
                                        const glm::dvec3& v, const glm::dvec3& w) {
  double farthest = 0.0;
  for (int c = 0; c < 8; ++c)
    farthest = std::max(farthest, glm::length(corner + double(c & 1) * u + double((c >> 1) & 1) * v +
                                              double((c >> 2) & 1) * w - eye));
  const glm::dmat3 box(u, v, w);
  const glm::dvec3 local = glm::clamp(glm::inverse(box) * (eye - corner), glm::dvec3(0.0), glm::dvec3(1.0));
  const double nearest = std::min(glm::length(corner + box * local - eye), farthest);
  return {std::max(0.0, nearest - 0.05 * farthest), farthest};
}

}  // namespace

void GridSlicer::setVolume(const Mesh&, FieldLocation, std::span<const double>) {
  throw std::invalid_argument("the texture slicer draws regular grids (SEG-Y, image data), not meshes of "
                              "tetrahedra: choose another volume renderer for this model");
}

// Shells when the eye looks in perspective from inside the grid or closer to it than half
// its diagonal: there planes would be crossed ever more obliquely toward the picture's edges.
bool GridSlicer::useShells(const RenderContext& ctx) const {
  if (ctx.camera.projection() == Camera::Projection::Orthographic) return false;
  const RegularGrid& grid = volume_.grid();
  const glm::dvec3 u = grid.axes[0] * double(grid.dims[0] - 1), v = grid.axes[1] * double(grid.dims[1] - 1),
                   w = grid.axes[2] * double(grid.dims[2] - 1);
  const glm::dvec3 local =
      glm::clamp(glm::inverse(glm::dmat3(u, v, w)) * (ctx.camera.eye() - grid.origin), glm::dvec3(0.0), glm::dvec3(1.0));
  const double distance = glm::length(grid.origin + glm::dmat3(u, v, w) * local - ctx.camera.eye());
  return distance < 0.5 * glm::length(u + v + w);
}

void GridSlicer::initialize() {
  volume_.initialize();
  framebuffer_ = gl::createFramebuffer();
  vertexArray_ = gl::createVertexArray();
  vertices_ = gl::createBuffer();
  glEnableVertexArrayAttrib(vertexArray_.id(), 0);
  glVertexArrayAttribFormat(vertexArray_.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vertexArray_.id(), 0, 0);
  attachedImage_ = 0;
  quick_.release();
  gl::check("GridSlicer::initialize");
}

void GridSlicer::release() {
  quick_.release();
  framebuffer_.reset();
  vertexArray_.reset();
  vertices_.reset();
  attachedImage_ = 0;
  volume_.release();
}

void GridSlicer::uploadSlices(const RenderContext& ctx, double spacing) {
  const RegularGrid& grid = volume_.grid();
  const glm::dvec3 origin = volume_.mesh().origin;
  // Depths along the view direction from the eye (orthographic too: any point of the view
  // axis serves); perspective slices lie in front of the eye.
  const glm::dvec3 viewDir = ctx.camera.viewDirection();
  const glm::dvec3 eye = ctx.camera.eye() - origin;
  const bool ortho = ctx.camera.projection() == Camera::Projection::Orthographic;
  const double nearest = ortho ? -1e300 : 0.0;  // in front of the eye (the near plane clips the rest)
  // Slices grown by two pixels at their depth (fragments off the box discard themselves).
  const double pixelsAcross = double(std::min(ctx.width, ctx.height));
  const double halfAngle = std::tan(0.5 * glm::radians(ctx.camera.fieldOfView()));
  const auto twoPixels = [&](double depth) {
    return 2.0 * (ortho ? ctx.camera.viewHeight() : 2.0 * depth * halfAngle) / pixelsAcross;
  };
  std::vector<glm::vec3> vertices;
  brickDraws_.clear();
  lastSlices_ = 0;
  shells_ = useShells(ctx);
  for (const std::size_t b : volume_.gridBricksInOrder(ctx, true)) {
    const GridBrick& brick = volume_.gridBricks().bricks()[b];
    const glm::dvec3 corner = grid.origin - origin + grid.indexToWorld() * glm::dvec3(double(brick.first[0]),
                                                                                     double(brick.first[1]),
                                                                                     double(brick.first[2]));
    const glm::dvec3 u = grid.axes[0] * double(brick.points[0] - 1), v = grid.axes[1] * double(brick.points[1] - 1),
                     w = grid.axes[2] * double(brick.points[2] - 1);
    // The brick's part of the picture (clip-space x, y): the entry pass's and the shells'.
    const auto [lo, hi] = volume_.gridBrickOnScreen(ctx, b);
    const std::array<glm::vec3, 6> quad{glm::vec3(lo.x, lo.y, 0), glm::vec3(hi.x, lo.y, 0), glm::vec3(hi.x, hi.y, 0),
                                        glm::vec3(lo.x, lo.y, 0), glm::vec3(hi.x, hi.y, 0), glm::vec3(lo.x, hi.y, 0)};
    BrickDraw draw{b, vertices.size(), 0, 0};
    if (shells_) {
      // Shells k (distances k .. k + 1 spacings from the eye) that meet the brick, farthest first.
      const auto [near, far] = distanceRange(eye, corner, u, v, w);
      const double first = std::floor(near / spacing), last = std::floor(far / spacing);
      for (double k = last; k >= first && last - first <= 1e6; k -= 1.0, ++lastSlices_)
        for (const glm::vec3& q : quad) vertices.push_back(glm::vec3(q.x, q.y, float(k)));
    } else {
      std::size_t slices = 0;
      const std::vector<glm::vec3> triangles =
          slicePolygons(corner, u, v, w, eye, viewDir, spacing, nearest, &slices, twoPixels);
      lastSlices_ += slices;
      vertices.insert(vertices.end(), triangles.begin(), triangles.end());
    }
    draw.count = vertices.size() - draw.first;
    draw.entryFirst = vertices.size();
    vertices.insert(vertices.end(), quad.begin(), quad.end());
    brickDraws_.push_back(draw);
  }
  glNamedBufferData(vertices_.id(), GLsizeiptr(std::max<std::size_t>(vertices.size() * sizeof(glm::vec3), 16)),
                    vertices.data(), GL_STREAM_DRAW);
  glVertexArrayVertexBuffer(vertexArray_.id(), 0, vertices_.id(), 0, sizeof(glm::vec3));
}

GLuint GridSlicer::beginDrawing(const RenderContext& ctx, GLuint image, bool clear, double spacing) {
  GpuVolume::beginDrawingIntoImage(framebuffer_, attachedImage_, image, ctx, clear);
  const GLuint p = volume_.program({"volume/gridslice.vert", "volume/gridslice.frag"});
  glUseProgram(p);
  volume_.setSegmentUniforms(p, ctx);
  const glm::dvec3 viewDir = ctx.camera.viewDirection();
  const glm::dvec3 eye = ctx.camera.eye() - volume_.mesh().origin;
  const glm::mat4 vp = volume_.imageViewProjection(ctx);
  const auto uniform = [p](const char* n) { return glGetUniformLocation(p, n); };
  glProgramUniformMatrix4fv(p, uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(vp));
  glProgramUniform3f(p, uniform("viewDir"), float(viewDir.x), float(viewDir.y), float(viewDir.z));
  glProgramUniform1f(p, uniform("sliceSpacing"), float(spacing));
  glProgramUniform3f(p, uniform("sliceEye"), float(eye.x), float(eye.y), float(eye.z));
  volume_.bindSegmentResources(ctx);
  glBindVertexArray(vertexArray_.id());
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // back to front, premultiplied "over"
  return p;
}

void GridSlicer::drawSlices(GLuint program, std::size_t first, std::size_t count) {
  glProgramUniform1i(program, glGetUniformLocation(program, "entryPass"), 0);
  glProgramUniform1i(program, glGetUniformLocation(program, "shellPass"), shells_);
  glProgramUniform1i(program, glGetUniformLocation(program, "screenQuad"), shells_);
  glDrawArrays(GL_TRIANGLES, GLint(first), GLsizei(count));  // farthest first
}

void GridSlicer::drawEntry(GLuint program, const BrickDraw& draw) {
  if (shells_) return;  // shells leave no entry part
  glProgramUniform1i(program, glGetUniformLocation(program, "entryPass"), 1);
  glProgramUniform1i(program, glGetUniformLocation(program, "shellPass"), 0);
  glProgramUniform1i(program, glGetUniformLocation(program, "screenQuad"), 1);
  glDrawArrays(GL_TRIANGLES, GLint(draw.entryFirst), 6);  // the nearest part of the brick
}

void GridSlicer::endDrawing() {
  glDisable(GL_BLEND);
  glBindVertexArray(0);
}

double GridSlicer::drawWhole(const RenderContext& ctx, GLuint image, double spacing) {
  const auto start = std::chrono::steady_clock::now();
  uploadSlices(ctx, spacing);
  const GLuint p = beginDrawing(ctx, image, true, spacing);
  for (const BrickDraw& draw : brickDraws_) {
    volume_.bindGridBrick(p, draw.brick);
    drawSlices(p, draw.first, draw.count);
    drawEntry(p, draw);
  }
  endDrawing();
  if (!volume_.asynchronous()) return 0.0;
  glFinish();  // timed for sizing quick frames: the window's path only
  return millisecondsSince(start);
}

// Goes on where the last call stopped: brick refineBrick_, its slice vertices up to
// drawnVertices_ drawn (its entry last, then the next brick).
bool GridSlicer::refine(const RenderContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  const GLuint p = beginDrawing(ctx, volume_.image(), false, sliceSpacing());
  while (refineBrick_ < brickDraws_.size()) {
    const BrickDraw& draw = brickDraws_[refineBrick_];
    volume_.bindGridBrick(p, draw.brick);
    while (drawnVertices_ < draw.count) {
      const auto runStart = std::chrono::steady_clock::now();
      const std::size_t count = std::min(verticesPerRun_, draw.count - drawnVertices_);
      drawSlices(p, draw.first + drawnVertices_, count);
      glFinish();
      const double ms = millisecondsSince(runStart);
      refineMs_ += ms;
      drawnVertices_ += count;
      // The next run sized to the slice's time, in whole triangles.
      const double factor = std::clamp(quick_.sliceMs() / std::max(ms, 0.1), 0.25, 4.0);
      verticesPerRun_ = 3 * std::clamp<std::size_t>(std::size_t(double(verticesPerRun_ / 3) * factor), 1, 1u << 24);
      if (millisecondsSince(start) >= quick_.sliceMs()) {
        endDrawing();
        return false;
      }
    }
    const auto entryStart = std::chrono::steady_clock::now();
    drawEntry(p, draw);
    glFinish();
    refineMs_ += millisecondsSince(entryStart);
    drawnVertices_ = 0;
    ++refineBrick_;
    if (refineBrick_ < brickDraws_.size() && millisecondsSince(start) >= quick_.sliceMs()) {
      endDrawing();
      return false;
    }
  }
  endDrawing();
  quick_.measured(refineMs_, ctx.width, ctx.height);
  return true;
}

void GridSlicer::render(const RenderContext& ctx) {
  if (!volume_.initialized() || !volume_.hasGrid() || ctx.width <= 0 || ctx.height <= 0) return;
  volume_.prepare(ctx);
  if (!volume_.asynchronous()) {
    quick_.forget();
    drawWhole(ctx, volume_.image(), sliceSpacing());
    volume_.compositeOver(ctx);
    gl::check("GridSlicer::render");
    return;
  }
  const GLuint shown = quick_.frame(
      ctx, volume_.revision(), volume_.meshRevision(), 0, volume_.image(),
      [this, &ctx](const RenderContext& c, GLuint image) {
        // A quick frame of one pixel per r x r gets slices r times further apart: its
        // cost falls with its depth resolution as with its pixels.
        const int reduction = std::max(1, ctx.width / std::max(1, c.width));
        return drawWhole(c, image, sliceSpacing() * double(reduction));
      },
      [this, &ctx] {
        uploadSlices(ctx, sliceSpacing());  // the full frame's slices, kept while it is refined
        beginDrawing(ctx, volume_.image(), true, sliceSpacing());  // the full frame starts empty
        endDrawing();
        refineBrick_ = 0;
        drawnVertices_ = 0;
        refineMs_ = 0.0;
      },
      [this, &ctx] { return refine(ctx); });
  volume_.compositeOver(ctx, shown);
  gl::check("GridSlicer::render");
}

}  // namespace volpost::volume
