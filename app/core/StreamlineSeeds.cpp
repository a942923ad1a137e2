// SPDX-License-Identifier: MIT
#include "StreamlineSeeds.hpp"

#include <glm/geometric.hpp>

#include <charconv>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>

namespace volpost::app {
namespace {

std::vector<std::string> split(const std::string& s, char by) {
  std::vector<std::string> out;
  std::string part;
  std::istringstream in(s);
  while (std::getline(in, part, by)) out.push_back(part);
  if (!s.empty() && s.back() == by) out.push_back("");
  return out;
}

[[noreturn]] void bad(const std::string& spec, const std::string& why) {
  throw std::invalid_argument("seeds '" + spec + "': " + why +
                              " (point:X,Y,Z | line:A:B:N | disk:C:NORMAL:R:N | box:XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX:N | "
                              "boundary:C:R:N)");
}

std::vector<double> numbers(const std::string& spec, const std::string& text, std::size_t count) {
  const auto parts = split(text, ',');
  if (parts.size() != count) bad(spec, "'" + text + "' is not " + std::to_string(count) + " numbers");
  std::vector<double> out;
  for (const std::string& p : parts) {
    double v = 0.0;
    const auto r = std::from_chars(p.data(), p.data() + p.size(), v);
    if (r.ec != std::errc() || r.ptr != p.data() + p.size() || !std::isfinite(v)) bad(spec, "'" + p + "' is not a number");
    out.push_back(v);
  }
  return out;
}

glm::dvec3 point(const std::string& spec, const std::string& text) {
  const auto v = numbers(spec, text, 3);
  return {v[0], v[1], v[2]};
}

std::size_t count(const std::string& spec, const std::string& text, std::size_t most) {
  long long n = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), n);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || n < 1 || std::size_t(n) > most)
    bad(spec, "'" + text + "' is not a count from 1 to " + std::to_string(most));
  return std::size_t(n);
}

double positive(const std::string& spec, const std::string& text) {
  const double v = numbers(spec, text, 1)[0];
  if (!(v > 0.0)) bad(spec, "the radius must be positive");
  return v;
}

}  // namespace

std::vector<glm::dvec3> seedPoints(const std::string& spec, const ModelSession& session) {
  const auto part = split(spec, ':');
  const std::string kind = part.empty() ? "" : part[0];
  std::vector<glm::dvec3> out;
  if (kind == "point" && part.size() == 2) {
    out.push_back(point(spec, part[1]));
  } else if (kind == "line" && part.size() == 4) {
    const glm::dvec3 a = point(spec, part[1]), b = point(spec, part[2]);
    const std::size_t n = count(spec, part[3], kMaxSeeds);
    for (std::size_t i = 0; i < n; ++i) out.push_back(n == 1 ? 0.5 * (a + b) : a + (b - a) * (double(i) / double(n - 1)));
  } else if (kind == "disk" && part.size() == 5) {
    const glm::dvec3 c = point(spec, part[1]), normal = point(spec, part[2]);
    const double r = positive(spec, part[3]);
    const std::size_t n = count(spec, part[4], 100);
    if (!(glm::length(normal) > 0.0)) bad(spec, "the normal must not be zero");
    const glm::dvec3 w = glm::normalize(normal);
    const glm::dvec3 u = glm::normalize(glm::cross(w, std::abs(w.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 v = glm::cross(w, u);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        const double a = n == 1 ? 0.0 : -1.0 + 2.0 * double(i) / double(n - 1);
        const double b = n == 1 ? 0.0 : -1.0 + 2.0 * double(j) / double(n - 1);
        if (a * a + b * b <= 1.0 + 1e-12) out.push_back(c + r * (a * u + b * v));
      }
  } else if (kind == "box" && (part.size() == 3 || part.size() == 4)) {
    const auto box = numbers(spec, part[1], 6);
    for (int k = 0; k < 3; ++k)
      if (!(box[std::size_t(2 * k)] < box[std::size_t(2 * k + 1)])) bad(spec, "the box needs min < max on every axis");
    const std::size_t n = count(spec, part[2], kMaxSeeds);
    const std::uint64_t seed = part.size() == 4 ? std::uint64_t(count(spec, part[3], std::size_t(1) << 62)) : 1u;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (std::size_t i = 0; i < n; ++i) {
      glm::dvec3 p;
      for (int k = 0; k < 3; ++k) p[k] = box[std::size_t(2 * k)] + unit(rng) * (box[std::size_t(2 * k + 1)] - box[std::size_t(2 * k)]);
      out.push_back(p);
    }
  } else if (kind == "boundary" && part.size() == 4) {
    const glm::dvec3 c = point(spec, part[1]);
    const double r = positive(spec, part[2]);
    const std::size_t n = count(spec, part[3], kMaxSeeds);
    // Boundary triangles near C, chosen by area, a point in each (on the boundary face:
    // the tracer counts it in the mesh).
    const BoundarySurface& surface = session.surface();
    const SurfaceMesh& m = surface.mesh;
    std::vector<std::array<glm::dvec3, 3>> triangles;
    std::vector<double> areas;
    for (auto f : m.faces()) {
      std::array<glm::dvec3, 3> t;
      int k = 0;
      for (auto v : f.vertices()) {
        const auto p = m.point(v);
        t[std::size_t(k++)] = surface.origin + glm::dvec3(p[0], p[1], p[2]);
      }
      const glm::dvec3 centre = (t[0] + t[1] + t[2]) / 3.0;
      if (glm::length(centre - c) > r) continue;
      triangles.push_back(t);
      areas.push_back(0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0])));
    }
    if (triangles.empty()) bad(spec, "no boundary face lies within the radius of the centre");
    std::mt19937_64 rng(1);
    std::discrete_distribution<std::size_t> pick(areas.begin(), areas.end());
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (std::size_t i = 0; i < n; ++i) {
      const auto& t = triangles[pick(rng)];
      double a = unit(rng), b = unit(rng);
      if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
      out.push_back(t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]));
    }
  } else {
    bad(spec, "not a seed description");
  }
  return out;
}

std::vector<glm::dvec3> seedPoints(const std::vector<std::string>& specs, const ModelSession& session) {
  std::vector<glm::dvec3> all;
  for (const std::string& spec : specs) {
    const auto points = seedPoints(spec, session);
    all.insert(all.end(), points.begin(), points.end());
    if (all.size() > kMaxSeeds)
      throw std::invalid_argument("more than " + std::to_string(kMaxSeeds) + " seeds: fewer lines, please");
  }
  return all;
}

std::string rakeSpec(const glm::dvec3& a, const glm::dvec3& b, int n) {
  char text[256];
  std::snprintf(text, sizeof text, "line:%.9g,%.9g,%.9g:%.9g,%.9g,%.9g:%d", a.x, a.y, a.z, b.x, b.y, b.z, n);
  return text;
}

std::string pointSeedSpec(const glm::dvec3& p) {
  char text[128];
  std::snprintf(text, sizeof text, "point:%.9g,%.9g,%.9g", p.x, p.y, p.z);
  return text;
}

std::optional<glm::dvec3> pointSeed(const std::string& spec) {
  const auto part = split(spec, ':');
  if (part.size() != 2 || part[0] != "point") return std::nullopt;
  try {
    return point(spec, part[1]);
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

std::optional<std::array<glm::dvec3, 2>> rakeEnds(const std::string& spec) {
  const auto part = split(spec, ':');
  if (part.size() != 4 || part[0] != "line") return std::nullopt;
  try {
    return std::array<glm::dvec3, 2>{point(spec, part[1]), point(spec, part[2])};
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

}  // namespace volpost::app
