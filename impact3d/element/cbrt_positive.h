#pragma once
// Cube root of a positive, normal double in plain IEEE arithmetic, so that a loop over SIMD
// lanes vectorizes it (the C library's cbrt is a call per element).  The same function serves
// the scalar and the block kernels, so the two give the same bits; the result is the same on
// every machine (no FMA contraction, no library).  Accuracy: within 1 ulp of the exact cube
// root (tests/element/test_hex_block.cpp checks 10^6 values over 10^-30..10^30).
//
// An initial guess from the exponent (the bit pattern, read as an integer, divided by 3 and
// re-biased: about 3% off), then two Halley steps y <- y (y^3 + 2x) / (2 y^3 + x), each of
// which cubes the relative error (3e-2 -> 3e-5 -> 3e-14), and a Newton step written as a
// correction y + (x / y^2 - y) / 3 (error squared, rounding only in the small term).

#include <cstdint>
#include <cstring>

namespace impact3d {

inline double cbrt_positive(double x) {
  std::int64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  // bits / 3 in floating point (exact enough for a guess; converts both ways in SIMD)
  const std::int64_t guess_bits =
      std::int64_t(double(bits) * (1.0 / 3.0)) + std::int64_t(0x2A9F7893782DA1CEULL);
  double y;
  std::memcpy(&y, &guess_bits, sizeof y);
  for (int it = 0; it < 2; ++it) {
    const double y3 = y * y * y;
    y = y * (y3 + 2.0 * x) / (2.0 * y3 + x);
  }
  // last step as a small correction (Newton), so that its rounding stays in the correction
  return y + (x / (y * y) - y) * (1.0 / 3.0);
}

}  // namespace impact3d
