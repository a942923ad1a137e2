// SPDX-License-Identifier: MIT
#include "StreamlineTracing.hpp"

#include "StreamlineSeeds.hpp"

#include "host/ElementRefinement.hpp"
#include "host/PointLocator.hpp"

#include <volpost/core/optics/ElementField.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>

namespace volpost::app {

std::shared_ptr<const StreamlineResult> traceStreamlineLayer(const ModelSession& session, const StreamlineLayer& l,
                                                             std::size_t wantedStep, FieldInterpolation interpolation,
                                                             const Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  const ModelSession* session_ = &session;
  const Model& model = session_->model();
  const Field* f = model.findField(l.field);
  if (!f || f->components() != 3) throw std::invalid_argument("no vector field named '" + l.field + "'");
  const std::size_t step = std::min(wantedStep, f->stepCount() - 1);
  std::vector<double> nodal = f->values(step);
  if (f->location() == FieldLocation::Cell) nodal = averageCellVectorsToNodes(model.mesh(), nodal);
  const TetMesh& tets = session_->tetrahedra();
  const bool own = interpolation == FieldInterpolation::Element;
  const StreamlineTracer tracer(tets, tetNodeVectors(tets, model.mesh(), nodal), own ? &model.mesh() : nullptr);
  const std::vector<glm::dvec3> seeds = seedPoints(l.seeds, *session_);
  auto result = std::make_shared<StreamlineResult>();
  result->layer = l;
  result->session = session_;
  result->step = wantedStep;
  result->interpolation = interpolation;
  result->seeds = seeds.size();
  result->lines = tracer.traceAll(seeds, l.settings, &result->outside, progress);
  if (!seeds.empty() && result->outside == seeds.size()) {
    const Bounds b = model.bounds();
    char text[256];
    std::snprintf(text, sizeof text, "x [%g, %g]  y [%g, %g]  z [%g, %g]", b.min.x, b.max.x, b.min.y, b.max.y, b.min.z,
                  b.max.z);
    const std::string which =
        seeds.size() == 1 ? "the seed lies" : "all " + std::to_string(seeds.size()) + " seeds lie";
    throw std::invalid_argument(which + " outside the mesh (its bounds: " + text + ")");
  }
  // The values the lines are colored by: the speed, or a quantity interpolated at each point.
  if (l.colorBy.empty()) {
    result->valueName = l.field + " speed";
    for (const Streamline& line : result->lines) {
      std::vector<double> v;
      for (const glm::dvec3& u : line.velocity) v.push_back(glm::length(u));
      result->values.push_back(std::move(v));
    }
  } else {
    const ScalarView view = session_->evaluate(session_->findQuantity(l.colorBy), step);
    result->valueName = view.quantity.displayName();
    const std::vector<double> values = session_->tetValues(view);
    const PointLocator locator(tets);
    // The cells' own field, where asked for and the values are at the nodes.
    std::vector<double> converted;
    const bool ownValues = own && view.location == FieldLocation::Node && hasNonlinearCells(model.mesh());
    const std::optional<optics::ElementField> field =
        ownValues ? std::optional<optics::ElementField>(std::in_place, model.mesh(), view.values.doubles(converted),
                                                        tets, glm::dvec3(0.0))
                  : std::nullopt;
    const auto valueAt = [&](const PointLocation& at, const glm::dvec3& p) {
      if (view.location != FieldLocation::Node) return values[at.tet];
      if (field) {
        const std::uint32_t cell = tets.sourceCell(at.tet);
        glm::dvec3 xi = field->start(cell);
        if (!field->linearIn(cell))
          if (const auto v = field->value(cell, p, xi)) return *v;
      }
      return PointLocator::interpolateNodal(at, values);
    };
    for (const Streamline& line : result->lines) {
      std::vector<double> v;
      for (const glm::dvec3& p : line.points) {
        const auto at = locator.locate(p, 1e-6);
        v.push_back(at ? valueAt(*at, p) : std::nan(""));
      }
      result->values.push_back(std::move(v));
    }
  }
  result->min = std::numeric_limits<double>::infinity();
  result->max = -std::numeric_limits<double>::infinity();
  for (const auto& v : result->values)
    for (double x : v)
      if (std::isfinite(x)) result->min = std::min(result->min, x), result->max = std::max(result->max, x);
  if (!(result->max > result->min)) {
    if (!std::isfinite(result->min)) result->min = 0.0;
    result->max = result->min + 1.0;
  }
  result->milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace volpost::app
