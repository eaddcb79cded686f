# normalize / try_normalize (src/quat.rs) through scale_for_squares and
# ScaledSquares::unit (src/float/norm.rs), the branch without rescaling:
# s = a a + b b + c c + d d left to right, n = sqrt(s), each component / n;
# a, b, c, d are x, y, z, w, the order of Quat::to_array that the code sums.
# f32, round to nearest even.
#
# Domain: the four components scaled by an exact power of four so that
# their exact sum of squares S lies in [1, 4] (every component then in
# [-2, 2]). The code's arithmetic commutes with that scaling wherever no
# square underflows or overflows, which holds in this branch (s in
# [2^-100, f32::MAX]) up to squares below 2^-126, whose absolute error
# 2^-150 is at most 2^-50 of s. The rescaled branches (normalize_scale.g)
# multiply by 2^100 exactly or by 2^-66 within 2^-150, and then run this
# same computation.
#
# Proven: s within 7 2^-24 (4.17e-7) of S (relative), n within 2.69e-7
# of N = sqrt(S) (relative), each quotient within 2^-24 of a / n, and the
# length of the quotients' error vector plus |N / n - 1| at most 3.88e-7.
# The exact quotients (a, b, c, d) / n have norm N / n, so by the triangle
# inequality the result's norm is within 3.88e-7 of 1.
#
# Gappa splits S at 1.5, 2 and 3: within each piece it bounds the rounding
# of every square and partial sum (each at most S) by the half ulp of
# that piece's binade, where over all of [1, 4] it takes the largest.
# What stays above the measured maximum (1.77e-7): interval arithmetic
# bounds each component's rounding separately, 2^-24 each and 2^-23 for
# the error vector, where the relative errors of the quotients, weighted
# by their squares, average to at most 2^-24; and the sum of squares'
# 7 2^-24 takes every square and partial sum at its largest together.
#
#! looser NORMALIZE_MAX_NORM_ERROR Deviation in [0, 3.88e-7] |normalize(q)| - 1 (error vector of the quotients plus |N/n - 1|; triangle inequality)
@rnd = float<ieee_32, ne>;

a = rnd(A); b = rnd(B); c = rnd(C); d = rnd(D);

s rnd= a * a + b * b + c * c + d * d;
n rnd= sqrt(s);
ca rnd= a / n; cb rnd= b / n; cc rnd= c / n; cd rnd= d / n;

S = a * a + b * b + c * c + d * d;
N = sqrt(S);
Deviation = sqrt((ca - a / n) * (ca - a / n) + (cb - b / n) * (cb - b / n) +
       (cc - c / n) * (cc - c / n) + (cd - d / n) * (cd - d / n))
    + |N / n - 1|;

{ S in [1, 4] /\ |a| <= 2 /\ |b| <= 2 /\ |c| <= 2 /\ |d| <= 2
  ->
  (s - S) / S in [-7b-24, 7b-24] /\
  (n - N) / N in [-2.69e-7, 2.69e-7] /\
  ca - a / n in [-1b-24, 1b-24] /\
  Deviation in [0, 3.88e-7]
}

# The partial sums of squares are at most S.
a * a + b * b -> S - (c * c + d * d);
a * a + b * b + c * c -> S - d * d;
N / n - 1 -> -((n - N) / N) / (1 + (n - N) / N);
# Split the sum of squares where its binade, or that of a square, changes.
$ S in (1.5, 2, 3);
