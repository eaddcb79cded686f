# The square root kernel (src/float/sqrt.rs): one correctly rounded f32
# square root (sqrtss, vsqrt.f32, fsqrt or libm's sqrtf, each correctly
# rounded as IEEE 754 requires). f32, round to nearest even.
#
# Proven: for every positive f32 input, subnormal to f32::MAX, the result
# is within 2^-24 (5.9605e-8) of the exact root, relative.
#
#! bound SQRT_MAX_REL_ERROR (r - sqrt(x)) / sqrt(x) in [-1b-24, 1b-24] relative error of sqrt
@rnd = float<ieee_32, ne>;

x = rnd(X);
r = rnd(sqrt(x));

{ x in [1b-149, 0x1.fffffep127] -> (r - sqrt(x)) / sqrt(x) in [-1b-24, 1b-24] }
