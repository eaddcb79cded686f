(* What the laws share: f32 rounding to nearest even as Flocq states it (the
   rounding of the Gappa certificates), its error, the norm of a
   vector whose components each carry a relative error, and three-vectors:
   their length, the triangle inequality, and the rounding of a cross
   product. *)
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

(* A square at most a power of two rounds to at most that power. *)
Lemma rnd_square_le : forall e t, (-149 <= e <= 127)%Z ->
  0 <= t * t <= bpow radix2 e -> 0 <= rnd (t * t) <= bpow radix2 e.
Proof.
  intros e t He Ht. split.
  - rewrite <- rnd_0. apply rnd_monotone. lra.
  - rewrite <- (rnd_bpow e He). apply rnd_monotone. lra.
Qed.

(* Four squares rounded each, summed exactly: within 2^-24 of their exact
   sum, relative, plus 4 2^-150 (normalize's and mul_renormalized's sum
   of squares, before the sums' own roundings). *)
Lemma squares_sum_err : forall a b c d,
  Rabs (rnd (a * a) + rnd (b * b) + rnd (c * c) + rnd (d * d)
        - (a * a + b * b + c * c + d * d))
  <= u * (a * a + b * b + c * c + d * d) + 4 * eta.
Proof.
  intros a b c d.
  pose proof (rnd_err (a * a)) as Ea; rewrite (Rabs_right (a * a)) in Ea by (apply Rle_ge; nra).
  pose proof (rnd_err (b * b)) as Eb; rewrite (Rabs_right (b * b)) in Eb by (apply Rle_ge; nra).
  pose proof (rnd_err (c * c)) as Ec; rewrite (Rabs_right (c * c)) in Ec by (apply Rle_ge; nra).
  pose proof (rnd_err (d * d)) as Ed; rewrite (Rabs_right (d * d)) in Ed by (apply Rle_ge; nra).
  apply abs_split in Ea; apply abs_split in Eb; apply abs_split in Ec; apply abs_split in Ed.
  apply abs_join. lra.
Qed.

(* The intervals of a Gappa certificate (BND x [Float2 m e, ...]) as
   inequalities between real numbers. *)
Ltac gappa_nums :=
  unfold BND in *; simpl in *; unfold float2R in *; simpl in *;
  unfold F2R in *; simpl in *; unfold Z.pow_pos in *; simpl in *.

(* The length of a three-vector. *)
Definition n3 (a b c : R) := sqrt (a * a + b * b + c * c).

Lemma n3_pos : forall a b c, 0 <= n3 a b c.
Proof. intros; apply sqrt_pos. Qed.

Lemma n3_sq : forall a b c, n3 a b c * n3 a b c = a * a + b * b + c * c.
Proof. intros; unfold n3; apply sqrt_sqrt; nra. Qed.

Lemma n3_triang : forall a1 a2 a3 b1 b2 b3,
  n3 (a1 + b1) (a2 + b2) (a3 + b3) <= n3 a1 a2 a3 + n3 b1 b2 b3.
Proof.
  intros.
  pose proof (n3_pos a1 a2 a3) as Pa; pose proof (n3_pos b1 b2 b3) as Pb.
  pose proof (n3_sq a1 a2 a3) as Sa; pose proof (n3_sq b1 b2 b3) as Sb.
  set (A := n3 a1 a2 a3) in *; set (B := n3 b1 b2 b3) in *.
  assert (CS : a1 * b1 + a2 * b2 + a3 * b3 <= A * B).
  { assert (L : (a1 * b1 + a2 * b2 + a3 * b3) * (a1 * b1 + a2 * b2 + a3 * b3)
                <= (A * B) * (A * B)).
    { replace ((A * B) * (A * B)) with ((A * A) * (B * B)) by ring. rewrite Sa, Sb.
      pose proof (Rle_0_sqr (a1 * b2 - a2 * b1)); pose proof (Rle_0_sqr (a1 * b3 - a3 * b1));
      pose proof (Rle_0_sqr (a2 * b3 - a3 * b2)). unfold Rsqr in *. nra. }
    assert (0 <= A * B) by (apply Rmult_le_pos; lra).
    nra. }
  unfold n3 at 1. rewrite <- (sqrt_square (A + B)) by lra.
  apply sqrt_le_1_alt. nra.
Qed.

Lemma n3_le : forall d1 d2 d3 m1 m2 m3,
  Rabs d1 <= m1 -> Rabs d2 <= m2 -> Rabs d3 <= m3 -> n3 d1 d2 d3 <= n3 m1 m2 m3.
Proof.
  intros d1 d2 d3 m1 m2 m3 H1 H2 H3. unfold n3. apply sqrt_le_1_alt.
  assert (E : forall d m, Rabs d <= m -> d * d <= m * m).
  { intros d m H. pose proof (Rabs_pos d).
    replace (d * d) with (Rabs d * Rabs d) by (rewrite <- Rabs_mult; apply Rabs_right; nra).
    nra. }
  pose proof (E _ _ H1); pose proof (E _ _ H2); pose proof (E _ _ H3). lra.
Qed.

Lemma n3_const : forall h, 0 <= h -> n3 h h h <= 2 * h.
Proof.
  intros h H. unfold n3. rewrite <- (sqrt_square (2 * h)) by lra.
  apply sqrt_le_1_alt. nra.
Qed.

Lemma n3_plus_const : forall m1 m2 m3 h, 0 <= h ->
  n3 (m1 + h) (m2 + h) (m3 + h) <= n3 m1 m2 m3 + 2 * h.
Proof.
  intros. eapply Rle_trans; [apply n3_triang|]. pose proof (n3_const h H). lra.
Qed.

Lemma n3_scal : forall k a b c, n3 (k * a) (k * b) (k * c) = Rabs k * n3 a b c.
Proof.
  intros. unfold n3.
  replace (k * a * (k * a) + k * b * (k * b) + k * c * (k * c))
    with ((k * k) * (a * a + b * b + c * c)) by ring.
  rewrite sqrt_mult by nra. f_equal. apply sqrt_Rsqr_abs.
Qed.

(* The vector of a cross product's two terms in magnitude, |p_j q_l| +
   |p_l q_j| per component: at most sqrt(4/3) |p| |q| long. With
   m_i = |p_i q_i|, its squared length is |p|^2 |q|^2 + (sum m_i)^2
   - 2 sum m_i^2, and (sum m_i)^2 <= 3 sum m_i^2, sum m_i <= |p| |q|. *)
Lemma cross_terms : forall p1 p2 p3 q1 q2 q3,
  n3 (Rabs (p2 * q3) + Rabs (p3 * q2)) (Rabs (p3 * q1) + Rabs (p1 * q3))
     (Rabs (p1 * q2) + Rabs (p2 * q1))
  <= 1.1548 * (n3 p1 p2 p3 * n3 q1 q2 q3).
Proof.
  intros.
  pose proof (n3_pos p1 p2 p3); pose proof (n3_pos q1 q2 q3).
  pose proof (n3_sq p1 p2 p3) as Sp; pose proof (n3_sq q1 q2 q3) as Sq.
  unfold n3 at 1. rewrite <- (sqrt_square (1.1548 * _)) by (apply Rmult_le_pos; nra).
  apply sqrt_le_1_alt.
  replace (1.1548 * (n3 p1 p2 p3 * n3 q1 q2 q3) * (1.1548 * (n3 p1 p2 p3 * n3 q1 q2 q3)))
    with (1.1548 * 1.1548 * ((n3 p1 p2 p3 * n3 p1 p2 p3) * (n3 q1 q2 q3 * n3 q1 q2 q3))) by ring.
  rewrite Sp, Sq.
  rewrite !Rabs_mult.
  set (a1 := Rabs p1); set (a2 := Rabs p2); set (a3 := Rabs p3);
  set (b1 := Rabs q1); set (b2 := Rabs q2); set (b3 := Rabs q3).
  assert (E : forall t, t * t = Rabs t * Rabs t)
    by (intro t; rewrite <- Rabs_mult; symmetry; apply Rabs_right; nra).
  rewrite (E p1), (E p2), (E p3), (E q1), (E q2), (E q3). fold a1 a2 a3 b1 b2 b3.
  assert (0 <= a1) by apply Rabs_pos; assert (0 <= a2) by apply Rabs_pos;
  assert (0 <= a3) by apply Rabs_pos; assert (0 <= b1) by apply Rabs_pos;
  assert (0 <= b2) by apply Rabs_pos; assert (0 <= b3) by apply Rabs_pos.
  pose proof (Rle_0_sqr (a2 * b3 - a3 * b2)); pose proof (Rle_0_sqr (a3 * b1 - a1 * b3));
  pose proof (Rle_0_sqr (a1 * b2 - a2 * b1));
  pose proof (Rle_0_sqr (a1 * b1 - a2 * b2)); pose proof (Rle_0_sqr (a1 * b1 - a3 * b3));
  pose proof (Rle_0_sqr (a2 * b2 - a3 * b3)).
  unfold Rsqr in *. nra.
Qed.

(* Lagrange: |p x q| <= |p| |q|. *)
Lemma cross_len : forall p1 p2 p3 q1 q2 q3,
  n3 (p2 * q3 - p3 * q2) (p3 * q1 - p1 * q3) (p1 * q2 - p2 * q1)
  <= n3 p1 p2 p3 * n3 q1 q2 q3.
Proof.
  intros. pose proof (n3_pos p1 p2 p3); pose proof (n3_pos q1 q2 q3).
  unfold n3 at 1. rewrite <- (sqrt_square (n3 p1 p2 p3 * n3 q1 q2 q3)) by nra.
  apply sqrt_le_1_alt.
  replace (n3 p1 p2 p3 * n3 q1 q2 q3 * (n3 p1 p2 p3 * n3 q1 q2 q3))
    with ((n3 p1 p2 p3 * n3 p1 p2 p3) * (n3 q1 q2 q3 * n3 q1 q2 q3)) by ring.
  rewrite !n3_sq. pose proof (Rle_0_sqr (p1 * q1 + p2 * q2 + p3 * q3)). unfold Rsqr in *. nra.
Qed.

Lemma n3_abs : forall a b c, n3 (Rabs a) (Rabs b) (Rabs c) = n3 a b c.
Proof.
  intros. unfold n3.
  assert (E : forall t, Rabs t * Rabs t = t * t)
    by (intro t; rewrite <- Rabs_mult; apply Rabs_right; nra).
  rewrite !E. reflexivity.
Qed.

(* A combination of two non-negative vectors with non-negative weights. *)
Lemma n3_comb : forall a b x1 x2 x3 y1 y2 y3, 0 <= a -> 0 <= b ->
  n3 (a * x1 + b * y1) (a * x2 + b * y2) (a * x3 + b * y3)
  <= a * n3 x1 x2 x3 + b * n3 y1 y2 y3.
Proof.
  intros. eapply Rle_trans; [apply n3_triang|].
  rewrite !n3_scal, !Rabs_right by lra. lra.
Qed.

(* Doubling a float is exact (no overflow in Flocq's FLT format). *)
Lemma rnd_double : forall x, rnd (rnd x * 2) = rnd x * 2.
Proof.
  intro x. apply round_generic; [apply valid_rnd_N|].
  assert (F : generic_format radix2 (FLT_exp (-149) 24) (rnd x)).
  { apply generic_format_round; [apply FLT_exp_valid; reflexivity|apply valid_rnd_N]. }
  apply FLT_format_generic in F; [|reflexivity].
  destruct F as [[m e] Hx Hm He].
  apply generic_format_FLT. exists (Float radix2 m (e + 1)).
  - rewrite Hx. unfold F2R; simpl. rewrite bpow_plus. simpl. unfold Z.pow_pos; simpl. ring.
  - exact Hm.
  - simpl in *. lia.
Qed.

(* One component of a cross product, A - B with A and B products, each
   product and the difference rounded: the two products' errors and the
   difference's. *)
Lemma cross_comp : forall A B,
  Rabs (rnd (rnd A - rnd B) - (A - B))
  <= u * (1 + u) * (Rabs A + Rabs B) + u * Rabs (A - B) + 4 * eta.
Proof.
  intros A B.
  pose proof (rnd_err A) as EA; pose proof (rnd_err B) as EB.
  pose proof (rnd_err (rnd A - rnd B)) as ED.
  pose proof u_pos; pose proof eta_pos.
  set (a := rnd A) in *; set (b := rnd B) in *.
  assert (Ht : forall p q, Rabs (p + q) <= Rabs p + Rabs q) by apply Rabs_triang.
  assert (Hab : Rabs (a - b) <= Rabs (A - B) + Rabs (a - A) + Rabs (b - B)).
  { replace (a - b) with ((A - B) + ((a - A) + - (b - B))) by ring.
    eapply Rle_trans; [apply Ht|]. pose proof (Ht (a - A) (- (b - B))).
    rewrite Rabs_Ropp in *. lra. }
  replace (rnd (a - b) - (A - B)) with ((rnd (a - b) - (a - b)) + ((a - A) + - (b - B))) by ring.
  eapply Rle_trans; [apply Ht|]. pose proof (Ht (a - A) (- (b - B))). rewrite Rabs_Ropp in *.
  assert (u * Rabs (a - b) <= u * (Rabs (A - B) + (u * Rabs A + eta) + (u * Rabs B + eta))).
  { apply Rmult_le_compat_l; lra. }
  assert (u <= / 2) by (unfold u; lra).
  assert (u * eta <= / 2 * eta) by (apply Rmult_le_compat_r; lra).
  nra.
Qed.

(* A cross product p x q computed in f32 (each product rounded, then the
   difference): its error vector is at most (1 + sqrt(4/3)) 2^-24 |p| |q|
   long, to first order. *)
Lemma cross_err : forall p1 p2 p3 q1 q2 q3,
  n3 (rnd (rnd (p2 * q3) - rnd (p3 * q2)) - (p2 * q3 - p3 * q2))
     (rnd (rnd (p3 * q1) - rnd (p1 * q3)) - (p3 * q1 - p1 * q3))
     (rnd (rnd (p1 * q2) - rnd (p2 * q1)) - (p1 * q2 - p2 * q1))
  <= (u * (1 + u) * 1.1548 + u) * (n3 p1 p2 p3 * n3 q1 q2 q3) + 8 * eta.
Proof.
  intros.
  pose proof u_pos; pose proof eta_pos.
  eapply Rle_trans.
  { apply n3_le; apply cross_comp. }
  eapply Rle_trans; [apply n3_plus_const; lra|].
  eapply Rle_trans.
  { apply Rplus_le_compat_r.
    apply (n3_comb (u * (1 + u)) u (Rabs (p2 * q3) + Rabs (p3 * q2)) (Rabs (p3 * q1) + Rabs (p1 * q3))
             (Rabs (p1 * q2) + Rabs (p2 * q1)) (Rabs (p2 * q3 - p3 * q2)) (Rabs (p3 * q1 - p1 * q3))
             (Rabs (p1 * q2 - p2 * q1))); nra. }
  rewrite n3_abs.
  pose proof (cross_terms p1 p2 p3 q1 q2 q3); pose proof (cross_len p1 p2 p3 q1 q2 q3).
  assert (0 <= u * (1 + u)) by nra.
  assert (u * (1 + u) * n3 (Rabs (p2 * q3) + Rabs (p3 * q2)) (Rabs (p3 * q1) + Rabs (p1 * q3))
            (Rabs (p1 * q2) + Rabs (p2 * q1)) <= u * (1 + u) * (1.1548 * (n3 p1 p2 p3 * n3 q1 q2 q3)))
    by (apply Rmult_le_compat_l; lra).
  assert (u * n3 (p2 * q3 - p3 * q2) (p3 * q1 - p1 * q3) (p1 * q2 - p2 * q1)
          <= u * (n3 p1 p2 p3 * n3 q1 q2 q3)) by (apply Rmult_le_compat_l; lra).
  lra.
Qed.
