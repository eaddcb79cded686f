# The arctangent polynomial of the f32 atan2 kernel (src/float/atan2.rs,
# atan_poly(u)): s = u u, s2 = s s, then Estrin's scheme
# p = (A0 + s A1) + s2 ((A2 + s A3) + s2 (A4 + s A5)) and u + u (s p),
# f32, round to nearest even, every operation rounded, in the code's order
# (the code's u (s p) is the line m).
# Its error relative to atan(u), over the f32 u the kernel hands it.
#
# Domain: every f32 u in [2^-40, 0x1.17b4f8p-1]: up to tan(1/2) (TAN_HALF,
# 0x1.17b4f6p-1, the bound of the kernel's outer branches) and the f32
# above it, which an outer branch's quotient rounds to where the exact
# ratio exceeds TAN_HALF by less than 2^-24 of it (the branch's test rounds
# its product); the middle branch's quotient is at most 0.2934 in
# magnitude. atan_poly_tiny.g covers
# [2^-149, 2^-40] with the same computation; the two are one model split
# by domain, since Gappa's certificate for one domain with all the splits
# is several times the sum of the two. Negative u: atan_poly(-u) =
# -atan_poly(u) bit for bit (every rounding to nearest even is odd, and
# the polynomial is odd in u) and atan is odd, so the relative error is
# that of |u|. u = 0 gives 0 = atan(0) exactly.
#
# At stands for atan(u) = u Wa, with Wa = atan(u) / u decreasing from 1
# (at 0) to 0.91524 (at 0x1.17b4f8p-1), so in [0.915, 1] (a fact of calculus,
# stated here, not proven by Gappa). The approximation error of the exact
# polynomial P against atan(u) is Sollya's (atan_poly.sollya: 2.46059e-9
# relative over [2^-149, 0x1.17b4f8p-1], rounded up here to 2.461e-9).
#
# Proven: |y - atan(u)| <= 8.8e-8 atan(u) over the domain. Gappa splits u
# where the `$` line says; the last rounding's error relative to the
# result is largest where the sum before it lies just above a power of two
# (atan(u) crosses 0.5 at u = tan(1/2), just below TAN_HALF).
#
#! sollya atan_poly.sollya 2.461e-9
#! law - (y - At) / At in [-8.8e-8, 8.8e-8] the arctangent polynomial relative to atan(u), every f32 u in [2^-40, 0x1.17b4f8p-1]
@rnd = float<ieee_32, ne>;

u = rnd(U);

s rnd= u * u;
s2 rnd= s * s;
p rnd= (-0x1.55554ap-2 + s * 0x1.9993e2p-3) + s2 * ((-0x1.241192p-3 + s * 0x1.bc822ep-4) + s2 * (-0x1.39b8b4p-4 + s * 0x1.19308cp-5));
m rnd= u * (s * p);
y rnd= u + m;

S = u * u;
S2 = S * S;
PP = (-0x1.55554ap-2 + S * 0x1.9993e2p-3) + S2 * ((-0x1.241192p-3 + S * 0x1.bc822ep-4) + S2 * (-0x1.39b8b4p-4 + S * 0x1.19308cp-5));
Q = u * (S * PP);
P = u + Q;
z = u + m;
At = u * Wa;

{ u in [1b-40, 0x1.17b4f8p-1] /\ Wa in [0.915, 1]
  /\ (P - At) / At in [-2.461e-9, 2.461e-9]
  ->
  (y - At) / At in [-8.8e-8, 8.8e-8]
}

# The last rounding relative to its sum z; z relative to atan(u) through
# its parts over u: the evaluation of m (relative to Q, times Q / u) and
# the approximation error (relative to atan(u), times atan(u) / u).
(y - At) / At -> ((y - z) / z) * (1 + (z - At) / At) + (z - At) / At;
(z - At) / At -> ((z - At) / u) / Wa;
(z - At) / u -> ((m - Q) / Q) * (S * PP) + ((P - At) / At) * Wa;
$ u in (1b-20, 1b-4, 0.25, 0.4, 0.5, 0.52, 0.53, 0.54);
