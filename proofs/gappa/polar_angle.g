# The angles of q.pow(alpha), q.to_axis_angle() and q.to_scaled_axis()
# (src/quat/power.rs: polar and pow; src/quat/conversion.rs;
# src/quat/exp_log.rs): the vector part (x, y, z) of q through
# scale_for_squares (the sum x x + y y + z z + 0 0, left to right), b =
# sqrt of it, the axis k = (x, y, z) / b, ph = atan2(b, w) (the atan2
# kernel); then pow's a = alpha ph, (s, c) = sin_cos(a) and the result
# (c, k s); to_scaled_axis's k (2 ph); to_axis_angle's 2 ph (of q.cn(),
# the same computation). y and z go through x's operations: the model
# writes x's. f32, round to nearest even.
#
# Exact: Q and B = sqrt(Q) the vector part's squared length and length;
# Phi = atan2(B, w), half the angle of q (of q / |q|: atan2 is
# scale-free, so q need not be unit); Phib = atan2(b, w); Sin and Cos the
# sine and cosine of the f32 angle a.
#
# Hypotheses, each from another result:
# - (b - B) / B within 0x1.81p-23: proven by normalize.g (whose sum is
#   this one with a fourth component w; here it is 0, and 0 * 0 adds
#   exactly), with normalize_norm.v proving its hypothesis.
# - (ph - Phib) / Phib within 1.9074e-7: the atan2 kernel's 1.6 ulp
#   (ATAN2_MAX_ULP), an ulp of a value being at most 2^-23 (1 + 2^-24)
#   of it. Swept (every f32 quotient, quotient_sweep), not proven.
# - (Phib - Phi) / Phi within 1.7929e-7, on paper from the first: with
#   b = B (1 + e), w > 0 and t = B / w, |atan(t (1 + e)) - atan(t)| <=
#   |e| t / ((1 + t^2) (1 - |e|)^2) <= |e| atan(t) / (1 - |e|)^2, since
#   t / (1 + t^2) <= atan(t); for w < 0, Phi = pi - atan(B / |w|) moves by
#   the same amount and is larger than atan(B / |w|); for w = 0 both are
#   pi/2. (1.7928e-7 / (1 - 1.7928e-7)^2 < 1.7929e-7.)
# - |s - Sin| and |c - Cos| at most 6.4e-8: SIN_COS_MAX_ABS_ERROR, every
#   f32 of [-10, 10] (exhaustive_kernel_sweep). Swept, not proven.
#
# Domain: (x, y, z) scaled by an exact power of four so that Q lies in
# [1, 4] (scale_for_squares scales exactly, w by the same power, for
# every component of a unit q; the angles are scale-free), alpha and the
# components' signs taken positive (the roundings are odd), and every
# rounded value in f32's normal range: |x| at least 2^-25, |s| at least
# 2^-99, Phi and Phib at least 2^-100, a at least 2^-125 and at most 10.
# Outside, the roundings that leave the normal range are absolute, at
# most 2^-150 each: against the lengths they belong to (|s| times the
# unit axis, 2 Phi times it, at least 2^-99 where the relative bounds
# below are claimed) at most 2^-48 relative, which the bounds' last digits
# hold; where a is below 2^-125 the angle error is at most 2^-148 rad;
# beyond |a| = 10 (|alpha| theta above 20) the sine and cosine are within
# 1.25 ulp (SIN_COS_MAX_ULP, 1.25 2^-23 absolute), whose share of the
# bound below is then 2 sqrt(2) 1.25 2^-23 / 20 = 2.1e-8, less than it is
# here. to_scaled_axis's relative bound is claimed for angles theta of at
# least 2^-99: below, its components are near or below f32's normal range
# and round absolutely (6.4e-6 relative found at theta = 3.1e-40).
#
# Proven:
# - Rel = |a - alpha Phi| / |alpha Phi| <= 4.3e-7: the atan2 kernel, the
#   length's rounding through the angle, and the product's rounding.
# - Er, each component of the vector part against s k0, k0 = (x, y, z) / b
#   the exact quotient, within 0x1.000001p-23 relative (two roundings).
# - Turn: the angle of pow's result against the exact rotation (cos(alpha
#   Phi), sin(alpha Phi) K), K = (x, y, z) / B, per max(1, |alpha| theta),
#   is at most Rel + 2.000001 Sc + 1.000001 |B / b - 1| + 2.000001 |Er| <=
#   1.03e-6, by this argument on paper. The rotation angle between two
#   quaternions is twice the angle between their lines, which obeys the
#   triangle inequality. Going from the exact R to r = (c, r_k): R1 =
#   (cos a, sin a K) is 2 |alpha Phi - a| = |alpha| theta Rel from R (the
#   same axis); R2 = (c, s K) is within asin(Sc) of R1 (R1 unit, Sc =
#   |R2 - R1|; asin(d) <= 1.000001 d here); R3 = (c, (B / b) s K) = (c,
#   s k0) turns from R2 in their common plane by at most |B / b - 1| |s c| /
#   (min(1, B / b)^2 (c^2 + s^2)) <= |B / b - 1| / 2 (1 + 4e-7); r differs
#   from R3 by (0, s k0 Er_i) per component, of length at most |Er| times
#   |s k0|, which is at most |R3|: within asin(|Er|). Doubled, with
#   |alpha| theta Rel + A <= (Rel + A) max(1, |alpha| theta).
# - Eph: |ph - Phi| / Phi <= 3.7016e-7, so to_axis_angle's 2 ph (the
#   doubling is exact) is within 3.7016e-7 theta of theta, below pow's
#   bound per max(1, theta).
# - to_scaled_axis: each component of k t, t = 2 ph, against the exact
#   K 2 Phi within 6.6912e-7 relative, so the vector within 6.6912e-7 of
#   its length (the components' relative errors bound the vector's).
#
# What stays above the worst cases found (2.968e-7 for pow and 2.612e-7
# for to_scaled_axis by search, 2.624e-7 random): each hypothesis taken
# at its worst at once, the atan2 kernel's error in ulps taken at the
# bottom of its binade, and the roundings of the axis across the result
# in full.
#
#! looser POW_MAX_ANGLE_ERROR Turn in [0, 1.03e-6] angle error of q.pow(alpha) per max(1, |alpha| theta), given the atan2 and sine and cosine kernels' swept bounds
#! looser POW_MAX_ANGLE_ERROR |Eph| in [0, 3.7016e-7] relative error of the angle of to_axis_angle, given the atan2 kernel's swept bound
#! looser TO_SCALED_AXIS_MAX_REL_ERROR (vx - Vx) / Vx in [-6.6912e-7, 6.6912e-7] to_scaled_axis relative to the angle, given the atan2 kernel's swept bound
@rnd = float<ieee_32, ne>;

