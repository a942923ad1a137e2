// SPDX-License-Identifier: MIT
#include "VolpostReading.h"

#include "AllReaders.hpp"
#include "SegyReader.hpp"

#include <volpost/core/ReaderRegistry.hpp>

#include <vtkMultiProcessController.h>
#include <vtkMultiProcessStream.h>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace volpost::paraview {

namespace {

const ReaderRegistry& registry() {
  static const meshio::AllReaders meshReaders;
  static const seismic::SegyReader segy;
  static const ReaderRegistry all = [] {
    ReaderRegistry r;
    for (const MeshReader* reader : meshReaders.list()) r.add(reader);
    r.add(&segy);
    return r;
  }();
  return all;
}

bool strictlyIncreasing(const std::vector<Step>& steps) {
  for (std::size_t s = 0; s < steps.size(); ++s) {
    if (!std::isfinite(steps[s].time)) return false;
    if (s > 0 && !(steps[s].time > steps[s - 1].time)) return false;
  }
  return true;
}

}  // namespace

std::unique_ptr<Model> readModel(const std::string& path, const ReaderOptions& options, const Progress& progress) {
  return registry().load(path, options, progress);
}

bool canRead(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;
  return std::ifstream(path, std::ios::binary).good();
}

TimeSteps timeSteps(const Model& model) {
  TimeSteps result;
  std::size_t most = 0;
  for (const auto& field : model.fields) {
    most = std::max(most, field->stepCount());
    if (!strictlyIncreasing(field->steps())) result.fromFile = false;
  }
  if (most < 2) return result;
  if (result.fromFile) {
    for (const auto& field : model.fields)
      for (const Step& step : field->steps()) result.times.push_back(step.time);
    std::sort(result.times.begin(), result.times.end());
    result.times.erase(std::unique(result.times.begin(), result.times.end()), result.times.end());
  } else {
    for (std::size_t s = 1; s <= most; ++s) result.times.push_back(double(s));
  }
  return result;
}

std::size_t fieldStepAt(const Field& field, const TimeSteps& steps, double time) {
  const std::size_t count = field.stepCount();
  if (count <= 1) return 0;
  if (!steps.fromFile) {
    const double number = std::clamp(std::round(time), 1.0, double(count));
    return std::size_t(number) - 1;
  }
  std::size_t chosen = 0;
  for (std::size_t s = 0; s < count; ++s)
    if (field.steps()[s].time <= time + 1e-12 * std::max(1.0, std::abs(time))) chosen = s;
  return chosen;
}

bool ModelCache::load(const std::string& path, const ReaderOptions& options, const Progress& progress) {
  std::error_code unknown;
  const auto written = std::filesystem::last_write_time(path, unknown);
  if (model_ && path == path_ && options == options_ && !unknown && written == written_) return false;
  model_.reset();
  steps_ = {};
  auto model = readModel(path, options, progress);
  steps_ = timeSteps(*model);
  model_ = std::move(model);
  path_ = path;
  options_ = options;
  written_ = unknown ? std::filesystem::file_time_type{} : written;
  return true;
}

}  // namespace volpost::paraview

namespace volpost::paraview {

std::string readOnFirstRank(vtkVolpostModelCache& cache, const std::string& path, const ReaderOptions& options,
                            const Progress& progress, bool& read) {
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  const int rank = controller ? controller->GetLocalProcessId() : 0;
  read = false;
  std::string error;
  if (rank == 0) {
    try {
      read = cache.load(path, options, progress);
      cache.announced = cache.steps();
    } catch (const std::exception& e) {
      error = e.what();
      if (error.empty()) error = path + ": could not be read";
    }
  }
  if (ranks > 1) {
    vtkMultiProcessStream stream;
    if (rank == 0) {
      stream << error << int(cache.announced.fromFile) << int(cache.announced.times.size());
      for (const double t : cache.announced.times) stream << t;
    }
    controller->Broadcast(stream, 0);
    if (rank > 0) {
      int fromFile = 1, count = 0;
      stream >> error >> fromFile >> count;
      cache.announced.fromFile = fromFile != 0;
      cache.announced.times.assign(std::size_t(std::max(count, 0)), 0.0);
      for (double& t : cache.announced.times) stream >> t;
    }
  }
  return error;
}

}  // namespace volpost::paraview
