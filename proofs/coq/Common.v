(* What the laws share: f32 rounding to nearest even as Flocq states it (the
   rounding of the Gappa certificates), its error, and the norm of a
   vector whose components each carry a relative error. *)
Require Import Reals Psatz.
Require Import Flocq.Core.Core Flocq.Prop.Relative.
Require Import Gappa.Gappa_library.

Open Scope R_scope.

(* One f32 rounding, as the certificates write it. *)
Notation rnd := (rounding_float rndNE 24 (-149)).

Global Instance prec_24 : Prec_gt_0 24%Z.
Proof. reflexivity. Qed.

Definition u := / 16777216.          (* 2^-24, half an ulp of [1, 2) *)
Definition eta := / 2 ^ 150.         (* half the smallest subnormal *)

Lemma u_pos : 0 < u.
Proof. unfold u; lra. Qed.

Lemma eta_pos : 0 < eta.
Proof. unfold eta; apply Rinv_0_lt_compat, pow_lt; lra. Qed.

(* Every rounding: |rnd x - x| <= u |x| + eta (Flocq's error_N_FLT). *)
Lemma rnd_err : forall x, Rabs (rnd x - x) <= u * Rabs x + eta.
Proof.
  intro x.
  destruct (error_N_FLT radix2 (-149) 24 eq_refl
              (fun z => negb (Z.even z)) x) as (e & d & He & Hd & _ & Hr).
  change (Generic_fmt.round radix2 (FLT.FLT_exp (-149) 24)
            (Generic_fmt.Znearest (fun z : Z => negb (Z.even z))) x)
    with (rnd x) in Hr.
  rewrite Hr.
  replace (x * (1 + e) + d - x) with (x * e + d) by ring.
  assert (He2 : Rabs e <= u).
  { eapply Rle_trans; [exact He|]. right. unfold u; simpl; unfold Z.pow_pos; simpl; lra. }
  assert (Hd2 : Rabs d <= eta).
  { eapply Rle_trans; [exact Hd|]. right. unfold eta; simpl; unfold Z.pow_pos; simpl; lra. }
  clear He Hd.
  eapply Rle_trans; [apply Rabs_triang|].
  rewrite Rabs_mult.
  apply Rplus_le_compat; [|exact Hd2].
  rewrite Rmult_comm. apply Rmult_le_compat_r; [apply Rabs_pos|exact He2].
Qed.

Lemma rnd_monotone : forall x y, x <= y -> rnd x <= rnd y.
Proof. intros x y H; apply round_le; [apply FLT_exp_valid; reflexivity|unfold rndNE; apply valid_rnd_N|exact H]. Qed.

Lemma rnd_0 : rnd 0 = 0.
Proof. apply round_0. unfold rndNE; apply valid_rnd_N. Qed.

(* A power of two in f32's range rounds to itself. *)
Lemma rnd_bpow : forall e, (-149 <= e <= 127)%Z -> rnd (bpow radix2 e) = bpow radix2 e.
Proof.
  intros e He.
  apply round_generic; [unfold rndNE; apply valid_rnd_N|].
  apply generic_format_bpow. unfold FLT_exp. lia.
Qed.

(* The sum of four magnitudes is at most twice the vector's length. *)
Lemma sum_abs_le : forall x0 x1 x2 x3,
  Rabs x0 + Rabs x1 + Rabs x2 + Rabs x3
  <= 2 * sqrt (x0 * x0 + x1 * x1 + x2 * x2 + x3 * x3).
Proof.
  intros.
  set (s := Rabs x0 + Rabs x1 + Rabs x2 + Rabs x3).
  assert (Hs : 0 <= s) by (unfold s; pose proof (Rabs_pos x0); pose proof (Rabs_pos x1);
                           pose proof (Rabs_pos x2); pose proof (Rabs_pos x3); lra).
  replace (2 * sqrt _) with (sqrt (4 * (x0 * x0 + x1 * x1 + x2 * x2 + x3 * x3))).
  2: { rewrite sqrt_mult by nra. replace 4 with (2 * 2) by ring.
       rewrite sqrt_square; lra. }
  rewrite <- (sqrt_square s) by exact Hs.
  apply sqrt_le_1_alt.
  unfold s.
  assert (E : forall x, x * x = Rabs x * Rabs x).
  { intro x. rewrite <- Rabs_mult. symmetry. apply Rabs_right. nra. }
  rewrite (E x0), (E x1), (E x2), (E x3).
  set (a0 := Rabs x0); set (a1 := Rabs x1); set (a2 := Rabs x2); set (a3 := Rabs x3).
  pose proof (Rle_0_sqr (a0 - a1)); pose proof (Rle_0_sqr (a0 - a2));
  pose proof (Rle_0_sqr (a0 - a3)); pose proof (Rle_0_sqr (a1 - a2));
  pose proof (Rle_0_sqr (a1 - a3)); pose proof (Rle_0_sqr (a2 - a3)).
  unfold Rsqr in *. nra.
Qed.

(* A vector whose every component is off by at most a relative u plus an
   absolute d: its length is off by at most u times the length plus 2 d.
   Upper side. *)
Lemma norm4_upper : forall q0 q1 q2 q3 c0 c1 c2 c3 k d, 0 <= k -> 0 <= d ->
  Rabs (c0 - q0) <= k * Rabs q0 + d -> Rabs (c1 - q1) <= k * Rabs q1 + d ->
  Rabs (c2 - q2) <= k * Rabs q2 + d -> Rabs (c3 - q3) <= k * Rabs q3 + d ->
  sqrt (c0 * c0 + c1 * c1 + c2 * c2 + c3 * c3)
  <= (1 + k) * sqrt (q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3) + 2 * d.
Proof.
  intros q0 q1 q2 q3 c0 c1 c2 c3 k d Hk Hd H0 H1 H2 H3.
  set (Q := sqrt (q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)).
  assert (HQ : 0 <= Q) by apply sqrt_pos.
  assert (HQ2 : Q * Q = q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
    by (apply sqrt_sqrt; nra).
  pose proof (sum_abs_le q0 q1 q2 q3) as Hs; fold Q in Hs.
  assert (B : forall c q, Rabs (c - q) <= k * Rabs q + d ->
                c * c <= ((1 + k) * Rabs q + d) * ((1 + k) * Rabs q + d)).
  { intros c q H.
    assert (Hc : Rabs c <= (1 + k) * Rabs q + d).
    { pose proof (Rabs_triang_inv c q). lra. }
    assert (E : c * c = Rabs c * Rabs c).
    { rewrite <- Rabs_mult, Rabs_right; nra. }
    rewrite E. pose proof (Rabs_pos c). nra. }
  pose proof (B _ _ H0); pose proof (B _ _ H1); pose proof (B _ _ H2); pose proof (B _ _ H3).
  rewrite <- (sqrt_square ((1 + k) * Q + 2 * d)) by nra.
  apply sqrt_le_1_alt.
  assert (E : forall q, Rabs q * Rabs q = q * q).
  { intro x. rewrite <- Rabs_mult. apply Rabs_right. nra. }
  pose proof (E q0); pose proof (E q1); pose proof (E q2); pose proof (E q3).
  pose proof (Rabs_pos q0); pose proof (Rabs_pos q1);
  pose proof (Rabs_pos q2); pose proof (Rabs_pos q3).
  assert (0 <= (1 + k) * d * (2 * Q - (Rabs q0 + Rabs q1 + Rabs q2 + Rabs q3))).
  { apply Rmult_le_pos; [apply Rmult_le_pos|]; lra. }
  nra.
Qed.

(* Lower side: the squared length is at least (1 - k)^2 Q^2 - 4 d Q. *)
Lemma norm4_lower : forall q0 q1 q2 q3 c0 c1 c2 c3 k d, 0 <= k <= 1 -> 0 <= d ->
  Rabs (c0 - q0) <= k * Rabs q0 + d -> Rabs (c1 - q1) <= k * Rabs q1 + d ->
  Rabs (c2 - q2) <= k * Rabs q2 + d -> Rabs (c3 - q3) <= k * Rabs q3 + d ->
  let Q := sqrt (q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3) in
  (1 - k) * (1 - k) * (Q * Q) - 4 * d * Q
  <= c0 * c0 + c1 * c1 + c2 * c2 + c3 * c3.
Proof.
  intros q0 q1 q2 q3 c0 c1 c2 c3 k d Hk Hd H0 H1 H2 H3 Q.
  assert (HQ2 : Q * Q = q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
    by (apply sqrt_sqrt; nra).
  pose proof (sum_abs_le q0 q1 q2 q3) as Hs; fold Q in Hs.
  assert (B : forall c q, Rabs (c - q) <= k * Rabs q + d ->
                (1 - k) * (1 - k) * (q * q) - 2 * d * Rabs q <= c * c).
  { intros c q H.
    assert (Hc : (1 - k) * Rabs q - d <= Rabs c).
    { pose proof (Rabs_triang_inv q c). rewrite Rabs_minus_sym in H. lra. }
    assert (E : c * c = Rabs c * Rabs c).
    { rewrite <- Rabs_mult, Rabs_right; nra. }
    assert (Eq : q * q = Rabs q * Rabs q).
    { rewrite <- Rabs_mult, Rabs_right; nra. }
    rewrite E, Eq. pose proof (Rabs_pos c). pose proof (Rabs_pos q).
    set (t := (1 - k) * Rabs q).
    assert (0 <= t) by (unfold t; apply Rmult_le_pos; lra).
    replace ((1 - k) * (1 - k) * (Rabs q * Rabs q)) with (t * t) by (unfold t; ring).
    assert (0 <= d * Rabs q * k) by (repeat apply Rmult_le_pos; lra).
    assert (2 * d * Rabs q - 2 * d * t = 2 * (d * Rabs q * k)) by (unfold t; ring).
    destruct (Rle_or_lt d t) as [Hdt|Hdt].
    - assert (0 <= (Rabs c - (t - d)) * (Rabs c + (t - d))).
      { apply Rmult_le_pos; unfold t in *; lra. }
      assert ((Rabs c - (t - d)) * (Rabs c + (t - d))
              = Rabs c * Rabs c - t * t + 2 * (t * d) - d * d) by ring.
      pose proof (Rle_0_sqr d). unfold Rsqr in *. lra.
    - assert (0 <= t * (2 * d - t)) by (apply Rmult_le_pos; lra).
      assert (0 <= Rabs c * Rabs c) by (apply Rmult_le_pos; lra).
      assert (t * (2 * d - t) = 2 * (t * d) - t * t) by ring.
      lra. }
  pose proof (B _ _ H0); pose proof (B _ _ H1); pose proof (B _ _ H2); pose proof (B _ _ H3).
  assert (0 <= 2 * d * (2 * Q - (Rabs q0 + Rabs q1 + Rabs q2 + Rabs q3))).
  { apply Rmult_le_pos; lra. }
  assert (Hk2 : (1 - k) * (1 - k) * (Q * Q) = (1 - k) * (1 - k) * (q0 * q0) + (1 - k) * (1 - k) * (q1 * q1)
      + (1 - k) * (1 - k) * (q2 * q2) + (1 - k) * (1 - k) * (q3 * q3)) by (rewrite HQ2; ring).
  lra.
Qed.

Lemma abs_split : forall x a, Rabs x <= a -> -a <= x <= a.
Proof.
  intros x a H. pose proof (Rle_abs x). pose proof (Rle_abs (- x)).
  rewrite Rabs_Ropp in *. lra.
Qed.

Lemma abs_join : forall x a, -a <= x <= a -> Rabs x <= a.
Proof. intros x a H. apply Rabs_le. exact H. Qed.

(* The intervals of a Gappa certificate (BND x [Float2 m e, ...]) as
   inequalities between real numbers. *)
Ltac gappa_nums :=
  unfold BND in *; simpl in *; unfold float2R in *; simpl in *;
  unfold F2R in *; simpl in *; unfold Z.pow_pos in *; simpl in *.
