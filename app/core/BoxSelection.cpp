// SPDX-License-Identifier: MIT
#include "BoxSelection.hpp"

#include "CellSection.hpp"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace volpost::app {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A point as the picture has it: pixel position, the projection's w (for interpolation
// that is right under perspective), and the model point.
struct Projected {
  glm::dvec2 pixel{0.0};
  double w = 1.0;
  double depth = 0.0;  ///< along the view direction from the eye
  glm::dvec3 point{0.0};
};

class Projector {
 public:
  Projector(const Camera& camera, const glm::dvec3& origin, double width, double height)
      : toClip_(camera.projectionMatrix(width / height) * camera.viewMatrix(origin)),
        origin_(origin),
        eye_(camera.eye()),
        direction_(camera.viewDirection()),
        width_(width),
        height_(height) {}
  std::optional<Projected> operator()(const glm::dvec3& p) const {
    const glm::dvec4 clip = toClip_ * glm::dvec4(p - origin_, 1.0);
    if (!(clip.w > 0.0)) return std::nullopt;  // behind the eye
    return Projected{{(clip.x / clip.w + 1.0) * 0.5 * width_, (1.0 - clip.y / clip.w) * 0.5 * height_},
                     clip.w,
                     glm::dot(p - eye_, direction_),
                     p};
  }

 private:
  glm::dmat4 toClip_;
  glm::dvec3 origin_, eye_, direction_;
  double width_, height_;
};

// The clip planes and box: what they cut away is not there to select.
class Kept {
 public:
  Kept(const Scene& scene, double diagonal)
      : cuts_(scene.state().volume.allClipPlanes()), tolerance_(1e-9 * std::max(diagonal, 1e-300)) {
    for (ClipPlane& c : cuts_) c.normal = glm::normalize(c.normal);
  }
  bool operator()(const glm::dvec3& p) const {
    for (const ClipPlane& c : cuts_)
      if (glm::dot(p - c.point, c.normal) < -tolerance_) return false;
    return true;
  }
  const std::vector<ClipPlane>& planes() const { return cuts_; }

 private:
  std::vector<ClipPlane> cuts_;
  double tolerance_;
};

struct PixelBounds {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< pixels [x0, x1) x [y0, y1)
  bool empty() const { return x1 <= x0 || y1 <= y0; }
};

PixelBounds pixelBounds(const PictureBox& box, double width, double height) {
  PixelBounds b;
  b.x0 = std::clamp(int(std::floor(std::min(box.x0, box.x1))), 0, int(width));
  b.x1 = std::clamp(int(std::ceil(std::max(box.x0, box.x1))), 0, int(width));
  b.y0 = std::clamp(int(std::floor(std::min(box.y0, box.y1))), 0, int(height));
  b.y1 = std::clamp(int(std::ceil(std::max(box.y0, box.y1))), 0, int(height));
  if (b.x1 == b.x0 && b.x0 < int(width)) ++b.x1;  // a click: the pixel under it
  if (b.y1 == b.y0 && b.y0 < int(height)) ++b.y1;
  return b;
}

bool inBox(const glm::dvec2& p, const PictureBox& box) {
  return p.x >= std::min(box.x0, box.x1) && p.x <= std::max(box.x0, box.x1) && p.y >= std::min(box.y0, box.y1) &&
         p.y <= std::max(box.y0, box.y1);
}

// The nearest depth and element of each pixel of the box, drawn triangle by triangle.
class DepthBuffer {
 public:
  DepthBuffer(PixelBounds bounds, const Kept& kept)
      : b_(bounds),
        kept_(kept),
        depth_(std::size_t(b_.x1 - b_.x0) * std::size_t(b_.y1 - b_.y0), kInfinity),
        owner_(depth_.size(), kNone) {}

