// SPDX-License-Identifier: MIT
#include "Glyphs.hpp"

#include "CellSection.hpp"

#include <volpost/core/Quantity.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace volpost::app {
namespace {

constexpr int kSides = 8;  // of a shaft, a cone, a bar's cross-section is 4

const Field* glyphField(const ModelSession& session, const std::string& name) {
  const Field* f = session.model().findField(name);
  if (f && f->location() == FieldLocation::Node && f->stepCount() > 0 &&
      (f->kind() == FieldKind::Vector || f->kind() == FieldKind::SymTensor))
    return f;
  std::string choices;
  for (const auto& field : session.model().fields)
    if (field->location() == FieldLocation::Node &&
        (field->kind() == FieldKind::Vector || field->kind() == FieldKind::SymTensor))
      choices += (choices.empty() ? "" : ", ") + field->name();
  throw std::invalid_argument("glyphs need a nodal vector or symmetric tensor field; '" + name + "' is not one" +
                              (choices.empty() ? " (this model has none)" : " (this model has: " + choices + ")"));
}

// Two unit vectors across `axis`, the three orthonormal.
std::pair<glm::dvec3, glm::dvec3> across(const glm::dvec3& axis) {
  const glm::dvec3 other = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(axis, other));
  return {u, glm::cross(axis, u)};
}

struct Builder {
  GlyphGeometry& out;
  void triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double value) {
    out.corners.insert(out.corners.end(), {a, b, c});
    out.values.insert(out.values.end(), {value, value, value});
  }
  // From `base` along `axis` (unit) for `length`: a shaft of radius 0.03 length and a cone
  // of 0.35 length and radius 0.1 length, as ParaView's arrow source.
  void arrow(const glm::dvec3& base, const glm::dvec3& axis, double length, double value) {
    const auto [u, w] = across(axis);
    const double shaftRadius = 0.03 * length, coneRadius = 0.1 * length;
    const glm::dvec3 neck = base + axis * (0.65 * length), tip = base + axis * length;
    const auto ring = [&](const glm::dvec3& centre, double r, int i) {
      const double a = 2.0 * std::numbers::pi * i / kSides;
      return centre + r * (std::cos(a) * u + std::sin(a) * w);
    };
    for (int i = 0; i < kSides; ++i) {
      const glm::dvec3 b0 = ring(base, shaftRadius, i), b1 = ring(base, shaftRadius, i + 1);
      const glm::dvec3 n0 = ring(neck, shaftRadius, i), n1 = ring(neck, shaftRadius, i + 1);
      triangle(b0, b1, n1, value);
      triangle(b0, n1, n0, value);
      const glm::dvec3 c0 = ring(neck, coneRadius, i), c1 = ring(neck, coneRadius, i + 1);
      triangle(c0, c1, tip, value);
      triangle(c1, c0, neck, value);  // the cone's base
    }
  }
  // A square bar centred on `centre` along `axis`, `length` long, 0.08 length thick.
  void bar(const glm::dvec3& centre, const glm::dvec3& axis, double length, double value) {
    const auto [u0, w0] = across(axis);
    const double h = 0.04 * length;
    const glm::dvec3 u = u0 * h, w = w0 * h, half = axis * (0.5 * length);
    const glm::dvec3 corner[4] = {u + w, -u + w, -u - w, u - w};
    for (int i = 0; i < 4; ++i) {
      const glm::dvec3 a = corner[i], b = corner[(i + 1) % 4];
      triangle(centre - half + a, centre - half + b, centre + half + b, value);
      triangle(centre - half + a, centre + half + b, centre + half + a, value);
    }
    for (const double end : {-1.0, 1.0}) {
      const glm::dvec3 c = centre + end * half;
      triangle(c + corner[0], c + corner[1], c + corner[2], value);
      triangle(c + corner[0], c + corner[2], c + corner[3], value);
    }
  }
};

// The nodes glyphs may sit on: the surface's, or every node some cell uses.
std::vector<NodeIndex> chosenNodes(const ModelSession& session, bool allNodes) {
  std::vector<char> used(session.model().nodeCount(), 0);
  if (allNodes) {
    const Mesh& mesh = session.model().mesh();
    for (std::size_t c = 0; c < mesh.cellCount(); ++c)
      for (const NodeIndex n : mesh.cellNodes(c))
        if (n < used.size()) used[n] = 1;
  } else {
    const BoundarySurface& s = session.surface();
    for (const auto v : s.mesh.vertices()) {
      const NodeIndex n = s.mesh.property(s.nodeOfVertex, v);
      if (n < used.size()) used[n] = 1;
    }
  }
  std::vector<NodeIndex> nodes;
  for (std::size_t n = 0; n < used.size(); ++n)
    if (used[n]) nodes.push_back(NodeIndex(n));
  return nodes;
}

