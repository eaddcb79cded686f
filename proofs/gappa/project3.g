# The projection of a onto the line of b and the rejection
# (src/vec/template/lengths.rs, Cvec3::project_onto and reject_from), as
# project4.g for Cvec4: scale_for_squares pads the three components with
# a fourth, 0 (the `0 * 0` of s), which the dot product (Cvec3::dot) and
# the scaling leave out; f32, round to nearest even.
#
# This model ties the computation to the code (the correspondence test)
# and to the law proofs/coq/project3_bound.v, whose rounded terms s, n,
# u0..u2, t, p0..p2 and r0..r2 are this model's (checked by the same
# test): the error vectors of p and r are at most 7.7584e-7 |a| and
# 7.8175e-7 |a| long, on the domain of project4.g. Gappa proves only the
# bound below on the dot product, by intervals.
#
#! law - t - D in [-15b-24, 15b-24] |a.dot(u) - exact dot of a and u| for |a_i| <= 1, |b_i| <= 2, |b|^2 in [1, 4]
@rnd = float<ieee_32, ne>;

a0 = rnd(A0); a1 = rnd(A1); a2 = rnd(A2);
b0 = rnd(B0); b1 = rnd(B1); b2 = rnd(B2);

s rnd= b0 * b0 + b1 * b1 + b2 * b2 + 0 * 0;
n rnd= sqrt(s);
u0 rnd= b0 / n; u1 rnd= b1 / n; u2 rnd= b2 / n;
t rnd= a0 * u0 + a1 * u1 + a2 * u2;
p0 rnd= u0 * t; p1 rnd= u1 * t; p2 rnd= u2 * t;
r0 rnd= a0 - p0; r1 rnd= a1 - p1; r2 rnd= a2 - p2;

S = b0 * b0 + b1 * b1 + b2 * b2;
D = a0 * u0 + a1 * u1 + a2 * u2;

{ S in [1, 4] /\ |a0| <= 1 /\ |a1| <= 1 /\ |a2| <= 1 /\
  |b0| <= 2 /\ |b1| <= 2 /\ |b2| <= 2
  ->
  t - D in [-15b-24, 15b-24]
}
