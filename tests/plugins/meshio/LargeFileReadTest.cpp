// SPDX-License-Identifier: MIT
// A generated 1.6M-cell model written as VTK writes it (appended raw, Int64 connectivity)
// and read back by the streaming path: the same counts, nodes, cells and field values as
// the model written (hashes over every entry), the connectivity taken by the mesh without
// offsets (17 bytes per tet), and the nodal field still read on first use, from the file
// where it lies (the file is over the size from which it is not read whole), after the file
// was removed (the reader holds it open).
#include "VtuReader.hpp"

#include "host/VtuWriter.hpp"
#include "support/TetGrid.hpp"
#include "support/TestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>

using namespace volpost;

namespace {

std::uint64_t hashCells(const Mesh& m) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::size_t c = 0; c < m.cellCount(); ++c) {
    h = (h ^ std::uint64_t(m.cellType(c))) * 1099511628211ull;
    for (NodeIndex n : m.cellNodes(c)) h = (h ^ n) * 1099511628211ull;
  }
  return h;
}

std::uint64_t hashDoubles(const std::vector<double>& values) {
  std::uint64_t h = 1469598103934665603ull;
  for (double v : values) h = (h ^ std::uint64_t(std::llround(v * 1e9))) * 1099511628211ull;
  return h;
}

}  // namespace

TEST(LargeFileRead, AStreamedReadGivesTheModelWrittenEntryForEntry) {
  Model written;
  written.mesh() = volpost::test::tetGrid(64, 64, 64);
  std::vector<double> wave;
  for (const auto& p : written.mesh().nodes) wave.push_back(std::sin(0.1 * p.x) * std::cos(0.07 * p.y) + 0.01 * p.z);
  written.fields.push_back(Field::fromValues("wave", FieldLocation::Node, 1, {wave}));
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "volpost_large_read_test.vtu";
  writeVtu(written, file.string());
  ASSERT_GT(std::filesystem::file_size(file), meshio::kReadVtkXmlInPlaceFrom) << "large enough to be read in place";

  const auto read = meshio::VtuReader().read(file.string(), {});
  std::filesystem::remove(file);  // still open: the field reads it on first use
  ASSERT_EQ(read->mesh().cellCount(), written.mesh().cellCount());
  ASSERT_EQ(read->mesh().nodeCount(), written.mesh().nodeCount());
  EXPECT_EQ(hashCells(read->mesh()), hashCells(written.mesh()));
  std::vector<double> coordinates;
  for (const auto& p : read->mesh().nodes) coordinates.insert(coordinates.end(), {p.x, p.y, p.z});
  std::vector<double> expected;
  for (const auto& p : written.mesh().nodes) expected.insert(expected.end(), {p.x, p.y, p.z});
  EXPECT_EQ(hashDoubles(coordinates), hashDoubles(expected));
  EXPECT_EQ(read->mesh().cellBytes(), read->mesh().cellCount() * 17) << "one byte of type and 16 of nodes per tet, no offsets";
  const Field* f = read->findField("wave");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(hashDoubles(f->values(0)), hashDoubles(wave));
}
