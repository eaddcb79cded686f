# The atan2 kernel's outer branches (src/float/atan2.rs, atan2_kernel and
# angle_of_quotient), with a = |x|, b = |y|: the lower branch (b <= a
# tan(1/2)) u = b / a, phi = 0 + (atan_poly(u) + 0), and the upper one
# (a <= b tan(1/2)) u = -a / b, phi = PIO2_HI + (atan_poly(u) + PIO2_LO);
# for a negative x, PI_HI - (phi - PI_LO). f32, round to nearest even,
# every operation rounded, in the code's order. The absolute error of each
# result against the exact angle of the exact arguments: atan(b / a),
# pi/2 - atan(a / b), and pi minus these for a negative x. The sign of y
# is copied exactly, so these bound every sign.
#
# Inputs: the quotient u = rnd(R), R the exact ratio b / a (lower) or
# -a / b (upper), one correctly rounded division; and y, the polynomial's
# result atan_poly(u), an f32 in the model.
#
# Domain: R in [2^-149, 0x1.17b4f8p-1] (lower) and its negative (upper):
# the branch's test, on arguments scaled exactly where it matters (the
# code's comment), rounds its product by TAN_HALF once, so the exact ratio
# is at most TAN_HALF (1 + 2^-24) < 0x1.17b4f8p-1. Below 2^-149 in
# magnitude (argued here; a zero or infinite argument, after the code's
# substitutions, gives such a ratio) |u| is 0 or 2^-149 and atan_poly(u)
# = u: in the lower branch the result is within 2^-149 of atan(R), or,
# for a negative x, PI_HI - (u - PI_LO) rounds to PI_HI, within 8.8e-8 of
# pi; in the upper one PIO2_HI + (u + PIO2_LO) rounds to PIO2_HI, within
# 4.4e-8 of pi/2 - atan(|R|), and PI_HI - (PIO2_HI - PI_LO) to PIO2_HI -
# 2^-23, within 7.6e-8 of pi/2 + atan(|R|).
#
# What the model assumes (stated here, not proven by Gappa):
# - the polynomial's error relative to atan(u): the goal of atan_poly.g
#   and atan_poly_tiny.g, (y - A) / A in [-8.8e-8, 8.8e-8] (over every f32
#   |u| in [2^-149, 0x1.17b4f8p-1]; negative u by the polynomial's
#   symmetry);
# - atan(u) = u - u^3 K with K = (u - atan u) / u^3 in [0.2839, 1/3] for
#   |u| <= 0x1.17b4f8p-1 (K decreases from 1/3 at 0 to 0.28399 there):
#   A is written so;
# - the mean value theorem: atan(u) - atan(R) = (u - R) J with J = 1 /
#   (1 + xi^2), xi between u and R, so J in [0.77, 1] (|xi| <=
#   0x1.17b4f8p-1): B = atan(R) is written A - (u - R) J;
# - the constants' heads and tails: PIO2_HI + PIO2_LO - pi/2 and PI_HI +
#   PI_LO - pi are 1.71512e-15 and 3.43025e-15 (to 50 digits: Dpio2, Dpi);
# - for a negative x in the upper branch, w = rnd(phi - PI_LO) is phi +
#   2^-23 exactly: phi is an f32 in [1, 2 - 2^-23] (a multiple of 2^-23),
#   and -PI_LO = 0x1.777a5cp-24 is 0.7336 of 2^-23, so phi - PI_LO lies
#   between phi and phi + 2^-23, nearer the latter, and rounds to it: the
#   hypothesis that w - (phi - PI_LO) is 2^-23 + PI_LO = 0x1.110b48p-25
#   (interval arithmetic cannot see the grid phi lies on). Checked for
#   every such phi by `pi_lo_moves_every_phi_of_the_upper_branch_by_one_ulp`
#   in src/float/atan2.rs.
#
# Proven: the results within 8e-8 (lower, x > 0), 2.3e-7 (lower, x < 0),
# 1.65e-7 (upper, x > 0) and 3.16e-7 (upper, x < 0) of the exact angle.
#
#! bound ATAN2_MAX_ABS_ERROR rh - (Pi - (Pio2 + Bh)) in [-3.16e-7, 3.16e-7] the atan2 kernel's outer branches, every sign, against the angle of the exact arguments
# The side conditions' factorizations (`#! side`): A = u (1 - u^2 K).
#! side Al -> ul * (1 - ul * ul * Kl);
#! side Ah -> uh * (1 - uh * uh * Kh);
@rnd = float<ieee_32, ne>;

ul = rnd(RL);
yl = rnd(YL);
uh = rnd(RH);
yh = rnd(YH);

# The lower branch adds the head and the tail 0, exactly: the code's
# 0 + (y + 0) is y.
pl rnd= yl;
wl rnd= pl - -0x1.777a5cp-24;
rl rnd= 0x1.921fb6p+1 - wl;
vh rnd= yh + -0x1.777a5cp-25;
ph rnd= 0x1.921fb6p+0 + vh;
wh rnd= ph - -0x1.777a5cp-24;
rh rnd= 0x1.921fb6p+1 - wh;

Al = ul - ul * ul * ul * Kl;
Bl = Al - (ul - RL) * Jl;
Ah = uh - uh * uh * uh * Kh;
Bh = Ah - (uh - RH) * Jh;
Pio2 = 0x1.921fb6p+0 + -0x1.777a5cp-25 - Dpio2;
Pi = 0x1.921fb6p+1 + -0x1.777a5cp-24 - Dpi;

{ RL in [1b-149, 0x1.17b4f8p-1] /\ RH in [-0x1.17b4f8p-1, -1b-149]
  /\ Kl in [0.2839, 0.33334] /\ Kh in [0.2839, 0.33334] /\ Jl in [0.77, 1] /\ Jh in [0.77, 1]
  /\ Dpio2 in [1.7151e-15, 1.7152e-15] /\ Dpi in [3.4302e-15, 3.4303e-15]
  /\ wh - (ph - -0x1.777a5cp-24) in [0x1.110b48p-25, 0x1.110b48p-25]
  /\ (yl - Al) / Al in [-8.8e-8, 8.8e-8] /\ (yh - Ah) / Ah in [-8.8e-8, 8.8e-8]
  ->
  pl - Bl in [-8e-8, 8e-8] /\ rl - (Pi - Bl) in [-2.3e-7, 2.3e-7]
  /\ ph - (Pio2 + Bh) in [-1.65e-7, 1.65e-7] /\ rh - (Pi - (Pio2 + Bh)) in [-3.16e-7, 3.16e-7]
}

# Each error as its roundings, the constants' tails, the polynomial's
# error and the quotient's rounding carried by J.
yl - Al -> Al * ((yl - Al) / Al);
yh - Ah -> Ah * ((yh - Ah) / Ah);
pl - Bl -> (pl - yl) + (yl - Al) + (ul - RL) * Jl;
rl - (Pi - Bl) -> (rl - (0x1.921fb6p+1 - wl)) - (wl - (pl - -0x1.777a5cp-24)) + Dpi - (pl - Bl);
ph - (Pio2 + Bh) -> (ph - (0x1.921fb6p+0 + vh)) + (vh - (yh + -0x1.777a5cp-25)) + Dpio2 + (yh - Ah) + (uh - RH) * Jh;
rh - (Pi - (Pio2 + Bh)) -> (rh - (0x1.921fb6p+1 - wh)) - (wh - (ph - -0x1.777a5cp-24)) + Dpi - (ph - (Pio2 + Bh));
$ RH in (-0.5, -0.43);
