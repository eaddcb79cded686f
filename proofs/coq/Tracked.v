(* Forward error analysis of a straight-line computation, one rounding at
   a time: `near x X A k e` says that the computed x is within k A + e of
   the exact X, where A bounds |X| (for a sum of products, the sum of the
   products' magnitudes). Each rounded operation multiplies the relative
   part by (1 + u) and adds u; the absolute part e collects the 2^-150 of
   roundings near underflow. This is the classical bound of a sum of terms
   whose every term carries its own rounding errors, |computed - exact| <=
   ((1 + u)^n - 1) sum |terms|, which interval arithmetic cannot state:
   it bounds each term's share by the whole. No law of its own; the laws
   of the determinants build on it. *)
Require Import Reals Psatz.
Require Import Laws.Common.

Open Scope R_scope.

Definition near (x X A k e : R) := Rabs X <= A /\ Rabs (x - X) <= k * A + e.

(* An f32 input is its own exact value. *)
Lemma near_exact : forall x, near x x (Rabs x) 0 0.
Proof.
  intro x. split; [lra|]. replace (x - x) with 0 by ring. rewrite Rabs_R0.
  pose proof (Rabs_pos x). lra.
Qed.

Lemma near_weaken : forall x X A k e k' e',
  near x X A k e -> 0 <= A -> k <= k' -> e <= e' -> near x X A k' e'.
Proof.
  intros x X A k e k' e' [H1 H2] HA Hk He. split; [exact H1|].
  assert (k * A <= k' * A) by (apply Rmult_le_compat_r; lra). lra.
Qed.

(* The rounding of a value within k A + e of X, with |X| <= A: within
   (u + k + u k) A + (1 + u) e + eta. *)
Lemma near_round : forall y Y A k e, 0 <= k -> 0 <= e ->
  Rabs Y <= A -> Rabs (y - Y) <= k * A + e ->
  near (rnd y) Y A (u + k + u * k) ((1 + u) * e + eta).
Proof.
  intros y Y A k e Hk He HY Hy. split; [exact HY|].
  pose proof (rnd_err y) as Hr. pose proof u_pos.
  assert (Hy2 : Rabs y <= (1 + k) * A + e).
  { pose proof (Rabs_triang_inv y Y). lra. }
  assert (u * Rabs y <= u * ((1 + k) * A + e)) by (apply Rmult_le_compat_l; lra).
  replace (rnd y - Y) with ((rnd y - y) + (y - Y)) by ring.
  eapply Rle_trans; [apply Rabs_triang|]. nra.
Qed.

Lemma near_add : forall x X A y Y B k e f, 0 <= k -> 0 <= e -> 0 <= f ->
  near x X A k e -> near y Y B k f ->
  near (rnd (x + y)) (X + Y) (A + B) (u + k + u * k) ((1 + u) * (e + f) + eta).
Proof.
  intros x X A y Y B k e f Hk He Hf [HX Hx] [HY Hy].
  apply near_round; try lra.
  - eapply Rle_trans; [apply Rabs_triang|lra].
  - replace (x + y - (X + Y)) with ((x - X) + (y - Y)) by ring.
    eapply Rle_trans; [apply Rabs_triang|lra].
Qed.

Lemma near_sub : forall x X A y Y B k e f, 0 <= k -> 0 <= e -> 0 <= f ->
  near x X A k e -> near y Y B k f ->
  near (rnd (x - y)) (X - Y) (A + B) (u + k + u * k) ((1 + u) * (e + f) + eta).
Proof.
  intros x X A y Y B k e f Hk He Hf [HX Hx] [HY Hy].
  apply near_round; try lra.
  - eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_Ropp. lra.
  - replace (x - y - (X - Y)) with ((x - X) + - (y - Y)) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_Ropp. lra.
Qed.

(* A product of two approximations. *)
Lemma near_mul : forall x X A y Y B k e f, 0 <= k -> 0 <= e -> 0 <= f ->
  near x X A k e -> near y Y B k f ->
  near (rnd (x * y)) (X * Y) (A * B) (u + (2 * k + k * k) + u * (2 * k + k * k))
    ((1 + u) * ((1 + k) * (A * f + B * e) + e * f) + eta).
Proof.
  intros x X A y Y B k e f Hk He Hf [HX Hx] [HY Hy].
  assert (HA : 0 <= A) by (pose proof (Rabs_pos X); lra).
  assert (HB : 0 <= B) by (pose proof (Rabs_pos Y); lra).
  apply near_round.
  - nra.
  - pose proof u_pos. repeat apply Rplus_le_le_0_compat; repeat apply Rmult_le_pos; nra.
  - rewrite Rabs_mult. apply Rmult_le_compat; try apply Rabs_pos; lra.
  - replace (x * y - X * Y) with ((x - X) * y + X * (y - Y)) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. rewrite !Rabs_mult.
    assert (Hy2 : Rabs y <= (1 + k) * B + f).
    { pose proof (Rabs_triang_inv y Y). lra. }
    assert (Rabs (x - X) * Rabs y <= (k * A + e) * ((1 + k) * B + f))
      by (apply Rmult_le_compat; try apply Rabs_pos; lra).
    assert (Rabs X * Rabs (y - Y) <= A * (k * B + f))
      by (apply Rmult_le_compat; try apply Rabs_pos; lra).
    nra.
Qed.

(* A product with an f32 value taken exactly. *)
Lemma near_scale : forall a x X A k e, 0 <= k -> 0 <= e ->
  near x X A k e ->
  near (rnd (a * x)) (a * X) (Rabs a * A) (u + k + u * k) ((1 + u) * (Rabs a * e) + eta).
Proof.
  intros a x X A k e Hk He [HX Hx].
  assert (HA : 0 <= A) by (pose proof (Rabs_pos X); lra).
  pose proof (Rabs_pos a).
  apply near_round.
  - lra.
  - apply Rmult_le_pos; lra.
  - rewrite Rabs_mult. apply Rmult_le_compat_l; lra.
  - replace (a * x - a * X) with (a * (x - X)) by ring. rewrite Rabs_mult.
    assert (Rabs a * Rabs (x - X) <= Rabs a * (k * A + e)) by (apply Rmult_le_compat_l; lra).
    lra.
Qed.

(* The rounded product of two f32 values. *)
Lemma near_product : forall a b, near (rnd (a * b)) (a * b) (Rabs a * Rabs b) u eta.
Proof.
  intros a b. pose proof (near_scale a b b (Rabs b) 0 0 (Rle_refl 0) (Rle_refl 0) (near_exact b)).
  replace (u + 0 + u * 0) with u in H by ring.
  replace ((1 + u) * (Rabs a * 0) + eta) with eta in H by ring.
  exact H.
Qed.
