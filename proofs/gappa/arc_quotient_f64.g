# The quotient of slerp's f64 arc (src/quat/slerp/in_f64.rs, Pair::arc):
# from the f32 squared norms n2 and on2, the f32 |a . b| (dot) and the f32
# squared wedge, t2 = wedge / (m + dot)^2 with m = (n2 + on2) / 2, the
# tangent of the half angle squared, which arc_f64.g takes on. f64, round
# to nearest even, every operation rounded.
#
# Domain: what the code hands it where the evaluation applies (squared
# norms at most 2^32, wedge at least 2^-100), with the squared norms above
# 2^-60 (the wedge is at most their product, up to rounding).
#
# Proven: t2 within 6.67e-16 of the exact quotient of the same f32 values,
# relative. Its error against the inputs' exact tan^2(phi / 2), from the
# f32 rounding of the norms, the dot product and the wedge, is not bounded
# here (see arc_f64.g).
#
#! law - 6.67e-16 relative rounding error of the arc's quotient t2 for its f32 inputs
@rnd = float<ieee_64, ne>;
@f32 = float<ieee_32, ne>;

n2 = f32(N2); on2 = f32(On2); dot = f32(Dot); wedge = f32(W);

m rnd= 0.5 * (n2 + on2);
d rnd= m + dot;
dd rnd= d * d;
t2 rnd= wedge / dd;

M = 0.5 * (n2 + on2);
T = wedge / ((M + dot) * (M + dot));

{ n2 in [1b-60, 1b32] /\ on2 in [1b-60, 1b32] /\ dot in [0, 1b32] /\ wedge in [1b-100, 1b66]
  ->
  (t2 - T) / T in [-6.67e-16, 6.67e-16]
}
