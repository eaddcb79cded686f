# The projection of a onto the line of b and the rejection
# (src/vec/template/lengths.rs, Cvec4::project_onto and reject_from):
# u = b.try_normalize() (scale_for_squares and ScaledSquares::unit in
# src/float/norm.rs: s = b0 b0 + b1 b1 + b2 b2 + b3 b3 left to right,
# n = sqrt(s), each component / n), t = a.dot(u) (Cvec4::dot, left to
# right), the projection p = u * t, the rejection r = a - p; f32, round
# to nearest even. The branch of scale_for_squares without rescaling; the
# rescaled branches scale b by an exact power of two first
# (normalize_scale.g says how exactly), which u does not see.
#
# This model ties the computation to the code (the correspondence test)
# and to the law proofs/coq/project4_bound.v, whose rounded terms s, n,
# u0..u3, t, p0..p3 and r0..r3 are this model's, written in Coq (checked
# by the same test). The law proves what interval arithmetic cannot: that
# the error vectors of p and r against the exact projection
# (a . b / |b|^2) b and rejection are at most 7.7584e-7 |a| and
# 7.8175e-7 |a| long, for |b|^2 in [1, 4] (every b after an exact scaling
# by a power of four, as in normalize.g) and |a| from 2^-100 up, where
# the roundings near underflow are below 2^-50 |a|. Gappa bounds each
# rounding by the half ulp of its range's top binade and adds the
# components' errors as intervals, so it can only prove the bound below
# on the dot product, for every |a_i| <= 1 and |b_i| <= 2.
#
#! law - t - D in [-13b-23, 13b-23] |a.dot(u) - exact dot of a and u| for |a_i| <= 1, |b_i| <= 2, |b|^2 in [1, 4]
@rnd = float<ieee_32, ne>;

a0 = rnd(A0); a1 = rnd(A1); a2 = rnd(A2); a3 = rnd(A3);
b0 = rnd(B0); b1 = rnd(B1); b2 = rnd(B2); b3 = rnd(B3);

s rnd= b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3;
n rnd= sqrt(s);
u0 rnd= b0 / n; u1 rnd= b1 / n; u2 rnd= b2 / n; u3 rnd= b3 / n;
t rnd= a0 * u0 + a1 * u1 + a2 * u2 + a3 * u3;
p0 rnd= u0 * t; p1 rnd= u1 * t; p2 rnd= u2 * t; p3 rnd= u3 * t;
r0 rnd= a0 - p0; r1 rnd= a1 - p1; r2 rnd= a2 - p2; r3 rnd= a3 - p3;

S = b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3;
D = a0 * u0 + a1 * u1 + a2 * u2 + a3 * u3;

{ S in [1, 4] /\ |a0| <= 1 /\ |a1| <= 1 /\ |a2| <= 1 /\ |a3| <= 1 /\
  |b0| <= 2 /\ |b1| <= 2 /\ |b2| <= 2 /\ |b3| <= 2
  ->
  t - D in [-13b-23, 13b-23]
}
