// SPDX-License-Identifier: MIT
// The SEG-Y reader: every sample format in both byte orders round-trips through the
// writer; geometry from the headers (rotation, labels, missing traces); refusals that name
// the defect (truncated, text only, pre-stack, a count that does not fit); the real F3
// crop in its five formats and both byte orders reads the same numbers.
#include "SegyReader.hpp"
#include "SegyWriter.hpp"

#include "support/TestSupport.hpp"

#include <volpost/core/Error.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace volpost::seismic {
namespace {

namespace fs = std::filesystem;

fs::path tempFile(const std::string& name) { return fs::temp_directory_path() / ("volpost_segy_" + name); }

std::vector<char> bytesOf(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}
void writeBytes(const fs::path& p, const std::vector<char>& bytes) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

// A 4 x 3 x 6 survey, rotated 30 degrees, 25 m x 12.5 m bins, inlines 100, 102, ...,
// crosslines 7, 8, ..., times 8, 12, ... ms; integer amplitudes so every format is exact.
RegularGrid surveyGrid() {
  RegularGrid g;
  g.dims = {4, 3, 6};
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  g.origin = {620000.0, 6070000.0, -8.0};
  g.axes = {glm::dvec3(25 * c, 25 * s, 0), glm::dvec3(-12.5 * s, 12.5 * c, 0), glm::dvec3(0, 0, -4)};
  g.firstLabel = {100, 7, 8};
  g.labelStep = {2, 1, 4};
  return g;
}
std::vector<double> surveyValues(const RegularGrid& g) {
  std::vector<double> v(g.pointCount());
  for (std::size_t n = 0; n < v.size(); ++n) v[n] = double(int(n * 7 % 101) - 50);
  return v;
}

TEST(SegyLayout, IbmFloatsDecodeExactly) {
  EXPECT_EQ(ibmToDouble(0xC276A000u), -118.625);  // the standard's example
  EXPECT_EQ(ibmToDouble(0x42640000u), 100.0);
  EXPECT_EQ(ibmToDouble(0x00000000u), 0.0);
  EXPECT_EQ(ibmToDouble(0x41100000u), 1.0);
}

TEST(SegyReader, EveryFormatAndByteOrderRoundTrips) {
  const RegularGrid grid = surveyGrid();
  const std::vector<double> values = surveyValues(grid);
  for (SampleFormat f : {SampleFormat::IbmFloat32, SampleFormat::Int32, SampleFormat::Int16, SampleFormat::IeeeFloat32,
                         SampleFormat::IeeeFloat64, SampleFormat::Int8})
    for (ByteOrder order : {ByteOrder::Big, ByteOrder::Little}) {
      SCOPED_TRACE(describe(f) + (order == ByteOrder::Big ? " big" : " little"));
      const fs::path p = tempFile("roundtrip.sgy");
      writeSegy(p.string(), grid, values, {f, order});
      EXPECT_GT(SegyReader().sniff(std::string_view(bytesOf(p).data(), 3600)), 50);
      const auto model = readSegy(p.string(), {});
      ASSERT_TRUE(model->grid);
      const RegularGrid& r = *model->grid;
      EXPECT_EQ(r.dims, grid.dims);
      EXPECT_EQ(r.firstLabel, grid.firstLabel);
      EXPECT_EQ(r.labelStep, grid.labelStep);
      for (int a = 0; a < 3; ++a) EXPECT_LT(glm::distance(r.axes[a], grid.axes[a]), 0.02) << "axis " << a;
      EXPECT_LT(glm::distance(r.origin, grid.origin), 0.02);
      EXPECT_FALSE(model->meshBuilt()) << "a grid's cells are built only when asked for";
      // The samples stay in the file's type: 1, 2 or 4 bytes each (IBM floats as 32-bit floats).
      const SampleType stored = f == SampleFormat::Int8 ? SampleType::Int8 : f == SampleFormat::Int16 ? SampleType::Int16
                                : f == SampleFormat::Int32 ? SampleType::Int32 : f == SampleFormat::IeeeFloat64 ? SampleType::Float64
                                                                                                              : SampleType::Float32;
      ASSERT_TRUE(model->fields.at(0)->storesSamples());
      EXPECT_EQ(model->fields.at(0)->samples(0).type(), stored);
      EXPECT_EQ(model->fields.at(0)->samples(0).toDoubles(), values);
      EXPECT_EQ(model->mesh().nodeCount(), grid.pointCount());
      EXPECT_EQ(model->mesh().cellCount(), grid.cellCount());
      EXPECT_EQ(model->fields.at(0)->values(0), values);
      EXPECT_TRUE(model->diagnostics.empty());
      fs::remove(p);
    }
}

// An IBM float beyond a 32-bit float's range (IBM reaches 7e75) widens the kept samples to
// 64-bit floats instead of turning into infinity, and is flagged.
TEST(SegyReader, IbmFloatsBeyondAFloatsRangeAreKeptAsDoubles) {
  const RegularGrid grid = surveyGrid();
  std::vector<double> values = surveyValues(grid);
  values[17] = 1e40;
  values[40] = -3e-45;  // below a float's normal range: not exact as a float either
  const fs::path p = tempFile("ibm_wide.sgy");
  writeSegy(p.string(), grid, values, {SampleFormat::IbmFloat32, ByteOrder::Big});
  const auto model = readSegy(p.string(), {});
  const SampleArray& kept = model->fields.at(0)->samples(0);
  EXPECT_EQ(kept.type(), SampleType::Float64);
  EXPECT_NEAR(kept[17], 1e40, 1e34);
  EXPECT_NEAR(kept[40], -3e-45, 1e-51);
  EXPECT_EQ(kept[16], values[16]);
  // Kept, and said: such a sample is usually junk, and it stretches the color scale.
  ASSERT_EQ(model->diagnostics.size(), 1u);
  EXPECT_EQ(model->diagnostics[0].code, "samples-beyond-float");
  EXPECT_NE(model->diagnostics[0].message.find("1 sample beyond a 32-bit float's range (up to 1e+40)"),
            std::string::npos)
      << model->diagnostics[0].message;
  fs::remove(p);
}

TEST(SegyReader, MissingTracesAreFilledWithZeroAndFlagged) {
  const RegularGrid grid = surveyGrid();
  const std::vector<double> values = surveyValues(grid);
  const fs::path p = tempFile("missing.sgy");
  writeSegy(p.string(), grid, values, {SampleFormat::IeeeFloat32, ByteOrder::Big});
  std::vector<char> bytes = bytesOf(p);
  const std::size_t traceBytes = 240 + 6 * 4;
  // Drop the 5th trace (inline index 1, crossline index 1).
  bytes.erase(bytes.begin() + std::ptrdiff_t(3600 + 4 * traceBytes), bytes.begin() + std::ptrdiff_t(3600 + 5 * traceBytes));
  writeBytes(p, bytes);
  const auto model = readSegy(p.string(), {});
  ASSERT_EQ(model->diagnostics.size(), 1u);
  EXPECT_EQ(model->diagnostics[0].code, "missing-traces");
  const std::vector<double>& read = model->fields[0]->values(0);
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(read[grid.pointIndex(1, 1, k)], 0.0);
    EXPECT_EQ(read[grid.pointIndex(1, 2, k)], values[grid.pointIndex(1, 2, k)]);
  }
  fs::remove(p);
}

