# q * q.inv() (src/quat.rs: inv is [w, -x, -y, -z], exact; the product is
# src/quat/product.rs's). f32, round to nearest even.
#
# The real part is w w - x (-x) - y (-y) - z (-z), left to right: the sum
# of the four squares. Domain: every component in [-1, 1] and the exact
# sum of squares S within 2^-22 (2.4e-7) of 1.
#
# Proven: the real part is within 3e-7 (about 5 2^-24) of S, so within
# 5.4e-7 of 1. The vector part is exactly zero for every input
# by the symmetry of rounding to nearest (rnd(-p) = -rnd(p)): its terms
# cancel pairwise, w (-x) + x w and y (-z) - z (-y) (checked bit for bit
# by the correspondence test, not by Gappa).
#
#! law - 5.4e-7 real part of q * q.inv() - 1 for |q|^2 within 2^-22 of 1
@rnd = float<ieee_32, ne>;

w = rnd(W); x = rnd(X); y = rnd(Y); z = rnd(Z);

pw rnd= w * w - x * (-x) - y * (-y) - z * (-z);

PW = w * w - x * (-x) - y * (-y) - z * (-z);
S = w * w + x * x + y * y + z * z;

{ |w| <= 1 /\ |x| <= 1 /\ |y| <= 1 /\ |z| <= 1 /\
  S in [0.999999761581420898, 1.000000238418579102]
  ->
  pw - S in [-3e-7, 3e-7] /\ pw - 1 in [-5.4e-7, 5.4e-7]
}

PW -> S;
# The partial sums of squares are at most S.
w * w - x * (-x) -> S - (y * y + z * z);
w * w - x * (-x) - y * (-y) -> S - z * z;
