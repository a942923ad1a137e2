// SPDX-License-Identifier: MIT
// Large VTK XML files are not read whole into memory: their appended arrays are decoded
// from the file where they lie. Forcing that path on every small file of the suite must
// give the same model (nodes, cells, every field's values) or the same error as reading
// it whole; zlib blocks that cut a value in two are joined; and a field read after its
// file was changed is refused, naming the file, instead of reading the new bytes as the old.
#include "VtiReader.hpp"
#include "VtuReader.hpp"

#include "support/TestSupport.hpp"

#include <volpost/core/ResourceLimits.hpp>

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace volpost;

namespace {

// Everything a reader gives, as text: counts, every node and cell, every field's values,
// or the error (of the read, or of a field's first use).
std::string describe(const MeshReader& reader, const std::string& path) {
  std::ostringstream out;
  out.precision(17);
  std::unique_ptr<Model> model;
  try {
    model = reader.read(path, {});
  } catch (const std::exception& e) {
    return std::string("read error: ") + e.what();
  }
  out << model->nodeCount() << " nodes, " << model->cellCount() << " cells\n";
  if (model->grid) {
    out << "grid " << model->grid->dims[0] << "x" << model->grid->dims[1] << "x" << model->grid->dims[2] << "\n";
  } else {
    for (const auto& p : model->mesh().nodes) out << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (std::size_t c = 0; c < model->mesh().cellCount(); ++c) {
      out << int(model->mesh().cellType(c));
      for (NodeIndex n : model->mesh().cellNodes(c)) out << ' ' << n;
      out << '\n';
    }
  }
  for (const auto& d : model->diagnostics) out << "diagnostic: " << d.message << '\n';
  for (const auto& field : model->fields) {
    out << "field " << field->name() << " (" << field->components() << ")\n";
    for (std::size_t s = 0; s < field->steps().size(); ++s) {
      try {
        for (double v : field->valuesCopy(s)) out << v << ' ';
      } catch (const std::exception& e) {
        out << "error: " << e.what();
      }
      out << '\n';
    }
  }
  return out.str();
}

std::string littleEndian64(std::uint64_t v) { return std::string(reinterpret_cast<const char*>(&v), 8); }

std::string zlibBlock(const std::string& raw) {
  uLongf size = compressBound(uLong(raw.size()));
  std::string out(size, '\0');
  EXPECT_EQ(compress(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size())),
            Z_OK);
  out.resize(size);
  return out;
}

// A VTK compressed array (UInt64 header) in blocks of `blockSize` bytes.
std::string compressedArray(const std::string& raw, std::size_t blockSize) {
  std::vector<std::string> blocks;
  for (std::size_t at = 0; at < raw.size(); at += blockSize) blocks.push_back(zlibBlock(raw.substr(at, blockSize)));
  const std::size_t last = raw.size() % blockSize;
  std::string out = littleEndian64(blocks.size()) + littleEndian64(blockSize) + littleEndian64(last);
  for (const auto& b : blocks) out += littleEndian64(b.size());
  for (const auto& b : blocks) out += b;
  return out;
}

template <typename T>
std::string bytesOf(const std::vector<T>& values) {
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// One tet with a nodal field, every array zlib-compressed in blocks of 12 bytes: each
// 8-byte value of the points and the field is cut by a block's end somewhere.
std::string oneTetInSmallZlibBlocks() {
  const std::string points = compressedArray(bytesOf<double>({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}), 12);
  const std::string conn = compressedArray(bytesOf<std::int64_t>({0, 1, 2, 3}), 12);
  const std::string offsets = compressedArray(bytesOf<std::int64_t>({4}), 12);
  const std::string types = compressedArray(std::string(1, char(10)), 12);
  const std::string wave = compressedArray(bytesOf<double>({0.5, -1.25, 3.0e10, 1.0 / 3.0}), 12);
  // Offsets in the order the arrays follow each other in the appended data.
  const std::string waveAt = "0", pointsAt = std::to_string(wave.size()),
                    connAt = std::to_string(wave.size() + points.size()),
                    offsetsAt = std::to_string(wave.size() + points.size() + conn.size()),
                    typesAt = std::to_string(wave.size() + points.size() + conn.size() + offsets.size());
  std::string xml =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">\n<UnstructuredGrid>\n"
      "<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<PointData>\n"
      "<DataArray type=\"Float64\" Name=\"wave\" format=\"appended\" offset=\"" + waveAt + "\"/>\n</PointData>\n"
      "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" offset=\"" + pointsAt +
      "\"/></Points>\n<Cells>\n"
      "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" offset=\"" + connAt + "\"/>\n"
      "<DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"" + offsetsAt + "\"/>\n"
      "<DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"" + typesAt + "\"/>\n"
      "</Cells>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_";
  return xml + wave + points + conn + offsets + types + "\n</AppendedData>\n</VTKFile>\n";
}

std::filesystem::path writeTemp(const std::string& name, const std::string& bytes) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

}  // namespace

