# The arctangent polynomial of the f32 atan2 kernel (src/float/atan2.rs,
# atan_poly(u)) for the smallest u: the computation, the hypotheses and
# the hints of atan_poly.g (see there), on the rest of its domain.
#
# Domain: every f32 u in [2^-149, 2^-40], subnormals included. There the
# result is u to the last bit (u (s p) is below 2^-81 u, far under half an
# ulp of u; below 2^-75, s = u u rounds to 0); Gappa needs no argument for
# it beyond the split of u at the smallest normal 2^-126 and at 2^-60.
#
# Proven: |y - atan(u)| <= 8.8e-8 atan(u) over the domain.
#
#! sollya atan_poly.sollya 2.461e-9
#! law - (y - At) / At in [-8.8e-8, 8.8e-8] the arctangent polynomial relative to atan(u), every f32 u in [2^-149, 2^-40]
@rnd = float<ieee_32, ne>;

u = rnd(U);

s rnd= u * u;
s2 rnd= s * s;
p rnd= (-0x1.55554ap-2 + s * 0x1.9993e2p-3) + s2 * ((-0x1.241192p-3 + s * 0x1.bc822ep-4) + s2 * (-0x1.39b8b4p-4 + s * 0x1.19308cp-5));
m rnd= u * (s * p);
y rnd= u + m;

S = u * u;
S2 = S * S;
PP = (-0x1.55554ap-2 + S * 0x1.9993e2p-3) + S2 * ((-0x1.241192p-3 + S * 0x1.bc822ep-4) + S2 * (-0x1.39b8b4p-4 + S * 0x1.19308cp-5));
Q = u * (S * PP);
P = u + Q;
z = u + m;
At = u * Wa;

{ u in [1b-149, 1b-40] /\ Wa in [0.915, 1]
  /\ (P - At) / At in [-2.461e-9, 2.461e-9]
  ->
  (y - At) / At in [-8.8e-8, 8.8e-8]
}

# The last rounding relative to its sum z; z relative to atan(u) through
# its parts over u: the evaluation of m (relative to Q, times Q / u) and
# the approximation error (relative to atan(u), times atan(u) / u).
(y - At) / At -> ((y - z) / z) * (1 + (z - At) / At) + (z - At) / At;
(z - At) / At -> ((z - At) / u) / Wa;
(z - At) / u -> ((m - Q) / Q) * (S * PP) + ((P - At) / At) * Wa;
$ u in (1b-126, 1b-60);
