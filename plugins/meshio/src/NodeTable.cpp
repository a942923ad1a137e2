// SPDX-License-Identifier: MIT
#include "NodeTable.hpp"

namespace volpost::meshio {

namespace {
constexpr std::int64_t kDenseLimit = std::int64_t(1) << 28;
}

bool IdIndex::add(std::int64_t id, std::uint32_t index) {
  if (id >= 0 && id < kDenseLimit && (id < std::int64_t(dense_.size()) * 2 + 1024)) {
    if (std::size_t(id) >= dense_.size()) dense_.resize(std::size_t(id) * 3 / 2 + 16, kNone);
    if (dense_[std::size_t(id)] != kNone) return false;
    dense_[std::size_t(id)] = index;
  } else {
    if (id >= 0 && std::uint64_t(id) < dense_.size() && dense_[std::size_t(id)] != kNone) return false;
    if (!sparse_.emplace(id, index).second) return false;
  }
  ++count_;
  return true;
}

std::optional<std::uint32_t> IdIndex::find(std::int64_t id) const {
  if (id >= 0 && std::uint64_t(id) < dense_.size() && dense_[std::size_t(id)] != kNone)
    return dense_[std::size_t(id)];
  if (sparse_.empty()) return std::nullopt;
  const auto it = sparse_.find(id);
  if (it == sparse_.end()) return std::nullopt;
  return it->second;
}

}  // namespace volpost::meshio
