# The arc of slerp's f64 evaluation (src/quat/slerp/in_f64.rs, Arc::from_quotient)
# from the quotient t2 = tan^2(phi / 2) that arc_quotient_f64.g computes:
# h = 1 + t2 p(t2) with p the degree-7 polynomial of ATAN
# (src/quat/slerp/in_f64.rs) by Estrin's scheme as atan_polynomial
# writes it; phi^2 = (4 t2) (h h) and phi / sin(phi) = h (1 + t2). f64,
# round to nearest even, every operation rounded. (The quotient's lines are
# a model of their own: here, every term of the certificate would repeat
# the whole chain from the f32 inputs, and Coq would take five times as
# long to check it.)
#
# At stands for atan(sqrt(t2)) / sqrt(t2) of the f64 t2 the code computes;
# the exact results for that t2 are phi^2 = 4 t2 At^2 (Phi2) and
# phi / sin(phi) = At (1 + t2) (Pos), as phi = 2 atan(sqrt(t2)) and
# sin(phi) = 2 sqrt(t2) / (1 + t2). The hypothesis on At is the
# approximation error of the exact polynomial H, which Sollya bounds
# (atan_f64.sollya: 1.69581e-8 over sqrt(t2) in [0, 1.00005], rounded up
# here to 1.6959e-8).
#
# Domain, a hypothesis on the t2 the code computes: t2 in [2^-170, 1.0001],
# wider than the code needs. Its upper end follows from the code: t2 is
# |a - cn(b)|^2 over |a + cn(b)|^2, below 1 where the evaluation applies. Below its
# lower end the code computes arcs too (t2 down to 0) but never uses them:
# slerp takes the result only where phi^2 is above 2^-24, where t2 is
# above 2^-27 (in_f64/tests.rs's arc_quotient_stays_within_the_models_domain
# tests both ends on random, right-angled and nearly identical unit
# pairs). The error of t2 against the inputs' exact tan^2(phi / 2) is the
# inputs' error, not part of the bounds.
#
# Proven: phi^2 within 3.392e-8 and phi / sin(phi) within 1.696e-8 of
# their exact values for the computed t2, relative; phi / sin(phi) in
# [0.4, 2.1] (coefficient_f64.g's hypotheses).
#
#! sollya atan_f64.sollya 1.6959e-8
#! bound PHI_SQUARED_F64_MAX_REL_ERROR (phi2 - Phi2) / Phi2 in [-3.392e-8, 3.392e-8] relative error of the arc's phi^2 for its t2
#! bound PHI_OVER_SINE_F64_MAX_REL_ERROR (pos - Pos) / Pos in [-1.696e-8, 1.696e-8] relative error of the arc's phi / sin(phi) for its t2
@rnd = float<ieee_64, ne>;

t2 = rnd(T2);

z2 rnd= t2 * t2;
z4 rnd= z2 * z2;
low rnd= (-0x1.5554dc2343771p-2 + t2 * 0x1.9978f3b40f785p-3) + z2 * (-0x1.230adc19a37efp-3 + t2 * 0x1.b4e12e9505e18p-4);
high rnd= (-0x1.3556be4cac7f9p-4 + t2 * 0x1.61fded6d4e340p-5) + z2 * (-0x1.0c2c2c26f5424p-6 + t2 * 0x1.7ed26148ac171p-9);
p rnd= low + z4 * high;
h rnd= 1 + t2 * p;
hh rnd= h * h;
phi2 rnd= (4 * t2) * hh;
pos rnd= h * (1 + t2);

P = ((-0x1.5554dc2343771p-2 + t2 * 0x1.9978f3b40f785p-3) + (t2 * t2) * (-0x1.230adc19a37efp-3 + t2 * 0x1.b4e12e9505e18p-4)) + ((t2 * t2) * (t2 * t2)) * ((-0x1.3556be4cac7f9p-4 + t2 * 0x1.61fded6d4e340p-5) + (t2 * t2) * (-0x1.0c2c2c26f5424p-6 + t2 * 0x1.7ed26148ac171p-9));
H = 1 + t2 * P;
Phi2 = 4 * t2 * (At * At);
Pos = At * (1 + t2);
E = (H - At) / At;
eh = (h - H) / H;

# At in [0.785, 1]: atan(x) / x falls from 1 at 0 to 0.78537 at
# x = sqrt(1.0001) (a property of the arctangent, stated so that At is
# known to be nonzero where the hints divide by it).
{ t2 in [1b-170, 1.0001] /\ At in [0.785, 1] /\ (H - At) / At in [-1.6959e-8, 1.6959e-8]
  ->
  (phi2 - Phi2) / Phi2 in [-3.392e-8, 3.392e-8] /\
  (pos - Pos) / Pos in [-1.696e-8, 1.696e-8] /\
  pos in [0.4, 2.1]
}

(h - H) / H -> ((h - (1 + t2 * p)) + t2 * (p - P)) / H;
(phi2 - Phi2) / Phi2 -> ((phi2 - (4 * t2) * hh) / ((4 * t2) * hh) + 1) * ((hh - h * h) / (h * h) + 1) * (eh + 1) * (eh + 1) * (E + 1) * (E + 1) - 1;
(pos - Pos) / Pos -> ((pos - h * (1 + t2)) / (h * (1 + t2)) + 1) * (eh + 1) * (E + 1) - 1;
