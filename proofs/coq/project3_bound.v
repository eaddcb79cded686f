(* The projection and the rejection of Cvec3 (src/vec/template/lengths.rs,
   project_onto and reject_from, as project4_bound.v states them for
   Cvec4): the same computation with a zero fourth component, which
   scale_for_squares adds to the sum of squares (the rnd (0 * 0) of s)
   and the dot product and the scaling leave out, so that the error
   vectors against the exact projection P = (a . b / |b|^2) b and
   rejection a - P are at most 7.7584e-7 |a| and 7.8175e-7 |a| long
   (project3_main), the larger over |a| at most 7.83e-7 (project3), on
   the domain of project4_bound.v. The rounded terms are those of
   proofs/gappa/project3.g, which computes the code's bits (the
   correspondence test checks both). *)
(*! bound PROJECT_MAX_REL_ERROR project3 <= 7.83e-7 the larger of |project_onto - P| / |a| and |reject_from - (a - P)| / |a|, Cvec3 *)
Require Import Reals Psatz.
Require Import Flocq.Core.Core.
Require Import Laws.Common.
Require Import Laws.project4_bound.

Open Scope R_scope.

Lemma rnd_rnd : forall x, rnd (rnd x) = rnd x.
Proof.
  intro x. apply round_generic; [apply valid_rnd_N|].
  apply generic_format_round; [apply FLT_exp_valid; reflexivity|apply valid_rnd_N].
Qed.

Lemma rnd_zero_mul : forall x, rnd (0 * x) = 0.
Proof. intro x. rewrite Rmult_0_l. apply rnd_0. Qed.

Lemma rnd_zero_div : forall x, rnd (0 / x) = 0.
Proof. intro x. unfold Rdiv. apply rnd_zero_mul. Qed.

Lemma n4_n3 : forall a b c, n4 a b c 0 = n3 a b c.
Proof. intros. unfold n4, n3. f_equal. ring. Qed.

Ltac three :=
  repeat (rewrite ?rnd_0, ?rnd_zero_div, ?rnd_zero_mul, ?Rmult_0_l, ?Rmult_0_r,
            ?Rplus_0_r, ?Rminus_0_r, ?rnd_rnd, ?n4_n3).
Ltac three_in M :=
  repeat (rewrite ?rnd_0, ?rnd_zero_div, ?rnd_zero_mul, ?Rmult_0_l, ?Rmult_0_r,
            ?Rplus_0_r, ?Rminus_0_r, ?rnd_rnd, ?n4_n3 in M).

Lemma project3_main : forall a0 a1 a2 B0 B1 B2 : R,
  1 <= rnd B0 * rnd B0 + rnd B1 * rnd B1 + rnd B2 * rnd B2 <= 4 ->
  / 2 ^ 100 <= n3 a0 a1 a2 ->
  let sq := rnd (rnd (rnd (rnd (rnd B0 * rnd B0) + rnd (rnd B1 * rnd B1)) + rnd (rnd B2 * rnd B2))
                + rnd (0 * 0)) in
  let nq := rnd (sqrt (sq)) in
  let tq := rnd (rnd (rnd (a0 * rnd (rnd B0 / nq)) + rnd (a1 * rnd (rnd B1 / nq)))
                + rnd (a2 * rnd (rnd B2 / nq))) in
  let T := (a0 * rnd B0 + a1 * rnd B1 + a2 * rnd B2)
           / (rnd B0 * rnd B0 + rnd B1 * rnd B1 + rnd B2 * rnd B2) in
  n3 (rnd (rnd (rnd B0 / nq) * tq) - T * rnd B0) (rnd (rnd (rnd B1 / nq) * tq) - T * rnd B1)
     (rnd (rnd (rnd B2 / nq) * tq) - T * rnd B2) <= 7.7584e-7 * n3 a0 a1 a2 /\
  n3 (rnd (a0 - rnd (rnd (rnd B0 / nq) * tq)) - (a0 - T * rnd B0))
     (rnd (a1 - rnd (rnd (rnd B1 / nq) * tq)) - (a1 - T * rnd B1))
     (rnd (a2 - rnd (rnd (rnd B2 / nq) * tq)) - (a2 - T * rnd B2)) <= 7.8175e-7 * n3 a0 a1 a2.
Proof.
  intros a0 a1 a2 B0 B1 B2 HS Ha. cbv zeta.
  pose proof (project4_main a0 a1 a2 0 B0 B1 B2 0) as M. cbv zeta in M.
  three. three_in M. apply M; assumption.
Qed.

Theorem project3 : forall a0 a1 a2 B0 B1 B2 : R,
  let b0 := rnd B0 in
  let b1 := rnd B1 in
  let b2 := rnd B2 in
  1 <= b0 * b0 + b1 * b1 + b2 * b2 <= 4 ->
  / 2 ^ 100 <= n3 a0 a1 a2 ->
  let s := rnd (rnd (rnd (rnd (b0 * b0) + rnd (b1 * b1)) + rnd (b2 * b2)) + rnd (0 * 0)) in
  let n := rnd (sqrt (s)) in
  let u0 := rnd (b0 / n) in
  let u1 := rnd (b1 / n) in
  let u2 := rnd (b2 / n) in
  let t := rnd (rnd (rnd (a0 * u0) + rnd (a1 * u1)) + rnd (a2 * u2)) in
  let p0 := rnd (u0 * t) in
  let p1 := rnd (u1 * t) in
  let p2 := rnd (u2 * t) in
  let r0 := rnd (a0 - p0) in
  let r1 := rnd (a1 - p1) in
  let r2 := rnd (a2 - p2) in
  let T := (a0 * b0 + a1 * b1 + a2 * b2) / (b0 * b0 + b1 * b1 + b2 * b2) in
  Rmax (n3 (p0 - T * b0) (p1 - T * b1) (p2 - T * b2) / n3 a0 a1 a2)
       (n3 (r0 - (a0 - T * b0)) (r1 - (a1 - T * b1)) (r2 - (a2 - T * b2)) / n3 a0 a1 a2) <= 7.83e-7.
Proof.
  intros a0 a1 a2 B0 B1 B2 b0 b1 b2 HS Ha.
  assert (Hpos : 0 < n3 a0 a1 a2)
    by (assert (0 < / 2 ^ 100) by (apply Rinv_0_lt_compat, pow_lt; lra); lra).
  pose proof (project3_main a0 a1 a2 B0 B1 B2 HS Ha) as M. cbv zeta in M |- *.
  unfold b0, b1, b2 in *. destruct M as [Hp Hr].
  apply Rmax_lub; apply ratio; try assumption; lra.
Qed.