// Trace bytes 203-204 (revision 1): the unit of the values, shown in the legend and the
// probe; traces that disagree, or a revision 0 file, give none.
TEST(SegyReader, ValueUnitsComeFromTheTraceHeaders) {
  const RegularGrid grid = surveyGrid();
  const fs::path p = tempFile("units.sgy");
  SegyWriteOptions options;
  options.valueUnitCode = 1;  // Pascal
  writeSegy(p.string(), grid, surveyValues(grid), options);
  const auto unitsOf = [](const Model& m, const std::string& field) { return m.findField(field)->units(); };
  {
    const auto model = readSegy(p.string(), {});
    EXPECT_EQ(unitsOf(*model, "amplitude"), "Pa");
    EXPECT_EQ(unitsOf(*model, "envelope"), "Pa");  // amplitudes too
    EXPECT_EQ(unitsOf(*model, "RMS amplitude"), "Pa");
    EXPECT_EQ(unitsOf(*model, "phase (degrees)"), "");  // its name says it
    EXPECT_TRUE(model->diagnostics.empty());
  }
  std::vector<char> bytes = bytesOf(p);
  const std::size_t traceBytes = 240 + 6 * 4, third = 3600 + 2 * traceBytes;
  bytes[third + 202] = 0, bytes[third + 203] = 5;  // metres, in one trace
  writeBytes(p, bytes);
  {
    const auto model = readSegy(p.string(), {});
    EXPECT_EQ(unitsOf(*model, "amplitude"), "");
    ASSERT_EQ(model->diagnostics.size(), 1u);
    EXPECT_EQ(model->diagnostics[0].code, "trace-value-units");
    EXPECT_NE(model->diagnostics[0].message.find("5 in trace 3, at byte " + std::to_string(third + 202)),
              std::string::npos)
        << model->diagnostics[0].message;
  }
  bytes[third + 203] = 1;
  bytes[3500] = 0;  // revision 0: bytes 203-204 are not the unit there
  writeBytes(p, bytes);
  EXPECT_EQ(unitsOf(*readSegy(p.string(), {}), "amplitude"), "");
  fs::remove(p);
  EXPECT_EQ(traceValueUnits(7), "m/s^2");
  EXPECT_EQ(traceValueUnits(0), "");
  EXPECT_EQ(traceValueUnits(-1), "");  // "other": the standard does not say which
  EXPECT_EQ(traceValueUnits(10), "");
}

