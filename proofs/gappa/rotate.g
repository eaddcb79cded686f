# Rotating a vector, q * v (src/quat.rs, Mul<Cvec3> for Quat):
# t = (u x v) * 2, then (v + t * w) + u x t, with u = (x, y, z) the vector
# part of q and every cross product (Cvec3::cross) component a b - c d.
# f32, round to nearest even.
#
# Domain: q with |q|^2 within 2^-20 (9.5e-7) of 1 (every output of
# normalize: proofs/coq/normalize_norm.v bounds its norm's error by 2.391e-7), v scaled by
# an exact power of two so that |v|^2 is in [1/4, 1] (every non-zero v has
# such a scaling, and the arithmetic commutes with it where nothing
# underflows).
#
# Proven: the error vector's length at most 3.8e-6 |v|.
# proofs/coq/rotate_error.v proves 6.5e-7 |v| (the constant's bound) on
# the same terms by vectors, without this certificate. (On the way Gappa
# bounds |t|^2 = |2 u x v|^2 by 4.00001 and each component of the result
# within 13 2^-23 of the exact value of the same formula; those are not
# goals, which halves Coq's time on the certificate.) For unit q
# the formula is the rotation q [0, v] q^-1, which preserves length: the
# result's length is within 3.8e-6 |v| of |v| (for |q|^2 = 1 + e, the
# exact formula scales v by 1 + e besides).
#
# The hints give Gappa the geometry that interval arithmetic lacks:
# Lagrange's identity |u x v|^2 = |u|^2 |v|^2 - (u . v)^2, per pair of
# components, bounds each component of t and of u x t by the lengths;
# |u|^2 = |q|^2 - w^2 and |v|^2 bound the components' squares. What stays
# above the measured maximum (4.71e-7): each component of v + t w is
# bounded by |v_i| + |t_i| |w| (up to 3, so its rounding is that of
# [2, 4)), where v and t are orthogonal and the sum is at most sqrt(2)
# long; and the three components' errors are added as if independent.
#
#! looser ROTATE_MAX_REL_ERROR RelativeError in [0, 3.8e-6] |q*v - rotation of v| / |v| for unit q
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

Q = w * w + x * x + y * y + z * z;
V = vx * vx + vy * vy + vz * vz;
U = x * x + y * y + z * z;
T2 = Tx * Tx + Ty * Ty + Tz * Tz;
RelativeError = sqrt((rx - Rx) * (rx - Rx) + (ry - Ry) * (ry - Ry) + (rz - Rz) * (rz - Rz))
    / sqrt(V);

{ Q in [0.99999904632568359375, 1.00000095367431640625] /\ V in [0.25, 1] /\
  |w| <= 1 /\ |x| <= 1 /\ |y| <= 1 /\ |z| <= 1 /\
  |vx| <= 1 /\ |vy| <= 1 /\ |vz| <= 1
  ->
  RelativeError in [0, 3.8e-6]
}

# Lagrange's identity: |u x v|^2 = |u|^2 |v|^2 - (u . v)^2, per pair of components.
(y * vz - z * vy) * (y * vz - z * vy) -> (y * y + z * z) * (vy * vy + vz * vz) - (y * vy + z * vz) * (y * vy + z * vz);
(z * vx - x * vz) * (z * vx - x * vz) -> (z * z + x * x) * (vz * vz + vx * vx) - (z * vz + x * vx) * (z * vz + x * vx);
(x * vy - y * vx) * (x * vy - y * vx) -> (x * x + y * y) * (vx * vx + vy * vy) - (x * vx + y * vy) * (x * vx + y * vy);
y * y + z * z -> Q - (w * w + x * x);
z * z + x * x -> Q - (w * w + y * y);
x * x + y * y -> Q - (w * w + z * z);
vy * vy + vz * vz -> V - vx * vx;
vz * vz + vx * vx -> V - vy * vy;
vx * vx + vy * vy -> V - vz * vz;
vx * vx -> V - (vy * vy + vz * vz);
vy * vy -> V - (vx * vx + vz * vz);
vz * vz -> V - (vx * vx + vy * vy);
T2 -> 4 * ((Q - w * w) * V - (x * vx + y * vy + z * vz) * (x * vx + y * vy + z * vz));
# The same for u x t, with t = Tx + (tx - Tx), ...
(y * Tz - z * Ty) * (y * Tz - z * Ty) -> (y * y + z * z) * (Ty * Ty + Tz * Tz) - (y * Ty + z * Tz) * (y * Ty + z * Tz);
Ty * Ty + Tz * Tz -> T2 - Tx * Tx;
y * tz - z * ty -> (y * Tz - z * Ty) + (y * (tz - Tz) - z * (ty - Ty));
# Split |v|^2 where the binade of its components' bound changes.
$ V in (0.5);
(z * Tx - x * Tz) * (z * Tx - x * Tz) -> (z * z + x * x) * (Tz * Tz + Tx * Tx) - (z * Tz + x * Tx) * (z * Tz + x * Tx);
Tz * Tz + Tx * Tx -> T2 - Ty * Ty;
z * tx - x * tz -> (z * Tx - x * Tz) + (z * (tx - Tx) - x * (tz - Tz));
(x * Ty - y * Tx) * (x * Ty - y * Tx) -> (x * x + y * y) * (Tx * Tx + Ty * Ty) - (x * Tx + y * Ty) * (x * Tx + y * Ty);
Tx * Tx + Ty * Ty -> T2 - Tz * Tz;
x * ty - y * tx -> (x * Ty - y * Tx) + (x * (ty - Ty) - y * (tx - Tx));
