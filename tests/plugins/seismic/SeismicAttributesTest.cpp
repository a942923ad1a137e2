// SPDX-License-Identifier: MIT
// The seismic attributes against analytic signals: a cosine's envelope is its amplitude,
// its phase advances linearly, its instantaneous frequency is its own; a modulated cosine's
// envelope is the modulation; the RMS of a sine over whole periods is A / sqrt(2). And the
// attributes arrive as fields of a SEG-Y model, computed when first asked for.
#include "AnyLengthFft.hpp"
#include "SegyReader.hpp"
#include "SegyWriter.hpp"
#include "SeismicAttributes.hpp"

#include "support/TestSupport.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>

namespace volpost::seismic {
namespace {

constexpr double kDt = 0.004;  // 4 ms

std::vector<double> cosine(std::size_t n, double amplitude, double hz, double phase0) {
  std::vector<double> x(n);
  for (std::size_t k = 0; k < n; ++k) x[k] = amplitude * std::cos(2.0 * M_PI * hz * double(k) * kDt + phase0);
  return x;
}

double wrapDegrees(double d) { return std::remainder(d, 360.0); }

TEST(SeismicAttributes, ACosinesEnvelopePhaseAndFrequency) {
  // 25 Hz over 200 samples of 4 ms: exactly 20 periods, so the FFT sees no edge.
  const std::vector<double> x = cosine(200, 3.0, 25.0, 0.4);
  const TraceAttributes a = traceAttributes(x, kDt);
  for (std::size_t k = 0; k < x.size(); ++k) {
    EXPECT_NEAR(a.envelope[k], 3.0, 3e-5) << k;
    const double expected = (2.0 * M_PI * 25.0 * double(k) * kDt + 0.4) * 180.0 / M_PI;
    EXPECT_NEAR(wrapDegrees(a.phaseDegrees[k] - expected), 0.0, 1e-3) << k;
    EXPECT_NEAR(a.frequencyHz[k], 25.0, 1e-3) << k;
  }
}

TEST(SeismicAttributes, FrequenciesUpToNyquistAreTheirOwn) {
  // At 4 ms Nyquist is 125 Hz. The phase advance over two samples wraps above 62.5 Hz (a
  // 70 Hz cosine read -55 Hz); each one-sample advance wraps only at Nyquist. 500 samples:
  // two seconds, whole periods of every frequency below.
  for (double hz : {10.0, 62.0, 63.0, 70.0, 80.0, 95.0, 110.0, 120.0, 124.0}) {
    const std::vector<double> x = cosine(500, 1.0, hz, 0.3);
    const TraceAttributes a = traceAttributes(x, kDt);
    for (std::size_t k = 0; k < x.size(); ++k) ASSERT_NEAR(a.frequencyHz[k], hz, 1e-6) << hz << " Hz, sample " << k;
  }
}

TEST(SeismicAttributes, APrimeTraceLengthGivesTheSameTransformQuickly) {
  // A length of one prime factor goes through the chirp-z transform: the same DFT as the
  // direct sum, and the attributes of a trace of 65,521 samples (the largest 16-bit prime)
  // in the time of a few power-of-two transforms, not n^2 (about 4e9 operations).
  for (std::size_t n : {7, 97, 101, 1009}) {
    const AnyLengthFft fft(n);
    EXPECT_EQ(fft.usesChirp(), n > 61) << n;
    std::vector<std::complex<double>> x(n);
    for (std::size_t j = 0; j < n; ++j) x[j] = {std::sin(0.37 * double(j * j % 101)), std::cos(1.3 * double(j))};
    const auto forward = fft.transform(x, false), back = fft.transform(forward, true);
    for (std::size_t k = 0; k < n; k += std::max<std::size_t>(1, n / 17)) {
      std::complex<double> sum(0.0);
      for (std::size_t j = 0; j < n; ++j) sum += x[j] * std::polar(1.0, -2.0 * M_PI * double(j * k % n) / double(n));
      EXPECT_LT(std::abs(forward[k] - sum), 1e-10 * double(n)) << n << " " << k;
      EXPECT_LT(std::abs(back[k] / double(n) - x[k]), 1e-12) << n << " " << k;
    }
  }
  EXPECT_EQ(largestPrimeFactor(65521), 65521u);
  const std::vector<double> x = cosine(65521, 2.0, 30.0, 0.0);
  const TraceAttributes a = traceAttributes(x, kDt);
  // Not whole periods, so only away from the ends.
  for (std::size_t k = 1000; k + 1000 < x.size(); k += 997) {
    EXPECT_NEAR(a.envelope[k], 2.0, 1e-3) << k;
    EXPECT_NEAR(a.frequencyHz[k], 30.0, 1e-2) << k;
  }
}

TEST(SeismicAttributes, AModulatedCosinesEnvelopeIsItsModulation) {
  // (2 + cos(2 pi 2 t)) cos(2 pi 50 t): bands 48..52 Hz, all below Nyquist (125 Hz).
  const std::size_t n = 250;  // 1 s: whole periods of both
  std::vector<double> x(n), modulation(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = double(k) * kDt;
    modulation[k] = 2.0 + std::cos(2.0 * M_PI * 2.0 * t);
    x[k] = modulation[k] * std::cos(2.0 * M_PI * 50.0 * t);
  }
  const TraceAttributes a = traceAttributes(x, kDt);
  for (std::size_t k = 0; k < n; ++k) EXPECT_NEAR(a.envelope[k], modulation[k], 1e-4) << k;
}

TEST(SeismicAttributes, RmsAmplitudeOfASine) {
  const std::vector<double> x = cosine(400, 2.0, 25.0, 0.0);  // 10 samples per period
  const std::vector<double> rms = rmsAmplitude(x, 21);        // windows of two whole periods (and one sample)
  for (std::size_t k = 10; k + 10 < x.size(); ++k) EXPECT_NEAR(rms[k], std::sqrt(2.0), 0.08) << k;
  const std::vector<double> whole = rmsAmplitude(x, 801);
  EXPECT_NEAR(whole[200], std::sqrt(2.0), 1e-9);  // the whole trace: 40 periods
}

TEST(SeismicAttributes, ASegyModelOffersThemAsFieldsComputedOnFirstUse) {
  RegularGrid g;
  g.dims = {3, 2, 200};
  g.axes = {glm::dvec3(25, 0, 0), glm::dvec3(0, 25, 0), glm::dvec3(0, 0, -4)};
  g.labelStep = {1, 1, 4};
  std::vector<double> values(g.pointCount());
  const std::vector<double> trace = cosine(200, 1000.0, 25.0, 0.0);
  for (std::size_t k = 0; k < 200; ++k)
    for (std::size_t t = 0; t < 6; ++t) values[t + 6 * k] = trace[k];
  const auto path = (std::filesystem::temp_directory_path() / "volpost_attributes.sgy").string();
  writeSegy(path, g, values, {SampleFormat::IeeeFloat32, ByteOrder::Big});
  const auto model = readSegy(path, {});
  std::vector<std::string> names;
  for (const auto& f : model->fields) names.push_back(f->name());
  EXPECT_EQ(names, (std::vector<std::string>{"amplitude", "envelope", "phase (degrees)", "frequency (Hz)", "RMS amplitude"}));
  const Field* frequency = model->findField("frequency (Hz)");
  ASSERT_NE(frequency, nullptr);
  EXPECT_FALSE(frequency->isLoaded(0));
  for (double f : frequency->values(0)) EXPECT_NEAR(f, 25.0, 1e-3);
  for (double e : model->findField("envelope")->values(0)) EXPECT_NEAR(e, 1000.0, 0.05);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace volpost::seismic
