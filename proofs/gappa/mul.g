# The Hamilton product a * b (src/quat/scalar.rs: hamilton, and src/quat/sse2.rs,
# which sums the same terms in the same order). f32, round to nearest even,
# every operation rounded, each component summed left to right.
#
# Domain: two quaternions with |a|^2 and |b|^2 within 2^-20 (9.5e-7) of 1
# (every output of normalize, whose norm proofs/coq/normalize_norm.v bounds within 2.391e-7
# of 1) and every component in [-1, 1].
#
# Proven: each component of the computed product is within 3.58e-7 (about
# 6 2^-24) of the exact product of the same f32 inputs, and the error
# vector within 7.16e-7 in length. The exact product has norm |a| |b|, so
# by the triangle inequality the computed product's norm is within
# 7.16e-7 of |a| |b|; proofs/coq/mul_norm.v proves 2.84e-7 relative on
# this certificate (the norm moves with the error's projection on the
# product, a weighted average this model cannot state), and uses the
# error vector's length for its second-order term.
#
# The hints bound every partial sum of a component by 1 + 2^-20 (Cauchy-
# Schwarz), where interval arithmetic alone allows 2, 3 and 4. What stays
# above the measured maximum: each rounding is bounded by the half ulp of
# [1, 2), since 1 + 2^-20 reaches it, where most terms are smaller; and
# the error vector's length is not its projection on the product, which
# is what moves the norm.
#
#! law - ErrorLength in [0, 7.16e-7] |a*b - exact product| for a, b within 2^-20 of unit norm (length of the error vector)
@rnd = float<ieee_32, ne>;

aw = rnd(Aw); ax = rnd(Ax); ay = rnd(Ay); az = rnd(Az);
bw = rnd(Bw); bx = rnd(Bx); by = rnd(By); bz = rnd(Bz);

pw rnd= aw * bw - ax * bx - ay * by - az * bz;
px rnd= aw * bx + ax * bw + ay * bz - az * by;
py rnd= aw * by - ax * bz + ay * bw + az * bx;
pz rnd= aw * bz + ax * by - ay * bx + az * bw;

Pw = aw * bw - ax * bx - ay * by - az * bz;
Px = aw * bx + ax * bw + ay * bz - az * by;
Py = aw * by - ax * bz + ay * bw + az * bx;
Pz = aw * bz + ax * by - ay * bx + az * bw;
QA = aw * aw + ax * ax + ay * ay + az * az;
QB = bw * bw + bx * bx + by * by + bz * bz;
ErrorLength = sqrt((pw - Pw) * (pw - Pw) + (px - Px) * (px - Px) +
       (py - Py) * (py - Py) + (pz - Pz) * (pz - Pz));

{ QA in [0.99999904632568359375, 1.00000095367431640625] /\
  QB in [0.99999904632568359375, 1.00000095367431640625] /\
  |aw| <= 1 /\ |ax| <= 1 /\ |ay| <= 1 /\ |az| <= 1 /\
  |bw| <= 1 /\ |bx| <= 1 /\ |by| <= 1 /\ |bz| <= 1
  ->
  
  pw - Pw in [-3.58e-7, 3.58e-7] /\ px - Px in [-3.58e-7, 3.58e-7] /\
  py - Py in [-3.58e-7, 3.58e-7] /\ pz - Pz in [-3.58e-7, 3.58e-7] /\
  ErrorLength in [0, 7.16e-7]
}
# Cauchy-Schwarz for the partial sums of two and three terms, by
# Lagrange's identity (sum a_i b_i)^2 = sum a_i^2 sum b_i^2 - sum over
# i < j of (a_i b_j - a_j b_i)^2, and the partial sums of squares from
# the norms.
(aw * bw - ax * bx) * (aw * bw - ax * bx) -> (aw * aw + ax * ax) * (bw * bw + bx * bx) - (aw * (-bx) - ax * bw) * (aw * (-bx) - ax * bw);
(aw * bw - ax * bx - ay * by) * (aw * bw - ax * bx - ay * by) -> (aw * aw + ax * ax + ay * ay) * (bw * bw + bx * bx + by * by) - (aw * (-bx) - ax * bw) * (aw * (-bx) - ax * bw) - (aw * (-by) - ay * bw) * (aw * (-by) - ay * bw) - (ax * (-by) - ay * (-bx)) * (ax * (-by) - ay * (-bx));
(aw * bx + ax * bw) * (aw * bx + ax * bw) -> (aw * aw + ax * ax) * (bx * bx + bw * bw) - (aw * bw - ax * bx) * (aw * bw - ax * bx);
(aw * bx + ax * bw + ay * bz) * (aw * bx + ax * bw + ay * bz) -> (aw * aw + ax * ax + ay * ay) * (bx * bx + bw * bw + bz * bz) - (aw * bw - ax * bx) * (aw * bw - ax * bx) - (aw * bz - ay * bx) * (aw * bz - ay * bx) - (ax * bz - ay * bw) * (ax * bz - ay * bw);
(aw * by - ax * bz) * (aw * by - ax * bz) -> (aw * aw + ax * ax) * (by * by + bz * bz) - (aw * (-bz) - ax * by) * (aw * (-bz) - ax * by);
(aw * by - ax * bz + ay * bw) * (aw * by - ax * bz + ay * bw) -> (aw * aw + ax * ax + ay * ay) * (by * by + bz * bz + bw * bw) - (aw * (-bz) - ax * by) * (aw * (-bz) - ax * by) - (aw * bw - ay * by) * (aw * bw - ay * by) - (ax * bw - ay * (-bz)) * (ax * bw - ay * (-bz));
(aw * bz + ax * by) * (aw * bz + ax * by) -> (aw * aw + ax * ax) * (bz * bz + by * by) - (aw * by - ax * bz) * (aw * by - ax * bz);
(aw * bz + ax * by - ay * bx) * (aw * bz + ax * by - ay * bx) -> (aw * aw + ax * ax + ay * ay) * (bz * bz + by * by + bx * bx) - (aw * by - ax * bz) * (aw * by - ax * bz) - (aw * (-bx) - ay * bz) * (aw * (-bx) - ay * bz) - (ax * (-bx) - ay * by) * (ax * (-bx) - ay * by);
aw * aw + ax * ax -> QA - (ay * ay + az * az);
aw * aw + ax * ax + ay * ay -> QA - (az * az);
bw * bw + bx * bx -> QB - (by * by + bz * bz);
bw * bw + bx * bx + by * by -> QB - (bz * bz);
bx * bx + bw * bw -> QB - (by * by + bz * bz);
bx * bx + bw * bw + bz * bz -> QB - (by * by);
by * by + bz * bz -> QB - (bw * bw + bx * bx);
by * by + bz * bz + bw * bw -> QB - (bx * bx);
bz * bz + by * by -> QB - (bw * bw + bx * bx);
bz * bz + by * by + bx * bx -> QB - (bw * bw);
