# The scale of Quat::mul_renormalized (src/quat.rs) on the product p it
# scales: n2 = p.norm_squared() (Quat::dot: w w + x x + y y + z z, left to
# right), t = 3 - n2, s = t * 0.5. f32, round to nearest even, every
# operation rounded as the code rounds it.
#
# Domain: the product's squared norm P = |p|^2 within 2^-18 of 1, which
# holds for every product of two quaternions with squared norms within 2^-20
# of 1 (proofs/coq/renormalized_norm.v derives it from mul_norm.v), the
# rounded squares in [0, 2].
#
# Proven: |p| s within 1.35e-7 of 1 (about 2.25 2^-24), given that the
# rounded squares sum to within 2^-24 + 2^-48 of P, relative. That
# hypothesis (each square's rounding is relative, and the squares are
# non-negative) and the last step, the four roundings of c * s (each
# relative, so the result's length is within 2^-24 of |p| s), are proven
# in Coq by proofs/coq/renormalized_norm.v.
#
# The Newton step for 1 / sqrt(P) takes P's distance from 1 away to second
# order: |p| (3 - P) / 2 - 1 = -(|p| - 1)^2 (|p| + 2) / 2, at most 6e-12
# here. What is left is this step's own rounding: the sum of squares'
# (the squares' relative 2^-24, and the three additions', each the half
# ulp of its binade), 3 - n2's (exact for n2 in [1, 2], half an ulp of
# [2, 4) below), and none for * 0.5. Gappa splits the three partial sums
# at 1, where their half ulp changes; below 1 every one is 2^-25, and
# only there does 3 - n2 round.
#
#! law - Q * s - 1 in [-1.35e-7, 1.35e-7] |p| s - 1, the renormalizing scale s of mul_renormalized against the product's norm |p|, for |p|^2 within 2^-18 of 1
@rnd = float<ieee_32, ne>;

pw = rnd(Pw); px = rnd(Px); py = rnd(Py); pz = rnd(Pz);

sw = rnd(pw * pw); sx = rnd(px * px); sy = rnd(py * py); sz = rnd(pz * pz);
s1 = rnd(sw + sx);
s2 = rnd(s1 + sy);
n2 = rnd(s2 + sz);
t = rnd(3 - n2);
s = rnd(t * 0.5);

P = pw * pw + px * px + py * py + pz * pz;
T = sw + sx + sy + sz;
Q = sqrt(P);

{ P in [0.99999618530273437500, 1.00000381469726562500] /\
  sw in [0, 2] /\ sx in [0, 2] /\ sy in [0, 2] /\ sz in [0, 2] /\
  (T - P) / P in [-0x1.000001p-24, 0x1.000001p-24]
  ->
  Q * s - 1 in [-1.35e-7, 1.35e-7]
}

# The partial sums of the rounded squares are at most their sum T, and T is
# P up to the relative error the hypothesis bounds.
sw + sx -> T - (sy + sz);
s1 + sy -> T - sz + (s1 - (sw + sx));
T -> P + (T - P) / P * P;
# The Newton step: Q (3 - P) / 2 - 1 is -(Q - 1)^2 (Q + 2) / 2 (Q^2 = P).
Q * s - 1 -> Q * (s - (3 - P) * 0.5) - (Q - 1) * (Q - 1) * (Q + 2) * 0.5;
s - (3 - P) * 0.5 -> (s - t * 0.5) + (t - (3 - n2)) * 0.5 - (n2 - P) * 0.5;
n2 - P -> (n2 - (s2 + sz)) + (s2 - (s1 + sy)) + (s1 - (sw + sx)) + (T - P);
# The side conditions' sum of squares (`#! side`, used only by the model of
# the side conditions, which has no other hint) is P.
#! side px * px + pw * pw + pz * pz + py * py -> P;
# Split the partial sums between 1 - 2^-24 and 1, where their ulp changes.
$ s1 in (0.999999970198), s2 in (0.999999970198), n2 in (0.999999970198);
