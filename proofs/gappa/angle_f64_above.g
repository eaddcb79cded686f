# slerp's f64 angle (src/quat/slerp/kernels_f64.rs, atan2_of_root(w, x)), the
# branch w > x x (for w = x x the code takes the result of angle_f64.g,
# with z = 1): z = (x x) / w, a as in angle_f64.g, and the result
# FRAC_PI_2 - a (quarter = 1, a's sign flipped). f64, round to nearest
# even; f32 for z's conversion and its square root, as the code.
#
# At stands for atan(sqrt(Z)), Z = x x / w exactly, with the hypothesis of
# angle_f64.g (Sollya's bound, angle_f64.sollya); Pi2 for pi/2, which
# FRAC_PI_2 (0x1.921fb54442d18p0) approximates within 6.2e-17.
#
# Domain: w scaled by a power of four into [1, 4] (x by its root: exact),
# Z in [2^-64, 1].
#
# Proven: the result within 1.337e-7 of pi/2 - atan(sqrt(Z)) =
# atan2(sqrt(w), x) (relative), for any such f64 inputs, the pairs (1, t)
# of ANGLE_F64_MAX_REL_ERROR's domain among them: above the constant
# (9.0e-8, swept 7.552e-8). Interval arithmetic takes the worst relative
# error of a (1.0611e-7) together with the largest ratio a / (pi/2 - a).
# Splitting Z into 16 pieces (`$ Z in 16;`), Gappa proves 6.66e-8, which
# with angle_f64.g's 7.64e-8 would prove the constant; but Coq takes more
# than five minutes on that certificate (46,000 lines with 4 pieces), too
# long for CI, so neither is claimed here.
#
#! sollya angle_f64.sollya 1.67e-8
#! looser ANGLE_F64_MAX_REL_ERROR 1.337e-7 relative error of atan2_of_root(w, x) for w > x x, any f64 (the pairs (1, t))
@rnd = float<ieee_64, ne>;
@f32 = float<ieee_32, ne>;
w = rnd(Wi); x = rnd(Xi);

x2 rnd= x * x;
z rnd= x2 / w;
zf = f32(z);
u = f32(sqrt(zf));
z2 rnd= z * z;
z4 rnd= z2 * z2;
low rnd= (-0x1.5554dc2343771p-2 + z * 0x1.9978f3b40f785p-3) + z2 * (-0x1.230adc19a37efp-3 + z * 0x1.b4e12e9505e18p-4);
high rnd= (-0x1.3556be4cac7f9p-4 + z * 0x1.61fded6d4e340p-5) + z2 * (-0x1.0c2c2c26f5424p-6 + z * 0x1.7ed26148ac171p-9);
p rnd= low + z4 * high;
m rnd= z * p;
n rnd= u * m;
a rnd= u + n;
res rnd= 0x1.921fb54442d18p0 - a;


Z = (x * x) / w;
P = ((-0x1.5554dc2343771p-2 + Z * 0x1.9978f3b40f785p-3) + (Z * Z) * (-0x1.230adc19a37efp-3 + Z * 0x1.b4e12e9505e18p-4)) + ((Z * Z) * (Z * Z)) * ((-0x1.3556be4cac7f9p-4 + Z * 0x1.61fded6d4e340p-5) + (Z * Z) * (-0x1.0c2c2c26f5424p-6 + Z * 0x1.7ed26148ac171p-9));
R = 1 + Z * P;
A = sqrt(Z) * R;
r = 1 + z * p;
Q = u * (z * p);
E = (a - At) / At;

{ w in [1, 4] /\ Z in [1b-64, 1] /\ (A - At) / At in [-1.67e-8, 1.67e-8] /\
  Pi2 in [1.5707963267948966192, 1.5707963267948966193]
  ->
  (a - At) / At in [-1.0611e-7, 1.0611e-7] /\
  (res - (Pi2 - At)) / (Pi2 - At) in [-1.337e-7, 1.337e-7]
}

(a - At) / At -> (a - A) / A + (A - At) / At + ((a - A) / A) * ((A - At) / At);
(a - A) / A -> ((a - (u + Q)) / (u + Q) + 1) * ((u - sqrt(Z)) / sqrt(Z) + 1) * ((r - R) / R + 1) - 1;
(r - R) / R -> (z * p - Z * P) / R;
(u - sqrt(Z)) / sqrt(Z) -> ((u - sqrt(zf)) / sqrt(zf) + 1) * ((sqrt(zf) - sqrt(Z)) / sqrt(Z) + 1) - 1;
zf / Z -> ((zf - z) / z + 1) * ((z - Z) / Z + 1);
x * x -> Z * w;
(a - (u + Q)) / (u + Q) -> (a - (u + n)) / (u + n) * (1 + (n - Q) / (u + Q)) + (n - Q) / (u + Q);
(n - Q) / (u + Q) -> ((n - Q) / Q) * ((z * p) / r);
u + n -> (u + Q) * (1 + (n - Q) / (u + Q));
u + Q -> u * r;
At -> A / (1 + (A - At) / At);
(res - (Pi2 - At)) / (Pi2 - At) -> ((res - (0x1.921fb54442d18p0 - a)) + (0x1.921fb54442d18p0 - Pi2) - E * At) / (Pi2 - At);
