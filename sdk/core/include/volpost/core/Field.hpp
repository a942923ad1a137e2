// SPDX-License-Identifier: MIT
// Result fields: values per node or per cell, for one or more steps, read lazily.
#pragma once

#include <volpost/core/SampleArray.hpp>

#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace volpost {

enum class FieldLocation { Node, Cell };
/// Scalar: 1 component; Vector: 3 (x y z); SymTensor: 6 (xx yy zz xy yz zx, VTK/CalculiX
/// order); Array: any other number of components.
enum class FieldKind { Scalar, Vector, SymTensor, Array };

const char* toString(FieldLocation location);
const char* toString(FieldKind kind);
FieldKind kindForComponents(int components);

/// One load case or time step of a field.
struct Step {
  std::string label;  ///< e.g. "step 1", "t = 0.5", "mode 3"
  double time = 0.0;
};

/// Produces the values of one step: entityCount x components doubles, row-major.
/// Throws on failure (a lazy read of a damaged file).
using StepLoader = std::function<std::vector<double>(std::size_t step)>;
/// Produces the values of one step in the type the file stores them in.
using SampleLoader = std::function<SampleArray(std::size_t step)>;

class Field {
 public:
  Field(std::string name, FieldLocation location, int components, std::size_t entityCount,
        std::vector<Step> steps, StepLoader loader);
  /// A field whose values are already in memory (one vector per step), kept without a copy.
  static std::shared_ptr<Field> fromValues(std::string name, FieldLocation location,
                                           int components,
                                           std::vector<std::vector<double>> stepValues,
                                           std::vector<Step> steps = {});
  /// A field that keeps its values as the file stored them (samples()), read lazily by
  /// `loader`; values() converts a step to doubles and keeps that copy too, evaluate()
  /// (volpost/core/Quantity.hpp) and valuesCopy() convert without keeping one.
  static std::shared_ptr<Field> fromSamples(std::string name, FieldLocation location, int components,
                                            std::size_t entityCount, std::vector<Step> steps, SampleLoader loader);
  /// One step of samples already in memory.
  static std::shared_ptr<Field> fromSamples(std::string name, FieldLocation location, int components,
                                            SampleArray samples);

  const std::string& name() const { return name_; }
  /// While a model is being built (a reader's or the registry's): another name.
  void rename(std::string name) { name_ = std::move(name); }
  FieldLocation location() const { return location_; }
  FieldKind kind() const { return kindForComponents(components_); }
  int components() const { return components_; }
  std::size_t entityCount() const { return entityCount_; }
  const std::vector<Step>& steps() const { return steps_; }
  std::size_t stepCount() const { return steps_.size(); }
  /// The units of the values as the file states them ("Pa"), empty when it says nothing
  /// (most finite-element formats store none). Set by the reader while building the model.
  const std::string& units() const { return units_; }
  void setUnits(std::string units) { units_ = std::move(units); }

  /// Values of a step, loaded on first use and kept. Thread-safe.
  const std::vector<double>& values(std::size_t step) const;
  bool isLoaded(std::size_t step) const;
  /// Whether the field keeps its values in the file's own type (fromSamples).
  bool storesSamples() const { return static_cast<bool>(sampleLoader_); }
  /// A step's values in their stored type, loaded on first use and kept. Thread-safe.
  /// Throws std::logic_error for a field that does not store samples.
  const SampleArray& samples(std::size_t step) const;
  /// A step's values as doubles in a vector of the caller's: for a field of stored samples,
  /// converted without keeping a double copy in the field.
  std::vector<double> valuesCopy(std::size_t step) const;

  /// What the loaded steps of every field in the process hold, in bytes. A step is loaded
  /// only while this and its own size stay within memoryBudget() (else std::runtime_error).
  static std::size_t bytesHeldByAllFields();

  ~Field();
  Field(const Field&) = delete;
  Field& operator=(const Field&) = delete;

 private:
  void hold(std::size_t bytes) const;

  std::string name_;
  std::string units_;
  FieldLocation location_;
  int components_;
  std::size_t entityCount_;
  std::vector<Step> steps_;
  StepLoader loader_;
  SampleLoader sampleLoader_;
  mutable std::mutex mutex_;
  mutable std::vector<std::unique_ptr<std::vector<double>>> cache_;
  mutable std::vector<std::unique_ptr<SampleArray>> sampleCache_;
  mutable std::size_t heldBytes_ = 0;  ///< this field's share of bytesHeldByAllFields()
};

}  // namespace volpost
