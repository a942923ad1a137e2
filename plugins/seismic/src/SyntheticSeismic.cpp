// SPDX-License-Identifier: MIT
#include "SyntheticSeismic.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

namespace volpost::seismic {

double ricker(double frequencyHz, double seconds) {
  const double a = M_PI * frequencyHz * seconds;
  return (1.0 - 2.0 * a * a) * std::exp(-a * a);
}

SyntheticVolume makeSyntheticSeismic(const SyntheticSurvey& s) {
  if (s.inlines < 2 || s.crosslines < 2 || s.samples < 2)
    throw std::invalid_argument("a synthetic survey needs at least 2 inlines, crosslines and samples");
  if (!(s.sampleIntervalMs > 0.0) || !(s.peakFrequencyHz > 0.0) || !(s.binSize > 0.0) || s.layers < 1)
    throw std::invalid_argument("the sample interval, frequency, bin size and layer count must be positive");
  SyntheticVolume out;
  RegularGrid& g = out.grid;
  g.dims = {s.inlines, s.crosslines, s.samples};
  const double angle = s.rotationDegrees * M_PI / 180.0;
  g.origin = {620000.0, 6080000.0, 0.0};
  g.axes = {glm::dvec3(s.binSize * std::cos(angle), s.binSize * std::sin(angle), 0.0),
            glm::dvec3(-s.binSize * std::sin(angle), s.binSize * std::cos(angle), 0.0),
            glm::dvec3(0.0, 0.0, -s.sampleIntervalMs)};
  g.axisNames = {"inline", "crossline", "time (ms)"};
  g.firstLabel = {1000.0, 2000.0, 0.0};
  g.labelStep = {1.0, 1.0, s.sampleIntervalMs};
  g.sampleStorage = "synthetic";

  std::mt19937_64 random(s.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  // Layer impedances (a random walk: sands and shales) and their base times.
  const double duration = double(s.samples - 1) * s.sampleIntervalMs;
  std::vector<double> impedance(std::size_t(s.layers) + 1), interface(std::size_t(s.layers));
  impedance[0] = 5.0e6;
  for (std::size_t l = 1; l < impedance.size(); ++l) impedance[l] = impedance[l - 1] * (0.85 + 0.35 * uniform(random));
  for (std::size_t l = 0; l < interface.size(); ++l)
    interface[l] = duration * (0.12 + 0.8 * (double(l) + 0.3 + 0.4 * uniform(random)) / double(s.layers));

  // The wavelet, sampled over +-1.5 periods.
  const double dt = s.sampleIntervalMs / 1000.0;
  const int half = int(std::ceil(1.5 / s.peakFrequencyHz / dt));
  std::vector<double> wavelet(std::size_t(2 * half + 1));
  for (int n = -half; n <= half; ++n) wavelet[std::size_t(n + half)] = ricker(s.peakFrequencyHz, n * dt);

  const double ni = double(s.inlines - 1), nj = double(s.crosslines - 1);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  out.values.assign(g.pointCount(), 0.0);
  std::vector<double> reflectivity(s.samples), trace(s.samples);
  for (std::size_t j = 0; j < s.crosslines; ++j)
    for (std::size_t i = 0; i < s.inlines; ++i) {
      const double x = double(i) / ni, y = double(j) / nj;  // 0..1 across the survey
      const double r2 = (x - 0.45) * (x - 0.45) + (y - 0.55) * (y - 0.55);
      const double dome = s.domeHeightMs * std::exp(-r2 / 0.06);
      const bool downthrown = 0.8 * x + 0.6 * y > 0.95;  // a fault striking across the survey
      std::fill(reflectivity.begin(), reflectivity.end(), 0.0);
      for (std::size_t l = 0; l < interface.size(); ++l) {
        // Deeper layers follow the dome less (it grew while they were laid down).
        const double lift = dome * (0.4 + 0.6 * double(l + 1) / double(s.layers));
        const double t = interface[l] - lift + (downthrown ? s.faultThrowMs : 0.0);
        const double r = (impedance[l + 1] - impedance[l]) / (impedance[l + 1] + impedance[l]);
        const double at = t / s.sampleIntervalMs;
        const auto n = std::ptrdiff_t(std::floor(at));
        const double w = at - double(n);
        // Split between the two samples around the interface: it moves smoothly.
        if (n >= 0 && n < std::ptrdiff_t(s.samples)) reflectivity[std::size_t(n)] += r * (1.0 - w);
        if (n + 1 >= 0 && n + 1 < std::ptrdiff_t(s.samples)) reflectivity[std::size_t(n + 1)] += r * w;
      }
      for (std::size_t k = 0; k < s.samples; ++k) {
        double sum = 0.0;
        for (int m = -half; m <= half; ++m) {
          const auto src = std::ptrdiff_t(k) - m;
          if (src >= 0 && src < std::ptrdiff_t(s.samples)) sum += wavelet[std::size_t(m + half)] * reflectivity[std::size_t(src)];
        }
        trace[k] = sum;
      }
      for (std::size_t k = 0; k < s.samples; ++k) out.values[g.pointIndex(i, j, k)] = trace[k];
    }
  // Scale to a peak near 1, then noise relative to that.
  double peak = 0.0;
  for (double v : out.values) peak = std::max(peak, std::abs(v));
  const double scale = peak > 0.0 ? 1.0 / peak : 1.0;
  for (double& v : out.values) v = v * scale + s.noise * gaussian(random);
  return out;
}

}  // namespace volpost::seismic
