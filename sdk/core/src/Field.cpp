// SPDX-License-Identifier: MIT
#include <volpost/core/Field.hpp>

#include <stdexcept>

namespace volpost {
namespace {

// What a loader gave must be one value per entity and component.
void requireLoadedSize(const std::string& field, std::size_t step, std::size_t size, std::size_t expected) {
  if (size != expected)
    throw std::runtime_error("field " + field + ": step " + std::to_string(step + 1) + " has " + std::to_string(size) +
                             " values, expected " + std::to_string(expected));
}

}  // namespace

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
  const std::size_t stepCount = stepValues.size();
  std::string fieldName = name;
  auto field = std::make_shared<Field>(std::move(name), location, components, count, std::move(steps),
                                       [fieldName](std::size_t step) -> std::vector<double> {
                                         throw std::out_of_range("field " + fieldName + " has no step " +
                                                                 std::to_string(step + 1));
                                       });
  // The values become the cache itself: no second copy of them.
  for (std::size_t i = 0; i < stepCount && i < field->cache_.size(); ++i) {
    if (stepValues[i].size() != count * std::size_t(components))
      throw std::invalid_argument("field " + field->name() + ": step " + std::to_string(i + 1) + " has " +
                                  std::to_string(stepValues[i].size()) + " values, expected " +
                                  std::to_string(count * std::size_t(components)));
    field->cache_[i] = std::make_unique<std::vector<double>>(std::move(stepValues[i]));
  }
  return field;
}

std::shared_ptr<Field> Field::fromSamples(std::string name, FieldLocation location, int components,
                                          std::size_t entityCount, std::vector<Step> steps, SampleLoader loader) {
  auto field = std::make_shared<Field>(std::move(name), location, components, entityCount, std::move(steps),
                                       StepLoader{});
  field->sampleCache_.resize(field->steps_.size());
  field->sampleLoader_ = std::move(loader);
  return field;
}

std::shared_ptr<Field> Field::fromSamples(std::string name, FieldLocation location, int components,
                                          SampleArray samples) {
  const std::size_t count = samples.size() / std::size_t(components);
  auto shared = std::make_shared<SampleArray>(std::move(samples));
  auto field = fromSamples(std::move(name), location, components, count, {{"", 0.0}},
                           [shared](std::size_t) { return SampleArray(); });
  field->sampleCache_[0] = std::make_unique<SampleArray>(std::move(*shared));  // kept as given, no copy
  return field;
}

const SampleArray& Field::samples(std::size_t step) const {
  if (!storesSamples()) throw std::logic_error("field " + name_ + " does not keep stored samples");
  if (step >= steps_.size())
    throw std::out_of_range("field " + name_ + " has no step " + std::to_string(step + 1));
  std::lock_guard lock(mutex_);
  if (!sampleCache_[step]) {
    auto loaded = std::make_unique<SampleArray>(sampleLoader_(step));
    requireLoadedSize(name_, step, loaded->size(), entityCount_ * std::size_t(components_));
    sampleCache_[step] = std::move(loaded);
  }
  return *sampleCache_[step];
}

std::vector<double> Field::valuesCopy(std::size_t step) const {
  if (storesSamples() && !isLoaded(step)) return samples(step).toDoubles();
  return values(step);
}

const std::vector<double>& Field::values(std::size_t step) const {
  if (step >= steps_.size())
    throw std::out_of_range("field " + name_ + " has no step " + std::to_string(step + 1));
  if (storesSamples()) {
    const SampleArray& stored = samples(step);  // outside the lock below: it takes it too
    std::lock_guard lock(mutex_);
    if (!cache_[step]) cache_[step] = std::make_unique<std::vector<double>>(stored.toDoubles());
    return *cache_[step];
  }
  std::lock_guard lock(mutex_);
  if (!cache_[step]) {
    auto loaded = std::make_unique<std::vector<double>>(loader_(step));
    requireLoadedSize(name_, step, loaded->size(), entityCount_ * std::size_t(components_));
    cache_[step] = std::move(loaded);
  }
  return *cache_[step];
}

bool Field::isLoaded(std::size_t step) const {
  std::lock_guard lock(mutex_);
  return step < cache_.size() && cache_[step] != nullptr;
}

}  // namespace volpost
