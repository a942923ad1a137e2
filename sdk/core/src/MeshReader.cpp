// SPDX-License-Identifier: MIT
#include <volpost/core/MeshReader.hpp>

#include <stdexcept>

namespace volpost {

void refuseUnknownOptions(const MeshReader& reader, const ReaderOptions& given) {
  const std::vector<ReaderOption> known = reader.options();
  for (const auto& [name, value] : given) {
    bool found = false;
    for (const ReaderOption& o : known) found = found || o.name == name;
    if (found) continue;
    std::string list;
    for (const ReaderOption& o : known) list += (list.empty() ? "" : ", ") + o.name;
    throw ReaderOptionError("reader option " + name + "=" + value + ": the " + reader.formatName() + " reader " +
                                (known.empty() ? std::string("takes no options") : "takes " + list));
  }
}

std::unique_ptr<Model> MeshReader::readWith(const std::string& path, const ReaderOptions& options,
                                            const Progress& progress) const {
  refuseUnknownOptions(*this, options);
  return read(path, progress);
}

}  // namespace volpost
