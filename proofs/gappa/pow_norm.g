# The norm of q.pow(alpha) (src/quat/power.rs, pow and polar), for
# |alpha| <= f32::MAX / 4: the vector part (x, y, z) of q through
# scale_for_squares (src/float/norm.rs: the sum x x + y y + z z + 0 0,
# left to right), b = sqrt of it, the axis k = (x, y, z) / b, then
# (s, c) = sin_cos(alpha phi) and the result (c, k s). f32, round to
# nearest even.
#
# s and c are the sine and cosine kernel's results for the f32 angle
# alpha phi; Sin and Cos stand for the exact sine and cosine of that same
# angle, so that (Cos, Sin K), with K = (x, y, z) / B the exact axis, is
# exactly unit. The hypothesis on them is the kernel's bound: within 1.25
# ulp (SIN_COS_MAX_ULP; SIN_COS_NARROW_MAX_ULP = 1.0 up to 3 pi/4) of the
# exact value rounded to f32, whose ulp is at most 2^-23 for a magnitude
# up to 1 (2^-23 where it rounds to 1, 2^-24 below), so within 1.25 2^-23
# absolute. That bound is swept (every finite f32 argument,
# exhaustive_kernel_sweep), not proven. (Where neither rounds to 1, that
# is 1.25 2^-24 and the bound below would be 5.51e-7; splitting the cases
# as implications makes Gappa run for minutes.) Which angle alpha phi is,
# and so atan2, does not matter for the norm.
#
# Domain: (x, y, z) scaled by an exact power of four so that its exact sum
# of squares Q lies in [1, 4], as in normalize.g (the rescaled branches of
# scale_for_squares are normalize_scale.g's).
#
# Proven: the sum within 6 2^-24 of Q (relative), |B / b - 1| within
# 2.39e-7, and the length of the error vector (c, k s) - (Cos, Sin K) at
# most 6.56e-7, as the sum of three lengths (triangle inequality, with
# (c, r) - (Cos, Sin K) = (c - Cos, (s - Sin) K) + (0, r - k s) +
# (0, s (k - K)), r the rounded products): the kernel's errors
# (c - Cos, s - Sin), at
# most 2.11e-7 (|K| = 1); the roundings of the products k s, at most
# 1.04e-7; and |s| <= |Sin| + |s - Sin| times the axis's error |k - K|
# (the quotients' roundings plus |B / b - 1|, since x / b - K = K (B / b
# - 1)). Since (Cos, Sin K) is unit, the result's norm is within 6.56e-7
# of 1. For |alpha| > f32::MAX / 4, pow ends with normalize (normalize.g).
#
# What stays above the measured maximum: as in normalize.g, each
# component's rounding is bounded separately, and the axis's norm error
# (|B / b - 1|, up to 2.39e-7) counts in full where only its part along
# the result moves the norm.
#
#! looser UNIT_NORM_ERROR Deviation in [0, 6.56e-7] |q.pow(alpha)| - 1, given the sine and cosine kernel's 1.25 ulp (swept)
@rnd = float<ieee_32, ne>;

x = rnd(X); y = rnd(Y); z = rnd(Z);
s = rnd(SK); c = rnd(CK);

q rnd= x * x + y * y + z * z + 0 * 0;
b rnd= sqrt(q);
kx rnd= x / b; ky rnd= y / b; kz rnd= z / b;
rx rnd= kx * s; ry rnd= ky * s; rz rnd= kz * s;

Q = x * x + y * y + z * z + 0 * 0;
B = sqrt(Q);
Deviation = sqrt((c - Cos) * (c - Cos) + (s - Sin) * (s - Sin))
    + sqrt((rx - kx * s) * (rx - kx * s) + (ry - ky * s) * (ry - ky * s) + (rz - kz * s) * (rz - kz * s))
    + (|Sin| + |s - Sin|) * (sqrt((kx - x / b) * (kx - x / b) + (ky - y / b) * (ky - y / b) + (kz - z / b) * (kz - z / b))
               + |B / b - 1|);

{ Q in [1, 4] /\ |x| <= 2 /\ |y| <= 2 /\ |z| <= 2 /\
  |Sin| <= 1 /\ |Cos| <= 1 /\
  s - Sin in [-5b-25, 5b-25] /\ c - Cos in [-5b-25, 5b-25]
  ->
  (q - Q) / Q in [-6b-24, 6b-24] /\ |B / b - 1| in [0, 2.39e-7] /\ kx - x / b in [-1b-24, 1b-24] /\
  sqrt((c - Cos) * (c - Cos) + (s - Sin) * (s - Sin)) in [0, 2.11e-7] /\
  sqrt((rx - kx * s) * (rx - kx * s) + (ry - ky * s) * (ry - ky * s) + (rz - kz * s) * (rz - kz * s)) in [0, 1.04e-7] /\
  Deviation in [0, 6.56e-7]
}

# The partial sums of squares are at most Q.
x * x + y * y -> Q - z * z;
x * x + y * y + z * z -> Q;
B / b - 1 -> -((b - B) / B) / (1 + (b - B) / B);
# Split the sum of squares where its binade, or that of a square, changes.
$ Q in (1.5, 2, 3);
