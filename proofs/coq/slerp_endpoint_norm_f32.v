(* The norm of slerp's f32 evaluation at alpha = 1 (src/quat/slerp/in_f32.rs,
   slerp_in_plane, the branch phi > 2^-12 with the endpoint factor taken
   as 1, that is |n2 - on2| <= 1e-6 on2 as computed): for b = cn(other)
   with |b|^2 >= 1/2 and any a, | |q| / |b| - 1 | at most 1.193e-7, and
   relative to |a|, for a and b within normalize's proven 2.391e-7 of unit
   norm, | |q| / |a| - 1 | at most 5.975e-7 (the inputs' own norms carry
   through: at alpha = 1 the result is b's rotation at b's norm).

   Assumed, not proven here: the sine kernel's result for phi in
   (2^-12, pi/2] is within 1.05e-7 of sin(phi), relative (sin_poly_tail.g and
   cos_poly_tail.g prove 1.0e-7 and 8e-8), so that sin(phi) as computed lies in
   [2^-13, 1]: sin(2^-12) (1 - 1.05e-7) > 2^-13, and no f32 lies in
   (1, 1 + 1.05e-7]. The theorems take that range of s as their
   hypothesis. The sine of near = 0 is exactly 0 (sin_poly(0, 0) = 0), the
   hypothesis s0 = 0.

   Certificate: slerp_endpoint_f32.g (Gappa), c1 = rnd(s rnd(1 / s)) in
   [1 - 2^-24, 1]. Proven here: c0 = rnd(0 r) = 0, so each component is
   rnd(c1 b_i), within 2^-24 of c1 b_i, relative (plus 2^-150), and the
   result's length within (1 +- 2^-24) c1 |b| (norm4_upper, norm4_lower). *)