  void draw(const std::array<Projected, 3>& v, std::uint32_t cell) {
    const double area = edge(v[0].pixel, v[1].pixel, v[2].pixel);
    if (area == 0.0 || !std::isfinite(area)) return;
    const double minX = std::min({v[0].pixel.x, v[1].pixel.x, v[2].pixel.x});
    const double maxX = std::max({v[0].pixel.x, v[1].pixel.x, v[2].pixel.x});
    const double minY = std::min({v[0].pixel.y, v[1].pixel.y, v[2].pixel.y});
    const double maxY = std::max({v[0].pixel.y, v[1].pixel.y, v[2].pixel.y});
    const int x0 = std::max(b_.x0, int(std::floor(minX - 0.5)));
    const int x1 = std::min(b_.x1, int(std::ceil(maxX + 0.5)));
    const int y0 = std::max(b_.y0, int(std::floor(minY - 0.5)));
    const int y1 = std::min(b_.y1, int(std::ceil(maxY + 0.5)));
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const glm::dvec2 c(x + 0.5, y + 0.5);
        double b[3] = {edge(v[1].pixel, v[2].pixel, c) / area, edge(v[2].pixel, v[0].pixel, c) / area,
                       edge(v[0].pixel, v[1].pixel, c) / area};
        if (b[0] < 0.0 || b[1] < 0.0 || b[2] < 0.0) continue;
        // Weights right under perspective: linear in screen space over w.
        double sum = 0.0;
        for (int k = 0; k < 3; ++k) sum += b[k] /= v[std::size_t(k)].w;
        const glm::dvec3 point = (b[0] * v[0].point + b[1] * v[1].point + b[2] * v[2].point) / sum;
        const double depth = (b[0] * v[0].depth + b[1] * v[1].depth + b[2] * v[2].depth) / sum;
        double& d = depthAt(x, y);
        if (depth < d && kept_(point)) {
          d = depth;
          ownerAt(x, y) = cell;
        }
      }
  }

  /// Elements seen in the box.
  std::vector<std::uint32_t> owners() const {
    std::vector<std::uint32_t> out;
    for (const std::size_t o : owner_)
      if (o != kNone) out.push_back(std::uint32_t(o));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  /// Whether a point at `depth` over pixel `p` is seen: nothing nearer than it (within
  /// `tolerance`) at its pixel, or a face through it at a pixel beside it (a node on an
  /// edge lies between pixels' centres).
  bool seen(const glm::dvec2& p, double depth, double tolerance) const {
    const int px = int(std::floor(p.x)), py = int(std::floor(p.y));
    const auto inside = [&](int x, int y) { return x >= b_.x0 && x < b_.x1 && y >= b_.y0 && y < b_.y1; };
    if (inside(px, py) && depth <= depthAt(px, py) + tolerance) return true;
    for (int y = py - 1; y <= py + 1; ++y)
      for (int x = px - 1; x <= px + 1; ++x)
        if (inside(x, y) && std::isfinite(depthAt(x, y)) && std::abs(depth - depthAt(x, y)) <= tolerance) return true;
    return false;
  }

 private:
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  static double edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  }
  std::size_t index(int x, int y) const {
    return std::size_t(y - b_.y0) * std::size_t(b_.x1 - b_.x0) + std::size_t(x - b_.x0);
  }
  double& depthAt(int x, int y) { return depth_[index(x, y)]; }
  double depthAt(int x, int y) const { return depth_[index(x, y)]; }
  std::size_t& ownerAt(int x, int y) { return owner_[index(x, y)]; }

  PixelBounds b_;
  const Kept& kept_;
  std::vector<double> depth_;
  std::vector<std::size_t> owner_;
};

// The boundary surface's triangles (unless hidden) and the faces the clip planes cut
// (each cell's section by each plane, from the edges of its corners) into the buffer.
void drawSeen(DepthBuffer& buffer, const Scene& scene, const Projector& project, const Kept& kept) {
  const ModelSession& session = *scene.session();
  const Model& model = session.model();
  if (scene.state().surfaceShown) {
    const BoundarySurface& surface = session.surface();
    for (const auto face : surface.mesh.faces()) {
      std::array<Projected, 3> v;
      int k = 0;
      bool front = true;
      for (const auto vertex : surface.mesh.fv_range(face)) {
        const auto p = project(model.nodePosition(surface.mesh.property(surface.nodeOfVertex, vertex)));
        if (!p || k > 2) front = false;
        else v[std::size_t(k++)] = *p;
      }
      if (front && k == 3) buffer.draw(v, surface.mesh.property(surface.cellOfFace, face));
    }
  }
  for (const ClipPlane& plane : kept.planes())
    for (std::size_t c = 0; c < model.cellCount(); ++c) {
      const std::vector<SectionPoint> section = cellSection(model, c, plane);
      if (section.size() < 3) continue;
      const auto p0 = project(section[0].at);
      for (std::size_t i = 1; p0 && i + 1 < section.size(); ++i) {
        const auto p1 = project(section[i].at), p2 = project(section[i + 1].at);
        if (p1 && p2) buffer.draw({*p0, *p1, *p2}, std::uint32_t(c));
      }
    }
}

