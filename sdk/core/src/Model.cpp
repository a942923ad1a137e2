// SPDX-License-Identifier: MIT
#include <volpost/core/Model.hpp>

namespace volpost {

const Field* Model::findField(const std::string& name) const {
  for (const auto& f : fields)
    if (f->name() == name) return f.get();
  return nullptr;
}

}  // namespace volpost
