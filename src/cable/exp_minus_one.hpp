#pragma once
// Private to the cable laws: e^x - 1 for x <= 0 on four lanes at once (GCC's vector
// extensions: vector registers where the target has them, pairs of SSE2 registers
// otherwise), in straight-line arithmetic; std::expm1 is a library call, one number
// at a time.
//
// x = n ln 2 + r with n = round(x / ln 2) and |r| <= ln 2 / 2 (ln 2 in two parts, so
// n ln 2 is exact to the last bits), e^r - 1 by its Taylor series to r^13 (the first
// term left out is below 1e-17 of the sum), then e^x - 1 = 2^n (e^r - 1) + (2^n - 1):
// the product and the difference are exact for n <= 0, so the result is within about
// 1 ulp, relative, for small |x| as for large. x below -700 is taken as -700
// (e^-700 < 1e-304: the result is -1 to the last bit either way).

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

// GCC notes that a function returning these types would be called differently with and
// without AVX: these are inline, never called across files.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace stockbridge::cable {

using Lanes = double __attribute__((vector_size(32)));            // four doubles
using LaneMask = std::int64_t __attribute__((vector_size(32)));   // a comparison's result: 0 or -1 a lane

/// n rounded up to whole groups of four.
inline std::size_t lanes_padded(std::size_t n) { return (n + 3) / 4 * 4; }

/// Four doubles from `p` into lanes, and back (p need not be aligned).
[[gnu::always_inline]] inline Lanes load_lanes(const double* p) {
  Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
[[gnu::always_inline]] inline void store_lanes(double* p, Lanes v) { std::memcpy(p, &v, sizeof v); }
[[gnu::always_inline]] inline bool any_lane(LaneMask m) { return (m[0] | m[1] | m[2] | m[3]) != 0; }

[[gnu::always_inline]] inline Lanes exp_minus_one_of_nonpositive(Lanes x) {
  constexpr double inverse_ln2 = 1.4426950408889634;
  constexpr double ln2_high = 6.93147180369123816490e-01;  // ln 2's leading 32 bits: n ln2_high is exact
  constexpr double ln2_low = 1.90821492927058770002e-10;
  constexpr double shifter = 0x1.8p52;  // adding it rounds to an integer, held in the low bits
  x = x < -700.0 ? Lanes{} - 700.0 : x;
  const Lanes shifted = x * inverse_ln2 + shifter;
  const Lanes n = shifted - shifter;
  const Lanes r = (x - n * ln2_high) - n * ln2_low;
  // e^r - 1 = r + r^2 p(r), p(r) = 1/2! + r / 3! + ... + r^11 / 13!, by Estrin's
  // scheme: pairs of terms joined by r^2, r^4 and r^8, a chain of five dependent
  // operations where Horner's is twelve.
  const Lanes r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
  const Lanes q0 = 0.5 + r * (1.0 / 6.0), q1 = 1.0 / 24.0 + r * (1.0 / 120.0);
  const Lanes q2 = 1.0 / 720.0 + r * (1.0 / 5040.0), q3 = 1.0 / 40320.0 + r * (1.0 / 362880.0);
  const Lanes q4 = 1.0 / 3628800.0 + r * (1.0 / 39916800.0), q5 = 1.0 / 479001600.0 + r * (1.0 / 6227020800.0);
  const Lanes p = ((q0 + r2 * q1) + r4 * (q2 + r2 * q3)) + r8 * (q4 + r2 * q5);
  const Lanes r_minus_one = r + r2 * p;  // e^r - 1
  // 2^n from n's bits in `shifted` (n >= -1010 here, so 2^n is normal).
  const LaneMask n_bits = std::bit_cast<LaneMask>(shifted) - std::bit_cast<std::int64_t>(shifter);
  const Lanes scale = std::bit_cast<Lanes>((n_bits + 1023) << 52);
  return scale * r_minus_one + (scale - 1.0);
}

}  // namespace stockbridge::cable

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
