# A CUBICSPLINE translation or scale sampler (src/animation.rs:
# Sampler::sample with `Interpolation::CubicSpline` on Cvec3: the Hermite
# weights s0..s3 of `u` and Value::hermite's
# (s0 p0 + s2 p1) + td (s1 b0 + s3 a1)), one component. f32, round to
# nearest even.
#
# `u = U (1 + E)` as in sampler_linear.g (|E| < 1.7882e-7, on paper), and
# `td = t1 - t0` rounded once from the exact interval `TD`. The reference
# is the Hermite sum of the exact basis at `U` with the terms
# T = [p0, b0 TD, p1, a1 TD], as the constant measures it.
#
# Domain: `M`, at least every |T|, in [1/2, 1], and `TD` in [1/2, 1]: the
# values by an exact power-of-two scaling, and the tangents against the
# interval (b0 2^k with td 2^-k leaves td (s1 b0 + s3 a1) and b0 TD as they
# are), both exact wherever nothing underflows or overflows.
#
# Proven: the result is within 2.48e-6 M of the exact sum. The hints
# write each weight's error as its rounding plus the change of the exact
# basis from U to u, a polynomial in U times E (an identity Gappa checks),
# and split U in 16 pieces and M in 4, where interval arithmetic bounds
# U^2 (6 - 6 U) and the rounding of terms of size up to M. Most of the
# bound is the weights' errors: s0 and s2 within 6.04e-7 of the exact
# basis each, which add where p0 = -p1.
#
#! bound SAMPLER_VEC3_MAX_REL_ERROR (c - R) / M in [-2.48e-6, 2.48e-6] a CUBICSPLINE Cvec3 sampler's component against the exact Hermite sum at the exact u, relative to the largest term
@rnd = float<ieee_32, ne>;

p0 = rnd(P0); b0 = rnd(Bz); p1 = rnd(P1); a1 = rnd(Ao); u = rnd(Uc); td = rnd(TD);

uu rnd= u * u;
uuu rnd= uu * u;
s2 rnd= -2 * uuu + 3 * uu;
s3 rnd= uuu - uu;
s0 rnd= 1 - s2;
s1 rnd= s3 - uu + u;
w rnd= s1 * b0 + s3 * a1;
c rnd= (s0 * p0 + s2 * p1) + td * w;

UU = u * u;
UUU = UU * u;
h2 = -2 * UUU + 3 * UU;
h3 = UUU - UU;
h0 = 1 - h2;
h1 = h3 - UU + u;
H2 = -2 * U * U * U + 3 * U * U;
H3 = U * U * U - U * U;
H0 = 1 - H2;
H1 = H3 - U * U + U;
E = (u - U) / U;
B = b0 * TD;
A = a1 * TD;
R = H0 * p0 + H1 * B + H2 * p1 + H3 * A;

{ U in [1b-200, 1] /\ E in [-1.7882e-7, 1.7882e-7] /\ TD in [0.5, 1] /\
  M in [0.5, 1] /\
  p0 / M in [-1, 1] /\ p1 / M in [-1, 1] /\ B / M in [-1, 1] /\ A / M in [-1, 1]
  ->
  (c - R) / M in [-2.48e-6, 2.48e-6]
}
u -> U + U * E;
h2 - H2 -> E * (U * U) * (6 - 6 * U + E * (3 - 6 * U) - 2 * U * E * E);
h3 - H3 -> E * (U * U) * (3 * U - 2 + E * (3 * U - 1) + U * E * E);
h1 - H1 -> E * U * ((1 - U) * (1 - 3 * U) + E * U * (3 * U - 2) + E * E * U * U);
td * w - (H1 * B + H3 * A) -> (td - TD) / TD * (s1 * B + s3 * A) + td * (w - (s1 * b0 + s3 * a1)) + (s1 - H1) * B + (s3 - H3) * A;
(c - R) / M -> (c - ((s0 * p0 + s2 * p1) + td * w)) / M + (s0 - H0) * (p0 / M) + (s2 - H2) * (p1 / M) + (td * w - (H1 * B + H3 * A)) / M;
$ U in 16, M in 4;
