# The inverse identities of RigTForm (src/rigtform.rs): a.inv() is
# (-(r^-1 t), r^-1) with r^-1 = [w, -x, -y, -z] (exact), and the product
# a * b is (a.t + a.r b.t, a.r b.r). So the translation of a * a.inv() is
# t + r (-(r^-1 t)), and that of a.inv().inv() is -(r (-(r^-1 t))); their
# rotations are r r^-1 (quat_inv.g) and r, exactly. Each rotation is the
# computation of rotate.g. f32, round to nearest even.
#
# Domain: r with every component in [-1, 1]; t scaled by an exact power of
# two so that every component is in [-1, 1] and |t| >= 1/2.
#
# Proven: the computed translations are within the bounds below of the
# exact values of the same formulas, relative to |t|. For unit r those
# exact values are 0 and t (each rotation is q [0, v] q^-1). The bounds
# are loose (a search finds 1.75e-6 |t| against the exact identities):
# interval arithmetic does not know that the first rotation preserves
# length, so it lets the intermediate r^-1 t range over a box 27 times
# wider than |t|. proofs/coq/rigtform_inverse.v proves the identities
# themselves, on these terms (the names are its lets), within
# 3.22e-6 |t| for r a result of normalize.
#
#! law - ProductError in [0, 2.31e-4] |translation of a * a.inv()| / |t| for unit r
#! law - BackError in [0, 2.04e-4] |a.inv().inv().t - t| / |t| for unit r
@rnd = float<ieee_32, ne>;

w = rnd(W); x = rnd(X); y = rnd(Y); z = rnd(Z);
t1 = rnd(T1); t2 = rnd(T2); t3 = rnd(T3);

# i = r^-1 t: rotate.g with (x, y, z) negated.
ax rnd= ((-y) * t3 - (-z) * t2) * 2;
ay rnd= ((-z) * t1 - (-x) * t3) * 2;
az rnd= ((-x) * t2 - (-y) * t1) * 2;
ix rnd= (t1 + ax * w) + ((-y) * az - (-z) * ay);
iy rnd= (t2 + ay * w) + ((-z) * ax - (-x) * az);
iz rnd= (t3 + az * w) + ((-x) * ay - (-y) * ax);
# g = r (-i).
cx rnd= (y * (-iz) - z * (-iy)) * 2;
cy rnd= (z * (-ix) - x * (-iz)) * 2;
cz rnd= (x * (-iy) - y * (-ix)) * 2;
gx rnd= ((-ix) + cx * w) + (y * cz - z * cy);
gy rnd= ((-iy) + cy * w) + (z * cx - x * cz);
gz rnd= ((-iz) + cz * w) + (x * cy - y * cx);
# a * a.inv(): t + g; a.inv().inv(): -g.
ex rnd= t1 + gx;
ey rnd= t2 + gy;
ez rnd= t3 + gz;

AX = ((-y) * t3 - (-z) * t2) * 2;
AY = ((-z) * t1 - (-x) * t3) * 2;
AZ = ((-x) * t2 - (-y) * t1) * 2;
IX = (t1 + AX * w) + ((-y) * AZ - (-z) * AY);
IY = (t2 + AY * w) + ((-z) * AX - (-x) * AZ);
IZ = (t3 + AZ * w) + ((-x) * AY - (-y) * AX);
CX = (y * (-IZ) - z * (-IY)) * 2;
CY = (z * (-IX) - x * (-IZ)) * 2;
CZ = (x * (-IY) - y * (-IX)) * 2;
GX = ((-IX) + CX * w) + (y * CZ - z * CY);
GY = ((-IY) + CY * w) + (z * CX - x * CZ);
GZ = ((-IZ) + CZ * w) + (x * CY - y * CX);
ProductError = sqrt((ex - (t1 + GX)) * (ex - (t1 + GX)) + (ey - (t2 + GY)) * (ey - (t2 + GY)) + (ez - (t3 + GZ)) * (ez - (t3 + GZ)))
    / sqrt(t1 * t1 + t2 * t2 + t3 * t3);
BackError = sqrt((gx - GX) * (gx - GX) + (gy - GY) * (gy - GY) + (gz - GZ) * (gz - GZ))
    / sqrt(t1 * t1 + t2 * t2 + t3 * t3);

{ |w| <= 1 /\ |x| <= 1 /\ |y| <= 1 /\ |z| <= 1 /\
  |t1| <= 1 /\ |t2| <= 1 /\ |t3| <= 1 /\ t1 * t1 + t2 * t2 + t3 * t3 >= 0.25
  ->
  ProductError in [0, 2.31e-4] /\
  BackError in [0, 2.04e-4]
}
