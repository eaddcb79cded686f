# The quotient of slerp's f64 arc (src/quat/slerp/in_f64.rs, Arc::from_quotient,
# Arc::from_lengths): t2 = near / far, with near = |a - cn(b)|^2 and
# far = |a + cn(b)|^2 (the tangent of the half angle squared), which
# arc_f64.g takes on. f64, round to nearest even.
#
# Domain: what the code hands it where slerp takes the result. Both are
# |a|^2 + |b|^2 -+ 2 |a . b| in f64 from f32 components (squared norms at
# most 2^32, so each at most 2^34); near is above 2^-26 of far there
# (phi^2 above 2^-24; the hypothesis takes 2^-27), and far at least
# 2^-298 (a sum of squares of f32 values that is not zero).
#
# Proven: t2 within 1.12e-16 (just above 2^-53) of the exact quotient of
# the same f64 values, relative. The rounding of near and far themselves (each product
# of two f32 exact in f64, the sums rounded; near cancels as the angle
# shrinks) is not bounded here; Pair::near's doc gives it as measured,
# 8.5e-9 of near at most where slerp uses it.
#
#! law - (t2 - T) / T in [-1.12e-16, 1.12e-16] relative rounding error of the arc's quotient t2 for its f64 inputs
@rnd = float<ieee_64, ne>;

near = rnd(Near); far = rnd(Far);

t2 rnd= near / far;

T = near / far;

{ near in [1b-323, 1b35] /\ far in [1b-298, 1b35] /\ near / far in [1b-27, 1]
  ->
  (t2 - T) / T in [-1.12e-16, 1.12e-16]
}
