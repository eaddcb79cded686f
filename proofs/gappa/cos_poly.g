# The cosine polynomial of the f32 sine and cosine kernel
# (src/float/sin_cos.rs, cos_poly(r, t) with the tail t = 0, as the kernel
# calls it for |x| <= pi/4): s = r r, half = 0.5 s, w = 1 - half, then
# w + ((((1 - w) - half) - r t) + s s (C0 + s (C1 + s C2))), the
# rounding error of w recovered as in FreeBSD's k_cos.c. f32, round to
# nearest even, every operation rounded; the code's one inner sum is
# split over the lines d, e, k, ek here, which round the same operations.
#
# Cos stands for cos(r). The hypothesis on it is the approximation error
# of the exact polynomial P, which Sollya bounds (cos_poly.sollya:
# 1.2716e-10 absolute, rounded up here to 1.28e-10).
#
# Domain: every f32 r in [0, pi/4] (0.7854 is above pi/4 rounded to f32).
#
# Proven: |y - cos r| at most 0.834 2^-24. For r in [0, pi/4] the
# cosine is in [0.7071, 1], so an ulp of it rounded to f32 (the sweep's
# unit, src/float/sweep.rs) is 2^-24, or 2^-23 where it rounds to 1:
# y is within 0.834 ulp of the cosine. Of that, half an ulp is the last
# rounding, a quarter the rounding of s = r r (half carries it, and the
# recovered error of w does not), 3.8e-9 the polynomial's evaluation and
# 1.28e-10 its approximation error. The sweep's largest is 0.749 ulp.
#
# Gappa splits r at 2^-12: above it the sum before the last rounding is
# below 1 (half an ulp of [1/2, 1)); below it w = 1 and the result rounds
# to 1 (1 - 2^-25 ties to even).
#
#! sollya cos_poly.sollya 1.28e-10
#! looser SIN_COS_POLY_MAX_ULP (y - Cos) * 16777216 in [-0.834, 0.834] cosine polynomial on [0, pi/4], in ulps (the cosine half of the constant's domain; the sine is in the sin_poly_*.g models)
@rnd = float<ieee_32, ne>;

r = rnd(R); t = rnd(T);

s rnd= r * r;
half rnd= 0.5 * s;
w rnd= 1 - half;
d rnd= 1 - w;
e rnd= (d - half) - r * t;
k rnd= s * s * (0x1.55554ap-5 + s * (-0x1.6c0c34p-10 + s * 0x1.99eb9cp-16));
ek rnd= e + k;
y rnd= w + ek;

S = r * r;
PP = 0x1.55554ap-5 + S * (-0x1.6c0c34p-10 + S * 0x1.99eb9cp-16);
P = 1 - S * (0.5 - S * PP);

{ r in [0, 0.7854] /\ t in [0, 0] /\ P - Cos in [-1.28e-10, 1.28e-10]
  ->
  (y - Cos) * 16777216 in [-0.834, 0.834]
}

# The sum before the last rounding, against the exact polynomial: the
# rounding of s (half = 0.5 s is exact), the evaluation of the tail,
# the rounding of the inner sum, and the recovered error of w.
w + ek -> P + (w + ek - P);
w + ek - P -> (S * 0.5 - half) + (k - S * S * PP) + (ek - (e + k)) + (e - (d - half)) + (d - (1 - w));
S * 0.5 - half -> (S - s) * 0.5 + (0.5 * s - half);
# 1 - w is exact (Sterbenz), and (1 - w) - half is the rounding error of w.
d - half -> (1 - half) - w + (d - (1 - w));
e - (d - half) -> (e - ((d - half) - r * t)) - r * t;
$ r in (1b-12);