TEST(VtuInPlaceRead, EveryVtkXmlFileOfTheSuiteReadsTheSameFromItsPlaceAsWhole) {
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(VOLPOST_TEST_DATA)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".vtu" && ext != ".vti") continue;
    // The hostile files that claim gigabytes are for the memory budget's tests, not this one.
    if (entry.path().filename().string().rfind("mem_", 0) == 0) continue;
    const std::string path = entry.path().string();
    const bool image = ext == ".vti";
    const meshio::VtuReader wholeVtu, inPlaceVtu(0);
    const meshio::VtiReader wholeVti, inPlaceVti(0);
    const MeshReader& whole = image ? static_cast<const MeshReader&>(wholeVti) : wholeVtu;
    const MeshReader& inPlace = image ? static_cast<const MeshReader&>(inPlaceVti) : inPlaceVtu;
    EXPECT_EQ(describe(inPlace, path), describe(whole, path)) << path;
    ++files;
  }
  EXPECT_GE(files, 30u) << "the suite's VTK XML files: good ones, broken ones and attacks";
}

TEST(VtuInPlaceRead, ValuesCutByZlibBlocksAreJoined) {
  const auto path = writeTemp("volpost_small_zlib_blocks.vtu", oneTetInSmallZlibBlocks());
  for (const std::uint64_t from : {std::uint64_t(0), meshio::kReadVtkXmlInPlaceFrom}) {
    const auto model = meshio::VtuReader(from).read(path.string(), {});
    ASSERT_EQ(model->mesh().nodeCount(), 4u);
    EXPECT_EQ(model->mesh().nodes[3], glm::dvec3(0, 0, 1));
    ASSERT_EQ(model->mesh().cellCount(), 1u);
    EXPECT_EQ(std::vector<NodeIndex>(model->mesh().cellNodes(0).begin(), model->mesh().cellNodes(0).end()),
              (std::vector<NodeIndex>{0, 1, 2, 3}));
    EXPECT_EQ(model->findField("wave")->valuesCopy(0), (std::vector<double>{0.5, -1.25, 3.0e10, 1.0 / 3.0}));
  }
  std::filesystem::remove(path);
}

TEST(VtuInPlaceRead, AFieldOfAFileChangedAfterOpeningIsRefusedNamingTheFile) {
  const std::string bytes = oneTetInSmallZlibBlocks();
  const auto path = writeTemp("volpost_changed_after_open.vtu", bytes);
  const auto model = meshio::VtuReader(0).read(path.string(), {});
  const Field* wave = model->findField("wave");
  ASSERT_NE(wave, nullptr);
  ASSERT_FALSE(wave->isLoaded(0)) << "read on first use";
  std::ofstream(path, std::ios::binary | std::ios::app) << "<!-- a solver writing its next step -->\n";
  try {
    (void)wave->valuesCopy(0);
    ADD_FAILURE() << "the changed file's bytes were taken for the field";
  } catch (const ReadError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("changed after it was opened"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

TEST(VtuInPlaceRead, AFileRemovedAfterOpeningStillGivesItsFields) {
  const auto path = writeTemp("volpost_removed_after_open.vtu", oneTetInSmallZlibBlocks());
  const auto model = meshio::VtuReader(0).read(path.string(), {});
  std::filesystem::remove(path);  // the reader holds the file open: its bytes stay readable
  EXPECT_EQ(model->findField("wave")->valuesCopy(0).size(), 4u);
}

// Read in place, a compression table or base64 text is checked against the memory budget
// before it is read: a hostile header cannot make the reader hold more than the budget.
TEST(VtuInPlaceRead, TablesAndTextBeyondTheMemoryBudgetAreRefused) {
  const std::size_t budget = memoryBudget();
  // A compressed array claiming 20,000 blocks of 1 byte (its table and sizes 320 KB) in a
  // run that holds them: a file of 181 KB within a 256 KB budget, its table beyond it.
  std::string run = littleEndian64(20000) + littleEndian64(1) + littleEndian64(1);
  for (int k = 0; k < 20000; ++k) run += littleEndian64(1);
  run += std::string(20000, 'x');
  const std::string xml =
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\" "
      "compressor=\"vtkZLibDataCompressor\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"1\" NumberOfCells=\"0\">\n"
      "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" offset=\"0\"/></Points>\n"
      "</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_";
  const auto path = writeTemp("volpost_many_blocks.vtu", xml + run + "\n</AppendedData>\n</VTKFile>\n");
  setMemoryBudget(256 * 1024);
  try {
    (void)meshio::VtuReader(0).read(path.string(), {});
    ADD_FAILURE() << "read past the budget";
  } catch (const ReadError& e) {
    EXPECT_NE(std::string(e.what()).find("20000 blocks, more than the memory budget"), std::string::npos) << e.what();
  }
  const std::string base64 =
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "<UnstructuredGrid>\n<Piece NumberOfPoints=\"1\" NumberOfCells=\"0\">\n"
      "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" offset=\"0\"/></Points>\n"
      "</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"base64\">\n_" + std::string(100000, 'A') +
      "\n</AppendedData>\n</VTKFile>\n";
  const auto textPath = writeTemp("volpost_long_base64.vtu", base64);
  setMemoryBudget(128 * 1024);  // the file's 100 KB fit, its text and decoded bytes (175 KB) do not
  try {
    (void)meshio::VtuReader(0).read(textPath.string(), {});
    ADD_FAILURE() << "read past the budget";
  } catch (const ReadError& e) {
    EXPECT_NE(std::string(e.what()).find("of base64 text need more than the memory budget"), std::string::npos) << e.what();
  }
  setMemoryBudget(budget);
  std::filesystem::remove(path);
  std::filesystem::remove(textPath);
}