// Where a glyph may sit, with the field's components there and the coloring value.
struct Anchor {
  glm::dvec3 at{0.0};
  std::array<double, 6> c{};
  double color = std::numeric_limits<double>::quiet_NaN();
};

// The chosen nodes the clip planes keep (a glyph whose node is cut away is not drawn, and
// one whose node is kept is drawn whole), then, for the surface's glyphs, one at the centre
// of each cell's cut face, its values interpolated along the cut edges.
std::vector<Anchor> glyphAnchors(const ModelSession& session, const GlyphLayer& layer, const std::vector<double>& v,
                                 std::size_t width, const ScalarView* colors, const std::vector<ClipPlane>& cuts,
                                 bool onCutFaces) {
  const Model& model = session.model();
  const double tolerance = 1e-9 * std::max(session.bounds().diagonal(), 1e-300);
  const auto kept = [&](const glm::dvec3& p) {
    for (const ClipPlane& c : cuts)
      if (glm::dot(p - c.point, glm::normalize(c.normal)) < -tolerance) return false;
    return true;
  };
  const auto colorAt = [&](NodeIndex n) {
    return colors && n < colors->values.size() ? double(colors->values[n]) : std::numeric_limits<double>::quiet_NaN();
  };
  std::vector<Anchor> out;
  for (const NodeIndex n : chosenNodes(session, layer.allNodes)) {
    if (std::size_t(n) * width + width > v.size() || !kept(model.nodePosition(n))) continue;
    Anchor a;
    a.at = model.nodePosition(n);
    std::copy_n(v.data() + std::size_t(n) * width, width, a.c.begin());
    a.color = colorAt(n);
    out.push_back(a);
  }
  if (layer.allNodes || !onCutFaces || !model.meshBuilt()) return out;
  for (const ClipPlane& plane : cuts)
    for (std::size_t cell = 0; cell < model.cellCount(); ++cell) {
      const std::vector<SectionPoint> section = cellSection(model, cell, plane);
      if (section.size() < 3) continue;
      Anchor a;
      a.color = 0.0;
      bool inside = true;
      for (const SectionPoint& p : section) {
        if (std::size_t(std::max(p.a, p.b)) * width + width > v.size()) inside = false;
        if (!inside) break;
        const double share = 1.0 / double(section.size());
        a.at += p.at * share;
        for (std::size_t k = 0; k < width; ++k)
          a.c[k] += share * ((1.0 - p.t) * v[std::size_t(p.a) * width + k] + p.t * v[std::size_t(p.b) * width + k]);
        a.color += share * ((1.0 - p.t) * colorAt(p.a) + p.t * colorAt(p.b));
      }
      if (inside && kept(a.at)) out.push_back(a);
    }
  return out;
}

}  // namespace

void checkGlyphLayer(const ModelSession& session, const GlyphLayer& layer) {
  if (!layer.shown) return;
  (void)glyphField(session, layer.field);
  if (!layer.colorBy.empty()) {
    const Quantity q = session.findQuantity(layer.colorBy);  // throws naming the quantities
    if (session.fieldOf(q).location() != FieldLocation::Node)
      throw std::invalid_argument("glyphs are colored by a quantity at the nodes; " + layer.colorBy +
                                  " is given per element");
  }
  if (layer.scale && !(*layer.scale > 0.0 && std::isfinite(*layer.scale)))
    throw std::invalid_argument("the glyphs' scale must be a positive number");
  if (layer.every < 0) throw std::invalid_argument("glyphs at every k-th node need k >= 1 (0: automatic)");
}

