# The sine polynomial of the f32 sine and cosine kernel
# (src/float/sin_cos.rs, sin_poly(r, t) with the tail t = 0, as the kernel
# calls it for |x| <= pi/4): s = r r, then r + (t + r (s (S0 + s (S1 +
# s S2)))). f32, round to nearest even, every operation rounded; the code's
# t + m is left out, since for t = 0 it is m exactly (the correspondence
# test compares the bits with the kernel's).
#
# Sin stands for sin(r). The hypothesis on it is the approximation error
# of the exact polynomial P, which Sollya bounds (sin_poly.sollya:
# 7.9271e-9 relative, over [2^-149, 0.7854], rounded up here to 7.93e-9).
#
# The bound is in ulps of sin(r) rounded to f32, the sweep's unit
# (src/float/sweep.rs), and that ulp depends on the binade sin(r) rounds
# into, which for r just above a power of two 2^k is the one below (sin r
# < r). So each binade [2^k, 2^(k+1)) of r has two goals: where sin r <
# 2^k - 2^(k-25) (it rounds below 2^k: an ulp is 2^(k-24), and the sum
# r + m before the last rounding stays below 2^k, so that rounding is
# half of it), and where sin r >= 2^k - 2^(k-25) (an ulp is 2^(k-23)).
# Gappa proves each binade in a few seconds, but many in one model take
# it minutes, hence one model per three binades.
#
# Domain: every f32 r in [2^-6, 2^-3) (binades 2^-4, 2^-5, 2^-6).
#
# Proven: y within 0.85 ulp of sin(r) there. (The sweep's largest over
# [0, pi/4] is 0.805 ulp.) The other binades down to 2^-9 are in the
# other sin_poly_*.g models; below 2^-9 there is no model (see
# docs/verification-proofs.md).
#
#! sollya sin_poly.sollya 7.93e-9
#! looser SIN_COS_POLY_MAX_ULP (y - Sin) * 1b28 in [-0.85, 0.85] sine polynomial on [2^-6, 2^-3), in ulps (part of the constant's domain)
@rnd = float<ieee_32, ne>;

r = rnd(R);

s rnd= r * r;
p rnd= -0x1.555546p-3 + s * (0x1.11073cp-7 + s * -0x1.9943ep-13);
m rnd= r * (s * p);
y rnd= r + m;

S = r * r;
PP = -0x1.555546p-3 + S * (0x1.11073cp-7 + S * -0x1.9943ep-13);
Q = r * (S * PP);
P = r + Q;

# Sin in [0.0156, 0.7072]: sin is increasing on the domain, sin(2^-6) > 0.015624,
# sin(0.7854) < 0.70711 (stated so that Sin is known to be nonzero where
# the hints divide by it).
{ r in [1b-6, 0.7854] /\ Sin in [0.0156, 0.7072] /\ (P - Sin) / Sin in [-7.93e-9, 7.93e-9]
  ->
  (r in [1b-4, 16777215b-27] /\ Sin <= 33554431b-29 -> (y - Sin) * 1b28 in [-0.85, 0.85]) /\
  (r in [1b-4, 16777215b-27] /\ Sin >= 33554431b-29 -> (y - Sin) * 1b27 in [-0.85, 0.85]) /\
  (r in [1b-5, 16777215b-28] /\ Sin <= 33554431b-30 -> (y - Sin) * 1b29 in [-0.85, 0.85]) /\
  (r in [1b-5, 16777215b-28] /\ Sin >= 33554431b-30 -> (y - Sin) * 1b28 in [-0.85, 0.85]) /\
  (r in [1b-6, 16777215b-29] /\ Sin <= 33554431b-31 -> (y - Sin) * 1b30 in [-0.85, 0.85]) /\
  (r in [1b-6, 16777215b-29] /\ Sin >= 33554431b-31 -> (y - Sin) * 1b29 in [-0.85, 0.85])
}

# The sum before the last rounding, relative to sin(r): the evaluation's
# error (that of m, times m's share m / P of the sum) and the
# approximation error.
r + m - Sin -> Sin * ((r + m - Sin) / Sin);
r + m -> Sin * (1 + (r + m - Sin) / Sin);
(r + m - Sin) / Sin -> (r + m - P) / P + (P - Sin) / Sin + ((r + m - P) / P) * ((P - Sin) / Sin);
(r + m - P) / P -> ((m - Q) / Q) * (Q / P);
Q / P -> (Q / r) / (1 + Q / r);
Q / r -> S * PP;

