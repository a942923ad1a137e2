// SPDX-License-Identifier: MIT
// What the ParaView readers share: volpost's readers chosen as `volpost` chooses them, and the
// rule that turns each field's own steps into ParaView's one list of time steps.
#pragma once

#include <volpost/core/MeshReader.hpp>
#include <volpost/core/Model.hpp>

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace volpost::paraview {

/// Reads `path` with the reader that claims its extension and content, the mesh checks
/// included (their findings are the model's diagnostics). Throws ReadError or
/// ReaderOptionError with the message a user sees, Cancelled when `progress` says stop.
std::unique_ptr<Model> readModel(const std::string& path, const ReaderOptions& options, const Progress& progress);

/// Whether ParaView should give the file to a volpost reader: whenever it can be opened, so
/// that a damaged file gets the reader's account of what is wrong (a PNG named .frd, the line
/// where a deck breaks) rather than ParaView's "no reader found".
bool canRead(const std::string& path);

/// ParaView's time steps for a model whose fields each have their own steps.
struct TimeSteps {
  /// Strictly increasing; empty when no field has more than one step.
  std::vector<double> times;
  /// True when the times are the files' own (every field's steps strictly increasing in
  /// time: the union of them all); false when they are step numbers 1, 2, ... N.
  bool fromFile = true;
};
TimeSteps timeSteps(const Model& model);

/// The step of `field` shown at ParaView time `time`: with the file's times, its last step
/// at or before `time` (its first before any); with step numbers, step min(time, count) - 1.
std::size_t fieldStepAt(const Field& field, const TimeSteps& steps, double time);

/// The file a reader last read, kept between ParaView's requests: a new time step re-reads
/// nothing, a new file name, new options or a file changed on disk read again.
class ModelCache {
 public:
  /// Reads the file unless it is what is held; true when it read (its findings are new).
  /// On failure throws as readModel and holds nothing.
  bool load(const std::string& path, const ReaderOptions& options, const Progress& progress);
  const Model& model() const { return *model_; }
  const TimeSteps& steps() const { return steps_; }
  bool holds() const { return model_ != nullptr; }

 private:
  std::string path_;
  ReaderOptions options_;
  std::filesystem::file_time_type written_{};
  std::unique_ptr<Model> model_;
  TimeSteps steps_;
};

}  // namespace volpost::paraview

/// What the VTK classes hold (a name their headers can declare without namespaces): the model
/// (on the rank that reads it) and the time steps every rank announces.
struct vtkVolpostModelCache : volpost::paraview::ModelCache {
  volpost::paraview::TimeSteps announced;
};

namespace volpost::paraview {

/// Reads the file on the first MPI rank only (the others would each hold the whole model)
/// and tells every rank its time steps, or the reading's error. Returns the error's message,
/// empty when the file was read; `read` says whether this rank read it anew (its findings are
/// new). In one process, the same without messages.
std::string readOnFirstRank(vtkVolpostModelCache& cache, const std::string& path, const ReaderOptions& options,
                            const Progress& progress, bool& read);

}  // namespace volpost::paraview
