// SPDX-License-Identifier: MIT
#include "SeismicAttributes.hpp"

#include "AnyLengthFft.hpp"

#include <volpost/core/SampleView.hpp>
#include <volpost/core/WorkerThreads.hpp>

#include <cmath>
#include <complex>
#include <memory>
#include <stdexcept>

namespace volpost::seismic {
namespace {

// One plan per length and thread: a trace's attributes are computed on worker threads,
// trace after trace of the same length.
const AnyLengthFft& planFor(std::size_t n) {
  thread_local std::unique_ptr<AnyLengthFft> plan;
  if (!plan || plan->size() != n) plan = std::make_unique<AnyLengthFft>(n);
  return *plan;
}

// The analytic signal: the spectrum's negative frequencies dropped, the positive doubled
// (zero and Nyquist kept), back to time; the same as scipy.signal.hilbert of the trace.
std::vector<std::complex<double>> analyticSignal(std::span<const double> x) {
  const std::size_t n = x.size();
  if (n == 0) return {};
  const AnyLengthFft& fft = planFor(n);
  std::vector<std::complex<double>> spectrum = fft.transform({x.begin(), x.end()}, false);
  for (std::size_t k = 1; k < n; ++k) {
    const bool positive = 2 * k < n, nyquist = 2 * k == n;
    spectrum[k] *= positive ? 2.0 : nyquist ? 1.0 : 0.0;
  }
  std::vector<std::complex<double>> z = fft.transform(spectrum, true);
  for (auto& v : z) v /= double(n);
  return z;
}

// The phase advance from sample k to k + 1, in (-pi, pi]: up to half a turn a sample, so
// frequencies up to Nyquist are told apart.
double phaseAdvance(const std::vector<std::complex<double>>& z, std::size_t k) {
  return std::arg(z[k + 1] * std::conj(z[k]));
}

}  // namespace

TraceAttributes traceAttributes(std::span<const double> trace, double intervalSeconds) {
  TraceAttributes a;
  const std::size_t n = trace.size();
  const std::vector<std::complex<double>> z = analyticSignal(trace);
  a.envelope.resize(n);
  a.phaseDegrees.resize(n);
  a.frequencyHz.assign(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    a.envelope[k] = std::abs(z[k]);
    a.phaseDegrees[k] = std::arg(z[k]) * 180.0 / M_PI;
  }
  if (n < 2 || !(intervalSeconds > 0.0)) return a;
  // The mean of the advances into and out of each sample (one of them at the ends), each
  // wrapped on its own: the frequency at a sample, from -Nyquist to Nyquist.
  for (std::size_t k = 0; k < n; ++k) {
    double turn = 0.0;
    int advances = 0;
    if (k > 0) turn += phaseAdvance(z, k - 1), ++advances;
    if (k + 1 < n) turn += phaseAdvance(z, k), ++advances;
    a.frequencyHz[k] = turn / (2.0 * M_PI * double(advances) * intervalSeconds);
  }
  return a;
}

std::vector<double> rmsAmplitude(std::span<const double> trace, std::size_t window) {
  const std::size_t n = trace.size(), half = window / 2;
  std::vector<double> out(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t first = k >= half ? k - half : 0, last = std::min(n - 1, k + half);
    double sum = 0.0;
    for (std::size_t m = first; m <= last; ++m) sum += trace[m] * trace[m];
    out[k] = std::sqrt(sum / double(last - first + 1));
  }
  return out;
}

void addSeismicAttributes(Model& model) {
  if (!model.grid || model.fields.empty()) return;
  const RegularGrid grid = *model.grid;
  const std::shared_ptr<const Field> amplitude = model.fields.front();
  const double dt = grid.labelStep[2] / 1000.0;
  enum class Kind { Envelope, Phase, Frequency, Rms };
  const auto field = [&](const std::string& name, Kind kind) {
    // Kept as 32-bit floats (4 bytes a point, 7 significant digits): an attribute is a
    // derived picture of the amplitude, not a measurement to keep to 16 digits.
    return Field::fromSamples(
        name, FieldLocation::Node, 1, grid.pointCount(), amplitude->steps(), [grid, amplitude, dt, kind](std::size_t step) {
          std::vector<double> converted;  // only for an amplitude not kept as samples
          const SampleView x = amplitude->storesSamples() ? SampleView(amplitude->samples(step))
                                                          : SampleView(converted = amplitude->valuesCopy(step));
          SampleArray out(SampleType::Float32, x.size());
          const std::size_t traces = grid.dims[0] * grid.dims[1], samples = grid.dims[2];
          const auto computeTraces = [&](std::size_t first, std::size_t end) {
            std::vector<double> trace(samples);
            for (std::size_t t = first; t < end; ++t) {
              for (std::size_t k = 0; k < samples; ++k) trace[k] = x[t + traces * k];
              std::vector<double> result;
              if (kind == Kind::Rms) {
                result = rmsAmplitude(trace, kRmsWindow);
              } else {
                TraceAttributes a = traceAttributes(trace, dt);
                result = kind == Kind::Envelope ? std::move(a.envelope)
                         : kind == Kind::Phase  ? std::move(a.phaseDegrees)
                                                : std::move(a.frequencyHz);
              }
              for (std::size_t k = 0; k < samples; ++k) out.set(t + traces * k, result[k]);
            }
          };
          forEachChunk(traces, 256, computeTraces);  // on all cores: each chunk writes its own traces
          return out;
        });
  };
  // The envelope and the RMS amplitude are amplitudes: the amplitude's units. Phase and
  // frequency carry theirs in their names.
  auto envelope = field("envelope", Kind::Envelope), rms = field("RMS amplitude", Kind::Rms);
  envelope->setUnits(amplitude->units());
  rms->setUnits(amplitude->units());
  model.fields.push_back(std::move(envelope));
  model.fields.push_back(field("phase (degrees)", Kind::Phase));
  model.fields.push_back(field("frequency (Hz)", Kind::Frequency));
  model.fields.push_back(std::move(rms));
}

}  // namespace volpost::seismic
