# slerp's f32 evaluation at alpha = 1 (src/quat/slerp/in_f32.rs,
# slerp_in_plane, the branch phi > 2^-12 with the endpoint factor taken as
# 1): far = 1 * phi = phi and near = phi - far = 0 exactly, so that sin3
# gives s0 = sin_poly(0) = 0 and sin(far) and sin(phi) the same f32 s;
# r = 1 / sin(phi), the coefficients s0 * r and s * r, and the result
# weighted_sum: q = c0 a + c1 b component by component (0 to 3
# are w, x, y, z), each product rounded,
# then their sum. b is cn(other), exactly other or -other. f32, round to
# nearest even.
#
# Domain: s in [2^-13, 1], which holds for every phi in (2^-12, pi/2]
# given the sine kernel within 1.05e-7 of sin(phi), relative (the
# hypothesis of proofs/coq/slerp_endpoint_norm_f32.v, that the sin_poly and
# cos_poly models bound): sin(2^-12) (1 - 1.05e-7) > 2^-13, and no f32
# lies in (1, 1 + 1.05e-7].
#
# Proven here: c0 = 0 and c1 within [1 - 2^-24, 1]: r is 1 / s within
# 2^-24, relative, so s r lies in [1 - 2^-24, 1 + 2^-24], which rounds to
# 1 - 2^-24 or to 1 (1 + 2^-24 is a tie, to the even 1). The law
# proofs/coq/slerp_endpoint_norm_f32.v carries the components' roundings
# to the norm of the result.
@rnd = float<ieee_32, ne>;

s0 = rnd(S0); s = rnd(S);
a0 = rnd(A0); a1 = rnd(A1); a2 = rnd(A2); a3 = rnd(A3);
b0 = rnd(B0); b1 = rnd(B1); b2 = rnd(B2); b3 = rnd(B3);

r rnd= 1 / s;
c0 rnd= s0 * r;
c1 rnd= s * r;
q0 rnd= c0 * a0 + c1 * b0;
q1 rnd= c0 * a1 + c1 * b1;
q2 rnd= c0 * a2 + c1 * b2;
q3 rnd= c0 * a3 + c1 * b3;

{ s0 in [0, 0] /\ s in [0x1p-13, 1]
  ->
  c0 in [0, 0] /\ c1 - 1 in [-0x1p-24, 0]
}

# The rounding of s r, and r's relative error.
c1 - 1 -> (s * r - 1) + (c1 - s * r);
s * r - 1 -> (r - 1 / s) / (1 / s);
