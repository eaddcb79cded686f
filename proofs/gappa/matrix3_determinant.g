# The determinant of a 3x3 matrix (src/matrix/matrix3.rs:
# Matrix3::determinant, a . (b x c) of the columns a, b, c), f32, round to
# nearest even: each component of the cross product is the rounded
# difference of two rounded products, and the dot product sums its three
# rounded products left to right.
#
# This model ties the computation to the code (the correspondence test)
# and to the law proofs/coq/matrix3_determinant_bound.v, whose rounded
# terms x, y, z and d are this model's, written in Coq (checked by the
# same test). The law proves what interval arithmetic cannot: that the
# error is at most (1 + 2^-24)^5 - 1 (2.9803e-7) times the sum T of the
# magnitudes of the six products of the expansion, whatever their signs
# and sizes (plus 2^-147 (1 + |a|_1) where products round near
# underflow). Gappa bounds each rounding by the half ulp of its range's
# top binade, so for the whole sum it can only prove the bound below,
# for every entry in [-1, 1], where T is at most 6.
#
#! law - d - D in [-15b-24, 15b-24] |det - exact| for every entry in [-1, 1]
@rnd = float<ieee_32, ne>;

a0 = rnd(A0); a1 = rnd(A1); a2 = rnd(A2);
b0 = rnd(B0); b1 = rnd(B1); b2 = rnd(B2);
c0 = rnd(C0); c1 = rnd(C1); c2 = rnd(C2);

x rnd= b1 * c2 - b2 * c1;
y rnd= b2 * c0 - b0 * c2;
z rnd= b0 * c1 - b1 * c0;
d rnd= a0 * x + a1 * y + a2 * z;

D = a0 * (b1 * c2 - b2 * c1) + a1 * (b2 * c0 - b0 * c2) + a2 * (b0 * c1 - b1 * c0);

{ |a0| <= 1 /\ |a1| <= 1 /\ |a2| <= 1 /\ |b0| <= 1 /\ |b1| <= 1 /\ |b2| <= 1 /\
  |c0| <= 1 /\ |c1| <= 1 /\ |c2| <= 1
  ->
  d - D in [-15b-24, 15b-24]
}