// What both kinds of selection work from: the drawn model, its projection into the picture
// and the clip planes. nullopt where there is nothing to select (a grid, no cells, no picture).
struct Picture {
  const ModelSession& session;
  const Model& model;
  Projector project;
  Kept kept;
};

std::optional<Picture> pictureOf(const Scene& scene, const Camera& camera, double width, double height) {
  const ModelSession* session = scene.session();
  if (!session || !session->model().meshBuilt() || session->model().cellCount() == 0 || !(width > 0.0) ||
      !(height > 0.0))
    return std::nullopt;
  return Picture{*session, session->model(), Projector(camera, session->origin(), width, height),
                 Kept(scene, session->bounds().diagonal())};
}

}  // namespace

std::vector<std::uint32_t> elementsInBox(const Scene& scene, const Camera& camera, double width, double height,
                                         const PictureBox& box, SelectionDepth depth) {
  const std::optional<Picture> picture = pictureOf(scene, camera, width, height);
  if (!picture) return {};
  const auto& [session, model, project, kept] = *picture;
  if (depth == SelectionDepth::Surface) {
    const PixelBounds bounds = pixelBounds(box, width, height);
    if (bounds.empty()) return {};
    DepthBuffer buffer(bounds, kept);
    drawSeen(buffer, scene, project, kept);
    return buffer.owners();
  }
  std::vector<std::uint32_t> out;
  const Mesh& mesh = model.mesh();
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) {
    const auto nodes = mesh.cellNodes(c);
    const int corners = topology(mesh.cellType(c)).cornerCount;
    glm::dvec3 centre(0.0);
    for (int k = 0; k < corners; ++k) centre += model.nodePosition(nodes[std::size_t(k)]) / double(corners);
    const auto p = project(centre);
    if (p && inBox(p->pixel, box) && kept(centre)) out.push_back(std::uint32_t(c));
  }
  return out;
}

std::vector<std::uint32_t> nodesInBox(const Scene& scene, const Camera& camera, double width, double height,
                                      const PictureBox& box, SelectionDepth depth) {
  const std::optional<Picture> picture = pictureOf(scene, camera, width, height);
  if (!picture) return {};
  const auto& [session, model, project, kept] = *picture;
  std::vector<char> candidate(model.mesh().nodeCount(), 0);
  if (depth == SelectionDepth::Surface) {
    if (!scene.state().surfaceShown) return {};  // a cut face has no nodes on it
    const BoundarySurface& surface = session.surface();
    for (const auto vertex : surface.mesh.vertices())
      candidate[surface.mesh.property(surface.nodeOfVertex, vertex)] = 1;
  } else {
    for (const NodeIndex n : model.mesh().connectivity()) candidate[n] = 1;
  }
  std::optional<DepthBuffer> buffer;
  if (depth == SelectionDepth::Surface) {
    PixelBounds bounds = pixelBounds(box, width, height);
    // A node on the box's edge is tested against the pixels beside it too.
    bounds = {std::max(0, bounds.x0 - 1), std::max(0, bounds.y0 - 1), std::min(int(width), bounds.x1 + 1),
              std::min(int(height), bounds.y1 + 1)};
    if (bounds.empty()) return {};
    buffer.emplace(bounds, kept);
    drawSeen(*buffer, scene, project, kept);
  }
  // A node is seen when no face lies nearer than it by more than about two pixels' width
  // at its depth (the faces through it are sampled at the pixels' centres, not at it).
  const double pixelAtTarget = camera.viewHeight() / height;
  const bool perspective = camera.projection() == Camera::Projection::Perspective;
  std::vector<std::uint32_t> out;
  for (std::size_t n = 0; n < candidate.size(); ++n) {
    if (!candidate[n]) continue;
    const glm::dvec3 position = model.nodePosition(n);
    const auto p = project(position);
    if (!p || !inBox(p->pixel, box) || !kept(position)) continue;
    if (buffer) {
      const double pixel = perspective ? pixelAtTarget * p->depth / std::max(camera.distance(), 1e-300) : pixelAtTarget;
      if (!buffer->seen(p->pixel, p->depth, 3.0 * pixel + 1e-9 * session.bounds().diagonal())) continue;
    }
    out.push_back(std::uint32_t(n));
  }
  return out;
}

}  // namespace volpost::app
