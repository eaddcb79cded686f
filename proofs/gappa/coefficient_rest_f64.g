# slerp's coefficient of a (src/quat/slerp/in_f64.rs, Arc::coefficient,
# c0) before its rounding to f32: coefficient_f64.g with the share
# rest = 1 - alpha (rounded in f64: exact unless alpha is below about
# 2^-29) in place of alpha. Its hypotheses are coefficient_f64.g's, with
# Rest = 1 - alpha exactly and C = sin(Rest Phi) / sin(Phi).
#
# Proven: c within 4.09e-8 of C, relative, for every f32 alpha in
# [2^-149, 1 - 2^-24] (for alpha = 1, rest and c are exactly 0).
#
#! sollya sinc_f64.sollya 6.0966e-9
#! bound SLERP_COEFFICIENT_F64_MAX_REL_ERROR (c - C) / C in [-4.09e-8, 4.09e-8] relative error of slerp's f64 coefficient of a before its rounding to f32
# The exact values' ranges (properties of the functions, stated so that
# they are known to be nonzero where the hints divide by them): Phi2 is
# within 3.4e-8 of phi2 >= 2^-24; Pos = phi / sin(phi) is in [1, 1.5709]
# for phi up to 2 atan(sqrt(1.0001)); ScS = sin(x) / x is in [2 / pi, 1]
# for x up to pi / 2.
# The side conditions' factorizations (`#! side`, used only by the model of
# the side conditions, without the hints above): Gappa prints the
# denominators it assumed nonzero expanded in alpha, where interval
# arithmetic loses that (1 - alpha)^2 Phi2 and (1 - alpha) Pos ScS are
# positive and that the last is 2^70 GS. Gappa checks each as a polynomial
# identity, assuming nothing nonzero.
#! side (Phi2) - 2 * (alpha) * (Phi2) + ((alpha) * (alpha)) * (Phi2) -> (1 - alpha) * (1 - alpha) * Phi2;
#! side -(alpha) * (Pos) * (ScS) + (Pos) * (ScS) -> (1 - alpha) * Pos * ScS;
#! side 1403223072318631296 * ((alpha) * (alpha) * (alpha) * (alpha) * (alpha)) * ((Phi2) * (Phi2) * (Phi2)) - 172276317360332136 * ((alpha) * (alpha) * (alpha) * (alpha) * (alpha)) * ((Phi2) * (Phi2) * (Phi2) * (Phi2)) - 233870512053105216 * ((alpha) * (alpha) * (alpha) * (alpha) * (alpha) * (alpha)) * ((Phi2) * (Phi2) * (Phi2)) + 86138158680166068 * ((alpha) * (alpha) * (alpha) * (alpha) * (alpha) * (alpha)) * ((Phi2) * (Phi2) * (Phi2) * (Phi2)) - 24610902480047448 * ((alpha) * (alpha) * (alpha) * (alpha) * (alpha) * (alpha) * (alpha)) * ((Phi2) * (Phi2) * (Phi2) * (Phi2)) + 3076362810005931 * ((alpha) * (alpha) * (alpha) * (alpha) * (alpha) * (alpha) * (alpha) * (alpha)) * ((Phi2) * (Phi2) * (Phi2) * (Phi2)) + 393530372211674972160 * (alpha) * (Phi2) - 39351792740372488192 * (alpha) * ((Phi2) * (Phi2)) + 1403223072318631296 * (alpha) * ((Phi2) * (Phi2) * (Phi2)) + 1180591620717411303424 - 24610902480047448 * (alpha) * ((Phi2) * (Phi2) * (Phi2) * (Phi2)) - 196765186105837486080 * ((alpha) * (alpha)) * (Phi2) + 59027689110558732288 * ((alpha) * (alpha)) * ((Phi2) * (Phi2)) - 3508057680796578240 * ((alpha) * (alpha)) * ((Phi2) * (Phi2) * (Phi2)) + 86138158680166068 * ((alpha) * (alpha)) * ((Phi2) * (Phi2) * (Phi2) * (Phi2)) - 39351792740372488192 * ((alpha) * (alpha) * (alpha)) * ((Phi2) * (Phi2)) + 4677410241062104320 * ((alpha) * (alpha) * (alpha)) * ((Phi2) * (Phi2) * (Phi2)) - 172276317360332136 * ((alpha) * (alpha) * (alpha)) * ((Phi2) * (Phi2) * (Phi2) * (Phi2)) - 196765186105837486080 * (Phi2) + 9837948185093122048 * ((alpha) * (alpha) * (alpha) * (alpha)) * ((Phi2) * (Phi2)) + 9837948185093122048 * ((Phi2) * (Phi2)) - 233870512053105216 * ((Phi2) * (Phi2) * (Phi2)) - 3508057680796578240 * ((alpha) * (alpha) * (alpha) * (alpha)) * ((Phi2) * (Phi2) * (Phi2)) + 215345396700415170 * ((alpha) * (alpha) * (alpha) * (alpha)) * ((Phi2) * (Phi2) * (Phi2) * (Phi2)) + 3076362810005931 * ((Phi2) * (Phi2) * (Phi2) * (Phi2)) -> 1180591620717411303424 * GS;
@rnd = float<ieee_64, ne>;
@f32 = float<ieee_32, ne>;

