(* The norm of slerp's result on its f64 path (x86-64 and AArch64,
   src/quat/slerp/in_f64.rs, alpha in (0, 1]): | |r| / m - 1 | at most
   2.2e-7, with m = w0 |a| + w1 |b| the mean of the inputs' norms with
   the weights w0 = C0 cos(alpha phi) and w1 = C1 cos((1 - alpha) phi)
   (both in [0, 1], summing to 1), which is |a| itself for inputs of equal
   norms.

   The code: from f32 a and cn(b) (b with the sign that makes a . b
   >= 0, taken exactly), t2 = tan^2(phi / 2) in f64 (Pair::quotient), the
   coefficients c0 and c1 in f64 (Arc::coefficient), each rounded to f32
   (x0 = rnd c0, x1 = rnd c1), and the result r_i = rnd(rnd(x0 a_i) +
   rnd(x1 b_i)) in f32, round to nearest even (Quat::weighted_sum, and
   SSE2's same operations in lanes/sse2.rs). The f32 rounding of the
   products, the sum and the coefficients is Flocq's, as the certificates
   write it.

   Domain: a and b within 2^-20 of unit norm (squared: every result of
   normalize, whose norm normalize_norm.v bounds within 2.391e-7 of 1),
   alpha in [0, 1], t2 in (0, 1] (the code takes the f64 path only where
   near < far, so t2 < 1, and phi^2 > 2^-24, so t2 > 0).

   Hypotheses taken from the proven goals of Gappa models (certificates
   that cargo xtask prove checks; not re-derived here):
   - the coefficients before their rounding to f32 within 4.09e-8 of
     C0 = sin((1 - alpha) phi) / sin(phi) and C1 = sin(alpha phi) /
     sin(phi), relative, for phi = 2 atan(sqrt(t2)), the angle of the
     code's own t2 (coefficient_rest_f64.g, coefficient_f64.g, on
     arc_f64.g's bounds; at alpha = 1 the code's c0 is exactly 0 = C0);
   - the angle: (1 - t2) / (1 + t2), the cosine of that phi, within
     4e-15 of 2 (a . b) / (|a|^2 + |b|^2) (slerp_angle_f64.g).

   Proven here: the trigonometry (slerp_trig: phi in (0, pi/2], the sines
   and cosines of its shares, cos(phi) = (1 - t2) / (1 + t2)); that the
   exact coefficients make C0 + C1 cos(phi) = cos(alpha phi), C1 + C0
   cos(phi) = cos((1 - alpha) phi), C0^2 + C1^2 + 2 C0 C1 cos(phi) = 1, so
   that w0 + w1 = 1 and C0 + C1 <= sqrt(2); that for the exact
   coefficients |C0 a + C1 b|^2 = m^2 + w0 w1 (|a| - |b|)^2 up to the angle's
   error; that the coefficients' errors d0, d1 move the squared norm by
   2 (d0 (C0 |a|^2 + C1 a.b) + d1 (C1 |b|^2 + C0 a.b)), about
   2 (k1 |d0| + k0 |d1|) (k1 = cos(alpha phi), k0 = cos((1 - alpha) phi)),
   with |d| at most 4.09e-8 C plus the rounding to f32, which is at most
   u C (u = 2^-24) and, for a coefficient in [0, 1], at most u / 2 (half an
   ulp of [1/2, 1); above 1, 1 itself is the nearer float); as C0 + C1 >= 1,
   one coefficient is at least 1/2, and the weighted roundings sum to at
   most u (3/4 + C0 C1 cos(phi)) (h_key, h_mid); and that the weighted sum's
   roundings (two products and a sum per component, each within 2^-24 of
   itself, relative, plus 2^-150) move it by their projection on the exact
   sum R = x0 a + x1 b: per component |R_i| (|x0 a_i| + |x1 b_i| + |R_i|)
   is at most 2 R_i^2 + (x0 a_i - x1 b_i)^2 / 4 (the two products have the
   same sign, or R_i is their difference), which sum to
   7/4 |R|^2 + (x0^2 |a|^2 + x1^2 |b|^2) / 2, about 9/4 - C0 C1 cos(phi).
   The C0 C1 cos(phi) cancel: |r|^2 is within 2 (4.09e-8 + 3 u), 4.395e-7,
   of m^2, and |r| within 2.2e-7 of m, relative (sqrt_step). *)
