# The sine polynomial of the f32 sine and cosine kernel with its tail
# (src/float/sin_cos.rs, sin_poly(r, t)): s = r r, then
# r + (t + r (s (S0 + s (S1 + s S2)))), f32, round to nearest even, every
# operation rounded (the code's inner sum is split over the lines m, e).
# Its error relative to sin(r + t), the sine of the exact real sum of the
# head r and the tail t, over every (r, t) the kernel evaluates. The
# unit-norm proofs of from_axis_angle, pow and slerp take this bound as
# their hypothesis on the kernel.
#
# Domain (argued from the code, docs/verification-proofs.md): an f32 r in
# [2^-149, pi/4] (0.7854 is above pi/4 rounded to f32) and an f32 tail t
# with |t| <= 2^-24 r, written t = r Tr with Tr in [-2^-24, 2^-24] (the
# hypothesis t - r Tr in [0, 0]). The kernel's (r, t) are:
# - |x| <= pi/4: r = |x|, t = 0 (every f32 down to the subnormals);
# - pi/4 < |x| <= 3 pi/4: (r, t) = sum_and_tail(PIO2_HI - |x|, PIO2_LO),
#   whose head's difference is exact (Sterbenz) and which is Fast2Sum,
#   exact since PIO2_HI - |x| is 0 or a multiple of 2^-24 above |PIO2_LO|:
#   t is the rounding error of r, at most half an ulp of r, so |t| <=
#   2^-24 |r|; |r| <= pi/4;
# - beyond 3 pi/4: reduce_by_quarter_turns, |r| <= PIO4_HI and t the
#   Fast2Sum tail of r, at most half an ulp of r. Argued from the code
#   (docs/verification-proofs.md; tested at the extremes in
#   src/float/reduce.rs and for every f32 by exhaustive_kernel_sweep):
#   rounding the 64-bit fraction of a turn to the nearest quarter turn
#   leaves rest in [-2^61, 2^61); radians = floor(rest TWO_PI_FIXED /
#   2^64) is in [-1811004864519280711, 1811004864519280709] units of
#   2^-61 (shifted up by 12 bits and weighted 2^-12 below 2^49, still
#   below 2^61); its bits 37 to 60 (with the sign) and 13 to 36 are
#   integers below 2^24 in magnitude, converted exactly and weighted by
#   powers of two, so high + low is radians truncated to a multiple of
#   2^13 units, at most pi/4 + 8.6e-16 < PIO4_HI in magnitude, and r, its
#   rounding, at most PIO4_HI; high is 0 or above low in magnitude, so
#   sum_and_tail(high, low) is an exact Fast2Sum: r + t = high + low,
#   |t| <= half an ulp of r <= 2^-24 |r|.
# Negative r (the last two cases): sin_poly(-r, -t) = -sin_poly(r, t)
# bit for bit (every rounding to nearest even is odd) and sin is odd, so
# the relative error is the same as for (|r|, -t), which the domain holds.
# r = 0 gives t = 0 and the result 0 = sin 0 exactly.
#
# Sy stands for sin(r + t), written as Taylor's formula in t around r:
# sin(r + t) = sin r + t cos r - (t^2 / 2) sin xi, with xi between r and
# r + t, so Kt = -sin(xi) / 2 is in [-0.5, 0.5]; and cos r = 1 - r^2 Kc
# with Kc = (1 - cos r) / r^2 in [1/2 - r^2/24, 1/2], within [0.474, 0.5]
# for r <= 0.7854. Sin stands for sin r = r Ws, Ws = sin(r) / r in
# [1 - r^2/6, 1], within [0.897, 1]. These are facts of calculus (Taylor
# with Lagrange's remainder), stated here, not proven by Gappa. The
# approximation error of the exact polynomial P at r against sin r is
# Sollya's (sin_poly.sollya: 7.9271e-9 relative over [2^-149, 0.7854],
# rounded up here to 7.93e-9); what the code leaves out of sin(r + t),
# t (cos r - 1) and the t^2 term, is in the hints below.
#
# Proven: |y - sin(r + t)| <= 1.0e-7 sin(r + t) over the whole domain
# (including the subnormal r, where s = r r rounds to 0 and y = r + t
# rounded, t being 0 there). Gappa splits r
# where the case split says: below 2^-9 into pieces over which 2^-24 b /
# a stays small (so that every denominator of the hints keeps its sign
# without them, for the side conditions), above it finer, since the last
# rounding's error relative to the result is largest where the sum before
# it lies just above a power of two.
#
#! sollya sin_poly.sollya 7.93e-9
#! law - (y - Sy) / Sy in [-1.0e-7, 1.0e-7] the sine polynomial with its tail, relative to sin(r + t), every (r, t) the kernel evaluates
# The side conditions' bound on the tail (`#! side`, used only by the
# model of the side conditions, which has no other hint): t is r Tr.
#! side t -> r * Tr + (t - r * Tr);
@rnd = float<ieee_32, ne>;

r = rnd(R); t = rnd(T);

s rnd= r * r;
p rnd= -0x1.555546p-3 + s * (0x1.11073cp-7 + s * -0x1.9943ep-13);
m rnd= r * (s * p);
e rnd= t + m;
y rnd= r + e;

S = r * r;
PP = -0x1.555546p-3 + S * (0x1.11073cp-7 + S * -0x1.9943ep-13);
Q = r * (S * PP);
P = r + Q;
z = r + e;
Sin = r * Ws;
Sy = Sin + t * (1 - S * Kc) + t * t * Kt;

{ r in [1b-149, 0.7854] /\ Tr in [-1b-24, 1b-24] /\ t - r * Tr in [0, 0]
  /\ Ws in [0.897, 1] /\ Kc in [0.474, 0.5] /\ Kt in [-0.5, 0.5]
  /\ (P - Sin) / Sin in [-7.93e-9, 7.93e-9]
  ->
  (y - Sy) / Sy in [-1.0e-7, 1.0e-7]
}

# The tail relative to r, the sum before the last rounding relative to
# sin(r + t) and its parts: the rounding of t + m, the evaluation of m
# (relative to Q, times Q / r), the approximation error (relative to
# sin r, times sin(r) / r), and what the code leaves out, t (cos r - 1)
# and the t^2 term; then the last rounding, relative to its sum.
t -> r * Tr + (t - r * Tr);
t / r -> Tr + (t - r * Tr) / r;
(y - Sy) / Sy -> ((y - z) / z) * (1 + (z - Sy) / Sy) + (z - Sy) / Sy;
(z - Sy) / Sy -> ((z - Sy) / r) / (Sy / r);
(z - Sy) / r -> (e - (t + m)) / r + ((m - Q) / Q) * (S * PP) + ((P - Sin) / Sin) * Ws + (t / r) * S * Kc - (t / r) * t * Kt;
Sy / r -> Ws + (t / r) * (1 - S * Kc) + (t / r) * t * Kt;
$ r in (1b-126, 1b-103, 1b-80, 1b-57, 1b-34, 1b-20, 1b-12, 1b-9, 1b-6, 1b-5, 1b-4, 1b-3, 0.25, 0.5, 0.55, 0.6, 0.65, 0.7, 0.72, 0.74, 0.76);
