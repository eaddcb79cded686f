# slerp's coefficient of b (src/quat/slerp/in_f64.rs, Arc::coefficient,
# c1) before its rounding to f32: from the arc's f64 phi^2 (phi2) and
# phi / sin(phi) (pos) and the f32 alpha, s = (alpha alpha) phi2,
# g = sinc(s) as sinc_f64.g, c = (alpha pos) g. f64, round to nearest
# even, every operation rounded. coefficient_rest_f64.g is the
# coefficient of a, c0.
#
# The exact coefficient is C = sin(alpha Phi) / sin(Phi) = alpha Pos
# sinc(alpha Phi), with Phi2 = Phi^2 and Pos = Phi / sin(Phi) the exact
# values of the arc for its t2, S = alpha^2 Phi2 exactly, and ScS standing
# for sinc(sqrt(S)) = sin(sqrt(S)) / sqrt(S). Hypotheses:
# - the relative errors of phi2 and pos, and pos in [0.4, 2.1]: what
#   arc_f64.g proves (under its domain, t2 up to 1.0001);
# - phi2 in [2^-24, 2.4676]: 2^-24 is where the code takes the evaluation
#   (phi_squared above SMALL_ANGLE_SQUARED_F64); 2.4676 follows from
#   arc_f64.g's domain by a calculation (4 atan(sqrt(1.0001))^2 (1 +
#   3.392e-8) < 2.46756), not by a prover;
# - the approximation error of the exact polynomial GS at S (at most
#   2.4676 (1 + 3.4e-8) < 2.4677, within Sollya's domain), sinc_f64.sollya.
# sinc's polynomial at the computed s against that at S is proven here
# from their divided difference D (Gs - GS = (s - S) D, an identity of
# polynomials), so nothing is assumed of sin's derivative.
#
# Proven: c within 4.09e-8 of C, relative, for every f32 alpha in
# [2^-149, 1], with S split into 8 pieces (`$ S in 8;`): interval
# arithmetic overestimates the change of the polynomial (S D / GS) on wide
# intervals; in one piece Gappa proves 4.74e-8, in 16 pieces 4.05e-8 with
# a certificate twice as long again. The parts add up to about 4.0e-8.
#
#! sollya sinc_f64.sollya 6.0966e-9
#! bound SLERP_COEFFICIENT_F64_MAX_REL_ERROR (c - C) / C in [-4.09e-8, 4.09e-8] relative error of slerp's f64 coefficient of b before its rounding to f32
# The exact values' ranges (properties of the functions, stated so that
# they are known to be nonzero where the hints divide by them): Phi2 is
# within 3.4e-8 of phi2 >= 2^-24; Pos = phi / sin(phi) is in [1, 1.5709]
# for phi up to 2 atan(sqrt(1.0001)); ScS = sin(x) / x is in [2 / pi, 1]
# for x up to pi / 2.
@rnd = float<ieee_64, ne>;
@f32 = float<ieee_32, ne>;

alpha = f32(Al); phi2 = rnd(Ph2); pos = rnd(Po);

r2 rnd= alpha * alpha;
s rnd= r2 * phi2;
q rnd= (-0x1.55554bc836424p-3 + s * 0x1.110ed38056595p-7) + (s * s) * (-0x1.9f6ffeed2e992p-13 + s * 0x1.5dbdf10fb3356p-19);
g rnd= 1 + s * q;
k rnd= alpha * pos;
c rnd= k * g;

S = alpha * alpha * Phi2;
Qs = (-0x1.55554bc836424p-3 + s * 0x1.110ed38056595p-7) + (s * s) * (-0x1.9f6ffeed2e992p-13 + s * 0x1.5dbdf10fb3356p-19);
Gs = 1 + s * Qs;
GS = 1 + S * ((-0x1.55554bc836424p-3 + S * 0x1.110ed38056595p-7) + (S * S) * (-0x1.9f6ffeed2e992p-13 + S * 0x1.5dbdf10fb3356p-19));
D = -0x1.55554bc836424p-3 + 0x1.110ed38056595p-7 * (s + S) + -0x1.9f6ffeed2e992p-13 * (s * s + s * S + S * S) + 0x1.5dbdf10fb3356p-19 * (s * s * s + s * s * S + s * S * S + S * S * S);
C = alpha * Pos * ScS;
es = (s - S) / S;
eg = (g - Gs) / Gs;
ev = (Gs - GS) / GS;
ea = (GS - ScS) / ScS;
ep = (pos - Pos) / Pos;

{ alpha in [1b-149, 1] /\ phi2 in [1b-24, 2.4676] /\ pos in [0.4, 2.1] /\
  (phi2 - Phi2) / Phi2 in [-3.392e-8, 3.392e-8] /\
  (pos - Pos) / Pos in [-1.696e-8, 1.696e-8] /\
  (GS - ScS) / ScS in [-6.0966e-9, 6.0966e-9] /\
  Phi2 in [1b-25, 2.4677] /\ Pos in [1, 1.571] /\ ScS in [0.63, 1]
  ->
  (c - C) / C in [-4.09e-8, 4.09e-8]
}

es -> ((s - r2 * phi2) / (r2 * phi2) + 1) * ((r2 - alpha * alpha) / (alpha * alpha) + 1) * ((phi2 - Phi2) / Phi2 + 1) - 1;
eg -> ((g - (1 + s * q)) + s * (q - Qs)) / Gs;
Phi2 -> phi2 / ((phi2 - Phi2) / Phi2 + 1);
Gs - GS -> (s - S) * D;
ev -> es * (S * D / GS);
(c - C) / C -> ((c - k * g) / (k * g) + 1) * ((k - alpha * pos) / (alpha * pos) + 1) * (ep + 1) * (eg + 1) * (ev + 1) * (ea + 1) - 1;
$ S in 8;
