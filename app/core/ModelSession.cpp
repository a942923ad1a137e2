// SPDX-License-Identifier: MIT
#include "ModelSession.hpp"

#include <volpost/core/ResourceLimits.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>

namespace volpost::app {
namespace {

// Which nodes the cells use, where some are not: a part of a model (a threshold, element
// sets) shares the whole model's nodes, and its color range, like its bounds and its
// extremes, is that of the nodes it draws. Empty where every node is used (no cost then).
std::shared_ptr<const std::vector<char>> usedNodesIfNotAll(const Model& model) {
  if (!model.meshBuilt()) return nullptr;
  const Mesh& mesh = model.mesh();
  auto used = std::make_shared<std::vector<char>>(mesh.nodeCount(), 0);
  for (const NodeIndex n : mesh.connectivity())
    if (n < used->size()) (*used)[n] = 1;
  if (std::find(used->begin(), used->end(), 0) == used->end()) return nullptr;
  return used;
}

ValueRange rangeOfUsed(const SampleView& values, const std::vector<char>& used) {
  ValueRange r;
  r.min = std::numeric_limits<double>::infinity();
  r.max = -r.min;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i < used.size() && !used[i]) continue;
    const double x = values[i];
    if (!std::isfinite(x)) {
      ++r.nanCount;
      continue;
    }
    ++r.finiteCount;
    r.min = std::min(r.min, x);
    r.max = std::max(r.max, x);
  }
  if (!r.valid()) r.min = r.max = 0.0;  // as rangeOf gives it
  return r;
}

// A grid's boundary comes from its index ranges while its hexahedra are not built.
BoundarySurface boundaryOf(const Model& model, const Progress& progress = {}) {
  return model.meshBuilt() ? extractBoundary(model.mesh(), progress) : extractBoundary(*model.grid, progress);
}

}  // namespace

std::shared_ptr<ModelSession> ModelSession::load(const ReaderRegistry& readers, const std::string& path,
                                                 const Progress& progress, Boundary boundary,
                                                 const ReaderOptions& options) {
  // The caller's progress sees one bar with named stages; cancelling it cancels the stage.
  Progress stage = progress;
  stage.setStage("reading");
  const double readShare = boundary == Boundary::Now ? 0.8 : 1.0;
  Progress readProgress([&](double f, const std::string&) {
    stage.report(readShare * f);
    return true;
  });
  std::shared_ptr<Model> model = readers.load(path, options, readProgress);
  Progress rest([&](double f, const std::string&) {
    stage.report(readShare + (1.0 - readShare) * f);
    return true;
  });
  auto session = fromModel(std::move(model), rest, boundary);
  session->readerOptions_ = options;
  return session;
}

std::shared_ptr<ModelSession> ModelSession::fromModel(std::shared_ptr<Model> model, const Progress& progress,
                                                      Boundary boundary) {
  auto session = std::make_shared<ModelSession>();
  session->model_ = std::move(model);
  const Bounds b = session->model_->bounds();
  session->origin_ = b.valid ? b.center() : glm::dvec3(0.0);
  session->bounds_ = b;
  session->usedNodes_ = usedNodesIfNotAll(*session->model_);
  if (boundary == Boundary::Now) {
    Progress stage = progress;
    stage.setStage("extracting the boundary");
    Geometry& g = *session->geometry_;
    std::call_once(g.surfaceOnce, [&] {
      g.surface = std::make_unique<BoundarySurface>(boundaryOf(*session->model_, stage));
      g.surfaceExtracted = true;
    });
  }
  return session;
}

std::shared_ptr<ModelSession> ModelSession::withFormulas(const ModelSession& base,
                                                         const std::vector<FormulaSpec>& formulas) {
  // The file's own fields: the base may itself carry formulas, which these replace.
  auto model = std::make_shared<Model>(base.model());  // nodes copied, cells and fields shared
  model->fields.resize(model->fields.size() - base.formulas_.size());
  for (const FormulaSpec& f : formulas) {
    for (const FormulaSpec& earlier : formulas)
      if (&earlier != &f && earlier.name == f.name) throw FormulaError("two formulas are named '" + f.name + "'");
    model->fields.push_back(formulaField(*model, f));
  }
  auto session = std::make_shared<ModelSession>();
  session->model_ = std::move(model);
  session->readerOptions_ = base.readerOptions_;
  session->origin_ = base.origin_;
  session->bounds_ = base.bounds_;
  session->usedNodes_ = base.usedNodes_;
  session->geometry_ = base.geometry_;
  session->formulas_ = formulas;
  return session;
}

std::shared_ptr<ModelSession> ModelSession::withSets(const ModelSession& base, const std::string& origin,
                                                     std::vector<EntitySet> sets) {
  auto model = std::make_shared<Model>(base.model());  // nodes copied, cells and fields shared
  std::erase_if(model->sets, [&](const EntitySet& s) { return s.origin == origin; });
  for (EntitySet& s : sets) {
    s.origin = origin;
    model->sets.push_back(std::move(s));
  }
  auto session = std::make_shared<ModelSession>();
  session->model_ = std::move(model);
  session->readerOptions_ = base.readerOptions_;
  session->origin_ = base.origin_;
  session->bounds_ = base.bounds_;
  session->usedNodes_ = base.usedNodes_;
  session->geometry_ = base.geometry_;
  session->formulas_ = base.formulas_;
  return session;
}

