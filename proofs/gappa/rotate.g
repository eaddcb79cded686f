# Rotating a vector, q * v (src/quat.rs, Mul<Cvec3> for Quat):
# t = (u x v) * 2, then (v + t * w) + u x t, with u = (x, y, z) the vector
# part of q and every cross product (Cvec3::cross) component a b - c d.
# f32, round to nearest even.
#
# Domain: q with every component in [-1, 1] (every unit quaternion), v
# scaled by an exact power of two so that every component is in [-1, 1]
# and its length is at least 1/2 (the arithmetic commutes with that
# scaling where nothing underflows).
#
# Proven: each component of the result within 17 2^-23 (2.03e-6) of the
# exact value of the same formula, and the error vector's length at most
# 7.03e-6 |v|. For unit q the formula is the rotation q [0, v] q^-1, which
# preserves length: the result's length is within 7.03e-6 |v| of |v|.
#
#! looser ROTATE_MAX_REL_ERROR 7.03e-6 |q*v - rotation of v| / |v| for unit q
@rnd = float<ieee_32, ne>;

w = rnd(W); x = rnd(X); y = rnd(Y); z = rnd(Z);
vx = rnd(VX); vy = rnd(VY); vz = rnd(VZ);

tx rnd= (y * vz - z * vy) * 2;
ty rnd= (z * vx - x * vz) * 2;
tz rnd= (x * vy - y * vx) * 2;
rx rnd= (vx + tx * w) + (y * tz - z * ty);
ry rnd= (vy + ty * w) + (z * tx - x * tz);
rz rnd= (vz + tz * w) + (x * ty - y * tx);

Tx = (y * vz - z * vy) * 2;
Ty = (z * vx - x * vz) * 2;
Tz = (x * vy - y * vx) * 2;
Rx = (vx + Tx * w) + (y * Tz - z * Ty);
Ry = (vy + Ty * w) + (z * Tx - x * Tz);
Rz = (vz + Tz * w) + (x * Ty - y * Tx);

{ |w| <= 1 /\ |x| <= 1 /\ |y| <= 1 /\ |z| <= 1 /\
  |vx| <= 1 /\ |vy| <= 1 /\ |vz| <= 1 /\ vx * vx + vy * vy + vz * vz >= 0.25
  ->
  rx - Rx in [-17b-23, 17b-23] /\ ry - Ry in [-17b-23, 17b-23] /\ rz - Rz in [-17b-23, 17b-23] /\
  sqrt((rx - Rx) * (rx - Rx) + (ry - Ry) * (ry - Ry) + (rz - Rz) * (rz - Rz))
    / sqrt(vx * vx + vy * vy + vz * vz) in [0, 7.03e-6]
}
