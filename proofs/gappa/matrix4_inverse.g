# An entry of the inverse of a 4x4 matrix (src/matrix/matrix4.rs:
# Matrix4::inverse): the minors s = a x b, t = c x d, u = a y - b x and
# v = c w - d z of the columns (a, x), (b, y), (c, z), (d, w), as
# matrix4_determinant.g computes them and det = s . v + t . u; r = 1 /
# det; each minor times r; an entry is a sum of three products of an
# entry of the matrix with a minor times r, left to right (a cross
# product's component plus a scaled minor times x, y, z or w, or a dot
# product, negated or not: negation is exact). f32, round to nearest
# even. The entry's three minors are g0 g1 - g2 g3, h0 h1 - h2 h3 and
# k0 k1 - k2 k3, its three entries f0, f1, f2 (the correspondence test
# maps each of the sixteen entries onto it, signs included).
#
# This model ties the computation to the code (the correspondence test)
# and to the law proofs/coq/matrix4_inverse_bound.v, whose rounded terms
# are this model's, written in Coq (checked by the same test). The law
# proves what interval arithmetic cannot: the entry within 5.376e-7
# (Ac + |C| T / |D|) / |D| of C / D (C = f0 M0 + f1 M1 + f2 M2 the
# cofactor, Ac its six products' magnitudes, T the determinant's 24),
# where the expansion cancels by at most 2^12. Gappa alone proves a
# minor's error and r's, relative, for a determinant in [1/4, 16] (every
# entry in [-1, 1]).
#
#! law - m0 - M0 in [-1b-23, 1b-23] a minor against the exact one, for every entry in [-1, 1]
#! law - (r - 1 / D) * D in [-1.3e-3, 1.3e-3] 1 / det, relative, for a determinant in [1/4, 16]
@rnd = float<ieee_32, ne>;

a0 = rnd(A0); a1 = rnd(A1); a2 = rnd(A2);
b0 = rnd(B0); b1 = rnd(B1); b2 = rnd(B2);
c0 = rnd(C0); c1 = rnd(C1); c2 = rnd(C2);
d0 = rnd(D0); d1 = rnd(D1); d2 = rnd(D2);
x = rnd(X); y = rnd(Y); z = rnd(Z); w = rnd(W);
f0 = rnd(F0); f1 = rnd(F1); f2 = rnd(F2);
g0 = rnd(G0); g1 = rnd(G1); g2 = rnd(G2); g3 = rnd(G3);
h0 = rnd(H0); h1 = rnd(H1); h2 = rnd(H2); h3 = rnd(H3);
k0 = rnd(K0); k1 = rnd(K1); k2 = rnd(K2); k3 = rnd(K3);

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
r rnd= 1 / det;
m0 rnd= g0 * g1 - g2 * g3;
m1 rnd= h0 * h1 - h2 * h3;
m2 rnd= k0 * k1 - k2 * k3;
n0 rnd= m0 * r;
n1 rnd= m1 * r;
n2 rnd= m2 * r;
e rnd= (f0 * n0 + f1 * n1) + f2 * n2;

D = ((a1 * b2 - a2 * b1) * (c0 * w - d0 * z) + (a2 * b0 - a0 * b2) * (c1 * w - d1 * z)
     + (a0 * b1 - a1 * b0) * (c2 * w - d2 * z))
  + ((c1 * d2 - c2 * d1) * (a0 * y - b0 * x) + (c2 * d0 - c0 * d2) * (a1 * y - b1 * x)
     + (c0 * d1 - c1 * d0) * (a2 * y - b2 * x));
M0 = g0 * g1 - g2 * g3;

{ |a0| <= 1 /\ |a1| <= 1 /\ |a2| <= 1 /\ |b0| <= 1 /\ |b1| <= 1 /\ |b2| <= 1 /\
  |c0| <= 1 /\ |c1| <= 1 /\ |c2| <= 1 /\ |d0| <= 1 /\ |d1| <= 1 /\ |d2| <= 1 /\
  |x| <= 1 /\ |y| <= 1 /\ |z| <= 1 /\ |w| <= 1 /\
  |f0| <= 1 /\ |f1| <= 1 /\ |f2| <= 1 /\
  |g0| <= 1 /\ |g1| <= 1 /\ |g2| <= 1 /\ |g3| <= 1 /\
  |h0| <= 1 /\ |h1| <= 1 /\ |h2| <= 1 /\ |h3| <= 1 /\
  |k0| <= 1 /\ |k1| <= 1 /\ |k2| <= 1 /\ |k3| <= 1 /\
  D in [0.25, 16]
  ->
  m0 - M0 in [-1b-23, 1b-23] /\ (r - 1 / D) * D in [-1.3e-3, 1.3e-3]
}
