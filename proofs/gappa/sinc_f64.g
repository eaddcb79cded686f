# The sin(x) / x of slerp's f64 evaluation (src/quat/slerp/in_f64.rs,
# sinc(s) for s = x^2, x = share phi): q = (S0 + s S1) + (s s) (S2 + s S3),
# g = 1 + s q, with the coefficients of SIN (src/quat/slerp/in_f64.rs).
# f64, round to nearest even, every operation rounded.
#
# Sc stands for sin(sqrt(s)) / sqrt(s) of the f64 s the code is given. The
# hypothesis on it is the approximation error of the exact polynomial G,
# which Sollya's supnorm bounds (sinc_f64.sollya: 6.09654e-9 over x in
# [0, 1.5709], rounded up here to 6.0966e-9).
#
# Domain: every f64 s in [0, 2.4676]: x from 0 to pi/2 and a little
# beyond. The code's s is at most its phi^2 (the share is at most 1), for
# which arc_f64.g's domain gives 4 atan(sqrt(1.0001))^2 (1 + 3.392e-8) <
# 2.46756 (a calculation, not part of the proof).
#
# Proven: the evaluation within 2.7e-16 of the exact polynomial, and the
# result within 6.0967e-9 of sin(x) / x, relative. The error of s itself
# (the f64 product of the share squared and phi^2) is the input's.
#
#! sollya sinc_f64.sollya 6.0966e-9
#! bound SINC_F64_MAX_REL_ERROR (g - Sc) / Sc in [-6.0967e-9, 6.0967e-9] relative error of sinc(s) against sin(x) / x, s = x^2
@rnd = float<ieee_64, ne>;

s = rnd(Sq);

q rnd= (-0x1.55554bc836424p-3 + s * 0x1.110ed38056595p-7) + (s * s) * (-0x1.9f6ffeed2e992p-13 + s * 0x1.5dbdf10fb3356p-19);
g rnd= 1 + s * q;

Q = (-0x1.55554bc836424p-3 + s * 0x1.110ed38056595p-7) + (s * s) * (-0x1.9f6ffeed2e992p-13 + s * 0x1.5dbdf10fb3356p-19);
G = 1 + s * Q;

# Sc in [0.63, 1]: sin(x) / x falls from 1 at 0 to 2 / pi = 0.6366 at
# pi / 2 (a property of the sine, stated so that Sc is known to be nonzero
# where the hints divide by it).
{ s in [0, 2.4676] /\ Sc in [0.63, 1] /\ (G - Sc) / Sc in [-6.0966e-9, 6.0966e-9]
  ->
  (g - G) / G in [-2.7e-16, 2.7e-16] /\
  (g - Sc) / Sc in [-6.0967e-9, 6.0967e-9]
}

(g - Sc) / Sc -> (g - G) / G + (G - Sc) / Sc + ((g - G) / G) * ((G - Sc) / Sc);
(g - G) / G -> ((g - (1 + s * q)) + s * (q - Q)) / G;
