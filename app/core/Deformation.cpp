// SPDX-License-Identifier: MIT
#include "Deformation.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace volpost::app {
namespace {

const Field& displacementField(const ModelSession& base, const std::string& name) {
  checkDeformationField(base, name);
  return *base.model().findField(name);
}

std::size_t clampedStep(const Field& f, std::size_t step) { return std::min(step, f.stepCount() - 1); }

}  // namespace

void checkDeformationField(const ModelSession& base, const std::string& name) {
  const Field* f = base.model().findField(name);
  if (f && f->location() == FieldLocation::Node && f->components() == 3 && f->stepCount() > 0) return;
  std::string candidates;
  for (const auto& field : base.model().fields)
    if (field->location() == FieldLocation::Node && field->components() == 3)
      candidates += (candidates.empty() ? "" : ", ") + field->name();
  throw std::invalid_argument("the deformation needs a nodal vector field; '" + name + "' is not one" +
                              (candidates.empty() ? " (this model has none)" : " (this model has: " + candidates + ")"));
}

double automaticDeformationScale(const ModelSession& base, const std::string& name, std::size_t step) {
  const Field& f = displacementField(base, name);
  const std::vector<double>& u = f.values(clampedStep(f, step));
  double largest = 0.0;
  for (std::size_t i = 0; i + 2 < u.size(); i += 3) {
    const double length = std::sqrt(u[i] * u[i] + u[i + 1] * u[i + 1] + u[i + 2] * u[i + 2]);
    if (std::isfinite(length)) largest = std::max(largest, length);
  }
  const double size = base.model().bounds().diagonal();
  return largest > 0.0 && size > 0.0 ? 0.1 * size / largest : 0.0;
}

std::shared_ptr<ModelSession> deformedSession(const ModelSession& base, const std::string& name, std::size_t step,
                                              double scale, double blend) {
  const Field& f = displacementField(base, name);
  if (!std::isfinite(scale)) throw std::invalid_argument("the deformation scale must be a finite number");
  const std::size_t at = clampedStep(f, step);
  std::vector<double> between;
  if (blend > 0.0 && at + 1 < f.stepCount()) {  // an in-between frame: that far toward the next step
    const std::vector<double>& a = f.values(at);
    const std::vector<double>& b = f.values(at + 1);
    between.resize(std::min(a.size(), b.size()));
    for (std::size_t i = 0; i < between.size(); ++i) between[i] = (1.0 - blend) * a[i] + blend * b[i];
  }
  const std::vector<double>& u = between.empty() ? f.values(at) : between;
  auto model = std::make_shared<Model>(base.model());  // the mesh is copied; fields are shared
  std::vector<glm::dvec3>& nodes = model->mesh().nodes;  // a grid's hexahedra are built here
  model->grid.reset();  // moved points are no regular grid: grid renderers must not draw it as one
  for (std::size_t n = 0; n < nodes.size() && 3 * n + 2 < u.size(); ++n) {
    const glm::dvec3 d(u[3 * n], u[3 * n + 1], u[3 * n + 2]);
    if (std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z)) nodes[n] += scale * d;  // NaN: left in place
  }
  return ModelSession::fromModel(std::move(model));
}

}  // namespace volpost::app
