# The Hamilton product a * b (src/quat/product.rs: by_formula, and by_lanes,
# which sums the same terms in the same order). f32, round to nearest even,
# every operation rounded, each component summed left to right.
#
# Inputs: two quaternions with every component in [-1, 1] (so every unit
# quaternion). Proven: each component of the computed product is within
# 7 2^-24 of the exact product of the same f32 inputs, and the error vector
# within 7 2^-23 (8.35e-7) in length. For unit inputs the exact product has
# norm |a| |b| = 1, so by the triangle inequality the computed product's
# norm is within 8.35e-7 of 1.
#
#! looser UNIT_NORM_ERROR 8.35e-7 |a*b| - 1 for unit a, b (length of the error vector; triangle inequality)
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

{ |aw| <= 1 /\ |ax| <= 1 /\ |ay| <= 1 /\ |az| <= 1 /\
  |bw| <= 1 /\ |bx| <= 1 /\ |by| <= 1 /\ |bz| <= 1
  ->
  pw - Pw in [-7b-24, 7b-24] /\ px - Px in [-7b-24, 7b-24] /\
  py - Py in [-7b-24, 7b-24] /\ pz - Pz in [-7b-24, 7b-24] /\
  sqrt((pw - Pw) * (pw - Pw) + (px - Px) * (px - Px) +
       (py - Py) * (py - Py) + (pz - Pz) * (pz - Pz)) in [0, 8.35e-7]
}
