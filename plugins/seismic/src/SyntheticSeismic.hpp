// SPDX-License-Identifier: MIT
// Synthetic post-stack seismic by the convolution model: a layered earth whose interfaces
// rise over a dome and drop across a normal fault, the reflection coefficients of its
// acoustic impedances placed at each interface's two-way time, convolved along every
// trace with a Ricker wavelet, plus band-limited noise. Any size, repeatable from a seed:
// test and benchmark volumes with known structure.
#pragma once

#include <volpost/core/RegularGrid.hpp>

#include <cstdint>
#include <vector>

namespace volpost::seismic {

struct SyntheticSurvey {
  std::size_t inlines = 64, crosslines = 64, samples = 128;
  double binSize = 25.0;            ///< metres between lines
  double sampleIntervalMs = 4.0;
  double rotationDegrees = 0.0;     ///< of the inline axis against x
  double peakFrequencyHz = 25.0;    ///< of the Ricker wavelet
  int layers = 12;
  double domeHeightMs = 60.0;       ///< how far the dome lifts the layers at its crest
  double faultThrowMs = 24.0;       ///< how far the layers drop across the fault
  double noise = 0.05;              ///< noise standard deviation over the signal's
  std::uint64_t seed = 1;
};

struct SyntheticVolume {
  RegularGrid grid;            ///< inline 1000.., crossline 2000.., time from 0 ms
  std::vector<double> values;  ///< amplitudes, peak about 1
};

/// Throws std::invalid_argument for fewer than 2 points on an axis or a non-positive
/// interval, frequency or bin.
SyntheticVolume makeSyntheticSeismic(const SyntheticSurvey& survey);

/// The Ricker wavelet (1 - 2 (pi f t)^2) exp(-(pi f t)^2) at t seconds.
double ricker(double frequencyHz, double seconds);

}  // namespace volpost::seismic
