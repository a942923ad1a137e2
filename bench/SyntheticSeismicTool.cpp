// SPDX-License-Identifier: MIT
// volpost_synthetic_seismic: writes a synthetic seismic volume (convolution model: layers,
// a dome, a fault, a Ricker wavelet, noise) as SEG-Y, any size, for tests and benchmarks.
#include "SegyWriter.hpp"
#include "SyntheticSeismic.hpp"

#include <volpost/core/Error.hpp>

#include <cstdio>
#include <stdexcept>
#include <cstdlib>
#include <string>

using namespace volpost;
using namespace volpost::seismic;

namespace {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const char* kUsage =
    "usage: volpost_synthetic_seismic [options] -o FILE.sgy\n"
    "Writes a synthetic post-stack seismic volume as SEG-Y rev 1 (big-endian): layers over a dome\n"
    "and across a fault, convolved with a Ricker wavelet, with noise.\n"
    "  --size NIxNXxNT     inlines x crosslines x samples (default 64x64x128)\n"
    "  --interval MS       sample interval in milliseconds (default 4)\n"
    "  --bin M             distance between lines in metres (default 25)\n"
    "  --rotation DEG      rotation of the inline axis against x (default 0)\n"
    "  --frequency HZ      peak frequency of the Ricker wavelet (default 25)\n"
    "  --noise F           noise standard deviation over the peak amplitude (default 0.05)\n"
    "  --format N          sample format: 1 IBM float, 2 int32, 3 int16, 5 IEEE float (default), 8 int8\n"
    "  --little-endian     write the little-endian variant\n"
    "  --seed N            random seed (default 1)\n";

double number(const std::string& option, const char* text) {
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0') throw UsageError(option + " " + text + " is not a number");
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    SyntheticSurvey survey;
    SegyWriteOptions write;
    std::string output;
    for (int a = 1; a < argc; ++a) {
      const std::string arg = argv[a];
      if (arg == "-h" || arg == "--help") {
        std::printf("%s", kUsage);
        return 0;
      }
      if (arg == "--little-endian") {
        write.order = ByteOrder::Little;
        continue;
      }
      if (a + 1 >= argc) throw UsageError(arg + " needs a value (or is not an option; see --help)");
      const char* value = argv[++a];
      if (arg == "-o") output = value;
      else if (arg == "--size") {
        unsigned long x = 0, y = 0, z = 0;
        char extra = 0;
        if (std::sscanf(value, "%lux%lux%lu%c", &x, &y, &z, &extra) != 3)
          throw UsageError(std::string("--size ") + value + " is not NIxNXxNT");
        survey.inlines = x, survey.crosslines = y, survey.samples = z;
      } else if (arg == "--interval") survey.sampleIntervalMs = number(arg, value);
      else if (arg == "--bin") survey.binSize = number(arg, value);
      else if (arg == "--rotation") survey.rotationDegrees = number(arg, value);
      else if (arg == "--frequency") survey.peakFrequencyHz = number(arg, value);
      else if (arg == "--noise") survey.noise = number(arg, value);
      else if (arg == "--seed") survey.seed = std::uint64_t(number(arg, value));
      else if (arg == "--format") {
        const auto f = sampleFormatOf(int(number(arg, value)));
        if (!f) throw UsageError(std::string("--format ") + value + " is not a SEG-Y sample format volpost writes");
        write.format = *f;
      } else
        throw UsageError("unknown option " + arg + " (see --help)");
    }
    if (output.empty()) throw UsageError("-o FILE.sgy is required (see --help)");
    SyntheticVolume volume = makeSyntheticSeismic(survey);
    if (write.format == SampleFormat::Int16 || write.format == SampleFormat::Int32 || write.format == SampleFormat::Int8) {
      const double peak = write.format == SampleFormat::Int8 ? 120.0 : 10000.0;  // integers: scale the ~1 peak up
      for (double& v : volume.values) v *= peak;
    }
    writeSegy(output, volume.grid, volume.values, write);
    std::printf("%s: %zu x %zu x %zu samples (%s)\n", output.c_str(), survey.inlines, survey.crosslines,
                survey.samples, describe(write.format).c_str());
    return 0;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "volpost_synthetic_seismic: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "volpost_synthetic_seismic: %s\n", e.what());
    return 1;
  }
}
