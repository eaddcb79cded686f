# An entry of the inverse of a 3x3 matrix (src/matrix/matrix3.rs:
# Matrix3::inverse): the rows of the inverse are b x c, c x a and a x b
# of the columns a, b, c, each component times r = 1 / det, with det =
# a . (b x c) as Matrix3::determinant computes it. f32, round to nearest
# even. The entry's minor is f0 g1 - f1 g0 for the two columns it
# crosses (the correspondence test maps each of the nine entries onto
# it); x, y, z and d are the determinant's, as matrix3_determinant.g.
#
# This model ties the computation to the code (the correspondence test)
# and to the law proofs/coq/matrix3_inverse_bound.v, whose rounded terms
# are this model's, written in Coq (checked by the same test). The law
# proves what interval arithmetic cannot: the entry within 3.585e-7
# (Am + |M| T / |D|) / |D| of M / D (Am the minor's two products'
# magnitudes, T the determinant's six), where the expansion cancels by
# at most 2^12. Gappa alone proves the minor's error and r's, relative,
# for a determinant in [1/4, 6] (every entry in [-1, 1]).
#
#! law - m - M in [-1b-23, 1b-23] the minor against the exact one, for every entry in [-1, 1]
#! law - (r - 1 / D) * D in [-6.6e-5, 6.6e-5] 1 / det, relative, for a determinant in [1/4, 6]
@rnd = float<ieee_32, ne>;

a0 = rnd(A0); a1 = rnd(A1); a2 = rnd(A2);
b0 = rnd(B0); b1 = rnd(B1); b2 = rnd(B2);
c0 = rnd(C0); c1 = rnd(C1); c2 = rnd(C2);
f0 = rnd(F0); f1 = rnd(F1); g0 = rnd(G0); g1 = rnd(G1);

x rnd= b1 * c2 - b2 * c1;
y rnd= b2 * c0 - b0 * c2;
z rnd= b0 * c1 - b1 * c0;
d rnd= a0 * x + a1 * y + a2 * z;
r rnd= 1 / d;
m rnd= f0 * g1 - f1 * g0;
e rnd= m * r;

D = a0 * (b1 * c2 - b2 * c1) + a1 * (b2 * c0 - b0 * c2) + a2 * (b0 * c1 - b1 * c0);
M = f0 * g1 - f1 * g0;

{ |a0| <= 1 /\ |a1| <= 1 /\ |a2| <= 1 /\ |b0| <= 1 /\ |b1| <= 1 /\ |b2| <= 1 /\
  |c0| <= 1 /\ |c1| <= 1 /\ |c2| <= 1 /\ |f0| <= 1 /\ |f1| <= 1 /\ |g0| <= 1 /\ |g1| <= 1 /\
  D in [0.25, 6]
  ->
  m - M in [-1b-23, 1b-23] /\ (r - 1 / D) * D in [-6.6e-5, 6.6e-5]
}
