# A LINEAR translation or scale sampler (src/animation.rs: Sampler::sample
# with `Interpolation::Linear` on Cvec3, which is Cvec3::lerp,
# a (1 - u) + b u), one component. f32, round to nearest even.
#
# The segment's `u` is the code's `(t - t0) / (t1 - t0)`, three roundings
# of the f32 times: each is relative (a difference of two f32 that is
# subnormal is exact), so `u = U (1 + E)` with `U` the exact quotient of
# the same times and |E| <= (1 + e)^2 / (1 - e) - 1 < 1.7882e-7, e =
# 2^-24 / (1 + 2^-24) (on paper: the model takes it as a hypothesis, for
# `t - t0` at least 2^-126, which keeps the quotient normal).
#
# Domain: `M`, the largest magnitude among the segment's values (of every
# component, as the constant measures; here any `M` at least |a| and |b|),
# taken in [1/2, 1] by an exact power-of-two scaling of the values (which
# commutes with the arithmetic wherever nothing underflows or overflows).
#
# Proven: the result is within 5.12e-7 M of the exact a (1 - U) + b U.
#
#! bound SAMPLER_VEC3_MAX_REL_ERROR (r - R) / M in [-5.12e-7, 5.12e-7] a LINEAR Cvec3 sampler's component against the exact interpolation at the exact u, relative to the largest value
@rnd = float<ieee_32, ne>;

a = rnd(A); b = rnd(B); u = rnd(Uc);

v rnd= 1 - u;
r rnd= a * v + b * u;

R = a * (1 - U) + b * U;
E = (u - U) / U;

{ U in [1b-200, 1] /\ E in [-1.7882e-7, 1.7882e-7] /\ M in [0.5, 1] /\
  a / M in [-1, 1] /\ b / M in [-1, 1]
  ->
  (r - R) / M in [-5.12e-7, 5.12e-7]
}
u -> U + U * E;
(r - R) / M -> (r - (a * v + b * u)) / M + (a * (v - (1 - u))) / M + (b / M - a / M) * (U * E);
$ M in 4, U in 4;
