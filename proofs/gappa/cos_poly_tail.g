# The cosine polynomial of the f32 sine and cosine kernel with its tail
# (src/float/sin_cos.rs, cos_poly(r, t)): s = r r, half = 0.5 s,
# w = 1 - half, then w + ((((1 - w) - half) - r t) + s s (C0 + s (C1 +
# s C2))), f32, round to nearest even, every operation rounded (the
# code's inner sum is split over the lines d, e, k, ek). Its error
# relative to cos(r + t), the cosine of the exact real sum of the head r
# and the tail t, over every (r, t) the kernel evaluates. The unit-norm
# proofs of from_axis_angle, pow and slerp take this bound as their
# hypothesis on the kernel.
#
# Domain (argued from the code, docs/verification-proofs.md; the cases
# are those of sin_poly_tail.g): an f32 r in [0, pi/4] (0.7854 is above
# pi/4 rounded to f32) and an f32 tail t with |t| <= 2^-24 r, written
# t = r Tr with Tr in [-2^-24, 2^-24] (the hypothesis t - r Tr in
# [0, 0]). Negative r: cos_poly(-r, -t) = cos_poly(r, t) bit for bit
# (r r and r t keep their values, every rounding to nearest even is odd)
# and cos is even, so (|r|, -t) in the domain covers it.
#
# Cy stands for cos(r + t), written as Taylor's formula in t around r:
# cos(r + t) = cos r - t sin r - (t^2 / 2) cos xi, with xi between r and
# r + t, so Kt = cos(xi) / 2 is in [0, 0.5]; and sin r = r - r^3 Ks with
# Ks = (r - sin r) / r^3 in [1/6 - r^2/120, 1/6], within [0.161, 0.1667]
# for r <= 0.7854. Cos stands for cos r, in [0.7071, 1] (cos 0.7854 >
# 0.70710). These are facts of calculus (Taylor with Lagrange's
# remainder), stated here, not proven by Gappa. The approximation error of
# the exact polynomial P at r against cos r is Sollya's (cos_poly.sollya:
# 1.2716e-10 absolute over [0, 0.7854], rounded up here to 1.28e-10);
# what the code computes in place of -t sin r, -r t, differs from it by
# t r^3 Ks, in the hints below.
#
# Proven: |y - cos(r + t)| <= 8e-8 cos(r + t) over the whole domain. (With
# t = 0 cos_poly.g proves 0.834 2^-24 absolute, 7.0e-8 relative to a
# cosine of at least 0.7071.)
#
#! sollya cos_poly.sollya 1.28e-10
#! law - (y - Cy) / Cy in [-8e-8, 8e-8] the cosine polynomial with its tail, relative to cos(r + t), every (r, t) the kernel evaluates
# The side conditions' bound on the tail (`#! side`, used only by the
# model of the side conditions, which has no other hint): t is r Tr.
#! side t -> r * Tr + (t - r * Tr);
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
Cy = Cos - t * (r - r * S * Ks) - t * t * Kt;

{ r in [0, 0.7854] /\ Tr in [-1b-24, 1b-24] /\ t - r * Tr in [0, 0]
  /\ Cos in [0.7071, 1] /\ Ks in [0.161, 0.1667] /\ Kt in [0, 0.5]
  /\ P - Cos in [-1.28e-10, 1.28e-10]
  ->
  (y - Cy) / Cy in [-8e-8, 8e-8]
}

# The sum before the last rounding against cos(r + t): the rounding of
# s (half = 0.5 s is exact), the evaluation of the tail k, the rounding
# of the inner sums, the recovered error of w (1 - w is exact, Sterbenz),
# the approximation error, and what the code leaves out, t r^3 Ks and
# the t^2 term.
t -> r * Tr + (t - r * Tr);
Cos -> P - (P - Cos);
y - Cy -> (y - (w + ek)) + (w + ek - P + r * t) + (P - Cos) - t * r * S * Ks + t * t * Kt;
w + ek - P + r * t -> (S * 0.5 - half) + (k - S * S * PP) + (ek - (e + k)) + (e - ((d - half) - r * t)) + (d - (1 - w));
S * 0.5 - half -> (S - s) * 0.5 + (0.5 * s - half);
$ r in (1b-12, 0.125, 0.25, 0.375, 0.5, 0.6, 0.7);