void expectRefused(const fs::path& p, const std::string& words) {
  try {
    (void)readSegy(p.string(), {});
    ADD_FAILURE() << p << " was read";
  } catch (const ReadError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
  }
}

TEST(SegyReader, RefusesDamagedFilesNamingTheDefect) {
  const RegularGrid grid = surveyGrid();
  const fs::path p = tempFile("damaged.sgy");
  writeSegy(p.string(), grid, surveyValues(grid), {SampleFormat::IeeeFloat32, ByteOrder::Big});
  const std::vector<char> good = bytesOf(p);

  writeBytes(p, std::vector<char>(good.begin(), good.end() - 100));
  expectRefused(p, "ends inside trace 12");
  writeBytes(p, std::vector<char>(good.begin(), good.begin() + 3600));
  expectRefused(p, "no traces");
  writeBytes(p, std::vector<char>(good.begin(), good.begin() + 1000));
  expectRefused(p, "3600 bytes of headers");
  std::vector<char> bad = good;
  bad[3224] = 0x00, bad[3225] = 0x07;  // format code 7
  writeBytes(p, bad);
  expectRefused(p, "format code");
  bad = good;
  bad[3220] = char(0xEA), bad[3221] = 0x60;  // 60000 samples per trace: far more than the file holds
  writeBytes(p, bad);
  expectRefused(p, "ends inside trace 1");
  // One inline only: not a volume.
  RegularGrid line = grid;
  line.dims = {1, 3, 6};
  writeSegy(p.string(), line, std::vector<double>(18, 1.0));
  expectRefused(p, "at least 2");
  fs::remove(p);
}

TEST(SegyReader, PreStackFilesAreRefusedOrReadAtTheChosenOffset) {
  const RegularGrid grid = surveyGrid();
  const fs::path p = tempFile("prestack.sgy");
  writeSegy(p.string(), grid, surveyValues(grid), {SampleFormat::IeeeFloat32, ByteOrder::Big});
  std::vector<char> bytes = bytesOf(p);
  const std::size_t traceBytes = 240 + 6 * 4;
  std::vector<char> extra(bytes.begin() + 3600, bytes.begin() + std::ptrdiff_t(3600 + traceBytes));
  extra[36 + 3] = 50;  // offset 50 at bytes 37-40
  bytes.insert(bytes.end(), extra.begin(), extra.end());
  writeBytes(p, bytes);
  expectRefused(p, "pre-stack data: 2 offsets (0, 50)");
  const auto model = readSegy(p.string(), {TraceFieldPositions{}, 0});
  EXPECT_EQ(model->grid->dims, grid.dims);
  EXPECT_THROW((void)readSegy(p.string(), {TraceFieldPositions{}, 7}), ReadError);
  fs::remove(p);
}

