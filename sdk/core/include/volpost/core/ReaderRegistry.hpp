// SPDX-License-Identifier: MIT
// Chooses the reader for a file by its extension and its content.
#pragma once

#include <volpost/core/MeshReader.hpp>

#include <memory>
#include <string>
#include <vector>

namespace volpost {

class ReaderRegistry {
 public:
  void add(const MeshReader* reader) { readers_.push_back(reader); }
  const std::vector<const MeshReader*>& readers() const { return readers_; }

  /// The reader whose sniff score is highest (ties go to the one that claims the
  /// extension). Throws ReadError when the file cannot be opened, is empty, or no reader
  /// recognises it; the message says what the content looks like.
  const MeshReader& choose(const std::string& path) const;
  /// choose() + read() + checkModel().
  std::unique_ptr<Model> load(const std::string& path, const Progress& progress = {}) const;
  /// The same with reader options (readWith): an option the chosen reader does not take, or
  /// a value it cannot use, throws ReaderOptionError before anything is read.
  std::unique_ptr<Model> load(const std::string& path, const ReaderOptions& options, const Progress& progress) const;

 private:
  std::vector<const MeshReader*> readers_;
};

}  // namespace volpost
