# The rotation matrix of a quaternion (src/matrix/matrix4.rs:
# Matrix4::from_quat, which Matrix3::from_quat takes the block of). f32,
# round to nearest even. The model computes one diagonal entry,
# 1 - (y (y + y) + z (z + z)), and one off-diagonal entry,
# x (y + y) + w (z + z); the code's other entries are these two with the
# components renamed and w negated (a negated product rounds to the
# negated rounding, and a - b is a + (-b)), which the correspondence test
# checks entry by entry.
#
# Domain: every component in [-1, 1] and |q|^2 within 1.2e-7 of 1: every
# f32 rounding of a unit quaternion (each component rounded with relative
# error at most 2^-24 moves |q|^2 by at most 2^-23 + 2^-48, 1.193e-7).
#
# Proven: against the exact rotation matrix of q / |q| (1 - 2 (y^2 + z^2)
# / |q|^2 and 2 (x y + w z) / |q|^2), a diagonal entry is within 6.58e-7
# and an off-diagonal entry within 4.19e-7. Of the diagonal's bound,
# 2.4e-7 is the input's distance from unit norm (2 (y^2 + z^2) (1 -
# |q|^2) / |q|^2, at most 2 |1 - |q|^2|) and the rest the rounding of the
# three operations, each bounded by the half ulp of its range's top
# binade (the sum of the two squares reaches 2, where the rounding is
# 2^-23).
#
# The hints: the partial sums of squares are |q|^2 minus the rest, and
# |2 x y| is at most x^2 + y^2 ((x - y)^2 >= 0 and (x + y)^2 >= 0), and
# |x y + w z| at most |q|^2 / 2, so that each off-diagonal term stays
# within [-1, 1] (up to the norm's 1.2e-7).
#
# The side condition (the hints divide by |q|^2, which Gappa prints in
# another order of its terms) is |q|^2 itself (`#! side`):
#! side ((x) * (x)) + ((w) * (w)) + ((z) * (z)) + ((y) * (y)) -> Q;
#! bound MATRIX_ENTRY_ERROR d - D in [-6.58e-7, 6.58e-7] a diagonal entry of Matrix4::from_quat(q) against the rotation of q / |q|, for |q|^2 within 1.2e-7 of 1
#! bound MATRIX_ENTRY_ERROR o - O in [-4.19e-7, 4.19e-7] an off-diagonal entry, the same
@rnd = float<ieee_32, ne>;

w = rnd(W); x = rnd(X); y = rnd(Y); z = rnd(Z);

y2 rnd= y + y;
z2 rnd= z + z;
yy rnd= y * y2;
zz rnd= z * z2;
xy rnd= x * y2;
wz rnd= w * z2;
d rnd= 1 - (yy + zz);
o rnd= xy + wz;

Q = w * w + x * x + y * y + z * z;
S = y * y + z * z;
P = x * y + w * z;
DR = 1 - (y * (y + y) + z * (z + z));
OR = x * (y + y) + w * (z + z);
D = 1 - 2 * S / Q;
O = 2 * P / Q;

{ Q in [0.99999988, 1.00000012] /\
  |w| <= 1 /\ |x| <= 1 /\ |y| <= 1 /\ |z| <= 1
  ->
  d - D in [-6.58e-7, 6.58e-7] /\ o - O in [-4.19e-7, 4.19e-7]
}
DR - D -> 2 * S * (1 - Q) / Q;
OR - O -> 2 * P * (Q - 1) / Q;
S -> Q - (w * w + x * x);
P -> Q / 2 - ((x - y) * (x - y) + (w - z) * (w - z)) / 2;
P -> ((x + y) * (x + y) + (w + z) * (w + z)) / 2 - Q / 2;
x * (y + y) -> (x * x + y * y) - (x - y) * (x - y);
x * (y + y) -> (x + y) * (x + y) - (x * x + y * y);
w * (z + z) -> (w * w + z * z) - (w - z) * (w - z);
w * (z + z) -> (w + z) * (w + z) - (w * w + z * z);
