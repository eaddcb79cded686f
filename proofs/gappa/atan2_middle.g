# The atan2 kernel's middle branch (src/float/atan2.rs, atan2_kernel and
# angle_of_quotient), with a = |x|, b = |y| and their scaled values qa,
# qb: u = (qb - qa) / (qb + qa), phi = PIO4_HI + (atan_poly(u) +
# PIO4_LO), and for a negative x, PI_HI - (phi - PI_LO). f32, round to
# nearest even, every operation rounded, in the code's order. The absolute
# error of each result against the exact angle of the exact arguments,
# pi/4 + atan((b - a) / (b + a)) (the identity atan(t) = pi/4 + atan((t -
# 1) / (t + 1)) for t = b / a), or pi minus it for a negative x; the
# model's p variables take d = qb - qa > 0, its n variables d < 0. The
# sign of y is copied exactly, so these bound every sign.
#
# Inputs: d = qb - qa, e = qb + qa rounded (e = rnd(S), S the exact sum),
# and y, the polynomial's result atan_poly(u), an f32 in the model.
#
# Domain, argued from the code (here, not proven by Gappa): the branch is
# taken where neither test passes, qb > rnd(qa TAN_HALF) and qa > rnd(qb
# TAN_HALF), so qb / qa lies within a factor 1 / (TAN_HALF (1 - 2^-24))
# < 2 of 1: qb - qa is exact (Sterbenz), and |d / S| = |t - 1| / (t + 1)
# for t = qb / qa is at most (1 - r) / (1 + r) = 0.293408 for r = TAN_HALF
# (1 - 2^-24). The scalings are exact there (by 2^60 for b <= 1, with a <
# 2; by 1/4 for b > 1, with a > 1/2), and one more power of two, which
# leaves u unchanged (every value normal), puts S in [1, 2]. qa and qb are
# multiples of 2^(E - 23), where 2^E <= min(qa, qb), and S < 2^(E + 3), so
# a nonzero d is at least 2^-26 S, and at most 0.2935 S < 0.59. d = 0 (a =
# b): u = 0, y = 0, phi = PIO4_HI + PIO4_LO rounded = PIO4_HI, within
# 2.2e-8 of pi/4, and PI_HI - (PIO4_HI - PI_LO) within 6e-9 of 3 pi/4.
#
# What the model assumes (stated here, not proven by Gappa):
# - the polynomial's error relative to atan(u): the goal of atan_poly.g
#   and atan_poly_tiny.g, (y - A) / A in [-8.8e-8, 8.8e-8] (negative u by
#   the polynomial's symmetry);
# - atan(u) = u - u^3 K with K = (u - atan u) / u^3 in [0.3, 1/3] for |u|
#   <= 0.2935 (0.3171 there; |u| is at most 0.293408 (1 + 2^-24)^2):
#   A is written so;
# - the mean value theorem: atan(u) - atan(R) = (u - R) J for R = d / S,
#   J = 1 / (1 + xi^2), xi between u and R, so J in [0.92, 1]: B = atan(R)
#   is written A - (u - R) J;
# - the constants' heads and tails: PIO4_HI + PIO4_LO - pi/4 and PI_HI +
#   PI_LO - pi are 8.5756e-16 and 3.43025e-15 (to 50 digits: Dpio4, Dpi).
#
# Proven: the results within 1.35e-7 (d > 0, x > 0), 3.13e-7 (d > 0, x <
# 0), 1.05e-7 (d < 0, x > 0) and 2.55e-7 (d < 0, x < 0) of the exact angle.
#
#! bound ATAN2_MAX_ABS_ERROR rp - (Pi - (Pio4 + Bp)) in [-3.13e-7, 3.13e-7] the atan2 kernel's middle branch, every sign, against the angle of the exact arguments
# The side conditions' factorizations (`#! side`): A = u (1 - u^2 K).
#! side Ap -> up * (1 - up * up * Kp);
#! side An -> un * (1 - un * un * Kn);
@rnd = float<ieee_32, ne>;

dp = rnd(DP);
ep = rnd(SP);
yp = rnd(YP);
dn = rnd(DN);
en = rnd(SN);
yn = rnd(YN);

up rnd= dp / ep;
vp rnd= yp + -0x1.777a5cp-26;
pp rnd= 0x1.921fb6p-1 + vp;
wp rnd= pp - -0x1.777a5cp-24;
rp rnd= 0x1.921fb6p+1 - wp;
un rnd= dn / en;
vn rnd= yn + -0x1.777a5cp-26;
pn rnd= 0x1.921fb6p-1 + vn;
wn rnd= pn - -0x1.777a5cp-24;
rn rnd= 0x1.921fb6p+1 - wn;

Ap = up - up * up * up * Kp;
Bp = Ap - (up - dp / SP) * Jp;
An = un - un * un * un * Kn;
Bn = An - (un - dn / SN) * Jn;
Pio4 = 0x1.921fb6p-1 + -0x1.777a5cp-26 - Dpio4;
Pi = 0x1.921fb6p+1 + -0x1.777a5cp-24 - Dpi;

{ SP in [1, 2] /\ dp in [1b-26, 0.59] /\ dp / SP in [0, 0.2935]
  /\ SN in [1, 2] /\ dn in [-0.59, -1b-26] /\ dn / SN in [-0.2935, 0]
  /\ Kp in [0.3, 0.33334] /\ Kn in [0.3, 0.33334] /\ Jp in [0.92, 1] /\ Jn in [0.92, 1]
  /\ Dpio4 in [8.575e-16, 8.576e-16] /\ Dpi in [3.4302e-15, 3.4303e-15]
  /\ (yp - Ap) / Ap in [-8.8e-8, 8.8e-8] /\ (yn - An) / An in [-8.8e-8, 8.8e-8]
  ->
  pp - (Pio4 + Bp) in [-1.35e-7, 1.35e-7] /\ rp - (Pi - (Pio4 + Bp)) in [-3.13e-7, 3.13e-7]
  /\ pn - (Pio4 + Bn) in [-1.05e-7, 1.05e-7] /\ rn - (Pi - (Pio4 + Bn)) in [-2.55e-7, 2.55e-7]
}

# Each error as its roundings, the constants' tails, the polynomial's
# error and the quotient's (with the sum's) rounding carried by J.
yp - Ap -> Ap * ((yp - Ap) / Ap);
yn - An -> An * ((yn - An) / An);
pp - (Pio4 + Bp) -> (pp - (0x1.921fb6p-1 + vp)) + (vp - (yp + -0x1.777a5cp-26)) + Dpio4 + (yp - Ap) + (up - dp / SP) * Jp;
rp - (Pi - (Pio4 + Bp)) -> (rp - (0x1.921fb6p+1 - wp)) - (wp - (pp - -0x1.777a5cp-24)) + Dpi - (pp - (Pio4 + Bp));
pn - (Pio4 + Bn) -> (pn - (0x1.921fb6p-1 + vn)) + (vn - (yn + -0x1.777a5cp-26)) + Dpio4 + (yn - An) + (un - dn / SN) * Jn;
rn - (Pi - (Pio4 + Bn)) -> (rn - (0x1.921fb6p+1 - wn)) - (wn - (pn - -0x1.777a5cp-24)) + Dpi - (pn - (Pio4 + Bn));
