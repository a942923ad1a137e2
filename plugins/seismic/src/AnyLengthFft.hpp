// SPDX-License-Identifier: MIT
// The discrete Fourier transform of any length in O(n log n), in double precision.
// KissFFT's butterflies cost n * p for each prime factor p of the length, so a trace of a
// prime number of samples (65,521 is legal in SEG-Y) would take n^2: such lengths go
// through Bluestein's chirp-z algorithm, which turns the transform into a convolution
// computed with power-of-two transforms. The result is the same length-n transform
// (no padding), so attributes agree with tools that transform the trace as it is.
#pragma once

#include <complex>
#include <cstddef>
#include <memory>
#include <vector>

namespace volpost::seismic {

class AnyLengthFft {
 public:
  explicit AnyLengthFft(std::size_t n);
  ~AnyLengthFft();
  AnyLengthFft(const AnyLengthFft&) = delete;
  AnyLengthFft& operator=(const AnyLengthFft&) = delete;

  std::size_t size() const { return n_; }
  /// X[k] = sum_j x[j] e^(-2 pi i jk / n) (forward) or with +i (inverse; not divided by n).
  std::vector<std::complex<double>> transform(const std::vector<std::complex<double>>& x, bool inverse) const;
  /// Whether this length goes through Bluestein's algorithm (its largest prime factor is big).
  bool usesChirp() const { return chirp_ != nullptr; }

 private:
  struct Direct;
  struct Chirp;
  std::size_t n_;
  std::unique_ptr<Direct> direct_;
  std::unique_ptr<Chirp> chirp_;
};

/// The largest prime factor of n (1 for n <= 1).
std::size_t largestPrimeFactor(std::size_t n);

}  // namespace volpost::seismic
