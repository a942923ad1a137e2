// SPDX-License-Identifier: MIT
#include <volpost/core/Field.hpp>

#include <volpost/core/ResourceLimits.hpp>

#include <atomic>
#include <stdexcept>

namespace volpost {
namespace {

// What every field's loaded steps hold together: the memory budget counts the whole, not
// each array alone (forty arrays each within the budget must not together exceed it).
std::atomic<std::size_t> g_heldBytes{0};

// Before a step of `bytes` is loaded: room for it beside what is held.
void requireRoomFor(const std::string& field, std::size_t step, double bytes) {
  const double held = double(g_heldBytes.load()), budget = double(memoryBudget());
  if (held + bytes > budget)
    throw std::runtime_error("field " + field + ": step " + std::to_string(step + 1) + " needs " + byteSizeText(bytes) +
                             ", and the fields read so far hold " + byteSizeText(held) + " of the memory budget of " +
                             byteSizeText(budget) +
                             " (set a larger one with VOLPOST_MEMORY_BUDGET or --memory-budget)");
}

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

Field::~Field() { g_heldBytes -= heldBytes_; }

std::size_t Field::bytesHeldByAllFields() { return g_heldBytes.load(); }

void Field::hold(std::size_t bytes) const {
  heldBytes_ += bytes;
  g_heldBytes += bytes;
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
    field->hold(field->cache_[i]->size() * sizeof(double));
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
  field->hold(field->sampleCache_[0]->bytes());
  return field;
}

const SampleArray& Field::samples(std::size_t step) const {
  if (!storesSamples()) throw std::logic_error("field " + name_ + " does not keep stored samples");
  if (step >= steps_.size())
    throw std::out_of_range("field " + name_ + " has no step " + std::to_string(step + 1));
  std::lock_guard lock(mutex_);
  if (!sampleCache_[step]) {
    requireRoomFor(name_, step, double(entityCount_) * double(components_));  // a byte each at least
    auto loaded = std::make_unique<SampleArray>(sampleLoader_(step));
    requireLoadedSize(name_, step, loaded->size(), entityCount_ * std::size_t(components_));
    hold(loaded->bytes());
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
    if (!cache_[step]) {
      requireRoomFor(name_, step, double(stored.size()) * sizeof(double));
      cache_[step] = std::make_unique<std::vector<double>>(stored.toDoubles());
      hold(cache_[step]->size() * sizeof(double));
    }
    return *cache_[step];
  }
  std::lock_guard lock(mutex_);
  if (!cache_[step]) {
    requireRoomFor(name_, step, double(entityCount_) * double(components_) * sizeof(double));
    auto loaded = std::make_unique<std::vector<double>>(loader_(step));
    requireLoadedSize(name_, step, loaded->size(), entityCount_ * std::size_t(components_));
    hold(loaded->size() * sizeof(double));
    cache_[step] = std::move(loaded);
  }
  return *cache_[step];
}

bool Field::isLoaded(std::size_t step) const {
  std::lock_guard lock(mutex_);
  return step < cache_.size() && cache_[step] != nullptr;
}

}  // namespace volpost
