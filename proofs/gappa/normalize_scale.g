# The rescaled branches of scale_for_squares (src/float/norm.rs), which
# then run the computation of normalize.g on the scaled components.
# f32, round to nearest even, subnormals included.
#
# Small branch: the sum of squares is below 2^-100, so every component is
# below 2^-50 in magnitude; times 2^100 it is exact (subnormals included).
# Huge branch: the sum overflowed, so some component is at least 2^63;
# times 2^-66 every component is within 2^-150 of its exact scaled value
# (only those below 2^-60 round, into subnormals; the rest are exact),
# at most 2^-147 of the
# largest scaled component (at least 2^-3).
#
#! law - up - v * 0x1p100 in [0, 0] scaling up by 2^100 is exact
#! law - down - v * 0x1p-66 in [-1b-150, 1b-150] scaling down by 2^-66 errs by at most 2^-150
@rnd = float<ieee_32, ne>;

v = rnd(V);
up rnd= v * 0x1p100;
down rnd= v * 0x1p-66;

{ (|v| <= 1b-50 -> up - v * 0x1p100 in [0, 0]) /\
  (|v| <= 1b-60 -> down - v * 0x1p-66 in [-1b-150, 1b-150]) /\
  (|v| in [1b-60, 0x1.fffffep127] -> down - v * 0x1p-66 in [0, 0]) }
