// SPDX-License-Identifier: MIT
// Node ids as FE files number them (any positive integers, gaps allowed) to the 0-based
// indices of the model.
#pragma once

#include <volpost/core/Mesh.hpp>

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace volpost::meshio {

class IdIndex {
 public:
  /// Returns false when `id` is already there (the caller reports the duplicate).
  bool add(std::int64_t id, std::uint32_t index);
  std::optional<std::uint32_t> find(std::int64_t id) const;
  std::size_t size() const { return count_; }

 private:
  // Dense ids (the usual 1..n) go to a vector; sparse or huge ones to a hash map.
  static constexpr std::uint32_t kNone = 0xffffffffu;
  std::vector<std::uint32_t> dense_;
  std::unordered_map<std::int64_t, std::uint32_t> sparse_;
  std::size_t count_ = 0;
};

}  // namespace volpost::meshio
