# q * q.inv() (src/quat.rs: inv is [w, -x, -y, -z], exact; the product is
# src/quat/scalar.rs and src/quat/sse2.rs). f32, round to nearest even.
#
# The real part is w w - x (-x) - y (-y) - z (-z), left to right: the sum
# of the four squares. Domain: every component in [-1, 1] and the exact
# sum of squares S within 2^-20 (9.5e-7) of 1: every result of normalize,
# whose norm proofs/coq/normalize_norm.v bounds within 2.391e-7 of 1 (so S within 4.8e-7).
#
# Proven: the real part is within 3e-7 (about 5 2^-24) of S, so within
# 1.26e-6 of 1; and each component of the vector part (exactly zero) is
# within 2^-22 of zero. The x component is in fact exactly zero for every
# finite input, its terms cancelling in adjacent pairs, w (-x) + x w and
# y (-z) - z (-y), by the symmetry of rounding to nearest (rnd(-p) =
# -rnd(p)); in y and z the cancelling terms are not adjacent and leave
# rounding errors. (The correspondence test checks the x component's zero;
# Gappa does not.)
#
#! law - pw - 1 in [-1.26e-6, 1.26e-6] real part of q * q.inv() - 1 for |q|^2 within 2^-20 of 1 (every result of normalize)
#! law - py in [-1b-22, 1b-22] each vector component of q * q.inv()
@rnd = float<ieee_32, ne>;

w = rnd(W); x = rnd(X); y = rnd(Y); z = rnd(Z);

pw rnd= w * w - x * (-x) - y * (-y) - z * (-z);
px rnd= w * (-x) + x * w + y * (-z) - z * (-y);
py rnd= w * (-y) - x * (-z) + y * w + z * (-x);
pz rnd= w * (-z) + x * (-y) - y * (-x) + z * w;

PW = w * w - x * (-x) - y * (-y) - z * (-z);
S = w * w + x * x + y * y + z * z;
PX = w * (-x) + x * w + y * (-z) - z * (-y);
PY = w * (-y) - x * (-z) + y * w + z * (-x);
PZ = w * (-z) + x * (-y) - y * (-x) + z * w;

{ |w| <= 1 /\ |x| <= 1 /\ |y| <= 1 /\ |z| <= 1 /\
  S in [0.99999904632568359375, 1.00000095367431640625]
  ->
  pw - S in [-3e-7, 3e-7] /\ pw - 1 in [-1.26e-6, 1.26e-6] /\
  px in [-1b-22, 1b-22] /\ py in [-1b-22, 1b-22] /\ pz in [-1b-22, 1b-22]
}

PW -> S;
# The partial sums of squares are at most S.
w * w - x * (-x) -> S - (y * y + z * z);
w * w - x * (-x) - y * (-y) -> S - z * z;
# The exact vector part is zero.
px -> (px - PX) + PX;
py -> (py - PY) + PY;
pz -> (pz - PZ) + PZ;
PX -> 0;
PY -> 0;
PZ -> 0;
