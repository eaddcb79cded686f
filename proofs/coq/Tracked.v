(* Forward error analysis of a straight-line computation, one rounding at
   a time: `near x X A k e` says that the computed x is within k A + e of
   the exact X, where A bounds |X| (for a sum of products, the sum of the
   products' magnitudes). Each rounded operation multiplies the relative
   part by (1 + u) and adds u; the absolute part e collects the 2^-150 of
   roundings near underflow. This is the classical bound of a sum of terms
   whose every term carries its own rounding errors, |computed - exact| <=
   ((1 + u)^n - 1) sum |terms|, which interval arithmetic cannot state:
   it bounds each term's share by the whole. No law of its own; the laws
   of the determinants and of the inverses' entries build on it. *)
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

(* An entry of an inverse, M / D, computed through r = rnd (1 / d): the
   entry's own arithmetic is carried through with the computed r taken as
   an exact factor, which puts e within k |r| A + c |r| + e0 of r M
   (|M| <= A); d is within kd T + ed of D, where D's expansion cancels by
   at most 2^12 (|D| <= T <= 4096 |D|) and ed is at most 2^-40 |D|. Then
   r is within (u + kd + 2^-40) T / D^2 of 1 / D, up to the factor
   1 / (1 - 4096 (kd + 2^-40)) that d's error allows, and e within
   1.0025 k A / |D| + 1.0021 (u + kd + 2^-40) |M| T / D^2 of M / D,
   besides what the roundings near underflow add. *)
Lemma inverse_entry : forall e M A r d D T k c e0 kd ed,
  0 <= k <= 4e-7 -> 0 <= kd <= 5e-7 -> 0 <= c -> 0 <= e0 -> 0 <= ed ->
  Rabs M <= A ->
  Rabs (e - r * M) <= k * (Rabs r * A) + c * Rabs r + e0 ->
  r = rnd (1 / d) ->
  Rabs (d - D) <= kd * T + ed ->
  0 < Rabs D -> Rabs D <= T -> T <= 4096 * Rabs D -> ed <= / 2 ^ 40 * Rabs D ->
  Rabs (e - M / D) <= 1.0025 * k * (A / Rabs D)
    + 1.0021 * (u + kd + / 2 ^ 40) * (Rabs M * T / (Rabs D * Rabs D))
    + c * (1.0025 / Rabs D + eta) + e0 + eta * (k * A + Rabs M).
Proof.
  intros e M A r d D T k c e0 kd ed Hk Hkd Hc He0 Hed HM He Hr Hd HD HT1 HT2 Hed2.
  set (a := Rabs D) in *.
  pose proof u_pos as Hu. pose proof eta_pos as Heta.
  assert (Hu1 : u <= 6e-8) by (unfold u; lra).
  assert (Hi40 : 0 < / 2 ^ 40 <= 1e-12) by (simpl; split; lra).
  set (g := kd + / 2 ^ 40) in *.
  assert (Hg : 0 <= g <= 5.00001e-7) by (unfold g; lra).
  set (dl := Rabs (d - D)).
  assert (Hdl : dl <= g * T).
  { unfold g. assert (/ 2 ^ 40 * a <= / 2 ^ 40 * T).
    { apply Rmult_le_compat_l. lra. exact HT1. }
    assert (kd * T + ed <= (kd + / 2 ^ 40) * T) by (ring_simplify; lra). unfold dl. lra. }
  assert (Hdl2 : dl <= 0.0020481 * a) by nra.
  set (ad := Rabs d).
  assert (Had : a - dl <= ad).
  { pose proof (Rabs_triang_inv D d) as H. rewrite Rabs_minus_sym in H. unfold a, ad, dl. lra. }
  assert (Had2 : 0.9979519 * a <= ad) by lra.
  assert (Hadp : 0 < ad) by lra.
  assert (Hd0 : d <> 0).
  { intro H0. unfold ad in Hadp. rewrite H0, Rabs_R0 in Hadp. lra. }
  assert (HD0 : D <> 0).
  { intro H0. unfold a in HD. rewrite H0, Rabs_R0 in HD. lra. }
  set (ia := / a). set (iad := / ad).
  assert (Hia : a * ia = 1) by (unfold ia; field; lra).
  assert (Hiad : ad * iad = 1) by (unfold iad; field; lra).
  assert (Hiap : 0 < ia) by (unfold ia; apply Rinv_0_lt_compat; lra).
  assert (Hiadp : 0 < iad) by (unfold iad; apply Rinv_0_lt_compat; lra).
  assert (Hinv : iad <= 1.0021 * ia).
  { assert (H : 0 <= (ad - 0.9979519 * a) * (ia * iad))
      by (apply Rmult_le_pos; [lra|apply Rmult_le_pos; lra]).
    replace ((ad - 0.9979519 * a) * (ia * iad)) with (ia * (ad * iad) - 0.9979519 * iad * (a * ia))
      in H by ring.
    rewrite Hiad, Hia in H. lra. }
  (* r against 1 / d, and 1 / d against 1 / D. *)
  assert (Hr1 : Rabs (r - 1 / d) <= u * iad + eta).
  { rewrite Hr. pose proof (rnd_err (1 / d)) as H.
    replace (Rabs (1 / d)) with iad in H; [exact H|].
    unfold iad, ad. unfold Rdiv. rewrite Rmult_1_l, Rabs_inv. reflexivity. }
  assert (Hr2 : Rabs (1 / d - 1 / D) = dl * iad * ia).
  { replace (1 / d - 1 / D) with ((D - d) * / d * / D) by (field; split; assumption).
    rewrite !Rabs_mult, !Rabs_inv, Rabs_minus_sym. reflexivity. }
  (* |r - 1 / D| <= 1.0021 (u + g) T / a^2 + eta. *)
  assert (HT3 : 1 <= T * ia).
  { assert (H : a * ia <= T * ia) by (apply Rmult_le_compat_r; lra). lra. }
  assert (Hrd : Rabs (r - 1 / D) <= 1.0021 * (u + g) * (T * ia * ia) + eta).
  { replace (r - 1 / D) with ((r - 1 / d) + (1 / d - 1 / D)) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. rewrite Hr2.
    (* u iad + dl iad ia <= (u + g) T ia iad *)
    assert (H1 : u * iad <= u * (T * ia) * iad).
    { assert (0 <= u * iad) by nra. nra. }
    assert (H2 : dl * iad * ia <= g * T * iad * ia).
    { assert (0 <= iad * ia) by nra. nra. }
    assert (H3 : (u + g) * T * ia * iad <= (u + g) * T * ia * (1.0021 * ia)).
    { assert (0 <= (u + g) * T * ia) by (apply Rmult_le_pos; [apply Rmult_le_pos|]; lra).
      apply Rmult_le_compat_l; lra. }
    nra. }
  (* |r| <= 1.0025 / a + eta. *)
  assert (Hrabs : Rabs r <= 1.0025 * ia + eta).
  { assert (H : Rabs r <= Rabs (1 / D) + Rabs (r - 1 / D)).
    { replace r with (1 / D + (r - 1 / D)) at 1 by ring. apply Rabs_triang. }
    replace (Rabs (1 / D)) with ia in H
      by (unfold ia, a; unfold Rdiv; rewrite Rmult_1_l, Rabs_inv; reflexivity).
    assert (H4 : T * ia * ia <= 4096 * ia).
    { assert (T * ia <= 4096) by (assert (T * ia <= 4096 * a * ia) by
          (apply Rmult_le_compat_r; lra); nra).
      nra. }
    assert (1.0021 * (u + g) * (T * ia * ia) <= 1.0021 * (u + g) * (4096 * ia)).
    { apply Rmult_le_compat_l; [nra|exact H4]. }
    nra. }
  (* Together. *)
  replace (e - M / D) with ((e - r * M) + M * (r - 1 / D)) by (field; assumption).
  eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_mult.
  assert (HA : 0 <= A) by (pose proof (Rabs_pos M); lra).
  assert (H5 : k * (Rabs r * A) <= k * ((1.0025 * ia + eta) * A)).
  { apply Rmult_le_compat_l; [lra|]. apply Rmult_le_compat_r; lra. }
  assert (H6 : Rabs M * Rabs (r - 1 / D) <= Rabs M * (1.0021 * (u + g) * (T * ia * ia) + eta))
    by (apply Rmult_le_compat_l; [apply Rabs_pos|exact Hrd]).
  replace (A / a) with (A * ia) by (unfold ia; field; lra).
  replace (Rabs M * T / (a * a)) with (Rabs M * (T * ia * ia)) by (unfold ia; field; lra).
  replace (u + kd + / 2 ^ 40) with (u + g) by (unfold g; ring).
  assert (E5 : k * ((1.0025 * ia + eta) * A) = 1.0025 * k * (A * ia) + eta * (k * A)) by ring.
  assert (E6 : Rabs M * (1.0021 * (u + g) * (T * ia * ia) + eta)
             = 1.0021 * (u + g) * (Rabs M * (T * ia * ia)) + eta * Rabs M) by ring.
  assert (E7 : eta * (k * A + Rabs M) = eta * (k * A) + eta * Rabs M) by ring.
  assert (H7 : c * Rabs r <= c * (1.0025 * ia + eta)) by (apply Rmult_le_compat_l; lra).
  replace (1.0025 / a) with (1.0025 * ia) by (unfold ia; field; lra).
  lra.
Qed.