(*! given coefficient_f64.g c1 <= 4.09e-8 the coefficient of b before its rounding to f32, relative *)
(*! given coefficient_rest_f64.g c0 <= 4.09e-8 the coefficient of a before its rounding to f32, relative *)
(*! given slerp_angle_f64.g cosine <= 4e-15 the cosine of the code's angle against the inputs' *)
(*! looser UNIT_NORM_ERROR slerp_norm_f64 <= 2.2e-7 | |slerp(a, b, alpha)| / m - 1 |, slerp's f64 path (x86-64 and AArch64), alpha in (0, 1], a, b within 2^-20 of unit norm; m the weighted mean of |a| and |b|, |a| for inputs of equal norms *)
Require Import Reals Psatz.
Require Import Flocq.Core.Core.
Require Import Laws.Common.
Require Import Laws.mul_norm.

Open Scope R_scope.

(* The angle whose tan^2(phi / 2) is t2, in (0, pi/2] for t2 in (0, 1],
   and the sines and cosines of its two shares. *)
Lemma slerp_trig : forall alpha t2, 0 <= alpha <= 1 -> 0 < t2 <= 1 ->
  let phi := 2 * atan (sqrt t2) in
  let s0 := sin ((1 - alpha) * phi) in let k0 := cos ((1 - alpha) * phi) in
  let s1 := sin (alpha * phi) in let k1 := cos (alpha * phi) in
  0 <= s0 /\ 0 <= k0 /\ 0 <= s1 /\ 0 <= k1 /\ 0 < sin phi /\
  s0 <= sin phi /\ s1 <= sin phi /\
  sin phi = s0 * k1 + k0 * s1 /\ cos phi = k0 * k1 - s0 * s1 /\
  s0 * s0 + k0 * k0 = 1 /\ s1 * s1 + k1 * k1 = 1 /\
  cos phi = (1 - t2) / (1 + t2).
Proof.
  intros alpha t2 Ha Ht phi s0 k0 s1 k1.
  assert (Hq : 0 < sqrt t2 <= 1).
  { split; [apply sqrt_lt_R0; lra|]. rewrite <- sqrt_1. apply sqrt_le_1_alt. lra. }
  assert (Hat : 0 < atan (sqrt t2) <= PI / 4).
  { split.
    - rewrite <- atan_0. apply atan_increasing. lra.
    - rewrite <- atan_1. destruct (Req_dec (sqrt t2) 1) as [E|E].
      + rewrite E. lra.
      + left. apply atan_increasing. lra. }
  pose proof PI_RGT_0 as Hpi.
  assert (Hphi : 0 < phi <= PI / 2) by (unfold phi; lra).
  assert (Hx : 0 <= (1 - alpha) * phi <= phi) by (split; nra).
  assert (Hy : 0 <= alpha * phi <= phi) by (split; nra).
  assert (E : phi = (1 - alpha) * phi + alpha * phi) by ring.
  assert (Sp : sin phi = s0 * k1 + k0 * s1) by (unfold s0, k0, s1, k1; rewrite E at 1; apply sin_plus).
  assert (Cp : cos phi = k0 * k1 - s0 * s1) by (unfold s0, k0, s1, k1; rewrite E at 1; apply cos_plus).
  assert (P0 : s0 * s0 + k0 * k0 = 1) by (pose proof (sin2_cos2 ((1 - alpha) * phi)); unfold Rsqr in *; unfold s0, k0; lra).
  assert (P1 : s1 * s1 + k1 * k1 = 1) by (pose proof (sin2_cos2 (alpha * phi)); unfold Rsqr in *; unfold s1, k1; lra).
  assert (Hc : cos phi = (1 - t2) / (1 + t2)).
  { unfold phi. rewrite cos_2a_cos, cos_atan.
    assert (Q : sqrt t2 * sqrt t2 = t2) by (apply sqrt_sqrt; lra).
    assert (R1 : 0 < 1 + (sqrt t2)²) by (unfold Rsqr; nra).
    assert (R2 : sqrt (1 + (sqrt t2)²) * sqrt (1 + (sqrt t2)²) = 1 + t2)
      by (rewrite sqrt_sqrt by lra; unfold Rsqr; lra).
    assert (R3 : 0 < sqrt (1 + (sqrt t2)²)) by (apply sqrt_lt_R0; lra).
    field_simplify; [|lra|lra].
    replace (sqrt (1 + (sqrt t2)²) ^ 2) with (1 + t2) by (simpl; lra).
    field. lra. }
  repeat split; try assumption.
  - apply sin_ge_0; lra.
  - apply cos_ge_0; lra.
  - apply sin_ge_0; lra.
  - apply cos_ge_0; lra.
  - apply sin_gt_0; lra.
  - apply sin_incr_1; lra.
  - apply sin_incr_1; lra.
Qed.

Definition U := u + u * u.

(* One component of the weighted sum: two rounded products, their rounded
   sum. *)
Lemma sum2_err : forall x0 x1 a b,
  Rabs (rnd (rnd (x0 * a) + rnd (x1 * b)) - (x0 * a + x1 * b))
  <= U * (Rabs x0 * Rabs a + Rabs x1 * Rabs b + Rabs (x0 * a + x1 * b)) + 5 * eta.
Proof.
  intros x0 x1 a b.
  pose proof u_pos as Hu; pose proof eta_pos as He.
  assert (Hu1 : u <= / 1000000) by (unfold u; lra).
  pose proof (rnd_err (x0 * a)) as D1; pose proof (rnd_err (x1 * b)) as D2.
  pose proof (rnd_err (rnd (x0 * a) + rnd (x1 * b))) as D3.
  set (d1 := rnd (x0 * a) - x0 * a) in *. set (d2 := rnd (x1 * b) - x1 * b) in *.
  set (s := rnd (x0 * a) + rnd (x1 * b)) in *.
  assert (Es : s = (x0 * a + x1 * b) + (d1 + d2)) by (unfold s, d1, d2; ring).
  assert (As : Rabs s <= Rabs (x0 * a + x1 * b) + Rabs d1 + Rabs d2).
  { rewrite Es. pose proof (Rabs_triang (x0 * a + x1 * b) (d1 + d2)). pose proof (Rabs_triang d1 d2). lra. }
  assert (E : rnd s - (x0 * a + x1 * b) = (rnd s - s) + d1 + d2) by (rewrite Es; ring).
  rewrite E. rewrite Rabs_mult in D1, D2.
  pose proof (Rabs_triang (rnd s - s + d1) d2); pose proof (Rabs_triang (rnd s - s) d1).
  assert (K : u * Rabs s <= u * (Rabs (x0 * a + x1 * b) + Rabs d1 + Rabs d2)) by (apply Rmult_le_compat_l; lra).
  pose proof (Rabs_pos d1); pose proof (Rabs_pos d2).
  assert (K1 : u * Rabs d1 <= u * (u * (Rabs x0 * Rabs a) + eta)) by (apply Rmult_le_compat_l; lra).
  assert (K2 : u * Rabs d2 <= u * (u * (Rabs x1 * Rabs b) + eta)) by (apply Rmult_le_compat_l; lra).
  assert (0 <= Rabs x0 * Rabs a) by (apply Rmult_le_pos; apply Rabs_pos).
  assert (0 <= Rabs x1 * Rabs b) by (apply Rmult_le_pos; apply Rabs_pos).
  assert (u * eta <= eta) by (rewrite <- (Rmult_1_l eta) at 2; apply Rmult_le_compat_r; lra).
  assert (0 <= u * u * Rabs (x0 * a + x1 * b)) by (apply Rmult_le_pos; [nra|apply Rabs_pos]).
  unfold U. lra.
Qed.

(* The last step: a squared norm within Y of m^2 is a norm within
   Y / (2 m^2), about, of m. *)
Lemma sqrt_step : forall nr m Y, 0 <= nr -> 0.9999995 <= m -> 0 <= Y <= 4.395e-7 ->
  Rabs (nr * nr - m * m) <= Y -> Rabs (nr / m - 1) <= 2.2e-7.
Proof.
  intros nr m Y Hn Hm HY H.
  assert (Hm0 : 0 < m) by lra.
  assert (K : Rabs (nr - m) <= 2.2e-7 * m).
  { destruct (Rle_dec m nr) as [G|G].
    - rewrite Rabs_right by lra. rewrite Rabs_right in H by nra. nra.
    - rewrite Rabs_left by lra. rewrite Rabs_left in H by nra.
      assert (Hd : (m - nr) * m <= Y) by nra.
      assert (Hd2 : m - nr <= 4.3951e-7) by nra.
      nra. }
  replace (nr / m - 1) with ((nr - m) * / m) by (field; lra).
  rewrite Rabs_mult, Rabs_inv. rewrite (Rabs_right m) by lra.
  apply (Rmult_le_reg_r m); [lra|].
  rewrite Rmult_assoc, Rinv_l, Rmult_1_r by lra. lra.
Qed.

Lemma n4_abs : forall a b c d, n4 (Rabs a) (Rabs b) (Rabs c) (Rabs d) = n4 a b c d.
Proof. intros; unfold n4; rewrite !sq_abs; reflexivity. Qed.

(* One component of the weighted sum: with p = x0 a, q = x1 b and R = p + q,
   |R| (|p| + |q|) is R^2 where p and q have the same sign and |R| |p - q|
   otherwise, at most R^2 + (p - q)^2 / 4 in both cases. *)

Lemma proj_comp : forall p q,
  Rabs (p + q) * (Rabs p + Rabs q) <= (p + q) * (p + q) + (p - q) * (p - q) / 4.
Proof.
  intros p q.
  assert (C : Rabs p + Rabs q = Rabs (p + q) \/ Rabs p + Rabs q = Rabs (p - q)).
  { destruct (Rle_dec 0 p) as [P|P]; destruct (Rle_dec 0 q) as [Q|Q].
    - left. rewrite (Rabs_right p), (Rabs_right q), (Rabs_right (p + q)) by lra. ring.
    - right. apply Rnot_le_lt in Q. rewrite (Rabs_right p), (Rabs_left q), (Rabs_right (p - q)) by lra. ring.
    - right. apply Rnot_le_lt in P. rewrite (Rabs_left p), (Rabs_right q), (Rabs_left1 (p - q)) by lra. ring.
    - left. apply Rnot_le_lt in P. apply Rnot_le_lt in Q.
      rewrite (Rabs_left p), (Rabs_left q), (Rabs_left (p + q)) by lra. ring. }
  rewrite <- (sq_abs (p + q)), <- (sq_abs (p - q)).
  pose proof (Rabs_pos (p + q)); pose proof (Rabs_pos (p - q)).
  destruct C as [C|C]; rewrite C.
  - assert (0 <= Rabs (p - q) * Rabs (p - q) / 4) by (apply Rmult_le_pos; [apply Rmult_le_pos|]; lra). lra.
  - pose proof (Rle_0_sqr (Rabs (p + q) - Rabs (p - q) / 2)). unfold Rsqr in *. lra.
Qed.

Lemma comp_bound : forall x0 x1 a b,
  Rabs (x0 * a + x1 * b) * (Rabs x0 * Rabs a + Rabs x1 * Rabs b + Rabs (x0 * a + x1 * b))
  <= 2 * ((x0 * a + x1 * b) * (x0 * a + x1 * b)) + (x0 * a - x1 * b) * (x0 * a - x1 * b) / 4.
Proof.
  intros x0 x1 a b. rewrite <- !Rabs_mult.
  pose proof (proj_comp (x0 * a) (x1 * b)) as P.
  replace (Rabs (x0 * a + x1 * b) * (Rabs (x0 * a) + Rabs (x1 * b) + Rabs (x0 * a + x1 * b)))
    with (Rabs (x0 * a + x1 * b) * (Rabs (x0 * a) + Rabs (x1 * b)) + Rabs (x0 * a + x1 * b) * Rabs (x0 * a + x1 * b)) by ring.
  rewrite sq_abs. lra.
Qed.

(* The errors of the components, projected on the exact sum R = x0 a + x1 b:
   each component's at most U (2 R_i^2 + (x0 a_i - x1 b_i)^2 / 4) (comp_bound),
   which sum to U (7/4 |R|^2 + (x0^2 |a|^2 + x1^2 |b|^2) / 2), plus the
   subnormal terms. *)
Lemma projection : forall x0 x1 a0 a1 a2 a3 b0 b1 b2 b3 e0 e1 e2 e3,
  let R0 := x0 * a0 + x1 * b0 in let R1 := x0 * a1 + x1 * b1 in
  let R2 := x0 * a2 + x1 * b2 in let R3 := x0 * a3 + x1 * b3 in
  Rabs e0 <= U * (Rabs x0 * Rabs a0 + Rabs x1 * Rabs b0 + Rabs R0) + 5 * eta ->
  Rabs e1 <= U * (Rabs x0 * Rabs a1 + Rabs x1 * Rabs b1 + Rabs R1) + 5 * eta ->
  Rabs e2 <= U * (Rabs x0 * Rabs a2 + Rabs x1 * Rabs b2 + Rabs R2) + 5 * eta ->
  Rabs e3 <= U * (Rabs x0 * Rabs a3 + Rabs x1 * Rabs b3 + Rabs R3) + 5 * eta ->
  let nR := n4 R0 R1 R2 R3 in
  Rabs (R0 * e0 + R1 * e1 + R2 * e2 + R3 * e3)
  <= U * (7 / 4 * (nR * nR) + (x0 * x0 * (a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3)
       + x1 * x1 * (b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3)) / 2) + 10 * eta * nR.
Proof.
  intros x0 x1 a0 a1 a2 a3 b0 b1 b2 b3 e0 e1 e2 e3 R0 R1 R2 R3 H0 H1 H2 H3 nR.
  assert (HU : 0 <= U) by (unfold U; pose proof u_pos; nra).
  pose proof eta_pos as He.
  assert (K : forall R e M, Rabs e <= U * M + 5 * eta -> Rabs (R * e) <= U * (Rabs R * M) + 5 * eta * Rabs R).
  { intros R e M H. rewrite Rabs_mult.
    assert (Rabs R * Rabs e <= Rabs R * (U * M + 5 * eta)) by (apply Rmult_le_compat_l; [apply Rabs_pos|lra]).
    lra. }
  pose proof (K R0 _ _ H0); pose proof (K R1 _ _ H1); pose proof (K R2 _ _ H2); pose proof (K R3 _ _ H3).
  pose proof (Rabs_triang (R0 * e0 + R1 * e1 + R2 * e2) (R3 * e3));
  pose proof (Rabs_triang (R0 * e0 + R1 * e1) (R2 * e2));
  pose proof (Rabs_triang (R0 * e0) (R1 * e1)).
  pose proof (comp_bound x0 x1 a0 b0) as W0. pose proof (comp_bound x0 x1 a1 b1) as W1.
  pose proof (comp_bound x0 x1 a2 b2) as W2. pose proof (comp_bound x0 x1 a3 b3) as W3.
  fold R0 in W0. fold R1 in W1. fold R2 in W2. fold R3 in W3.
  apply (Rmult_le_compat_l U) in W0; [|exact HU]. apply (Rmult_le_compat_l U) in W1; [|exact HU].
  apply (Rmult_le_compat_l U) in W2; [|exact HU]. apply (Rmult_le_compat_l U) in W3; [|exact HU].
  assert (Id : U * (2 * (R0 * R0) + (x0 * a0 - x1 * b0) * (x0 * a0 - x1 * b0) / 4)
    + U * (2 * (R1 * R1) + (x0 * a1 - x1 * b1) * (x0 * a1 - x1 * b1) / 4)
    + U * (2 * (R2 * R2) + (x0 * a2 - x1 * b2) * (x0 * a2 - x1 * b2) / 4)
    + U * (2 * (R3 * R3) + (x0 * a3 - x1 * b3) * (x0 * a3 - x1 * b3) / 4)
    = U * (7 / 4 * (nR * nR) + (x0 * x0 * (a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3)
       + x1 * x1 * (b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3)) / 2)).
  { unfold nR. rewrite n4_sq. unfold R0, R1, R2, R3. field. }
  pose proof (sum_abs_le R0 R1 R2 R3) as SA. fold (n4 R0 R1 R2 R3) in SA. fold nR in SA.
  assert (5 * eta * (Rabs R0 + Rabs R1 + Rabs R2 + Rabs R3) <= 5 * eta * (2 * nR)) by (apply Rmult_le_compat_l; lra).
  lra.
Qed.

(* A rounding to f32 of a number in [0, 1] is within 2^-25 = u / 2 of it:
   half an ulp of [1/2, 1). *)
Lemma rnd_half_ulp : forall c, 0 <= c <= 1 -> Rabs (rnd c - c) <= u / 2.
Proof.
  intros c Hc.
  destruct (Req_dec c 0) as [Z|Z].
  { rewrite Z, rnd_0, Rminus_0_r, Rabs_R0. unfold u; lra. }
  destruct (Req_dec c 1) as [O|O].
  { rewrite O. change 1 with (bpow radix2 0). rewrite rnd_bpow by lia.
    unfold Rminus; rewrite Rplus_opp_r, Rabs_R0. unfold u; lra. }
  eapply Rle_trans; [apply error_le_half_ulp; apply FLT_exp_valid; reflexivity|].
  rewrite ulp_neq_0 by exact Z. unfold cexp.
  assert (M : (mag radix2 c <= 0)%Z).
  { apply mag_le_bpow; [exact Z|]. rewrite Rabs_right by lra. simpl. lra. }
  assert (B : bpow radix2 (FLT_exp (-149) 24 (mag radix2 c)) <= bpow radix2 (-24)).
  { apply bpow_le. unfold FLT_exp. lia. }
  assert (E : bpow radix2 (-24) = u) by (unfold u; simpl; unfold Z.pow_pos; simpl; lra).
  lra.
Qed.

(* A coefficient within 4.09e-8 of C in [1/2, 1], relative, rounded to f32:
   within 4.09e-8 C + u / 2 of C if it is at most 1; if it is above 1,
   1 (a float) is nearer than the distance to C, and C is within 4.1e-8 of 1. *)
Lemma h_coef_half : forall c C, 0 <= C <= 1 -> Rabs (c - C) <= 4.09e-8 * C ->
  (c <= 1 /\ Rabs (rnd c - C) <= 4.09e-8 * C + u / 2) \/
  (1 < c /\ Rabs (rnd c - C) <= 4.09e-8 * C + 4.09e-8 /\ 1 - 4.1e-8 <= C).
Proof.
  intros c C HC H. apply Rabs_le_inv in H.
  pose proof (Rabs_triang (rnd c - c) (c - C)) as T.
  replace (rnd c - c + (c - C)) with (rnd c - C) in T by ring.
  destruct (Rle_dec c 1) as [L|L].
  - left. split; [exact L|].
    assert (0 <= c) by nra.
    pose proof (rnd_half_ulp c (conj H0 L)).
    assert (Rabs (c - C) <= 4.09e-8 * C) by (apply Rabs_le; lra). lra.
  - right. apply Rnot_le_lt in L. split; [lra|].
    assert (N : Rabs (rnd c - c) <= Rabs (1 - c)).
    { assert (F : rnd 1 = 1) by (change 1 with (bpow radix2 0); apply rnd_bpow; lia).
      assert (G : generic_format radix2 (FLT_exp (-149) 24) 1).
      { rewrite <- F. apply generic_format_round; [apply FLT_exp_valid; reflexivity|unfold rndNE; apply valid_rnd_N]. }
      destruct (round_N_pt radix2 (FLT_exp (-149) 24) (fun z => negb (Z.even z)) c) as [_ Hn].
      specialize (Hn 1 G).
      change (Generic_fmt.round radix2 (FLT.FLT_exp (-149) 24)
            (Generic_fmt.Znearest (fun z : Z => negb (Z.even z))) c) with (rnd c) in Hn.
      exact Hn. }
    rewrite (Rabs_left1 (1 - c)) in N by lra.
    assert (Rabs (c - C) <= 4.09e-8 * C) by (apply Rabs_le; lra).
    split; [lra|]. nra.
Qed.

Lemma h_mid : forall C0 C1 cp, 1/2 <= C0 <= 1 -> 1/2 <= C1 <= 1 -> 0 <= cp <= 1 ->
  C0 * C0 + C1 * C1 + 2 * C0 * C1 * cp = 1 ->
  (C0 + C1) * (1 + cp) / 2 <= 3/4 + C0 * C1 * cp.
Proof.
  intros C0 C1 cp H0 H1 Hc One.
  set (s := C0 + C1). set (p := C0 * C1).
  assert (Es : s * s = 1 + 2 * p * (1 - cp)) by (unfold s, p; lra).
  assert (A : p * (1 - cp) <= s * s * (1 - cp) / 4).
  { assert (0 <= (C0 - C1) * (C0 - C1) * (1 - cp)) by (apply Rmult_le_pos; [apply Rle_0_sqr|lra]).
    unfold s, p. lra. }
  assert (B : s * s * (1 + cp) / 2 <= 1) by lra.
  set (y := s * (1 + cp) / 2).
  assert (Y2 : y * y <= (1 + cp) / 2).
  { assert (E : y * y = (s * s * (1 + cp) / 2) * ((1 + cp) / 2)) by (unfold y; field).
    rewrite E. assert (0 <= (1 + cp) / 2) by lra.
    assert (s * s * (1 + cp) / 2 * ((1 + cp) / 2) <= 1 * ((1 + cp) / 2)) by (apply Rmult_le_compat_r; lra). lra. }
  assert (Y1 : y <= (y * y + 1) / 2) by (pose proof (Rle_0_sqr (y - 1)); unfold Rsqr in *; lra).
  assert (P : / 4 <= p) by (unfold p; assert (1/2 * (1/2) <= C0 * C1) by (apply Rmult_le_compat; lra); lra).
  assert (cp / 4 <= p * cp) by (apply Rmult_le_compat_r with (r := cp) in P; lra).
  fold y. lra.
Qed.

Lemma h_key : forall C0 C1 cp k0 k1 d0 d1,
  0 <= C0 <= 1 -> 0 <= C1 <= 1 -> 0 <= cp <= 1 ->
  C0 + C1 * cp = k1 -> C1 + C0 * cp = k0 -> 0 <= k0 <= 1 -> 0 <= k1 <= 1 ->
  C0 * C0 + C1 * C1 + 2 * C0 * C1 * cp = 1 ->
  Rabs d0 <= 1.00505e-7 * C0 + eta -> Rabs d1 <= 1.00505e-7 * C1 + eta ->
  (1/2 <= C0 -> Rabs d0 <= 4.09e-8 * C0 + u / 2 \/ (Rabs d0 <= 4.09e-8 * C0 + 4.09e-8 /\ 1 - 4.1e-8 <= C0)) ->
  (1/2 <= C1 -> Rabs d1 <= 4.09e-8 * C1 + u / 2 \/ (Rabs d1 <= 4.09e-8 * C1 + 4.09e-8 /\ 1 - 4.1e-8 <= C1)) ->
  k1 * Rabs d0 + k0 * Rabs d1 <= 4.09e-8 * (C0 * k1 + C1 * k0) + u * (3/4 + C0 * C1 * cp) + 1e-12.
Proof.
  intros C0 C1 cp k0 k1 d0 d1 H0 H1 Hc K1 K0 Hk0 Hk1 One D0 D1 M0 M1.
  pose proof eta_pos. pose proof (Rabs_pos d0). pose proof (Rabs_pos d1).
  assert (Heta : eta <= / 1000000000000000000000000000000) by (unfold eta; simpl; lra).
  assert (Hu : u = / 16777216) by reflexivity.
  assert (0 <= C0 * C1) by (apply Rmult_le_pos; lra).
  assert (0 <= C0 * C1 * cp) by (apply Rmult_le_pos; lra).
  assert (W0 : k1 * Rabs d0 <= k1 * (1.00505e-7 * C0 + eta)) by (apply Rmult_le_compat_l; lra).
  assert (W1 : k0 * Rabs d1 <= k0 * (1.00505e-7 * C1 + eta)) by (apply Rmult_le_compat_l; lra).
  assert (k1 * eta <= eta) by (rewrite <- (Rmult_1_l eta) at 2; apply Rmult_le_compat_r; lra).
  assert (k0 * eta <= eta) by (rewrite <- (Rmult_1_l eta) at 2; apply Rmult_le_compat_r; lra).
  assert (C1k0 : C1 * k0 = C1 * C1 + C0 * C1 * cp) by (rewrite <- K0; ring).
  assert (C0k1 : C0 * k1 = C0 * C0 + C0 * C1 * cp) by (rewrite <- K1; ring).
  assert (0 <= C0 * C0) by apply Rle_0_sqr. assert (0 <= C1 * C1) by apply Rle_0_sqr.
  destruct (Rle_dec (1/2) C0) as [A0|A0]; destruct (Rle_dec (1/2) C1) as [A1|A1].
  - assert (Q1 : 1/2 * (1/2) <= C1 * C1) by (apply Rmult_le_compat; lra).
    assert (Q0 : 1/2 * (1/2) <= C0 * C0) by (apply Rmult_le_compat; lra).
    destruct (M0 A0) as [B0|[B0 F0]].
    2: { exfalso. assert ((1 - 4.1e-8) * (1 - 4.1e-8) <= C0 * C0) by (apply Rmult_le_compat; lra). lra. }
    destruct (M1 A1) as [B1|[B1 F1]].
    2: { exfalso. assert ((1 - 4.1e-8) * (1 - 4.1e-8) <= C1 * C1) by (apply Rmult_le_compat; lra). lra. }
    pose proof (h_mid C0 C1 cp (conj A0 (proj2 H0)) (conj A1 (proj2 H1)) Hc One) as Mid.
    assert (k1 * Rabs d0 <= k1 * (4.09e-8 * C0 + u / 2)) by (apply Rmult_le_compat_l; lra).
    assert (k0 * Rabs d1 <= k0 * (4.09e-8 * C1 + u / 2)) by (apply Rmult_le_compat_l; lra).
    assert (E : k0 + k1 = (C0 + C1) * (1 + cp)) by (rewrite <- K0, <- K1; ring).
    assert (u * ((k0 + k1) / 2) <= u * (3/4 + C0 * C1 * cp)) by (apply Rmult_le_compat_l; [unfold u; lra|rewrite E; lra]).
    lra.
  - apply Rnot_le_lt in A1.
    assert (C1 * C1 <= / 4) by (assert (C1 * C1 <= 1/2 * (1/2)) by (apply Rmult_le_compat; lra); lra).
    destruct (M0 A0) as [B0|[B0 F0]].
    + assert (k1 * Rabs d0 <= k1 * (4.09e-8 * C0 + u / 2)) by (apply Rmult_le_compat_l; lra).
      assert (k1 * (u / 2) <= u / 2) by (apply Rmult_le_reg_r with (r := 2); [lra|]; unfold u in *; lra).
      unfold u in *. lra.
    + assert (k1 * Rabs d0 <= k1 * (4.09e-8 * C0 + 4.09e-8)) by (apply Rmult_le_compat_l; lra).
      assert ((1 - 4.1e-8) * (1 - 4.1e-8) <= C0 * C0) by (apply Rmult_le_compat; lra).
      assert (C1 * C1 <= 8.2e-8) by lra.
      unfold u in *. lra.
  - apply Rnot_le_lt in A0.
    assert (C0 * C0 <= / 4) by (assert (C0 * C0 <= 1/2 * (1/2)) by (apply Rmult_le_compat; lra); lra).
    destruct (M1 A1) as [B1|[B1 F1]].
    + assert (k0 * Rabs d1 <= k0 * (4.09e-8 * C1 + u / 2)) by (apply Rmult_le_compat_l; lra).
      assert (k0 * (u / 2) <= u / 2) by (apply Rmult_le_reg_r with (r := 2); [lra|]; unfold u in *; lra).
      unfold u in *. lra.
    + assert (k0 * Rabs d1 <= k0 * (4.09e-8 * C1 + 4.09e-8)) by (apply Rmult_le_compat_l; lra).
      assert ((1 - 4.1e-8) * (1 - 4.1e-8) <= C1 * C1) by (apply Rmult_le_compat; lra).
      assert (C0 * C0 <= 8.2e-8) by lra.
      unfold u in *. lra.
  - exfalso. apply Rnot_le_lt in A0. apply Rnot_le_lt in A1.
    assert (0 <= C0 * C1 * (1 - cp)) by (apply Rmult_le_pos; lra).
    assert (S : (C0 + C1) * (C0 + C1) < 1 * 1) by (apply Rmult_le_0_lt_compat; lra).
    lra.
Qed.

Lemma h_norm : forall Q, 1 - / 1048576 <= Q <= 1 + / 1048576 -> 0.9999995 <= sqrt Q <= 1.0000005.
Proof.
  intros Q H. pose proof (sqrt_pos Q). assert (E : sqrt Q * sqrt Q = Q) by (apply sqrt_sqrt; lra).
  split; nra.
Qed.

Lemma h_diff : forall na nb, 0.9999995 <= na -> 0.9999995 <= nb ->
  1 - / 1048576 <= na * na <= 1 + / 1048576 -> 1 - / 1048576 <= nb * nb <= 1 + / 1048576 ->
  (na - nb) * (na - nb) <= 9.2e-13.
Proof.
  intros na nb Ha Hb Qa Qb.
  assert (E : (na - nb) * (na + nb) = na * na - nb * nb) by ring.
  assert (A : Rabs (na - nb) * (na + nb) <= 2 / 1048576).
  { rewrite <- (Rabs_right (na + nb)) by lra. rewrite <- Rabs_mult, E. apply Rabs_le. lra. }
  assert (Rabs (na - nb) * 1.999999 <= Rabs (na - nb) * (na + nb)) by (apply Rmult_le_compat_l; [apply Rabs_pos|lra]).
  assert (B : Rabs (na - nb) <= 9.54e-7) by lra.
  rewrite <- sq_abs. pose proof (Rabs_pos (na - nb)).
  assert (Rabs (na - nb) * Rabs (na - nb) <= 9.54e-7 * 9.54e-7) by (apply Rmult_le_compat; lra).
  lra.
Qed.

Lemma h_mean : forall w0 w1 na nb, 0 <= w0 -> 0 <= w1 -> w0 + w1 = 1 ->
  0.9999995 <= na <= 1.0000005 -> 0.9999995 <= nb <= 1.0000005 ->
  0.9999995 <= w0 * na + w1 * nb <= 1.0000005 /\ w0 * w1 <= / 4.
Proof.
  intros w0 w1 na nb H0 H1 H Ha Hb.
  assert (w0 * 0.9999995 <= w0 * na <= w0 * 1.0000005) by (split; apply Rmult_le_compat_l; lra).
  assert (w1 * 0.9999995 <= w1 * nb <= w1 * 1.0000005) by (split; apply Rmult_le_compat_l; lra).
  assert (w0 * w1 = w0 * (1 - w0)) by (replace w1 with (1 - w0) by lra; ring).
  split; [lra|]. pose proof (Rle_0_sqr (w0 - / 2)). unfold Rsqr in *. nra.
Qed.

Lemma h_sum : forall C0 C1 cp, 0 <= C0 -> 0 <= C1 -> 0 <= cp ->
  C0 * C0 + C1 * C1 + 2 * C0 * C1 * cp = 1 -> C0 + C1 <= 1.41422.
Proof.
  intros C0 C1 cp H0 H1 Hc One.
  assert (0 <= C0 * C1 * cp) by (apply Rmult_le_pos; [apply Rmult_le_pos|]; lra).
  assert ((C0 + C1) * (C0 + C1) <= 2) by (pose proof (Rle_0_sqr (C0 - C1)); unfold Rsqr in *; nra).
  nra.
Qed.

Lemma h_coef : forall c C, 0 <= C <= 1 -> Rabs (c - C) <= 4.09e-8 * C ->
  Rabs (rnd c - C) <= 1.00505e-7 * C + eta.
Proof.
  intros c C HC H.
  pose proof (rnd_err c) as R. pose proof u_pos.
  assert (Rabs c <= C * (1 + 4.09e-8)).
  { replace c with (C + (c - C)) by ring. pose proof (Rabs_triang C (c - C)). rewrite (Rabs_right C) in * by lra. lra. }
  pose proof (Rabs_triang (rnd c - c) (c - C)). replace (rnd c - c + (c - C)) with (rnd c - C) in * by ring.
  assert (u * Rabs c <= u * (C * (1 + 4.09e-8))) by (apply Rmult_le_compat_l; lra).
  unfold u in *. lra.
Qed.

Lemma h_G : forall k Q C cp dQ Dd, 0 <= C <= 1 -> 0 <= cp <= 1 -> 0 <= k -> 0 <= Q ->
  Rabs dQ <= 2 / 1048576 -> Rabs Dd <= 4.1e-15 ->
  Rabs (k * Q + C * cp * dQ / 2 + C * Dd) <= k * Q + 9.6e-7.
Proof.
  intros k Q C cp dQ Dd HC Hc Hk HQ HdQ HDd.
  assert (Rabs (C * cp * dQ / 2) <= 9.54e-7).
  { unfold Rdiv. rewrite !Rabs_mult, (Rabs_right C), (Rabs_right cp), (Rabs_right (/ 2)) by lra.
    assert (0 <= C * cp <= 1) by (split; nra). pose proof (Rabs_pos dQ). nra. }
  assert (Rabs (C * Dd) <= 4.1e-15) by (rewrite Rabs_mult, (Rabs_right C) by lra; pose proof (Rabs_pos Dd); nra).
  pose proof (Rabs_triang (k * Q + C * cp * dQ / 2) (C * Dd)).
  pose proof (Rabs_triang (k * Q) (C * cp * dQ / 2)).
  assert (0 <= k * Q) by nra. rewrite (Rabs_right (k * Q)) in * by lra. lra.
Qed.

Lemma h_second : forall d0 d1 QA QB D, Rabs d0 <= 1.006e-7 -> Rabs d1 <= 1.006e-7 ->
  0 <= QA <= 1.000001 -> 0 <= QB <= 1.000001 -> Rabs D <= 1.000001 ->
  Rabs (d0 * d0 * QA + d1 * d1 * QB + 2 * d0 * d1 * D) <= 4.1e-14.
Proof.
  intros d0 d1 QA QB D H0 H1 HA HB HD.
  assert (A : d0 * d0 <= 1.0121e-14) by (rewrite <- sq_abs; pose proof (Rabs_pos d0); nra).
  assert (B : d1 * d1 <= 1.0121e-14) by (rewrite <- sq_abs; pose proof (Rabs_pos d1); nra).
  assert (C : Rabs (d0 * d1 * D) <= 1.0121e-14 * 1.000001).
  { rewrite !Rabs_mult. pose proof (Rabs_pos d0); pose proof (Rabs_pos d1); pose proof (Rabs_pos D).
    assert (Rabs d0 * Rabs d1 <= 1.0121e-14) by nra. nra. }
  apply Rabs_le. apply Rabs_le_inv in C.
  assert (0 <= d0 * d0) by nra. assert (0 <= d1 * d1) by nra.
  assert (d0 * d0 * QA <= 1.0121e-14 * 1.000001) by nra.
  assert (d1 * d1 * QB <= 1.0121e-14 * 1.000001) by nra.
  assert (0 <= d0 * d0 * QA) by nra. assert (0 <= d1 * d1 * QB) by nra.
  lra.
Qed.

Lemma h_Dd : forall cp D QA QB, 1.99 <= QA + QB <= 2.0001 ->
  Rabs (cp - 2 * D / (QA + QB)) <= 4e-15 -> Rabs (D - cp * (QA + QB) / 2) <= 4.1e-15.
Proof.
  intros cp D QA QB HQ H.
  assert (E : D - cp * (QA + QB) / 2 = - ((QA + QB) / 2) * (cp - 2 * D / (QA + QB))) by (field; lra).
  rewrite E, Rabs_mult, Rabs_Ropp, (Rabs_right ((QA + QB) / 2)) by lra.
  pose proof (Rabs_pos (cp - 2 * D / (QA + QB))). nra.
Qed.

Lemma h_U : U <= 5.9604649e-8.
Proof. unfold U, u. lra. Qed.

Lemma h_le_sq : forall x c, 0 <= c -> x * x <= c * c -> Rabs x <= c.
Proof.
  intros x c Hc H. rewrite <- sq_abs in H. pose proof (Rabs_pos x).
  destruct (Rle_dec (Rabs x) c) as [G|G]; [lra|].
  assert (c * c < Rabs x * Rabs x) by (apply Rmult_le_0_lt_compat; lra). lra.
Qed.

Lemma h_xs : forall x0 x1 C0 C1 na nb, 0 <= C0 -> 0 <= C1 -> C0 + C1 <= 1.41422 ->
  Rabs (x0 - C0) <= 1.00505e-7 * C0 + eta -> Rabs (x1 - C1) <= 1.00505e-7 * C1 + eta ->
  0 <= na <= 1.0000005 -> 0 <= nb <= 1.0000005 ->
  Rabs x0 * na + Rabs x1 * nb <= 1.4142286 /\ Rabs x0 <= 1.0000001006 * C0 + eta /\ Rabs x1 <= 1.0000001006 * C1 + eta.
Proof.
  intros x0 x1 C0 C1 na nb H0 H1 HS X0 X1 Na Nb. pose proof eta_pos.
  assert (Heta : eta <= / 1000000000000000000000000000000) by (unfold eta; simpl; lra).
  assert (A0 : Rabs x0 <= C0 * (1 + 1.00505e-7) + eta).
  { replace x0 with (C0 + (x0 - C0)) by ring. pose proof (Rabs_triang C0 (x0 - C0)). rewrite (Rabs_right C0) in * by lra. lra. }
  assert (A1 : Rabs x1 <= C1 * (1 + 1.00505e-7) + eta).
  { replace x1 with (C1 + (x1 - C1)) by ring. pose proof (Rabs_triang C1 (x1 - C1)). rewrite (Rabs_right C1) in * by lra. lra. }
  pose proof (Rabs_pos x0); pose proof (Rabs_pos x1).
  assert (Rabs x0 * na <= (C0 * (1 + 1.00505e-7) + eta) * 1.0000005) by (apply Rmult_le_compat; lra).
  assert (Rabs x1 * nb <= (C1 * (1 + 1.00505e-7) + eta) * 1.0000005) by (apply Rmult_le_compat; lra).
  split; [|split]; lra.
Qed.

Lemma h_eps : forall x0 x1 a b R e, Rabs x0 <= 1.0000002 -> Rabs x1 <= 1.0000002 ->
  Rabs a <= 1.0000005 -> Rabs b <= 1.0000005 -> Rabs R <= 1.0000007 ->
  Rabs e <= U * (Rabs x0 * Rabs a + Rabs x1 * Rabs b + Rabs R) + 5 * eta -> e * e <= 3.5e-14.
Proof.
  intros x0 x1 a b R e H0 H1 Ha Hb HR He. pose proof eta_pos. pose proof h_U.
  assert (Heta : eta <= / 1000000000000000000000000000000) by (unfold eta; simpl; lra).
  assert (0 <= U) by (unfold U; pose proof u_pos; nra).
  pose proof (Rabs_pos x0); pose proof (Rabs_pos x1); pose proof (Rabs_pos a); pose proof (Rabs_pos b); pose proof (Rabs_pos R).
  assert (Rabs x0 * Rabs a <= 1.0000002 * 1.0000005) by (apply Rmult_le_compat; lra).
  assert (Rabs x1 * Rabs b <= 1.0000002 * 1.0000005) by (apply Rmult_le_compat; lra).
  assert (M : 0 <= Rabs x0 * Rabs a + Rabs x1 * Rabs b + Rabs R <= 3.1) by (split; [nra|lra]).
  assert (U * (Rabs x0 * Rabs a + Rabs x1 * Rabs b + Rabs R) <= 5.9604649e-8 * 3.1) by (apply Rmult_le_compat; lra).
  assert (Rabs e <= 1.85e-7) by lra.
  rewrite <- sq_abs. pose proof (Rabs_pos e).
  assert (Rabs e * Rabs e <= 1.85e-7 * 1.85e-7) by (apply Rmult_le_compat; lra). lra.
Qed.

Lemma h_proj : forall nR X P cc, 0 <= nR <= 1.0000007 -> 0 <= cc -> X <= 1 - 2 * cc + 2.4e-6 ->
  Rabs P <= U * (7 / 4 * (nR * nR) + X / 2) + 10 * eta * nR ->
  2 * Rabs P <= 2.6822136e-7 - 2 * / 16777216 * cc.
Proof.
  intros nR X P cc HR Hcc HX H. pose proof eta_pos.
  assert (Heta : eta <= / 1000000000000000000000000000000) by (unfold eta; simpl; lra).
  assert (HU : U = / 16777216 + / 16777216 * / 16777216) by reflexivity.
  assert (0 <= U) by (rewrite HU; lra).
  assert (nR * nR <= 1.0000007 * 1.0000007) by (apply Rmult_le_compat; lra).
  assert (A : U * (7 / 4 * (nR * nR) + X / 2) <= U * (2.2500037 - cc)).
  { apply Rmult_le_compat_l; [lra|]. lra. }
  assert (B : U * (2.2500037 - cc) = U * 2.2500037 - U * cc) by ring.
  assert (U * cc >= / 16777216 * cc) by (apply Rle_ge, Rmult_le_compat_r; [lra|rewrite HU; lra]).
  assert (10 * eta * nR <= 10 * eta * 1.0000007) by (apply Rmult_le_compat_l; lra).
  rewrite HU in B. lra.
Qed.

Lemma h_first2 : forall d G k Q, 0 <= k <= 1 -> 0 <= Q <= 1 + / 1048576 -> Rabs d <= 1.006e-7 ->
  Rabs G <= k * Q + 9.6e-7 -> Rabs (d * G) <= k * Rabs d + 2.1e-13.
Proof.
  intros d G k Q Hk HQ Hd HG. rewrite Rabs_mult. pose proof (Rabs_pos d).
  assert (A : Rabs d * Rabs G <= Rabs d * (k * Q + 9.6e-7)) by (apply Rmult_le_compat_l; lra).
  assert (B : Rabs d * k * Q <= Rabs d * k * (1 + / 1048576)) by (apply Rmult_le_compat_l; [apply Rmult_le_pos|]; lra).
  assert (C : Rabs d * k <= Rabs d * 1) by (apply Rmult_le_compat_l; lra).
  lra.
Qed.

Lemma h_X : forall x0 x1 C0 C1 d0 d1 QA QB cc, x0 = C0 + d0 -> x1 = C1 + d1 ->
  0 <= C0 <= 1 -> 0 <= C1 <= 1 -> Rabs d0 <= 1.006e-7 -> Rabs d1 <= 1.006e-7 ->
  0 <= QA <= 1 + / 1048576 -> 0 <= QB <= 1 + / 1048576 -> C0 * C0 + C1 * C1 + 2 * cc = 1 ->
  x0 * x0 * QA + x1 * x1 * QB <= 1 - 2 * cc + 2.4e-6.
Proof.
  intros x0 x1 C0 C1 d0 d1 QA QB cc E0 E1 H0 H1 D0 D1 HA HB One.
  assert (S : forall C d x, x = C + d -> 0 <= C <= 1 -> Rabs d <= 1.006e-7 ->
    x * x <= C * C + 2.013e-7 /\ x * x <= 1.0000003).
  { intros C d x E HC Hd. subst x. pose proof (Rabs_pos d).
    assert (Rabs (C * d) <= 1 * 1.006e-7) by (rewrite Rabs_mult, (Rabs_right C) by lra; apply Rmult_le_compat; lra).
    assert (d * d <= 1.006e-7 * 1.006e-7) by (rewrite <- sq_abs; apply Rmult_le_compat; lra).
    apply Rabs_le_inv in H2.
    assert (C * C <= 1 * 1) by (apply Rmult_le_compat; lra).
    split; lra. }
  destruct (S C0 d0 x0 E0 H0 D0) as [A0 B0]. destruct (S C1 d1 x1 E1 H1 D1) as [A1 B1].
  assert (0 <= x0 * x0) by apply Rle_0_sqr. assert (0 <= x1 * x1) by apply Rle_0_sqr.
  assert (x0 * x0 * QA <= x0 * x0 * (1 + / 1048576)) by (apply Rmult_le_compat_l; lra).
  assert (x1 * x1 * QB <= x1 * x1 * (1 + / 1048576)) by (apply Rmult_le_compat_l; lra).
  lra.
Qed.

Theorem slerp_norm_f64 : forall a0 a1 a2 a3 b0 b1 b2 b3 alpha t2 c0 c1 : R,
  0 <= alpha <= 1 -> 0 < t2 <= 1 ->
  let phi := 2 * atan (sqrt t2) in
  let C0 := sin ((1 - alpha) * phi) / sin phi in
  let C1 := sin (alpha * phi) / sin phi in
  Rabs (c0 - C0) <= 4.09e-8 * C0 ->
  Rabs (c1 - C1) <= 4.09e-8 * C1 ->
  let QA := a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3 in
  let QB := b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3 in
  let D := a0 * b0 + a1 * b1 + a2 * b2 + a3 * b3 in
  1 - / 1048576 <= QA <= 1 + / 1048576 ->
  1 - / 1048576 <= QB <= 1 + / 1048576 ->
  Rabs ((1 - t2) / (1 + t2) - 2 * D / (QA + QB)) <= 4e-15 ->
  let x0 := rnd c0 in
  let x1 := rnd c1 in
  let r0 := rnd (rnd (x0 * a0) + rnd (x1 * b0)) in
  let r1 := rnd (rnd (x0 * a1) + rnd (x1 * b1)) in
  let r2 := rnd (rnd (x0 * a2) + rnd (x1 * b2)) in
  let r3 := rnd (rnd (x0 * a3) + rnd (x1 * b3)) in
  let m := C0 * cos (alpha * phi) * sqrt QA + C1 * cos ((1 - alpha) * phi) * sqrt QB in
  Rabs (n4 r0 r1 r2 r3 / m - 1) <= 2.2e-7.
Proof.
  intros a0 a1 a2 a3 b0 b1 b2 b3 alpha t2 c0 c1 Ha Ht phi C0 C1 Hc0 Hc1 QA QB D HQA HQB Hang
    x0 x1 r0 r1 r2 r3 m.
  pose proof u_pos as Hu; pose proof eta_pos as He.
  assert (Hu1 : u = / 16777216) by reflexivity.
  assert (Heta : eta <= / 1000000000000000000000000000000) by (unfold eta; simpl; lra).
  destruct (slerp_trig alpha t2 Ha Ht) as (Hs0 & Hk0 & Hs1 & Hk1 & HS & Hs0S & Hs1S & Sp & Cp & P0 & P1 & Hc).
  fold phi in Hs0, Hk0, Hs1, Hk1, HS, Hs0S, Hs1S, Sp, Cp, P0, P1, Hc.
  set (s0 := sin ((1 - alpha) * phi)) in *. set (k0 := cos ((1 - alpha) * phi)) in *.
  set (s1 := sin (alpha * phi)) in *. set (k1 := cos (alpha * phi)) in *.
  set (S := sin phi) in *. set (cp := cos phi) in *.
  (* The exact coefficients. *)
  assert (E0 : C0 * S = s0) by (unfold C0; field; lra).
  assert (E1 : C1 * S = s1) by (unfold C1; field; lra).
  assert (HC0 : 0 <= C0 <= 1).
  { split; [unfold C0, Rdiv; apply Rmult_le_pos; [lra|left; apply Rinv_0_lt_compat; lra]|].
    apply (Rmult_le_reg_r S); [lra|]. rewrite E0. lra. }
  assert (HC1 : 0 <= C1 <= 1).
  { split; [unfold C1, Rdiv; apply Rmult_le_pos; [lra|left; apply Rinv_0_lt_compat; lra]|].
    apply (Rmult_le_reg_r S); [lra|]. rewrite E1. lra. }
  assert (Hcp : 0 <= cp <= 1).
  { rewrite Hc. split; [unfold Rdiv; apply Rmult_le_pos; [lra|left; apply Rinv_0_lt_compat; lra]|].
    apply (Rmult_le_reg_r (1 + t2)); [lra|]. unfold Rdiv. rewrite Rmult_assoc, Rinv_l by lra. lra. }
  assert (K1 : C0 + C1 * cp = k1).
  { assert (Z : (C0 + C1 * cp - k1) * S = 0).
    { replace ((C0 + C1 * cp - k1) * S) with (C0 * S + C1 * S * cp - k1 * S) by ring.
      rewrite E0, E1, Cp, Sp.
      replace (s0 + s1 * (k0 * k1 - s0 * s1) - k1 * (s0 * k1 + k0 * s1)) with (s0 * (1 - (s1 * s1 + k1 * k1))) by ring.
      rewrite P1. ring. }
    apply Rmult_integral in Z. destruct Z; lra. }
  assert (K0 : C1 + C0 * cp = k0).
  { assert (Z : (C1 + C0 * cp - k0) * S = 0).
    { replace ((C1 + C0 * cp - k0) * S) with (C1 * S + C0 * S * cp - k0 * S) by ring.
      rewrite E0, E1, Cp, Sp.
      replace (s1 + s0 * (k0 * k1 - s0 * s1) - k0 * (s0 * k1 + k0 * s1)) with (s1 * (1 - (s0 * s0 + k0 * k0))) by ring.
      rewrite P0. ring. }
    apply Rmult_integral in Z. destruct Z; lra. }
  assert (One : C0 * C0 + C1 * C1 + 2 * C0 * C1 * cp = 1).
  { assert (Z : (C0 * C0 + C1 * C1 + 2 * C0 * C1 * cp - 1) * (S * S) = 0).
    { replace ((C0 * C0 + C1 * C1 + 2 * C0 * C1 * cp - 1) * (S * S))
        with ((C0 * S) * (C0 * S) + (C1 * S) * (C1 * S) + 2 * (C0 * S) * (C1 * S) * cp - S * S) by ring.
      rewrite E0, E1, Cp, Sp.
      replace (s0 * s0 + s1 * s1 + 2 * s0 * s1 * (k0 * k1 - s0 * s1) - (s0 * k1 + k0 * s1) * (s0 * k1 + k0 * s1))
        with (s0 * s0 * (1 - (k1 * k1 + s1 * s1)) + s1 * s1 * (1 - (k0 * k0 + s0 * s0))) by ring.
      replace (k1 * k1 + s1 * s1) with 1 by lra. replace (k0 * k0 + s0 * s0) with 1 by lra. ring. }
    assert (0 < S * S) by (apply Rmult_lt_0_compat; lra).
    apply Rmult_integral in Z. destruct Z as [Z|Z]; lra. }
  pose proof (h_sum C0 C1 cp (proj1 HC0) (proj1 HC1) (proj1 Hcp) One) as HSum.
  set (w0 := C0 * k1). set (w1 := C1 * k0).
  assert (Hw : w0 + w1 = 1) by (unfold w0, w1; rewrite <- K0, <- K1; lra).
  assert (Hw0 : 0 <= w0) by (unfold w0; apply Rmult_le_pos; lra).
  assert (Hw1 : 0 <= w1) by (unfold w1; apply Rmult_le_pos; lra).
  assert (Hk1' : k1 <= 1) by (unfold k1; apply COS_bound).
  assert (Hk0' : k0 <= 1) by (unfold k0; apply COS_bound).
  (* The norms. *)
  set (na := sqrt QA). set (nb := sqrt QB).
  assert (Qa : na * na = QA) by (apply sqrt_sqrt; lra).
  assert (Qb : nb * nb = QB) by (apply sqrt_sqrt; lra).
  pose proof (h_norm QA HQA) as Na. pose proof (h_norm QB HQB) as Nb. fold na in Na. fold nb in Nb.
  assert (Dab : (na - nb) * (na - nb) <= 9.2e-13)
    by (apply h_diff; try lra; rewrite ?Qa, ?Qb; lra).
  assert (Hm : m = w0 * na + w1 * nb) by (unfold m, w0, w1, na, nb; ring).
  destruct (h_mean w0 w1 na nb Hw0 Hw1 Hw Na Nb) as [Nm Hww]. rewrite <- Hm in Nm.
  (* The rounded coefficients. *)
  pose proof (h_coef c0 C0 HC0 Hc0) as X0. pose proof (h_coef c1 C1 HC1 Hc1) as X1.
  pose proof (h_coef_half c0 C0 HC0 Hc0) as Y0. pose proof (h_coef_half c1 C1 HC1 Hc1) as Y1.
  fold x0 in X0, Y0. fold x1 in X1, Y1.
  set (d0 := x0 - C0) in *. set (d1 := x1 - C1) in *.
  assert (Hd0 : Rabs d0 <= 1.006e-7) by lra.
  assert (Hd1 : Rabs d1 <= 1.006e-7) by lra.
  (* The angle. *)
  rewrite <- Hc in Hang.
  pose proof (h_Dd cp D QA QB ltac:(lra) Hang) as HDd.
  set (Dd := D - cp * (QA + QB) / 2) in *.
  assert (HD : Rabs D <= 1.000001).
  { replace D with (cp * (QA + QB) / 2 + Dd) by (unfold Dd; ring).
    pose proof (Rabs_triang (cp * (QA + QB) / 2) Dd).
    assert (0 <= cp * (QA + QB) / 2 <= 1.000000954).
    { assert (0 <= cp * (QA + QB) <= 1 * (QA + QB)) by (split; [apply Rmult_le_pos|apply Rmult_le_compat_r]; lra). lra. }
    rewrite (Rabs_right (cp * (QA + QB) / 2)) in * by lra. lra. }
  (* The exact sum of the rounded coefficients' terms. *)
  set (R0 := x0 * a0 + x1 * b0). set (R1 := x0 * a1 + x1 * b1).
  set (R2 := x0 * a2 + x1 * b2). set (R3 := x0 * a3 + x1 * b3).
  set (nR := n4 R0 R1 R2 R3).
  assert (NR2 : nR * nR = x0 * x0 * QA + x1 * x1 * QB + 2 * x0 * x1 * D)
    by (unfold nR; rewrite n4_sq; unfold R0, R1, R2, R3, QA, QB, D; ring).
  set (G0 := C0 * QA + C1 * D). set (G1 := C1 * QB + C0 * D).
  assert (Split : nR * nR - m * m = w0 * w1 * ((na - nb) * (na - nb)) + (2 * (d0 * G0) + 2 * (d1 * G1))
     + (d0 * d0 * QA + d1 * d1 * QB + 2 * d0 * d1 * D) + 2 * C0 * C1 * Dd).
  { assert (E : nR * nR - m * m = w0 * w1 * ((na - nb) * (na - nb)) + (2 * (d0 * G0) + 2 * (d1 * G1))
       + (d0 * d0 * QA + d1 * d1 * QB + 2 * d0 * d1 * D) + 2 * C0 * C1 * Dd
       + (1 - w0 - w1) * (w0 * QA + w1 * QB)).
    { rewrite NR2, Hm. unfold d0, d1, G0, G1, Dd, w0, w1. rewrite <- Qa, <- Qb, <- K0, <- K1. field. }
    rewrite E. replace (1 - w0 - w1) with 0 by lra. ring. }
  assert (BG0 : Rabs G0 <= k1 * QA + 9.6e-7).
  { replace G0 with (k1 * QA + C1 * cp * (QB - QA) / 2 + C1 * Dd) by (unfold G0, Dd; rewrite <- K1; field).
    apply h_G; try lra. apply Rabs_le; lra. }
  assert (BG1 : Rabs G1 <= k0 * QB + 9.6e-7).
  { replace G1 with (k0 * QB + C0 * cp * (QA - QB) / 2 + C0 * Dd) by (unfold G1, Dd; rewrite <- K0; field).
    apply h_G; try lra. apply Rabs_le; lra. }
  assert (M0 : 1/2 <= C0 -> Rabs d0 <= 4.09e-8 * C0 + u / 2 \/ (Rabs d0 <= 4.09e-8 * C0 + 4.09e-8 /\ 1 - 4.1e-8 <= C0))
    by (intros _; destruct Y0 as [[_ B]|[_ [B F]]]; [left; exact B|right; split; assumption]).
  assert (M1 : 1/2 <= C1 -> Rabs d1 <= 4.09e-8 * C1 + u / 2 \/ (Rabs d1 <= 4.09e-8 * C1 + 4.09e-8 /\ 1 - 4.1e-8 <= C1))
    by (intros _; destruct Y1 as [[_ B]|[_ [B F]]]; [left; exact B|right; split; assumption]).
  pose proof (h_key C0 C1 cp k0 k1 d0 d1 HC0 HC1 Hcp K1 K0 (conj Hk0 Hk0') (conj Hk1 Hk1') One X0 X1 M0 M1) as KEY.
  fold w0 w1 in KEY. unfold u in KEY.
  assert (CC : 0 <= C0 * C1 * cp <= / 2).
  { assert (0 <= C0 * C1) by (apply Rmult_le_pos; lra).
    assert (0 <= C0 * C1 * cp) by (apply Rmult_le_pos; lra).
    assert (0 <= C0 * C0) by apply Rle_0_sqr. assert (0 <= C1 * C1) by apply Rle_0_sqr. lra. }
  pose proof (h_first2 d0 G0 k1 QA (conj Hk1 Hk1') ltac:(lra) Hd0 BG0) as A0.
  pose proof (h_first2 d1 G1 k0 QB (conj Hk0 Hk0') ltac:(lra) Hd1 BG1) as A1.
  pose proof (h_second d0 d1 QA QB D Hd0 Hd1 ltac:(lra) ltac:(lra) HD) as F2.
  assert (F3 : Rabs (2 * C0 * C1 * Dd) <= 8.2e-15).
  { rewrite !Rabs_mult, (Rabs_right 2), (Rabs_right C0), (Rabs_right C1) by lra.
    assert (0 <= C0 * C1 <= 1) by (split; [apply Rmult_le_pos|rewrite <- (Rmult_1_l 1); apply Rmult_le_compat]; lra).
    pose proof (Rabs_pos Dd).
    assert (C0 * C1 * Rabs Dd <= 1 * 4.1e-15) by (apply Rmult_le_compat; lra). lra. }
  assert (F4 : 0 <= w0 * w1 * ((na - nb) * (na - nb)) <= 2.3e-13).
  { assert (0 <= w0 * w1) by (apply Rmult_le_pos; lra).
    assert (0 <= (na - nb) * (na - nb)) by apply Rle_0_sqr.
    split; [apply Rmult_le_pos; lra|].
    assert (w0 * w1 * ((na - nb) * (na - nb)) <= / 4 * 9.2e-13) by (apply Rmult_le_compat; lra). lra. }
  assert (YA : Rabs (nR * nR - m * m) <= 8.18e-8 + 2 * / 16777216 * (3/4 + C0 * C1 * cp) + 4e-12).
  { rewrite Split.
    pose proof (Rabs_triang (w0 * w1 * ((na - nb) * (na - nb)) + (2 * (d0 * G0) + 2 * (d1 * G1))
      + (d0 * d0 * QA + d1 * d1 * QB + 2 * d0 * d1 * D)) (2 * C0 * C1 * Dd)).
    pose proof (Rabs_triang (w0 * w1 * ((na - nb) * (na - nb)) + (2 * (d0 * G0) + 2 * (d1 * G1)))
      (d0 * d0 * QA + d1 * d1 * QB + 2 * d0 * d1 * D)).
    pose proof (Rabs_triang (w0 * w1 * ((na - nb) * (na - nb))) (2 * (d0 * G0) + 2 * (d1 * G1))).
    pose proof (Rabs_triang (2 * (d0 * G0)) (2 * (d1 * G1))).
    rewrite !(Rabs_mult 2), (Rabs_right 2) in * by lra.
    rewrite (Rabs_right (w0 * w1 * ((na - nb) * (na - nb)))) in * by lra.
    lra. }
  (* The rounding of the weighted sum. *)
  pose proof (sum2_err x0 x1 a0 b0) as S0. pose proof (sum2_err x0 x1 a1 b1) as S1.
  pose proof (sum2_err x0 x1 a2 b2) as S2. pose proof (sum2_err x0 x1 a3 b3) as S3.
  fold r0 R0 in S0. fold r1 R1 in S1. fold r2 R2 in S2. fold r3 R3 in S3.
  pose proof (projection x0 x1 a0 a1 a2 a3 b0 b1 b2 b3 (r0 - R0) (r1 - R1) (r2 - R2) (r3 - R3) S0 S1 S2 S3) as PJ.
  cbv zeta in PJ. fold R0 R1 R2 R3 nR QA QB in PJ.
  assert (HnR : 0 <= nR <= 1.0000007).
  { split; [apply n4_pos|]. rewrite <- (Rabs_right nR) by (apply Rle_ge, n4_pos).
    apply h_le_sq; [lra|].
    assert (m * m <= 1.0000005 * 1.0000005) by (apply Rmult_le_compat; lra).
    apply Rabs_le_inv in YA. lra. }
  destruct (h_xs x0 x1 C0 C1 na nb (proj1 HC0) (proj1 HC1) HSum X0 X1 ltac:(lra) ltac:(lra)) as (Hx & Hx0 & Hx1).
  pose proof (h_X x0 x1 C0 C1 d0 d1 QA QB (C0 * C1 * cp) ltac:(unfold d0; ring) ltac:(unfold d1; ring)
    HC0 HC1 Hd0 Hd1 ltac:(lra) ltac:(lra) ltac:(lra)) as XB.
  pose proof (h_proj nR (x0 * x0 * QA + x1 * x1 * QB) _ (C0 * C1 * cp) HnR (proj1 CC) XB PJ) as PJ2.
  (* Each component's error, squared. *)
  assert (Bx0 : Rabs x0 <= 1.0000002) by lra. assert (Bx1 : Rabs x1 <= 1.0000002) by lra.
  assert (Ai : forall t, t * t <= QA -> Rabs t <= 1.0000005) by (intros t Htt; apply h_le_sq; lra).
  assert (Bi : forall t, t * t <= QB -> Rabs t <= 1.0000005) by (intros t Htt; apply h_le_sq; lra).
  assert (Ri : forall t, t * t <= nR * nR -> Rabs t <= 1.0000007)
    by (intros t Htt; apply h_le_sq; [lra|]; assert (nR * nR <= 1.0000007 * 1.0000007) by (apply Rmult_le_compat; lra); lra).
  assert (SQ : forall p q r s, 0 <= p * p /\ 0 <= q * q /\ 0 <= r * r /\ 0 <= s * s) by (intros; repeat split; apply Rle_0_sqr).
  assert (NR2' : nR * nR = R0 * R0 + R1 * R1 + R2 * R2 + R3 * R3) by (unfold nR; apply n4_sq).
  destruct (SQ a0 a1 a2 a3) as (Sa0 & Sa1 & Sa2 & Sa3). destruct (SQ b0 b1 b2 b3) as (Sb0 & Sb1 & Sb2 & Sb3).
  destruct (SQ R0 R1 R2 R3) as (SR0 & SR1 & SR2 & SR3).
  pose proof (h_eps x0 x1 a0 b0 R0 (r0 - R0) Bx0 Bx1 ltac:(apply Ai; unfold QA; lra) ltac:(apply Bi; unfold QB; lra) ltac:(apply Ri; lra) S0) as Q0.
  pose proof (h_eps x0 x1 a1 b1 R1 (r1 - R1) Bx0 Bx1 ltac:(apply Ai; unfold QA; lra) ltac:(apply Bi; unfold QB; lra) ltac:(apply Ri; lra) S1) as Q1.
  pose proof (h_eps x0 x1 a2 b2 R2 (r2 - R2) Bx0 Bx1 ltac:(apply Ai; unfold QA; lra) ltac:(apply Bi; unfold QB; lra) ltac:(apply Ri; lra) S2) as Q2.
  pose proof (h_eps x0 x1 a3 b3 R3 (r3 - R3) Bx0 Bx1 ltac:(apply Ai; unfold QA; lra) ltac:(apply Bi; unfold QB; lra) ltac:(apply Ri; lra) S3) as Q3.
  (* The norm of the result. *)
  set (nr := n4 r0 r1 r2 r3).
  assert (NR : nr * nr = nR * nR + 2 * (R0 * (r0 - R0) + R1 * (r1 - R1) + R2 * (r2 - R2) + R3 * (r3 - R3))
     + ((r0 - R0) * (r0 - R0) + (r1 - R1) * (r1 - R1) + (r2 - R2) * (r2 - R2) + (r3 - R3) * (r3 - R3)))
    by (unfold nr; rewrite n4_sq, NR2'; ring).
  assert (Y : Rabs (nr * nr - m * m) <= 4.395e-7).
  { replace (nr * nr - m * m) with ((nR * nR - m * m) + 2 * (R0 * (r0 - R0) + R1 * (r1 - R1) + R2 * (r2 - R2) + R3 * (r3 - R3))
     + ((r0 - R0) * (r0 - R0) + (r1 - R1) * (r1 - R1) + (r2 - R2) * (r2 - R2) + (r3 - R3) * (r3 - R3))) by (rewrite NR; ring).
    set (P := R0 * (r0 - R0) + R1 * (r1 - R1) + R2 * (r2 - R2) + R3 * (r3 - R3)) in *.
    set (Q := (r0 - R0) * (r0 - R0) + (r1 - R1) * (r1 - R1) + (r2 - R2) * (r2 - R2) + (r3 - R3) * (r3 - R3)).
    assert (0 <= Q <= 1.4e-13).
    { unfold Q. pose proof (Rle_0_sqr (r0 - R0)); pose proof (Rle_0_sqr (r1 - R1));
      pose proof (Rle_0_sqr (r2 - R2)); pose proof (Rle_0_sqr (r3 - R3)). unfold Rsqr in *. lra. }
    pose proof (Rabs_triang (nR * nR - m * m + 2 * P) Q). pose proof (Rabs_triang (nR * nR - m * m) (2 * P)).
    rewrite (Rabs_mult 2), (Rabs_right 2) in * by lra. rewrite (Rabs_right Q) in * by lra. lra. }
  apply (sqrt_step nr m (Rabs (nr * nr - m * m))); [apply n4_pos|lra|split; [apply Rabs_pos|lra]|lra].
Qed.
