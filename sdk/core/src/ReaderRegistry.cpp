// SPDX-License-Identifier: MIT
#include <volpost/core/ReaderRegistry.hpp>

#include <volpost/core/MeshChecks.hpp>
#include <volpost/core/ResourceLimits.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace volpost {
namespace {

std::string extensionOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  if (!ext.empty()) ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// Names what a file that no reader recognises looks like, so the message helps.
std::string describeContent(std::string_view head) {
  const auto starts = [&](std::string_view magic) { return head.substr(0, magic.size()) == magic; };
  if (starts("\x1f\x8b")) return "gzip-compressed data (decompress it first)";
  if (starts("\x89PNG")) return "a PNG image";
  if (starts("PK\x03\x04")) return "a ZIP archive";
  if (starts("CDF\x01") || starts("CDF\x02") || starts("\x89HDF")) return "a netCDF/HDF5 file";
  std::size_t binary = 0;
  for (unsigned char c : head)
    if (c < 9 || (c > 13 && c < 32) || c == 127) ++binary;
  if (binary * 20 > head.size()) return "binary data of no known format";
  std::string first(head.substr(0, head.find('\n')));
  if (first.size() > 60) first = first.substr(0, 60) + "...";
  return "text beginning \"" + first + "\"";
}

}  // namespace

const MeshReader& ReaderRegistry::choose(const std::string& path) const {
  requireRegularFile(path);  // a FIFO would block here, a device would never end
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ReadError(path, std::string("cannot open: ") + std::strerror(errno));
  std::string head(4096, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  if (head.empty()) throw ReadError(path, "file is empty (0 bytes)");
  if (head.rfind("\xEF\xBB\xBF", 0) == 0) head.erase(0, 3);  // a UTF-8 byte-order mark says nothing of the format

  const std::string ext = extensionOf(path);
  const MeshReader* best = nullptr;
  int bestScore = 0;
  for (const MeshReader* r : readers_) {
    const auto exts = r->extensions();
    const bool claims = std::find(exts.begin(), exts.end(), ext) != exts.end();
    const int score = r->sniff(head);
    const int ranked = score > 0 ? score * 2 + (claims ? 1 : 0) : 0;
    if (ranked > bestScore) {
      best = r;
      bestScore = ranked;
    }
  }
  if (!best) {
    std::string known;
    for (const MeshReader* r : readers_)
      for (const auto& e : r->extensions()) known += (known.empty() ? "." : ", .") + e;
    throw ReadError(path, "not a mesh file volpost can read: the content is " +
                              describeContent(head) + " (readable formats: " +
                              (known.empty() ? "none, no reader plugin is loaded" : known) + ")");
  }
  return *best;
}

std::unique_ptr<Model> ReaderRegistry::load(const std::string& path, const Progress& progress) const {
  return load(path, ReaderOptions{}, progress);
}

std::unique_ptr<Model> ReaderRegistry::load(const std::string& path, const ReaderOptions& options,
                                            const Progress& progress) const {
  const MeshReader& reader = choose(path);
  std::unique_ptr<Model> model;
  try {
    model = options.empty() ? reader.read(path, progress) : reader.readWith(path, options, progress);
  } catch (const std::bad_alloc&) {
    throw ReadError(path, "ran out of memory while reading it: the file declares more data than this machine can "
                          "hold (memory budget " + byteSizeText(double(memoryBudget())) + ")");
  } catch (const std::length_error&) {
    throw ReadError(path, "declares an array too large to hold (a corrupt or hostile count)");
  }
  model->sourcePath = path;
  if (model->formatName.empty()) model->formatName = reader.formatName();
  model->makeFieldNamesUnique();
  checkModel(*model);
  return model;
}

}  // namespace volpost
