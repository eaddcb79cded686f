# The scale that Matrix4::to_scale_rotation_translation (src/matrix/
# transform.rs) returns for Matrix4::from_scale_rotation_translation(s, r,
# t): the first column of Matrix4::from_quat(r) (src/matrix/matrix3.rs,
# Matrix3::from_quat: 1 - (yy + zz), xy + wz, xz - wy, with y2 = y + y,
# yy = y y2 and so on), each entry times the scale s, and the column's
# norm (src/float/norm.rs: scale_for_squares and ScaledSquares::norm, the
# branch without rescaling): the squares summed left to right, then the
# square root. f32, round to nearest even.
#
# The other two columns are this one renamed: the second is (-w, y, x,
# z) (x (2 y) and y (2 x) are the same real, and a negated product rounds
# to the negated rounding), its squares summed as (o^2 + d^2) + p^2, the
# same bits as (d^2 + o^2) + p^2; the third is (w, z, x, y), its squares
# summed as (o^2 + p^2) + d^2, which qz and nz compute. The norm's sum of
# four squares adds the square of the padding 0, exactly, and divides by
# the scale 1, exactly: for |s| in [1e-3, 1e3] the sum of squares lies in
# [2^-100, f32::MAX], the branch without rescaling. The sign of the
# determinant on the x scale multiplies by 1 or -1, exactly, and it is
# the sign of sx for positive sy and sz: the computed determinant is
# within 2.9803e-7 T of the block's exact one (matrix3_determinant_bound.v),
# where T, the sum of the magnitudes of its six products, is at most
# 3^(3/2) (1 + 7e-7)^3 |sx sy sz|, and the exact one is sx sy sz times the
# determinant of the computed rotation block (entries within 6.6e-7 of a
# rotation's, MATRIX_ENTRY_ERROR), within 1e-5 of 1, times the products'
# roundings (on paper).
#
# This model ties the computation to the code (the correspondence test)
# and to the law proofs/coq/srt_scale_bound.v, whose rounded terms are
# this model's, written in Coq (checked by the same test). The law
# proves what interval arithmetic cannot: that n and nz are within
# 7.92e-7 of |s|, relative, for every f32 quaternion with |q|^2 within
# 1.2e-7 of 1 and every f32 scale with |s| >= 1e-3. Gappa bounds each
# rounding of the column's entries by the half ulp of its range's top
# binade, which gives the goals below (against the exact entries of q's
# formula, not divided by |q|^2) for every component in [-1, 1].
#
#! law - o - O in [-3b-23, 3b-23] an off-diagonal entry of from_quat's formula, for every component in [-1, 1]
#! law - d - D in [-5b-23, 5b-23] a diagonal entry, the same
@rnd = float<ieee_32, ne>;

w = rnd(W); x = rnd(X); y = rnd(Y); z = rnd(Z); s = rnd(Sc);

y2 rnd= y + y;
z2 rnd= z + z;
yy rnd= y * y2;
zz rnd= z * z2;
xy rnd= x * y2;
xz rnd= x * z2;
wy rnd= w * y2;
wz rnd= w * z2;
d rnd= 1 - (yy + zz);
o rnd= xy + wz;
p rnd= xz - wy;
m0 rnd= d * s;
m1 rnd= o * s;
m2 rnd= p * s;
q rnd= m0 * m0 + m1 * m1 + m2 * m2;
n rnd= sqrt(q);
qz rnd= m1 * m1 + m2 * m2 + m0 * m0;
nz rnd= sqrt(qz);

D = 1 - (y * (y + y) + z * (z + z));
O = x * (y + y) + w * (z + z);

{ |w| <= 1 /\ |x| <= 1 /\ |y| <= 1 /\ |z| <= 1 /\ |s| <= 1e3
  ->
  d - D in [-5b-23, 5b-23] /\ o - O in [-3b-23, 3b-23]
}