const BoundarySurface& ModelSession::surface() const {
  Geometry& g = *geometry_;
  std::call_once(g.surfaceOnce, [&] {
    g.surface = std::make_unique<BoundarySurface>(boundaryOf(*model_));
    g.surfaceExtracted = true;
  });
  return *g.surface;
}

std::vector<Quantity> ModelSession::quantities() const {
  std::vector<Quantity> out;
  for (const auto& f : model_->fields)
    for (const auto& q : quantitiesOf(*f)) out.push_back(q);
  return out;
}

std::optional<Quantity> ModelSession::defaultQuantity() const {
  for (FieldKind kind : {FieldKind::SymTensor, FieldKind::Vector, FieldKind::Scalar})
    for (const auto& f : model_->fields)
      if (f->kind() == kind && f->stepCount() > 0) return quantitiesOf(*f).front();
  return std::nullopt;
}

Quantity ModelSession::findQuantity(const std::string& key) const {
  for (const auto& f : model_->fields)
    if (auto q = parseQuantity(key, *f)) return *q;
  std::string known;
  for (const auto& q : quantities()) known += (known.empty() ? "" : ", ") + q.key();
  throw std::invalid_argument("no field or quantity named '" + key + "' in " + model_->sourcePath +
                              (known.empty() ? " (the model has no result fields)" : " (available: " + known + ")"));
}

const Field& ModelSession::fieldOf(const Quantity& q) const {
  const Field* f = model_->findField(q.field);
  if (!f) throw std::invalid_argument("no field named " + q.field);
  return *f;
}

ScalarView ModelSession::evaluate(const Quantity& q, std::size_t step) const {
  const Field& f = fieldOf(q);
  if (step >= f.stepCount())
    throw std::invalid_argument("field " + f.name() + " has " + std::to_string(f.stepCount()) + " step(s); step " +
                                std::to_string(step + 1) + " does not exist");
  ScalarView view;
  view.quantity = q;
  view.location = f.location();
  try {  // fields are read on first use: a failure here still names the file
    if (isStoredSamples(f, q)) {
      view.values = f.samples(step);
      for (const auto& owned : model_->fields)  // the model's fields are shared: the view keeps its own alive
        if (owned.get() == &f) view.owner = owned;
    } else {
      view.setValues(volpost::evaluate(f, q, step));
    }
  } catch (const std::bad_alloc&) {
    throw ReadError(model_->sourcePath, "ran out of memory reading field " + f.name() + " (memory budget " +
                                            byteSizeText(double(memoryBudget())) + ")");
  }
  view.range =
      view.location == FieldLocation::Node && usedNodes_ ? rangeOfUsed(view.values, *usedNodes_) : rangeOf(view.values);
  // Colors, transfer functions and legends divide by the range: a range whose width is
  // beyond a double (values near -1.7e308 and 1.7e308) cannot be drawn.
  if (!std::isfinite(view.range.max - view.range.min)) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "the values of %s run from %g to %g: the width of that range is beyond a double, so no color "
                  "scale can span it (such extremes are usually junk samples)",
                  q.displayName().c_str(), view.range.min, view.range.max);
    throw ReadError(model_->sourcePath, text);
  }
  view.stepLabel = f.steps()[step].label;
  const std::lock_guard lock(rangesMutex_);
  stepRanges_[{q.key(), step}] = view.range;
  return view;
}

ValueRange ModelSession::rangeOverSteps(const Quantity& q) const {
  {
    const std::lock_guard lock(rangesMutex_);
    if (const auto known = rangesOverSteps_.find(q.key()); known != rangesOverSteps_.end()) return known->second;
  }
  ValueRange all;
  for (std::size_t step = 0; step < fieldOf(q).stepCount(); ++step) {
    std::optional<ValueRange> seen;
    {
      const std::lock_guard lock(rangesMutex_);
      if (const auto known = stepRanges_.find({q.key(), step}); known != stepRanges_.end()) seen = known->second;
    }
    const ValueRange r = seen ? *seen : evaluate(q, step).range;
    if (r.valid()) {
      all.min = all.valid() ? std::min(all.min, r.min) : r.min;
      all.max = all.valid() ? std::max(all.max, r.max) : r.max;
    }
    all.finiteCount += r.finiteCount;
    all.nanCount += r.nanCount;
  }
  const std::lock_guard lock(rangesMutex_);
  rangesOverSteps_[q.key()] = all;
  return all;
}

const TetMesh& ModelSession::tetrahedra() const {
  Geometry& g = *geometry_;
  std::call_once(g.tetOnce, [&] { g.tets = std::make_unique<TetMesh>(tetrahedralize(model_->mesh())); });
  return *g.tets;
}

const PointLocator& ModelSession::locator() const {
  Geometry& g = *geometry_;
  std::call_once(g.locatorOnce, [&] { g.locator = std::make_unique<PointLocator>(tetrahedra()); });
  return *g.locator;
}

std::vector<double> ModelSession::tetValues(const ScalarView& view) const {
  const TetMesh& t = tetrahedra();
  std::vector<double> converted;  // samples in another type than double: a copy while the tet values are made
  const std::span<const double> values = view.values.doubles(converted);
  return view.location == FieldLocation::Node ? t.nodeValues(model_->mesh(), values) : t.cellValues(values);
}

void ScalarView::setValues(std::vector<double> computed) {
  auto owned = std::make_shared<const std::vector<double>>(std::move(computed));
  values = *owned;
  owner = std::move(owned);
}

}  // namespace volpost::app
