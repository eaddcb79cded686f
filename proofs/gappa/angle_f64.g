# slerp's f64 angle (src/quat/slerp/kernels_f64.rs, atan2_of_root(w, x), the angle
# atan2(sqrt(w), x) for w >= 0, x >= 0), the branch w < x x: z = w / (x x),
# the square root of z in f32, and a = u + u (z p(z)) with p the degree-7
# polynomial of ATAN in the code's grouping. The result is a (0 pi/2 + a,
# exactly). f64, round to nearest even, every operation rounded; f32 for
# z's conversion and its square root, as the code.
#
# At stands for atan(sqrt(Z)), Z = w / (x x) exactly. The hypothesis on it
# is the approximation error of the exact polynomial, which Sollya bounds
# (angle_f64.sollya: 1.66992e-8 over sqrt(Z) in [2^-32, 1], rounded up
# here to 1.67e-8).
#
# Domain: x scaled by a power of two into [1, 2] (w by its square: exact
# in f64), Z in [2^-64, 1].
#
# Proven: the result within 1.0611e-7 of atan2(sqrt(w), x) (relative) for
# any such f64 inputs; and within 7.64e-8 when z is an f32 (as for the
# pairs (t, 1) of ANGLE_F64_MAX_REL_ERROR's domain, where z = t exactly),
# since only the square root rounds in f32. The other branch is
# angle_f64_above.g.
#
#! sollya angle_f64.sollya 1.67e-8
#! law - 1.0611e-7 relative error of atan2_of_root(w, x) for w < x x, any f64
#! looser ANGLE_F64_MAX_REL_ERROR 7.64e-8 relative error on the pairs (t, 1) (half the constant's domain; angle_f64_above.g has the other)
@rnd = float<ieee_64, ne>;
@f32 = float<ieee_32, ne>;

w = rnd(Wi); x = rnd(Xi);

x2 rnd= x * x;
z rnd= w / x2;
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

Z = w / (x * x);
P = ((-0x1.5554dc2343771p-2 + Z * 0x1.9978f3b40f785p-3) + (Z * Z) * (-0x1.230adc19a37efp-3 + Z * 0x1.b4e12e9505e18p-4)) + ((Z * Z) * (Z * Z)) * ((-0x1.3556be4cac7f9p-4 + Z * 0x1.61fded6d4e340p-5) + (Z * Z) * (-0x1.0c2c2c26f5424p-6 + Z * 0x1.7ed26148ac171p-9));
R = 1 + Z * P;
A = sqrt(Z) * R;
r = 1 + z * p;
Q = u * (z * p);

{ x in [1, 2] /\ Z in [1b-64, 1] /\ (A - At) / At in [-1.67e-8, 1.67e-8]
  ->
  (a - At) / At in [-1.0611e-7, 1.0611e-7] /\
  (zf - z in [0, 0] -> (a - At) / At in [-7.64e-8, 7.64e-8])
}

(a - At) / At -> (a - A) / A + (A - At) / At + ((a - A) / A) * ((A - At) / At);
(a - A) / A -> ((a - (u + Q)) / (u + Q) + 1) * ((u - sqrt(Z)) / sqrt(Z) + 1) * ((r - R) / R + 1) - 1;
(r - R) / R -> (z * p - Z * P) / R;
(u - sqrt(Z)) / sqrt(Z) -> ((u - sqrt(zf)) / sqrt(zf) + 1) * ((sqrt(zf) - sqrt(Z)) / sqrt(Z) + 1) - 1;
zf / Z -> ((zf - z) / z + 1) * ((z - Z) / Z + 1);
w -> Z * (x * x);
(a - (u + Q)) / (u + Q) -> (a - (u + n)) / (u + n) * (1 + (n - Q) / (u + Q)) + (n - Q) / (u + Q);
(n - Q) / (u + Q) -> ((n - Q) / Q) * ((z * p) / r);
u + n -> (u + Q) * (1 + (n - Q) / (u + Q));
u + Q -> u * r;
