// SPDX-License-Identifier: MIT
#include "SetMembership.hpp"

#include <algorithm>

namespace volpost::app {

std::vector<std::string> setsHolding(const std::vector<EntitySet>& sets, SetKind kind, std::size_t index) {
  std::vector<std::string> out;
  for (const EntitySet& s : sets)  // members are sorted
    if (s.kind == kind && std::binary_search(s.members.begin(), s.members.end(), std::uint32_t(index)))
      out.push_back(s.name);
  return out;
}

std::string setNameList(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names)
    out += (out.empty() ? "" : ", ") + (n.find(' ') != std::string::npos ? "\"" + n + "\"" : n);
  return out;
}

}  // namespace volpost::app
