# The angle error of the Hamilton product a * b (src/quat/scalar.rs:
# hamilton, and src/quat/sse2.rs, which sums the same terms in the same
# order): the computation of mul.g, with the goal the angle. f32, round to
# nearest even, every operation rounded, each component summed left to
# right.
#
# Domain: two quaternions with |a|^2 and |b|^2 within 2^-20 (9.5e-7) of 1
# (every f32 rounding of a unit quaternion, and every result of
# normalize) and every component in [-1, 1].
#
# Proven: 2 |e| / (|a| |b| - |e|) <= 1.1922e-6, with e the error vector of
# the computed product p against the exact product P of the same inputs
# (each component within 5 2^-24, |e| within 10 2^-24). On paper: the
# angle between p and P as rotations is at most twice the angle phi
# between them as 4-vectors, and tan(phi) is |e|'s part across P over
# |P| plus its part along P, at most |e| / (|P| - |e|), with |P| = |a| |b|
# = sqrt(QA QB); 2 phi <= 2 tan(phi). So the angle error is at most
# 1.1922e-6.
#
# The hints are mul.g's, and the exact product's norm identity, which
# bounds the last sum of each component by |a| |b| (mul.g, without it,
# bounds each component within 6 2^-24). What stays above the measured
# maximum (2.988e-7 random, 3.324e-7 by search): only the error across P
# turns the product, where the bound takes all of |e|, and every rounding
# at the half ulp of [1, 2) or [1/2, 1).
#
#! bound MUL_MAX_ANGLE_ERROR 2 * ErrorLength / (sqrt(QA * QB) - ErrorLength) in [0, 1.1922e-6] angle error of a * b for |a|^2, |b|^2 within 2^-20 of 1 (at most 2 tan of the angle between the 4-vectors)
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
  
  2 * ErrorLength / (sqrt(QA * QB) - ErrorLength) in [0, 1.1922e-6]
}
# The exact product's norm is |a| |b|: Pw^2 is QA QB less the other
# components' squares (a polynomial identity, which Gappa checks).
Pw * Pw -> QA * QB - (Px * Px + Py * Py + Pz * Pz);
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
bw * bw + bx * bx -> QB - (by * by + bz * bz);
bx * bx + bw * bw -> QB - (by * by + bz * bz);
bx * bx + bw * bw + bz * bz -> QB - (by * by);
by * by + bz * bz -> QB - (bw * bw + bx * bx);
by * by + bz * bz + bw * bw -> QB - (bx * bx);
bz * bz + by * by -> QB - (bw * bw + bx * bx);
bz * bz + by * by + bx * bx -> QB - (bw * bw);