GlyphGeometry buildGlyphs(const ModelSession& session, const GlyphLayer& layer, std::size_t step,
                          const std::vector<ClipPlane>& cuts, bool onCutFaces) {
  checkGlyphLayer(session, layer);
  const Field& field = *glyphField(session, layer.field);
  const bool tensor = field.kind() == FieldKind::SymTensor;
  const std::vector<double>& v = field.values(std::min(step, field.stepCount() - 1));
  const std::size_t width = tensor ? 6 : 3;
  GlyphGeometry out;
  std::optional<ScalarView> colors;
  if (!layer.colorBy.empty()) {
    const Quantity q = session.findQuantity(layer.colorBy);
    colors = session.evaluate(q, std::min(step, session.fieldOf(q).stepCount() - 1));
  }
  const std::vector<Anchor> anchors =
      glyphAnchors(session, layer, v, width, colors ? &*colors : nullptr, cuts, onCutFaces);
  out.candidates = anchors.size();
  out.every = layer.every > 0 ? std::size_t(layer.every)
                              : std::max<std::size_t>(1, (anchors.size() + kAutomaticGlyphs - 1) / kAutomaticGlyphs);
  const std::size_t count = (anchors.size() + out.every - 1) / out.every;
  if (count > kMaxGlyphs)
    throw std::invalid_argument(std::to_string(count) + " glyphs (every " + std::to_string(out.every) + " of " +
                                std::to_string(anchors.size()) + " places); at most " + std::to_string(kMaxGlyphs) +
                                ": take every " + std::to_string((anchors.size() + kMaxGlyphs - 1) / kMaxGlyphs) +
                                "th node or more");
  // The largest length (or principal value) among the glyphs drawn sets the automatic scale.
  const auto sizeAt = [&](const Anchor& a, std::array<double, 3>* principal, PrincipalAxes* axes) {
    const double* c = a.c.data();
    if (!tensor) return std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    *axes = principalAxes(c);
    *principal = axes->values;
    return std::max({std::abs(axes->values[0]), std::abs(axes->values[1]), std::abs(axes->values[2])});
  };
  double largest = 0.0;
  for (std::size_t i = 0; i < anchors.size(); i += out.every) {
    std::array<double, 3> p{};
    PrincipalAxes a;
    const double s = sizeAt(anchors[i], &p, &a);
    if (std::isfinite(s)) largest = std::max(largest, s);
  }
  const double diagonal = session.bounds().diagonal();
  // At a stride the glyphs are further apart: the automatic length grows with it, up to
  // twice, so a coarse pick still reads.
  const double target = kAutomaticGlyphSize * diagonal * std::min(2.0, std::cbrt(double(out.every)));
  if (layer.fixedLength && !tensor) out.scale = layer.scale.value_or(target);
  else out.scale = layer.scale.value_or(largest > 0.0 ? target / largest : 0.0);
  out.valueName = !layer.colorBy.empty() ? layer.colorBy
                  : tensor               ? layer.field + " principal values"
                                         : layer.field + " magnitude";
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  Builder build{out};
  for (std::size_t i = 0; i < anchors.size(); i += out.every) {
    const Anchor& anchor = anchors[i];
    std::array<double, 3> principal{};
    PrincipalAxes axes;
    const double size = sizeAt(anchor, &principal, &axes);
    if (!std::isfinite(size) || size == 0.0 || out.scale == 0.0) continue;
    const glm::dvec3 at = anchor.at;
    const double colorValue = colors ? anchor.color : size;
    if (colors && !std::isfinite(colorValue)) continue;
    if (!tensor) {
      const double* c = anchor.c.data();
      const glm::dvec3 direction = glm::dvec3(c[0], c[1], c[2]) / size;
      build.arrow(at, direction, layer.fixedLength ? out.scale : size * out.scale, colorValue);
      lo = std::min(lo, colorValue);
      hi = std::max(hi, colorValue);
    } else {
      for (int k = 0; k < 3; ++k) {
        const double value = principal[std::size_t(k)];
        if (std::abs(value) == 0.0) continue;
        const glm::dvec3 d(axes.directions[std::size_t(k)][0], axes.directions[std::size_t(k)][1],
                           axes.directions[std::size_t(k)][2]);
        const double shown = colors ? colorValue : value;
        build.bar(at, d, std::abs(value) * out.scale, shown);
        lo = std::min(lo, shown);
        hi = std::max(hi, shown);
      }
    }
    ++out.glyphs;
  }
  if (out.glyphs == 0) lo = 0.0, hi = 1.0;
  out.dataMin = lo;
  out.dataMax = hi;
  if (tensor && !colors) {  // tension and compression on either side of the map's middle
    const double m = std::max({std::abs(lo), std::abs(hi), 1e-300});
    lo = -m, hi = m;
  }
  if (!(hi > lo)) hi = lo + (lo == 0.0 ? 1.0 : std::abs(lo) * 1e-6);
  out.min = lo;
  out.max = hi;
  return out;
}

}  // namespace volpost::app
