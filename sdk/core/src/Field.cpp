// SPDX-License-Identifier: MIT
#include <volpost/core/Field.hpp>

#include <stdexcept>

namespace volpost {

const char* toString(FieldLocation location) {
  return location == FieldLocation::Node ? "node" : "cell";
}

const char* toString(FieldKind kind) {
  switch (kind) {
    case FieldKind::Scalar: return "scalar";
    case FieldKind::Vector: return "vector";
    case FieldKind::SymTensor: return "symmetric tensor";
    case FieldKind::Array: return "array";
  }
  return "?";
}

FieldKind kindForComponents(int components) {
  switch (components) {
    case 1: return FieldKind::Scalar;
    case 3: return FieldKind::Vector;
    case 6: return FieldKind::SymTensor;
    default: return FieldKind::Array;
  }
}

Field::Field(std::string name, FieldLocation location, int components, std::size_t entityCount,
             std::vector<Step> steps, StepLoader loader)
    : name_(std::move(name)),
      location_(location),
      components_(components),
      entityCount_(entityCount),
      steps_(std::move(steps)),
      loader_(std::move(loader)),
      cache_(steps_.size()) {
  if (components_ < 1) throw std::invalid_argument("field " + name_ + ": no components");
}

std::shared_ptr<Field> Field::fromValues(std::string name, FieldLocation location, int components,
                                         std::vector<std::vector<double>> stepValues,
                                         std::vector<Step> steps) {
  if (steps.empty())
    for (std::size_t i = 0; i < stepValues.size(); ++i)
      steps.push_back({stepValues.size() == 1 ? "" : "step " + std::to_string(i + 1), double(i)});
  const std::size_t count =
      stepValues.empty() ? 0 : stepValues.front().size() / std::size_t(components);
  auto shared = std::make_shared<std::vector<std::vector<double>>>(std::move(stepValues));
  return std::make_shared<Field>(std::move(name), location, components, count, std::move(steps),
                                 [shared](std::size_t step) { return (*shared)[step]; });
}

const std::vector<double>& Field::values(std::size_t step) const {
  if (step >= steps_.size())
    throw std::out_of_range("field " + name_ + " has no step " + std::to_string(step + 1));
  std::lock_guard lock(mutex_);
  if (!cache_[step]) {
    auto loaded = std::make_unique<std::vector<double>>(loader_(step));
    if (loaded->size() != entityCount_ * std::size_t(components_))
      throw std::runtime_error("field " + name_ + ": step " + std::to_string(step + 1) + " has " +
                               std::to_string(loaded->size()) + " values, expected " +
                               std::to_string(entityCount_ * std::size_t(components_)));
    cache_[step] = std::move(loaded);
  }
  return *cache_[step];
}

bool Field::isLoaded(std::size_t step) const {
  std::lock_guard lock(mutex_);
  return step < cache_.size() && cache_[step] != nullptr;
}

}  // namespace volpost