alpha = f32(Al); phi2 = rnd(Ph2); pos = rnd(Po);

rest rnd= 1 - alpha;
r2 rnd= rest * rest;
s rnd= r2 * phi2;
q rnd= (-0x1.55554bc836424p-3 + s * 0x1.110ed38056595p-7) + (s * s) * (-0x1.9f6ffeed2e992p-13 + s * 0x1.5dbdf10fb3356p-19);
g rnd= 1 + s * q;
k rnd= rest * pos;
c rnd= k * g;

Rest = 1 - alpha;
S = Rest * Rest * Phi2;
Qs = (-0x1.55554bc836424p-3 + s * 0x1.110ed38056595p-7) + (s * s) * (-0x1.9f6ffeed2e992p-13 + s * 0x1.5dbdf10fb3356p-19);
Gs = 1 + s * Qs;
GS = 1 + S * ((-0x1.55554bc836424p-3 + S * 0x1.110ed38056595p-7) + (S * S) * (-0x1.9f6ffeed2e992p-13 + S * 0x1.5dbdf10fb3356p-19));
D = -0x1.55554bc836424p-3 + 0x1.110ed38056595p-7 * (s + S) + -0x1.9f6ffeed2e992p-13 * (s * s + s * S + S * S) + 0x1.5dbdf10fb3356p-19 * (s * s * s + s * s * S + s * S * S + S * S * S);
C = Rest * Pos * ScS;
es = (s - S) / S;
eg = (g - Gs) / Gs;
ev = (Gs - GS) / GS;
ea = (GS - ScS) / ScS;
ep = (pos - Pos) / Pos;
er = (rest - Rest) / Rest;

{ alpha in [1b-149, 0xffffffp-24] /\ phi2 in [1b-24, 2.4676] /\ pos in [0.4, 2.1] /\
  (phi2 - Phi2) / Phi2 in [-3.392e-8, 3.392e-8] /\
  (pos - Pos) / Pos in [-1.696e-8, 1.696e-8] /\
  (GS - ScS) / ScS in [-6.0966e-9, 6.0966e-9] /\
  Phi2 in [1b-25, 2.4677] /\ Pos in [1, 1.571] /\ ScS in [0.63, 1]
  ->
  (c - C) / C in [-4.09e-8, 4.09e-8]
}

es -> ((s - r2 * phi2) / (r2 * phi2) + 1) * ((r2 - rest * rest) / (rest * rest) + 1) * (er + 1) * (er + 1) * ((phi2 - Phi2) / Phi2 + 1) - 1;
eg -> ((g - (1 + s * q)) + s * (q - Qs)) / Gs;
Phi2 -> phi2 / ((phi2 - Phi2) / Phi2 + 1);
Gs - GS -> (s - S) * D;
ev -> es * (S * D / GS);
(c - C) / C -> ((c - k * g) / (k * g) + 1) * ((k - rest * pos) / (rest * pos) + 1) * (er + 1) * (ep + 1) * (eg + 1) * (ev + 1) * (ea + 1) - 1;
$ S in 8;
