// SPDX-License-Identifier: MIT
// libFuzzer target for one file reader (chosen at compile time by VOLPOST_FUZZ_READER).
// Every input must either load or be refused with ReadError: any other exception, a
// crash, a sanitizer report or a hang is a bug. Inputs go through a file, as in use.
//
// Besides libFuzzer's byte mutations, a structural mutator makes the changes that found
// the hostile-input bugs: counts replaced by huge, wrapping or negative values, lines
// (section headers) repeated, blocks swapped, files cut short.
#include "AbaqusInputReader.hpp"
#include "ExodusReader.hpp"
#include "FrdReader.hpp"
#include "GmshReader.hpp"
#include "NeutralFileReader.hpp"
#include "VtkLegacyReader.hpp"
#include "VtuReader.hpp"

#include <volpost/core/MeshChecks.hpp>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t maxSize);

namespace {

const std::string& inputPath() {
  static const std::string path = "/dev/shm/volpost_fuzz_" + std::to_string(getpid()) + "." VOLPOST_FUZZ_EXTENSION;
  return path;
}

}  // namespace

namespace {

// Byte ranges of the decimal integers in the input.
std::vector<std::pair<std::size_t, std::size_t>> integers(const std::string& s) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i < s.size();) {
    if (!std::isdigit(static_cast<unsigned char>(s[i]))) {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    out.push_back({start, i - start});
  }
  return out;
}

std::vector<std::pair<std::size_t, std::size_t>> lines(const std::string& s) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t end = std::min(s.find('\n', i), s.size());
    out.push_back({i, end + 1 - i});
    i = end + 1;
  }
  return out;
}

std::string structuralMutation(std::string s, std::mt19937_64& rng) {
  const auto pick = [&](std::size_t n) { return std::size_t(rng() % std::max<std::size_t>(n, 1)); };
  switch (rng() % 5) {
    case 0:
    case 1: {  // a count becomes hostile
      const auto ints = integers(s);
      if (ints.empty()) break;
      static const char* hostile[] = {"0", "-1", "4294967295", "4294967296", "2147483648", "9223372036854775807",
                                      "18446744073709551615", "1000000000000000", "6148914691236517206", "100000000"};
      const auto [at, length] = ints[pick(ints.size())];
      s.replace(at, length, hostile[pick(std::size(hostile))]);
      break;
    }
    case 2: {  // a line (a section header, a record) repeated further on
      const auto l = lines(s);
      if (l.size() < 2) break;
      const auto [from, length] = l[pick(l.size())];
      const auto to = l[pick(l.size())].first;
      s.insert(to, s.substr(from, length));
      break;
    }
    case 3: {  // two blocks of lines swapped
      const auto l = lines(s);
      if (l.size() < 4) break;
      std::size_t a = pick(l.size()), b = pick(l.size());
      if (a > b) std::swap(a, b);
      if (a == b) break;
      const std::string first = s.substr(l[a].first, l[a].second), second = s.substr(l[b].first, l[b].second);
      s.replace(l[b].first, l[b].second, first);
      s.replace(l[a].first, l[a].second, second);
      break;
    }
    default:  // cut short
      s.resize(pick(s.size()));
  }
  return s;
}

}  // namespace

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t maxSize,
                                               unsigned int seed) {
  std::mt19937_64 rng(seed);
  if (rng() % 3 != 0 || size == 0) return LLVMFuzzerMutate(data, size, maxSize);
  const std::string mutated = structuralMutation(std::string(reinterpret_cast<const char*>(data), size), rng);
  const std::size_t n = std::min(mutated.size(), maxSize);
  std::memcpy(data, mutated.data(), n);
  return n;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream out(inputPath(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  static const volpost::meshio::VOLPOST_FUZZ_READER reader;
  try {
    auto model = reader.read(inputPath(), {});
    volpost::checkModel(*model);  // what loading does next: must survive whatever loaded
    for (const auto& f : model->fields)
      for (std::size_t s = 0; s < f->stepCount(); ++s) (void)f->values(s);
  } catch (const volpost::ReadError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "not a ReadError: %s\n", e.what());
    std::abort();
  }
  return 0;
}