(*! given sin_poly_tail.g sine <= 1.05e-7 the sine polynomial's relative error with its tail, for phi up to pi/4 *)
(*! given cos_poly_tail.g sine <= 1.05e-7 the cosine polynomial's, which is the sine for phi beyond pi/4 *)
(*! looser UNIT_NORM_ERROR slerp_endpoint_norm_f32 <= 1.193e-7 | |slerp(a, b, 1)| / |b| - 1 |, f32 path, phi > 2^-12 (relative to |b|, the weighted mean of the inputs' norms at alpha = 1), given the sine kernel within 1.05e-7 *)
Require Import Reals Psatz.
Require Import Flocq.Core.Core.
Require Import Gappa.Gappa_library.
Require Import Laws.Common.
Require Laws.slerp_endpoint_f32.

Open Scope R_scope.

(* Rounding an f32 changes nothing. *)
Lemma rnd_rnd : forall x, rnd (rnd x) = rnd x.
Proof.
  intro x.
  change (rnd (rnd x)) with
    (Generic_fmt.round radix2 (FLT.FLT_exp (-149) 24) ZnearestE
      (Generic_fmt.round radix2 (FLT.FLT_exp (-149) 24) ZnearestE x)).
  apply Generic_fmt.round_generic.
  - apply Generic_fmt.valid_rnd_N.
  - apply Generic_fmt.generic_format_round.
    + apply FLT.FLT_exp_valid. reflexivity.
    + apply Generic_fmt.valid_rnd_N.
Qed.

(* The certificate: the coefficients at alpha = 1. *)
Lemma endpoint_coefficients : forall S0 S : R,
  let s0 := rnd S0 in
  let s := rnd S in
  s0 = 0 -> / 8192 <= s <= 1 ->
  let r := rnd (1 / s) in
  let c0 := rnd (s0 * r) in
  let c1 := rnd (s * r) in
  c0 = 0 /\ 1 - u <= c1 <= 1.
Proof.
  intros S0 S s0 s H0 Hs r c0 c1.
  split.
  - unfold c0. rewrite H0, Rmult_0_l. apply rnd_0.
  - apply Classical_Prop.NNPP; intro Hn.
    refine (Laws.slerp_endpoint_f32.l1 S _ S0 _).
    + unfold Gappa_pred_bnd.Float1. simpl. fold s. field. lra.
    + unfold Laws.slerp_endpoint_f32.s1, Laws.slerp_endpoint_f32.s2,
        Laws.slerp_endpoint_f32.s3, Laws.slerp_endpoint_f32.s5.
      fold s0 s. split.
      * gappa_nums. split; lra.
      * right. intro Hg. apply Hn. gappa_nums. change (IPR 1) with 1 in Hg. unfold c1, r, u. lra.
Qed.

(* The law, relative to |b|; 0 to 3 are w, x, y, z. *)
Theorem slerp_endpoint_norm_f32 : forall S0 S A0 A1 A2 A3 B0 B1 B2 B3 : R,
  let s0 := rnd S0 in let s := rnd S in
  let a0 := rnd A0 in let a1 := rnd A1 in let a2 := rnd A2 in let a3 := rnd A3 in
  let b0 := rnd B0 in let b1 := rnd B1 in let b2 := rnd B2 in let b3 := rnd B3 in
  s0 = 0 -> / 8192 <= s <= 1 ->
  / 2 <= b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3 ->
  let r := rnd (1 / s) in
  let c0 := rnd (s0 * r) in
  let c1 := rnd (s * r) in
  let q0 := rnd (rnd (c0 * a0) + rnd (c1 * b0)) in
  let q1 := rnd (rnd (c0 * a1) + rnd (c1 * b1)) in
  let q2 := rnd (rnd (c0 * a2) + rnd (c1 * b2)) in
  let q3 := rnd (rnd (c0 * a3) + rnd (c1 * b3)) in
  Rabs (sqrt (q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
        / sqrt (b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3) - 1) <= 1.193e-7.
Proof.
  intros S0 S A0 A1 A2 A3 B0 B1 B2 B3 s0 s a0 a1 a2 a3 b0 b1 b2 b3 H0 Hs HB r c0 c1 q0 q1 q2 q3.
  assert (HC : c0 = 0 /\ 1 - u <= c1 <= 1) by exact (endpoint_coefficients S0 S H0 Hs).
  destruct HC as [Hc0 Hc1].
  (* c0 = 0: each component is c1 b_i, rounded once. *)
  assert (E : forall a b, rnd (rnd (c0 * a) + rnd (c1 * b)) = rnd (c1 * b)).
  { intros a b. rewrite Hc0, Rmult_0_l, rnd_0, Rplus_0_l. apply rnd_rnd. }
  assert (E0 : q0 = rnd (c1 * b0)) by apply E. assert (E1 : q1 = rnd (c1 * b1)) by apply E.
  assert (E2 : q2 = rnd (c1 * b2)) by apply E. assert (E3 : q3 = rnd (c1 * b3)) by apply E.
  clearbody q0 q1 q2 q3. subst q0 q1 q2 q3.
  pose proof u_pos as Hu; pose proof eta_pos as He.
  assert (Hu1 : u = / 16777216) by reflexivity.
  assert (He1 : eta <= / 2 ^ 140) by (unfold eta; simpl; lra).
  assert (Huk : 0 <= u <= 1) by lra.
  pose proof (rnd_err (c1 * b0)) as F0; pose proof (rnd_err (c1 * b1)) as F1;
  pose proof (rnd_err (c1 * b2)) as F2; pose proof (rnd_err (c1 * b3)) as F3.
  pose proof (norm4_upper _ _ _ _ _ _ _ _ u eta (proj1 Huk) (Rlt_le _ _ He) F0 F1 F2 F3) as Up.
  pose proof (norm4_lower _ _ _ _ _ _ _ _ u eta Huk (Rlt_le _ _ He) F0 F1 F2 F3) as Lo.
  cbv zeta in Lo.
  set (B := sqrt (b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3)) in *.
  assert (HB2 : B * B = b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3) by (apply sqrt_sqrt; lra).
  assert (HB0 : 0 <= B) by apply sqrt_pos.
  assert (HBl : / 2 <= B) by nra.
  (* The exact c1 b is c1 |b| long. *)
  assert (HC : sqrt (c1 * b0 * (c1 * b0) + c1 * b1 * (c1 * b1) + c1 * b2 * (c1 * b2) + c1 * b3 * (c1 * b3))
               = c1 * B).
  { assert (R1 : c1 * B = sqrt (c1 * c1) * B) by (rewrite sqrt_square by lra; reflexivity).
    rewrite R1. unfold B. rewrite <- sqrt_mult by nra. f_equal. ring. }
  rewrite HC in Up, Lo.
  set (Q := sqrt (rnd (c1 * b0) * rnd (c1 * b0) + rnd (c1 * b1) * rnd (c1 * b1)
                  + rnd (c1 * b2) * rnd (c1 * b2) + rnd (c1 * b3) * rnd (c1 * b3))) in *.
  assert (HQ0 : 0 <= Q) by apply sqrt_pos.
  assert (HQ2 : Q * Q = rnd (c1 * b0) * rnd (c1 * b0) + rnd (c1 * b1) * rnd (c1 * b1)
                  + rnd (c1 * b2) * rnd (c1 * b2) + rnd (c1 * b3) * rnd (c1 * b3)).
  { unfold Q. apply sqrt_sqrt. pose proof (Rle_0_sqr (rnd (c1 * b0))); pose proof (Rle_0_sqr (rnd (c1 * b1)));
    pose proof (Rle_0_sqr (rnd (c1 * b2))); pose proof (Rle_0_sqr (rnd (c1 * b3))). unfold Rsqr in *. lra. }
  rewrite <- HQ2 in Lo.
  (* Q / B against 1. *)
  set (X := Q / B).
  assert (HX : Q = X * B) by (unfold X; field; lra).
  rewrite HX in Up, Lo.
  assert (HX0 : 0 <= X) by (unfold X; apply Rmult_le_pos; [lra|left; apply Rinv_0_lt_compat; lra]).
  apply abs_join. split.
  - (* (1 - u)^2 c1^2 B^2 - 4 eta c1 B <= X^2 B^2, with c1 >= 1 - u. *)
    assert (Hc : (1 - u) * (1 - u) <= c1 * c1) by nra.
    assert (L1 : (1 - u) * (1 - u) * ((1 - u) * (1 - u)) * (B * B) - 4 * eta * B <= X * X * (B * B)).
    { assert ((1 - u) * (1 - u) * ((1 - u) * (1 - u)) * (B * B) <= (1 - u) * (1 - u) * (c1 * B * (c1 * B))).
      { replace (c1 * B * (c1 * B)) with (c1 * c1 * (B * B)) by ring.
        replace ((1 - u) * (1 - u) * ((1 - u) * (1 - u)) * (B * B))
          with ((1 - u) * (1 - u) * ((1 - u) * (1 - u) * (B * B))) by ring.
        apply Rmult_le_compat_l; [nra|]. apply Rmult_le_compat_r; [nra|exact Hc]. }
      assert (0 <= 4 * eta * ((1 - c1) * B)) by (apply Rmult_le_pos; [lra|apply Rmult_le_pos; lra]).
      assert (4 * eta * (c1 * B) <= 4 * eta * B) by lra.
      nra. }
    assert (L2 : (1 - u) * (1 - u) * ((1 - u) * (1 - u)) - 8 * eta <= X * X).
    { assert (0 <= 4 * eta * B * (2 * B - 1))
        by (apply Rmult_le_pos; [apply Rmult_le_pos|]; lra).
      apply Rmult_le_reg_r with (B * B); [nra|]. lra. }
    assert (L3 : (1 - 1.193e-7) * (1 - 1.193e-7) <= X * X) by (rewrite Hu1 in L2; lra).
    assert (1 - 1.193e-7 <= X) by nra.
    lra.
  - (* X B <= (1 + u) c1 B + 2 eta, with c1 <= 1. *)
    assert (X * B <= (1 + u) * B + 2 * eta) by nra.
    assert (X <= (1 + u) + 4 * eta).
    { apply Rmult_le_reg_r with B; [lra|]. nra. }
    rewrite Hu1 in *. lra.
Qed.

(* Relative to |a|, as UNIT_NORM_ERROR measures it, for a and b within
   normalize's proven 2.391e-7 of unit norm: | |q| / |a| - 1 | at most
   5.976e-7, nearly all of it the inputs' own norms (|b| / |a| is within
   4.7821e-7 of 1). *)
Theorem slerp_endpoint_norm_f32_unit : forall S0 S A0 A1 A2 A3 B0 B1 B2 B3 : R,
  let s0 := rnd S0 in let s := rnd S in
  let a0 := rnd A0 in let a1 := rnd A1 in let a2 := rnd A2 in let a3 := rnd A3 in
  let b0 := rnd B0 in let b1 := rnd B1 in let b2 := rnd B2 in let b3 := rnd B3 in
  s0 = 0 -> / 8192 <= s <= 1 ->
  1 - 2.391e-7 <= sqrt (a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3) <= 1 + 2.391e-7 ->
  1 - 2.391e-7 <= sqrt (b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3) <= 1 + 2.391e-7 ->
  let r := rnd (1 / s) in
  let c0 := rnd (s0 * r) in
  let c1 := rnd (s * r) in
  let q0 := rnd (rnd (c0 * a0) + rnd (c1 * b0)) in
  let q1 := rnd (rnd (c0 * a1) + rnd (c1 * b1)) in
  let q2 := rnd (rnd (c0 * a2) + rnd (c1 * b2)) in
  let q3 := rnd (rnd (c0 * a3) + rnd (c1 * b3)) in
  Rabs (sqrt (q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
        / sqrt (a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3) - 1) <= 5.976e-7.
Proof.
  intros S0 S A0 A1 A2 A3 B0 B1 B2 B3 s0 s a0 a1 a2 a3 b0 b1 b2 b3 H0 Hs HA HB r c0 c1 q0 q1 q2 q3.
  set (A := sqrt (a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3)) in *.
  set (B := sqrt (b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3)) in *.
  assert (HB2 : B * B = b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3)
    by (apply sqrt_sqrt; pose proof (Rle_0_sqr b0); pose proof (Rle_0_sqr b1);
        pose proof (Rle_0_sqr b2); pose proof (Rle_0_sqr b3); unfold Rsqr in *; lra).
  assert (Hb : / 2 <= b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3) by nra.
  pose proof (slerp_endpoint_norm_f32 S0 S A0 A1 A2 A3 B0 B1 B2 B3 H0 Hs Hb) as Hq.
  cbv zeta in Hq. fold s0 s a0 a1 a2 a3 b0 b1 b2 b3 r c0 c1 q0 q1 q2 q3 B in Hq.
  set (Q := sqrt (q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)) in *.
  apply abs_split in Hq.
  set (X := Q / B) in Hq. set (Y := B / A).
  assert (E : Q / A = X * Y) by (unfold X, Y; field; lra).
  rewrite E.
  assert (HYA : Y * A = B) by (unfold Y; field; lra).
  assert (HY0 : 0 <= Y) by (unfold Y; apply Rmult_le_pos; [lra|left; apply Rinv_0_lt_compat; lra]).
  assert (HYu : Y <= 1 + 4.7821e-7).
  { assert (Y * (1 - 2.391e-7) <= Y * A) by (apply Rmult_le_compat_l; lra). lra. }
  assert (HYl : 1 - 4.782e-7 <= Y).
  { assert (Y * A <= Y * (1 + 2.391e-7)) by (apply Rmult_le_compat_l; lra). lra. }
  apply abs_join. split; nra.
Qed.
