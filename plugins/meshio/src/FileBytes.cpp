// SPDX-License-Identifier: MIT
#include "FileBytes.hpp"

#include <volpost/core/ResourceLimits.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>

namespace volpost::meshio {

std::shared_ptr<const std::string> readFileBytes(const std::string& path, const Progress& progress) {
  requireRegularFile(path);
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw ReadError(path, std::string("cannot open: ") + std::strerror(errno));
  const std::streamoff size = in.tellg();
  if (size <= 0) throw ReadError(path, "file is empty (0 bytes)");
  requireMemory(double(size), path, "the file's bytes");
  in.seekg(0);
  auto bytes = std::make_shared<std::string>(std::size_t(size), '\0');
  constexpr std::size_t kChunk = 16 << 20;
  for (std::size_t done = 0; done < bytes->size();) {
    const std::size_t n = std::min(kChunk, bytes->size() - done);
    if (!in.read(bytes->data() + done, std::streamsize(n)))
      throw ReadError::atOffset(path, done, "read error");
    done += n;
    progress.report(0.2 * double(done) / double(bytes->size()));
  }
  blankByteOrderMark(*bytes);
  return bytes;
}

void blankByteOrderMark(std::string& text) {
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.replace(0, 3, "   ");
}

std::int64_t lineAt(const std::string& bytes, std::size_t offset) {
  offset = std::min(offset, bytes.size());
  return 1 + std::count(bytes.begin(), bytes.begin() + std::ptrdiff_t(offset), '\n');
}

}  // namespace volpost::meshio