// Reader options (what `--reader-option` and File > Reader Options... hand the reader):
// header positions moved away from the standard bytes read as the original file does; the
// pre-stack offset by name; bad names and values refused before reading, naming them.
TEST(SegyReader, ReaderOptionsMoveHeaderPositionsAndPickAnOffset) {
  const RegularGrid grid = surveyGrid();
  const std::vector<double> values = surveyValues(grid);
  const fs::path p = tempFile("moved_headers.sgy");
  writeSegy(p.string(), grid, values, {SampleFormat::IeeeFloat32, ByteOrder::Big});
  const auto original = readSegy(p.string(), {});
  std::vector<char> bytes = bytesOf(p);
  const std::size_t traceBytes = 240 + 6 * 4, traces = 4 * 3;
  ASSERT_EQ(bytes.size(), 3600 + traces * traceBytes);
  for (std::size_t t = 0; t < traces; ++t) {  // inline number from byte 189 to byte 17, crossline from 193 to 21
    char* h = bytes.data() + 3600 + t * traceBytes;
    std::copy(h + 188, h + 196, h + 16);
    std::fill(h + 188, h + 196, char(0));
  }
  writeBytes(p, bytes);
  expectRefused(p, "at least 2");  // the standard bytes now hold zeros: one inline
  const SegyReader reader;
  const auto model = reader.readWith(p.string(), {{"inline-byte", "17"}, {"crossline-byte", "21"}}, {});
  EXPECT_EQ(model->grid->dims, grid.dims);
  EXPECT_EQ(model->grid->firstLabel, grid.firstLabel);
  EXPECT_EQ(model->grid->labelStep, grid.labelStep);
  EXPECT_EQ(model->grid->axes, original->grid->axes);
  EXPECT_EQ(model->grid->origin, original->grid->origin);

  const auto refused = [&](const ReaderOptions& options, const std::string& words) {
    try {
      (void)reader.readWith(p.string(), options, {});
      ADD_FAILURE() << "accepted " << options.begin()->first << "=" << options.begin()->second;
    } catch (const ReaderOptionError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused({{"inline-byte", "238"}}, "must start at byte 1..237");
  refused({{"inline-byte", "0"}}, "must start at byte 1..237");
  refused({{"scalar-byte", "240"}}, "1..239");
  refused({{"inline-byte", "17x"}}, "not a whole number");
  refused({{"inline", "17"}}, "takes inline-byte, crossline-byte");
  EXPECT_THROW((void)readSegy(p.string(), {TraceFieldPositions{240, 193}, std::nullopt}), std::invalid_argument)
      << "the library call checks positions too";
  fs::remove(p);

  // The pre-stack file of the test above, its offset chosen by option.
  const fs::path q = tempFile("prestack_option.sgy");
  writeSegy(q.string(), grid, values, {SampleFormat::IeeeFloat32, ByteOrder::Big});
  std::vector<char> pre = bytesOf(q);
  std::vector<char> extra(pre.begin() + 3600, pre.begin() + std::ptrdiff_t(3600 + traceBytes));
  extra[36 + 3] = 50;
  pre.insert(pre.end(), extra.begin(), extra.end());
  writeBytes(q, pre);
  expectRefused(q, "--reader-option offset=N");
  EXPECT_EQ(reader.readWith(q.string(), {{"offset", "0"}}, {})->grid->dims, grid.dims);
  EXPECT_THROW((void)reader.readWith(q.string(), {{"offset", "7"}}, {}), ReadError);
  fs::remove(q);
}

TEST(MeshReader, AReaderWithoutOptionsRefusesAnyButReadsWithNone) {
  struct Plain : MeshReader {
    std::string formatName() const override { return "plain"; }
    std::vector<std::string> extensions() const override { return {"txt"}; }
    int sniff(std::string_view) const override { return 1; }
    std::unique_ptr<Model> read(const std::string&, const Progress&) const override { return std::make_unique<Model>(); }
  } plain;
  EXPECT_TRUE(plain.options().empty());
  EXPECT_NE(plain.readWith("x.txt", {}, {}), nullptr);
  try {
    (void)plain.readWith("x.txt", {{"inline-byte", "9"}}, {});
    ADD_FAILURE() << "an option was accepted by a reader that takes none";
  } catch (const ReaderOptionError& e) {
    EXPECT_STREQ(e.what(), "reader option inline-byte=9: the plain reader takes no options");
  }
}

// ---- the shared test files ----------------------------------------------------------------

std::vector<double> readAmplitudes(const std::string& path, RegularGrid* grid = nullptr) {
  const auto model = readSegy(path, {});
  if (grid) *grid = *model->grid;
  return model->fields.at(0)->values(0);
}

TEST(SegyReader, TheF3CropReadsTheSameInEveryFormatAndByteOrder) {
  VOLPOST_SHARED_OR_SKIP(f3, "seismic/segyio/f3.sgy");
  RegularGrid grid;
  const std::vector<double> reference = readAmplitudes(f3, &grid);
  EXPECT_EQ(grid.dims, (std::array<std::size_t, 3>{23, 18, 75}));
  EXPECT_EQ(grid.firstLabel[0], 111);
  EXPECT_EQ(grid.firstLabel[1], 875);
  EXPECT_EQ(grid.labelStep[2], 4.0);
  EXPECT_NEAR(glm::length(grid.axes[0]), 25.0, 0.1);  // the F3 block's 25 m bins
  EXPECT_NEAR(glm::length(grid.axes[1]), 25.0, 0.1);
  EXPECT_EQ(*std::min_element(reference.begin(), reference.end()), -10239.0);
  EXPECT_EQ(*std::max_element(reference.begin(), reference.end()), 10827.0);
  const std::string dir = fs::path(f3).parent_path().string() + "/";
  for (const char* same : {"f3-lsb.sgy", "Format1msb.sgy", "Format1lsb.sgy", "Format3msb.sgy", "Format5msb.sgy"}) {
    SCOPED_TRACE(same);
    EXPECT_EQ(readAmplitudes(dir + same), reference);
  }
  const std::vector<double> int8 = readAmplitudes(dir + "Format8msb.sgy");
  EXPECT_EQ(*std::min_element(int8.begin(), int8.end()), -128.0);
  EXPECT_EQ(*std::max_element(int8.begin(), int8.end()), 127.0);
}

TEST(SegyReader, SmallSyntheticFilesAndARotatedSurvey) {
  VOLPOST_SHARED_OR_SKIP(small, "seismic/segyio/small.sgy");
  const std::string dir = fs::path(small).parent_path().string() + "/";
  RegularGrid grid;
  const std::vector<double> values = readAmplitudes(small, &grid);
  EXPECT_EQ(grid.dims, (std::array<std::size_t, 3>{5, 5, 50}));
  EXPECT_NEAR(*std::min_element(values.begin(), values.end()), 1.2, 1e-6);
  EXPECT_NEAR(*std::max_element(values.begin(), values.end()), 5.24, 1e-3);
  EXPECT_EQ(readAmplitudes(dir + "small-lsb.sgy"), values);
  RegularGrid acute;
  EXPECT_EQ(readAmplitudes(dir + "acute-small.sgy", &acute), values);
  // 45 degrees against the CDP x/y axes, as its coordinates say.
  EXPECT_NEAR(std::abs(acute.axes[0].x), std::abs(acute.axes[0].y), 1e-9);
  EXPECT_NEAR(glm::dot(acute.axes[0], acute.axes[1]), 0.0, 1e-9);
  RegularGrid tiny;
  (void)readAmplitudes(dir + "tiny.sgy", &tiny);
  EXPECT_EQ(tiny.dims, (std::array<std::size_t, 3>{3, 2, 4}));
  RegularGrid rev2;
  EXPECT_EQ(readAmplitudes(dir + "rotated-small-rev2.sgy", &rev2).size(), 1250u);
}

TEST(SegyReader, TheSharedBrokenFilesAreRefusedWithoutACrash) {
  VOLPOST_SHARED_OR_SKIP(broken, "seismic/segyio/broken.sgy");
  const std::string dir = fs::path(broken).parent_path().string() + "/";
  expectRefused(broken, "ends inside trace");
  expectRefused(dir + "text.sgy", "no traces");
  expectRefused(dir + "small-ps.sgy", "pre-stack");
  EXPECT_THROW((void)readSegy(dir + "long.sgy", {}), ReadError);  // segyio 1.8.3 aborts here
}

}  // namespace
}  // namespace volpost::seismic
