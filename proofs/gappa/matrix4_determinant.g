# The determinant of a 4x4 matrix (src/matrix/matrix4.rs:
# Matrix4::determinant, through Matrix4::cofactors): the columns' first
# three coordinates a, b, c, d and last x, y, z, w; s = a x b, t = c x d,
# u = a y - b x, v = c w - d z, each component the rounded difference of
# two rounded products; det = s . v + t . u, each dot product summed left
# to right. f32, round to nearest even. Every s_i v_i and t_i u_i is a
# product of two 2x2 minors, and the six together are the Laplace
# expansion by the columns (a, b) and (c, d): each of the 24 products of
# four entries of the Leibniz expansion is in exactly one of them.
#
# As matrix3_determinant.g: the correspondence test ties this model to
# the code and to the law proofs/coq/matrix4_determinant_bound.v, whose
# rounded terms are this model's; the law proves the error at most
# (1 + 2^-24)^8 - 1 (4.7684e-7) times the sum T of the magnitudes of the
# 24 products (plus 112 2^-150 (1 + M^2), M the largest entry, near
# underflow). Gappa proves, for every entry in [-1, 1] (T at most 24):
#
#! law - det - D in [-25b-22, 25b-22] |det - exact| for every entry in [-1, 1]
@rnd = float<ieee_32, ne>;

a0 = rnd(A0); a1 = rnd(A1); a2 = rnd(A2);
b0 = rnd(B0); b1 = rnd(B1); b2 = rnd(B2);
c0 = rnd(C0); c1 = rnd(C1); c2 = rnd(C2);
d0 = rnd(D0); d1 = rnd(D1); d2 = rnd(D2);
x = rnd(X); y = rnd(Y); z = rnd(Z); w = rnd(W);

s0 rnd= a1 * b2 - a2 * b1;
s1 rnd= a2 * b0 - a0 * b2;
s2 rnd= a0 * b1 - a1 * b0;
t0 rnd= c1 * d2 - c2 * d1;
t1 rnd= c2 * d0 - c0 * d2;
t2 rnd= c0 * d1 - c1 * d0;
u0 rnd= a0 * y - b0 * x;
u1 rnd= a1 * y - b1 * x;
u2 rnd= a2 * y - b2 * x;
v0 rnd= c0 * w - d0 * z;
v1 rnd= c1 * w - d1 * z;
v2 rnd= c2 * w - d2 * z;
det rnd= (s0 * v0 + s1 * v1 + s2 * v2) + (t0 * u0 + t1 * u1 + t2 * u2);

D = ((a1 * b2 - a2 * b1) * (c0 * w - d0 * z) + (a2 * b0 - a0 * b2) * (c1 * w - d1 * z)
     + (a0 * b1 - a1 * b0) * (c2 * w - d2 * z))
  + ((c1 * d2 - c2 * d1) * (a0 * y - b0 * x) + (c2 * d0 - c0 * d2) * (a1 * y - b1 * x)
     + (c0 * d1 - c1 * d0) * (a2 * y - b2 * x));

{ |a0| <= 1 /\ |a1| <= 1 /\ |a2| <= 1 /\ |b0| <= 1 /\ |b1| <= 1 /\ |b2| <= 1 /\
  |c0| <= 1 /\ |c1| <= 1 /\ |c2| <= 1 /\ |d0| <= 1 /\ |d1| <= 1 /\ |d2| <= 1 /\
  |x| <= 1 /\ |y| <= 1 /\ |z| <= 1 /\ |w| <= 1
  ->
  det - D in [-25b-22, 25b-22]
}
