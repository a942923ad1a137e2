// SPDX-License-Identifier: MIT
#include "AnyLengthFft.hpp"

#include <kissfft.hh>

#include <bit>
#include <cmath>
#include <stdexcept>

namespace volpost::seismic {
namespace {

// Lengths whose prime factors are all at most this go straight to KissFFT: its generic
// butterfly costs p per output and stage, cheaper than the chirp's three longer transforms.
constexpr std::size_t kLargestDirectFactor = 61;

using Complex = std::complex<double>;

}  // namespace

std::size_t largestPrimeFactor(std::size_t n) {
  std::size_t largest = 1;
  for (std::size_t p = 2; p * p <= n; ++p)
    while (n % p == 0) {
      largest = p;
      n /= p;
    }
  return n > 1 ? n : largest;
}

struct AnyLengthFft::Direct {
  kissfft<double> forward, inverse;
  explicit Direct(std::size_t n) : forward(n, false), inverse(n, true) {}
};

// Bluestein: with jk = (j^2 + k^2 - (k - j)^2) / 2, X[k] = c[k]* sum_j (x[j] c[j]*) c[k - j]
// where c[m] = e^(i pi m^2 / n): a convolution of length 2n - 1, done by power-of-two
// transforms of size m. The chirp's angle takes m^2 mod 2n first, exact in integers, so it
// keeps double precision for any length.
struct AnyLengthFft::Chirp {
  std::size_t n, m;
  std::vector<Complex> c;          // c[j], j < n
  std::vector<Complex> kernelHat;  // the transform of c[-(n-1) .. n-1] laid out circularly in m
  kissfft<double> forward, inverse;
  explicit Chirp(std::size_t length)
      : n(length), m(std::bit_ceil(2 * length - 1)), c(length), kernelHat(m), forward(m, false), inverse(m, true) {
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t square = (j * j) % (2 * n);  // j < 2^31 for any trace SEG-Y can hold
      c[j] = std::polar(1.0, M_PI * double(square) / double(n));
    }
    std::vector<Complex> kernel(m, Complex(0.0));
    kernel[0] = c[0];
    for (std::size_t j = 1; j < n; ++j) kernel[j] = kernel[m - j] = c[j];
    forward.transform(kernel.data(), kernelHat.data());
  }
  std::vector<Complex> transform(const std::vector<Complex>& x, bool inverseTransform) const {
    // The inverse transform is the forward one of the conjugate, conjugated.
    std::vector<Complex> a(m, Complex(0.0)), aHat(m), product(m);
    for (std::size_t j = 0; j < n; ++j) a[j] = (inverseTransform ? std::conj(x[j]) : x[j]) * std::conj(c[j]);
    forward.transform(a.data(), aHat.data());
    for (std::size_t k = 0; k < m; ++k) aHat[k] *= kernelHat[k];
    inverse.transform(aHat.data(), product.data());
    std::vector<Complex> out(n);
    for (std::size_t k = 0; k < n; ++k) {
      const Complex value = product[k] * std::conj(c[k]) / double(m);
      out[k] = inverseTransform ? std::conj(value) : value;
    }
    return out;
  }
};

AnyLengthFft::AnyLengthFft(std::size_t n) : n_(n) {
  if (n == 0) return;
  if (largestPrimeFactor(n) <= kLargestDirectFactor) direct_ = std::make_unique<Direct>(n);
  else chirp_ = std::make_unique<Chirp>(n);
}

AnyLengthFft::~AnyLengthFft() = default;

std::vector<Complex> AnyLengthFft::transform(const std::vector<Complex>& x, bool inverse) const {
  if (x.size() != n_) throw std::invalid_argument("AnyLengthFft: input length differs from the plan's");
  if (n_ == 0) return {};
  if (chirp_) return chirp_->transform(x, inverse);
  std::vector<Complex> out(n_);
  (inverse ? direct_->inverse : direct_->forward).transform(x.data(), out.data());
  return out;
}

}  // namespace volpost::seismic
