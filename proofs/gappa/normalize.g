# normalize / try_normalize (src/quat.rs) through scale_for_squares and
# ScaledSquares::unit (src/float/norm.rs), the branch without rescaling:
# s = a a + b b + c c + d d left to right, n = sqrt(s), each component / n;
# a, b, c, d are x, y, z, w, the order of Quat::to_array that the code sums.
# f32, round to nearest even.
#
# Domain: the four components scaled by an exact power of four so that
# their exact sum of squares S lies in [1, 4]. The code's arithmetic
# commutes with that scaling wherever no square underflows or overflows,
# which holds in this branch (s in [2^-100, f32::MAX]) up to squares below
# 2^-126, whose absolute error 2^-150 is at most 2^-50 of s. The rescaled
# branches (normalize_scale.g) multiply by 2^100 exactly or by 2^-66 within
# 2^-150, and then run this same computation.
#
# Proven here: n within 0x1.81p-23 (1.7941e-7) of N = sqrt(S), relative,
# given that the rounded squares sum to within 2^-24 + 2^-48 of S,
# relative. That hypothesis, and the last step to the norm of the result,
# are proven in Coq by proofs/coq/normalize_norm.v: each square's rounding
# is within 2^-24 of it, relative (plus 2^-150), so their errors, weighted
# by the squares, average to at most 2^-24; each quotient's rounding is
# relative too, so the result's length is within 2^-24 of N / n.
#
# Gappa splits S where the binade of the sum (or of a partial sum) changes,
# and bounds each addition's rounding by the half ulp of its binade.
@rnd = float<ieee_32, ne>;

a = rnd(A); b = rnd(B); c = rnd(C); d = rnd(D);

s rnd= a * a + b * b + c * c + d * d;
n rnd= sqrt(s);
ca rnd= a / n; cb rnd= b / n; cc rnd= c / n; cd rnd= d / n;

sa = rnd(a * a); sb = rnd(b * b); sc = rnd(c * c); sd = rnd(d * d);
S = a * a + b * b + c * c + d * d;
N = sqrt(S);
T = sa + sb + sc + sd;

{ S in [1, 4] /\
  sa in [0, 4] /\ sb in [0, 4] /\ sc in [0, 4] /\ sd in [0, 4] /\
  (T - S) / S in [-0x1.000001p-24, 0x1.000001p-24]
  ->
  (n - N) / N in [-0x1.81p-23, 0x1.81p-23]
}

# The partial sums of the rounded squares are at most their sum T, and T is
# S up to the relative error the hypothesis bounds.
sa + sb -> T - (sc + sd);
sa + sb + sc -> T - sd;
T -> S + (T - S) / S * S;
(s - S) / S -> (s - T) / S + (T - S) / S;
# The side conditions' sum of squares (`#! side`, used only by the model of
# the side conditions, which has no other hint) is S.
#! side b * b + a * a + d * d + c * c -> S;
# Split the sum of squares where its binade, or that of a partial sum, changes.
$ S in (1.0001, 1.5, 1.999, 2, 2.001, 3, 3.99);