x = rnd(X);
y = rnd(Y);
z = rnd(Z);
ph = rnd(PH);
al = rnd(AL);
s = rnd(SK);
c = rnd(CK);

q rnd= x * x + y * y + z * z + 0 * 0;
b rnd= sqrt(q);
kx rnd= x / b;
a rnd= al * ph;
rx rnd= kx * s;
t rnd= 2 * ph;
vx rnd= kx * t;

Q = x * x + y * y + z * z + 0 * 0;
B = sqrt(Q);
Vx = x / B * (2 * Phi);
Ea = (a - al * ph) / (al * ph);
Ep = (ph - Phib) / Phib;
Eb = (Phib - Phi) / Phi;
Eph = (ph - Phi) / Phi;
Ek = (kx - x / b) / (x / b);
Ekr = (rx - kx * s) / (kx * s);
Ev = (vx - kx * t) / (kx * t);
Et = (t - 2 * ph) / (2 * ph);
G = B / b - 1;
Er = (rx - x / b * s) / (x / b * s);
Rel = |(a - al * Phi) / (al * Phi)|;
Sc = sqrt((c - Cos) * (c - Cos) + (s - Sin) * (s - Sin));
Turn = Rel + 2.000001 * Sc + 1.000001 * |G| + 2.000001 * |Er|;

{ Q in [1, 4] /\ |y| <= 2 /\ |z| <= 2 /\
  x in [1b-25, 2] /\ s in [1b-99, 1] /\ al * ph in [1b-125, 10] /\
  Phib in [1b-100, 3.1416] /\ Phi in [1b-100, 3.1416] /\
  (b - B) / B in [-0x1.81p-23, 0x1.81p-23] /\
  Ep in [-1.9074e-7, 1.9074e-7] /\
  Eb in [-1.7929e-7, 1.7929e-7] /\
  |Sin| <= 1 /\ |Cos| <= 1 /\
  s - Sin in [-6.4e-8, 6.4e-8] /\ c - Cos in [-6.4e-8, 6.4e-8]
  ->
  |G| in [0, 1.7929e-7] /\
  Rel in [0, 4.3e-7] /\
  Er in [-0x1.000001p-23, 0x1.000001p-23] /\
  Sc in [0, 9.052e-8] /\
  Turn in [0, 1.03e-6] /\
  |Eph| in [0, 3.7016e-7] /\
  (vx - Vx) / Vx in [-6.6912e-7, 6.6912e-7]
}
B / b - 1 -> -((b - B) / B) / (1 + (b - B) / B);
(a - al * Phi) / (al * Phi) -> Ea + Eph + Ea * Eph;
Eph -> Ep + Eb + Ep * Eb;
Er -> Ekr + Ek + Ekr * Ek;
(vx - Vx) / Vx -> (1 + Ev) * (1 + Ek) * (1 + G) * (1 + Et) * (1 + Eph) - 1;
