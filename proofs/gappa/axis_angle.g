# The arithmetic of from_axis_angle (src/quat/construction.rs) and of
# q.pow(alpha) for |alpha| <= f32::MAX / 4 (src/quat/power.rs, pow and
# polar): the vector (x, y, z) (the axis, or q's vector part) through
# scale_for_squares (src/float/norm.rs: the sum x x + y y + z z + 0 0,
# left to right), b = sqrt of it, the axis k = (x, y, z) / b, then the
# result (c, k s) with (s, c) the sine and cosine kernel's results for the
# f32 argument angle / 2 or alpha phi (inputs here). f32, round to nearest
# even.
#
# The norm of (c, k s) is proofs/coq/axis_angle_norm.v's law: its terms
# are this model's (the correspondence test checks both against the code),
# and it rests on normalize.g's certificate for the root b.
#
# Domain: (x, y, z) scaled by an exact power of four so that its exact sum
# of squares Q lies in [1, 4], as in normalize.g (the rescaled branches of
# scale_for_squares are normalize_scale.g's).
#
# Proven here: the sum within 6 2^-24 of Q (relative), |B / b - 1| within
# 2.39e-7 and each quotient within 2^-24 of x / b (absolute, |x / b| < 2).
#
#! law - AxisLength in [0, 2.39e-7] |B / b - 1|, the axis's length error before the quotients' roundings (from_axis_angle, pow)
@rnd = float<ieee_32, ne>;

x = rnd(X); y = rnd(Y); z = rnd(Z);
s = rnd(SK); c = rnd(CK);

q rnd= x * x + y * y + z * z + 0 * 0;
b rnd= sqrt(q);
kx rnd= x / b; ky rnd= y / b; kz rnd= z / b;
rx rnd= kx * s; ry rnd= ky * s; rz rnd= kz * s;

Q = x * x + y * y + z * z + 0 * 0;
B = sqrt(Q);
AxisLength = |B / b - 1|;

{ Q in [1, 4] /\ |x| <= 2 /\ |y| <= 2 /\ |z| <= 2
  ->
  (q - Q) / Q in [-6b-24, 6b-24] /\ AxisLength in [0, 2.39e-7] /\ kx - x / b in [-1b-24, 1b-24]
}

# The partial sums of squares are at most Q.
x * x + y * y -> Q - z * z;
x * x + y * y + z * z -> Q;
B / b - 1 -> -((b - B) / B) / (1 + (b - B) / B);
# Split the sum of squares where its binade, or that of a square, changes.
$ Q in (1.5, 2, 3);
