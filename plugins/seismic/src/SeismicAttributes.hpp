// SPDX-License-Identifier: MIT
// Seismic attributes of a trace from its analytic signal z = x + i H[x] (the Hilbert
// transform by FFT along time, KissFFT): instantaneous amplitude (the envelope |z|),
// instantaneous phase (arg z) and instantaneous frequency (the phase's rate, from
// arg(z[k+1] conj z[k-1]) so no unwrapping is needed), and the RMS amplitude in a sliding
// window. Added to a seismic model as fields computed on first use.
#pragma once

#include <volpost/core/Model.hpp>

#include <span>
#include <vector>

namespace volpost::seismic {

struct TraceAttributes {
  std::vector<double> envelope;
  std::vector<double> phaseDegrees;  ///< -180 .. 180
  std::vector<double> frequencyHz;   ///< >= 0 for a signal whose phase advances
};

/// The attributes of one trace sampled every `intervalSeconds`.
TraceAttributes traceAttributes(std::span<const double> trace, double intervalSeconds);

/// sqrt(mean(x^2)) over `window` samples centred on each sample (shortened at the ends).
std::vector<double> rmsAmplitude(std::span<const double> trace, std::size_t window);

/// The samples in the window of the RMS amplitude field.
inline constexpr std::size_t kRmsWindow = 11;

/// Adds "envelope", "phase (degrees)", "frequency (Hz)" and "RMS amplitude" to a model
/// whose grid's third axis is time (sample interval grid.labelStep[2] ms) and whose first
/// field is the amplitude at the points; each is computed, trace by trace, when first shown.
void addSeismicAttributes(Model& model);

}  // namespace volpost::seismic
