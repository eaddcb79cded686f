(* The norm of a product a * b (src/quat/scalar.rs: hamilton, and
   src/quat/sse2.rs, the same terms in the same order): every component a
   sum of four rounded products, rounded left to right, for a and b with
   |a|^2 and |b|^2 within 2^-20 of 1 (every result of normalize, and
   every quaternion within 1.947e-7 of unit norm, whatever its
   components: one may be 1 + 2^-23): | |a b| / (|a| |b|) - 1 | at most
   2.84e-7.

   Proven here, with no certificate: each component's error is at
   most 2^-24 times M_i, the sum of the magnitudes of its four terms, its
   two partial sums and itself (sum4_err, to first order), and the norm
   moves by the projection P . (p - P) / |P| (P the exact product), at most
   2^-24 sum_i |P_i| M_i / |P|. By Cauchy-Schwarz four times that is at
   most 2^-24 (|T| + |S1| + |S2| + |P|), with T the terms' magnitudes per
   component (at most (|a_0| + ... + |a_3|) |b| long: a convolution
   over the indices' exclusive or, diagonal under the Walsh-Hadamard
   transform, klein), S1 and S2 the partial sums (themselves the
   products (a_0, a_1, 0, 0) b and (a_0, a_1, a_2, 0) b, so
   |(a_0, a_1)| |b| and |(a_0, a_1, a_2)| |b| long), and |P| = |a| |b|.
   Their sum over |a| |b| is at most 4.749 (chain: Cauchy-Schwarz three
   times; the largest is 1 + sqrt(1 + (1 + sqrt(4 + 2 sqrt 2))^2) =
   4.74896, at a = (0.629, 0.630, 0.369, 0.267) in magnitude). The
   second-order term |p - P|^2 is at most 2 uu^2 sum_i M_i^2 + 512 eta^2
   (err_sq), with sum_i M_i^2 <= 4 (|T|^2 + |S1|^2 + |S2|^2 + |P|^2)
   <= 28 |a|^2 |b|^2 (sq4, and |a_0| + ... + |a_3| <= 2 |a|): below
   2.0e-13. No step bounds a component, so the law needs none in
   [-1, 1] (mul.g's domain, which its own goals keep). *)
(*! looser UNIT_NORM_ERROR mul_norm <= 2.84e-7 | |a*b| / (|a| |b|) - 1 |, the product's own part of the constant, for a, b within 2^-20 of unit norm *)
Require Import Reals Psatz.
Require Import Flocq.Core.Core.
Require Import Gappa.Gappa_library.
Require Import Laws.Common.

Open Scope R_scope.

(* Rounding to nearest even is symmetric. *)
Lemma rnd_opp : forall x, rnd (- x) = - rnd x.
Proof.
  intro x.
  change (rnd (- x)) with (Generic_fmt.round radix2 (FLT.FLT_exp (-149) 24) ZnearestE (- x)).
  rewrite round_NE_opp. reflexivity.
Qed.

(* A factor at most 1 does not enlarge. *)
Lemma small_mul : forall k x, 0 <= k <= 1 -> 0 <= x -> k * x <= x.
Proof. intros k x Hk Hx. rewrite <- (Rmult_1_l x) at 2. apply Rmult_le_compat_r; lra. Qed.

(* A sum of four rounded products, rounded left to right: its error is at
   most 2^-24 times the sum of the magnitudes of every term and partial
   sum, to first order. *)
Lemma sum4_err : forall t1 t2 t3 t4,
  let p := rnd (rnd (rnd (rnd t1 + rnd t2) + rnd t3) + rnd t4) in
  let M := Rabs t1 + Rabs t2 + Rabs t3 + Rabs t4 + Rabs (t1 + t2) + Rabs (t1 + t2 + t3)
           + Rabs (t1 + t2 + t3 + t4) in
  Rabs (p - (t1 + t2 + t3 + t4)) <= u * M + 10 * (u * u) * M + 8 * eta.
Proof.
  intros t1 t2 t3 t4 p M. unfold p.
  pose proof u_pos as Hu; pose proof eta_pos as He.
  assert (Hu1 : u <= / 1000000) by (unfold u; lra).
  assert (Ht : forall a b, Rabs (a + b) <= Rabs a + Rabs b) by apply Rabs_triang.
  pose proof (rnd_err t1) as D1; pose proof (rnd_err t2) as D2;
  pose proof (rnd_err t3) as D3; pose proof (rnd_err t4) as D4.
  set (d1 := rnd t1 - t1) in *; set (d2 := rnd t2 - t2) in *;
  set (d3 := rnd t3 - t3) in *; set (d4 := rnd t4 - t4) in *.
  set (s1 := rnd (rnd t1 + rnd t2)).
  set (s2 := rnd (s1 + rnd t3)).
  pose proof (rnd_err (rnd t1 + rnd t2)) as C1; fold s1 in C1.
  pose proof (rnd_err (s1 + rnd t3)) as C2; fold s2 in C2.
  pose proof (rnd_err (s2 + rnd t4)) as C3.
  set (c1 := s1 - (rnd t1 + rnd t2)) in *; set (c2 := s2 - (s1 + rnd t3)) in *;
  set (c3 := rnd (s2 + rnd t4) - (s2 + rnd t4)) in *.
  assert (E1 : rnd t1 + rnd t2 = (t1 + t2) + (d1 + d2)) by (unfold d1, d2; ring).
  assert (E2 : s1 + rnd t3 = (t1 + t2 + t3) + (d1 + d2 + d3 + c1)) by (unfold d1, d2, d3, c1; ring).
  assert (E3 : s2 + rnd t4 = (t1 + t2 + t3 + t4) + (d1 + d2 + d3 + d4 + c1 + c2))
    by (unfold d1, d2, d3, d4, c1, c2; ring).
  assert (E : rnd (s2 + rnd t4) - (t1 + t2 + t3 + t4) = d1 + d2 + d3 + d4 + c1 + c2 + c3)
    by (unfold d1, d2, d3, d4, c1, c2, c3; ring).
  set (D := Rabs d1 + Rabs d2 + Rabs d3 + Rabs d4).
  assert (HD : D <= u * (Rabs t1 + Rabs t2 + Rabs t3 + Rabs t4) + 4 * eta) by (unfold D; lra).
  assert (HM : Rabs t1 + Rabs t2 + Rabs t3 + Rabs t4 <= M) by
    (unfold M; pose proof (Rabs_pos (t1 + t2)); pose proof (Rabs_pos (t1 + t2 + t3));
     pose proof (Rabs_pos (t1 + t2 + t3 + t4)); lra).
  assert (HM0 : 0 <= M) by (unfold M; pose proof (Rabs_pos t1); pose proof (Rabs_pos t2);
     pose proof (Rabs_pos t3); pose proof (Rabs_pos t4); pose proof (Rabs_pos (t1 + t2));
     pose proof (Rabs_pos (t1 + t2 + t3)); pose proof (Rabs_pos (t1 + t2 + t3 + t4)); lra).
  assert (HD2 : D <= u * M + 4 * eta).
  { assert (u * (Rabs t1 + Rabs t2 + Rabs t3 + Rabs t4) <= u * M) by (apply Rmult_le_compat_l; lra). lra. }
  pose proof (Rabs_pos d1); pose proof (Rabs_pos d2); pose proof (Rabs_pos d3); pose proof (Rabs_pos d4).
  pose proof (Rabs_pos c1); pose proof (Rabs_pos c2); pose proof (Rabs_pos c3).
  (* Each sum's rounding, relative to the exact partial sum plus the errors before it. *)
  assert (A1 : Rabs (rnd t1 + rnd t2) <= Rabs (t1 + t2) + D).
  { rewrite E1. eapply Rle_trans; [apply Ht|]. pose proof (Ht d1 d2). unfold D; lra. }
  assert (A2 : Rabs (s1 + rnd t3) <= Rabs (t1 + t2 + t3) + D + Rabs c1).
  { rewrite E2. eapply Rle_trans; [apply Ht|].
    pose proof (Ht (d1 + d2 + d3) c1); pose proof (Ht (d1 + d2) d3); pose proof (Ht d1 d2). unfold D; lra. }
  assert (A3 : Rabs (s2 + rnd t4) <= Rabs (t1 + t2 + t3 + t4) + D + Rabs c1 + Rabs c2).
  { rewrite E3. eapply Rle_trans; [apply Ht|].
    pose proof (Ht (d1 + d2 + d3 + d4 + c1) c2); pose proof (Ht (d1 + d2 + d3 + d4) c1);
    pose proof (Ht (d1 + d2 + d3) d4); pose proof (Ht (d1 + d2) d3); pose proof (Ht d1 d2). unfold D; lra. }
  assert (B1 : Rabs c1 <= u * Rabs (t1 + t2) + u * D + eta).
  { assert (u * Rabs (rnd t1 + rnd t2) <= u * (Rabs (t1 + t2) + D)) by (apply Rmult_le_compat_l; lra). lra. }
  assert (B2 : Rabs c2 <= u * Rabs (t1 + t2 + t3) + u * (D + Rabs c1) + eta).
  { assert (u * Rabs (s1 + rnd t3) <= u * (Rabs (t1 + t2 + t3) + D + Rabs c1)) by (apply Rmult_le_compat_l; lra). lra. }
  assert (B3 : Rabs c3 <= u * Rabs (t1 + t2 + t3 + t4) + u * (D + Rabs c1 + Rabs c2) + eta).
  { assert (u * Rabs (s2 + rnd t4) <= u * (Rabs (t1 + t2 + t3 + t4) + D + Rabs c1 + Rabs c2)) by (apply Rmult_le_compat_l; lra). lra. }
  (* The second-order parts. *)
  assert (Hc1 : Rabs c1 <= 2 * u * M + 2 * eta).
  { assert (u * Rabs (t1 + t2) <= u * M) by (apply Rmult_le_compat_l; [lra|]; unfold M; pose proof (Rabs_pos t1); pose proof (Rabs_pos t2); pose proof (Rabs_pos t3); pose proof (Rabs_pos t4); pose proof (Rabs_pos (t1 + t2 + t3)); pose proof (Rabs_pos (t1 + t2 + t3 + t4)); lra).
    assert (u * D <= u * (u * M + 4 * eta)) by (apply Rmult_le_compat_l; lra).
    assert (HuM : 0 <= u * M) by (apply Rmult_le_pos; lra).
    assert (u * (u * M) <= u * M) by (apply small_mul; lra).
    assert (u * (4 * eta) <= eta) by (replace (u * (4 * eta)) with ((4 * u) * eta) by ring; apply small_mul; lra).
    assert (u * (u * M + 4 * eta) = u * (u * M) + u * (4 * eta)) by ring. lra. }
  assert (Hc2 : Rabs c2 <= 3 * u * M + 3 * eta).
  { assert (u * Rabs (t1 + t2 + t3) <= u * M) by (apply Rmult_le_compat_l; [lra|]; unfold M; pose proof (Rabs_pos t1); pose proof (Rabs_pos t2); pose proof (Rabs_pos t3); pose proof (Rabs_pos t4); pose proof (Rabs_pos (t1 + t2)); pose proof (Rabs_pos (t1 + t2 + t3 + t4)); lra).
    assert (u * (D + Rabs c1) <= u * (3 * u * M + 6 * eta)) by (apply Rmult_le_compat_l; lra).
    assert (HuM : 0 <= u * M) by (apply Rmult_le_pos; lra).
    assert (u * (3 * u * M) <= u * M) by (replace (u * (3 * u * M)) with ((3 * u) * (u * M)) by ring; apply small_mul; lra).
    assert (u * (6 * eta) <= eta) by (replace (u * (6 * eta)) with ((6 * u) * eta) by ring; apply small_mul; lra).
    assert (u * (3 * u * M + 6 * eta) = u * (3 * u * M) + u * (6 * eta)) by ring. lra. }
  assert (S2 : u * (D + Rabs c1) + u * D + u * (D + Rabs c1 + Rabs c2) <= 10 * (u * u) * M + eta).
  { assert (X : 3 * D + 2 * Rabs c1 + Rabs c2 <= 3 * (u * M + 4 * eta) + 2 * (2 * u * M + 2 * eta) + (3 * u * M + 3 * eta)) by lra.
    assert (u * (3 * D + 2 * Rabs c1 + Rabs c2) <= u * (3 * (u * M + 4 * eta) + 2 * (2 * u * M + 2 * eta) + (3 * u * M + 3 * eta)))
      by (apply Rmult_le_compat_l; lra).
    assert (u * (19 * eta) <= eta) by (replace (u * (19 * eta)) with ((19 * u) * eta) by ring; apply small_mul; lra).
    assert (u * (3 * (u * M + 4 * eta) + 2 * (2 * u * M + 2 * eta) + (3 * u * M + 3 * eta))
            = 10 * (u * u) * M + u * (19 * eta)) by ring.
    assert (0 <= (u * u) * M) by (apply Rmult_le_pos; nra).
    assert (u * (D + Rabs c1) + u * D + u * (D + Rabs c1 + Rabs c2) = u * (3 * D + 2 * Rabs c1 + Rabs c2)) by ring.
    lra. }
  rewrite E. eapply Rle_trans.
  { pose proof (Ht (d1 + d2 + d3 + d4 + c1 + c2) c3); pose proof (Ht (d1 + d2 + d3 + d4 + c1) c2);
    pose proof (Ht (d1 + d2 + d3 + d4) c1); pose proof (Ht (d1 + d2 + d3) d4);
    pose proof (Ht (d1 + d2) d3); pose proof (Ht d1 d2).
    assert (Fin : Rabs (d1 + d2 + d3 + d4 + c1 + c2 + c3) <= D + Rabs c1 + Rabs c2 + Rabs c3) by (unfold D; lra).
    exact Fin. }
  assert (HDt : D <= u * (Rabs t1 + Rabs t2 + Rabs t3 + Rabs t4) + 4 * eta) by exact HD.
  unfold M. unfold M in S2. lra.
Qed.
(* The length of a four-vector. *)
Definition n4 (a b c d : R) := sqrt (a * a + b * b + c * c + d * d).

Lemma n4_sq : forall a b c d, n4 a b c d * n4 a b c d = a * a + b * b + c * c + d * d.
Proof. intros; unfold n4; apply sqrt_sqrt; nra. Qed.

Lemma n4_pos : forall a b c d, 0 <= n4 a b c d.
Proof. intros; apply sqrt_pos. Qed.

Lemma sq_abs : forall t, Rabs t * Rabs t = t * t.
Proof. intro t. rewrite <- Rabs_mult. apply Rabs_right. nra. Qed.

(* Cauchy-Schwarz, on magnitudes. *)
Lemma cs4 : forall x0 x1 x2 x3 y0 y1 y2 y3,
  Rabs x0 * y0 + Rabs x1 * y1 + Rabs x2 * y2 + Rabs x3 * y3
  <= n4 x0 x1 x2 x3 * n4 y0 y1 y2 y3.
Proof.
  intros.
  pose proof (n4_pos x0 x1 x2 x3); pose proof (n4_pos y0 y1 y2 y3).
  pose proof (n4_sq x0 x1 x2 x3) as Sx; pose proof (n4_sq y0 y1 y2 y3) as Sy.
  rewrite <- (sq_abs x0), <- (sq_abs x1), <- (sq_abs x2), <- (sq_abs x3) in Sx.
  set (X := n4 x0 x1 x2 x3) in *; set (Y := n4 y0 y1 y2 y3) in *.
  set (a0 := Rabs x0) in *; set (a1 := Rabs x1) in *; set (a2 := Rabs x2) in *; set (a3 := Rabs x3) in *.
  assert (L : (a0 * y0 + a1 * y1 + a2 * y2 + a3 * y3) * (a0 * y0 + a1 * y1 + a2 * y2 + a3 * y3) <= (X * Y) * (X * Y)).
  { replace ((X * Y) * (X * Y)) with ((X * X) * (Y * Y)) by ring. rewrite Sx, Sy.
    pose proof (Rle_0_sqr (a0 * y1 - a1 * y0)); pose proof (Rle_0_sqr (a0 * y2 - a2 * y0));
    pose proof (Rle_0_sqr (a0 * y3 - a3 * y0)); pose proof (Rle_0_sqr (a1 * y2 - a2 * y1));
    pose proof (Rle_0_sqr (a1 * y3 - a3 * y1)); pose proof (Rle_0_sqr (a2 * y3 - a3 * y2)).
    unfold Rsqr in *. nra. }
  assert (0 <= X * Y) by (apply Rmult_le_pos; lra). nra.
Qed.

(* The product's terms in magnitude, summed per component (a convolution
   over indices combined by exclusive or, as the product's are): at most
   (|a_0| + ... + |a_3|) |b| long. The Walsh-Hadamard transform
   diagonalizes it, with eigenvalues the four signed sums of the |a_j|. *)
Lemma klein : forall a0 a1 a2 a3 b0 b1 b2 b3, 0 <= a0 -> 0 <= a1 -> 0 <= a2 -> 0 <= a3 ->
  n4 (a0 * b0 + a1 * b1 + a2 * b2 + a3 * b3) (a0 * b1 + a1 * b0 + a2 * b3 + a3 * b2)
     (a0 * b2 + a1 * b3 + a2 * b0 + a3 * b1) (a0 * b3 + a1 * b2 + a2 * b1 + a3 * b0)
  <= (a0 + a1 + a2 + a3) * n4 b0 b1 b2 b3.
Proof.
  intros a0 a1 a2 a3 b0 b1 b2 b3 H0 H1 H2 H3.
  pose proof (n4_pos b0 b1 b2 b3). pose proof (n4_sq b0 b1 b2 b3) as Sb.
  unfold n4 at 1. rewrite <- (sqrt_square ((a0 + a1 + a2 + a3) * n4 b0 b1 b2 b3)) by nra.
  apply sqrt_le_1_alt.
  set (A := a0 + a1 + a2 + a3).
  set (h1 := a0 - a1 + a2 - a3); set (h2 := a0 + a1 - a2 - a3); set (h3 := a0 - a1 - a2 + a3).
  set (g0 := b0 + b1 + b2 + b3); set (g1 := b0 - b1 + b2 - b3);
  set (g2 := b0 + b1 - b2 - b3); set (g3 := b0 - b1 - b2 + b3).
  assert (E : 4 * ((a0 * b0 + a1 * b1 + a2 * b2 + a3 * b3) * (a0 * b0 + a1 * b1 + a2 * b2 + a3 * b3)
    + (a0 * b1 + a1 * b0 + a2 * b3 + a3 * b2) * (a0 * b1 + a1 * b0 + a2 * b3 + a3 * b2)
    + (a0 * b2 + a1 * b3 + a2 * b0 + a3 * b1) * (a0 * b2 + a1 * b3 + a2 * b0 + a3 * b1)
    + (a0 * b3 + a1 * b2 + a2 * b1 + a3 * b0) * (a0 * b3 + a1 * b2 + a2 * b1 + a3 * b0))
    = A * A * (g0 * g0) + h1 * h1 * (g1 * g1) + h2 * h2 * (g2 * g2) + h3 * h3 * (g3 * g3))
    by (unfold A, h1, h2, h3, g0, g1, g2, g3; ring).
  assert (G : 4 * (b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3) = g0 * g0 + g1 * g1 + g2 * g2 + g3 * g3)
    by (unfold g0, g1, g2, g3; ring).
  assert (K1 : h1 * h1 * (g1 * g1) <= A * A * (g1 * g1))
    by (apply Rmult_le_compat_r; [nra|]; unfold h1, A; nra).
  assert (K2 : h2 * h2 * (g2 * g2) <= A * A * (g2 * g2))
    by (apply Rmult_le_compat_r; [nra|]; unfold h2, A; nra).
  assert (K3 : h3 * h3 * (g3 * g3) <= A * A * (g3 * g3))
    by (apply Rmult_le_compat_r; [nra|]; unfold h3, A; nra).
  replace (A * n4 b0 b1 b2 b3 * (A * n4 b0 b1 b2 b3)) with (A * A * (n4 b0 b1 b2 b3 * n4 b0 b1 b2 b3)) by ring.
  rewrite Sb.
  assert (A * A * (4 * (b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3)) = A * A * (g0 * g0 + g1 * g1 + g2 * g2 + g3 * g3))
    by (rewrite G; reflexivity).
  lra.
Qed.

(* The scalar step: |a_0| + ... + |a_3| + |(a_0, a_1)| + |(a_0, a_1, a_2)|
   + |a| <= 4.749 |a|, by Cauchy-Schwarz three times (the largest is
   1 + sqrt(1 + (1 + sqrt(4 + 2 sqrt 2))^2) = 4.74896). *)
Lemma chain : forall a0 a1 a2 a3, 0 <= a0 -> 0 <= a1 -> 0 <= a2 -> 0 <= a3 ->
  a0 + a1 + a2 + a3 + sqrt (a0 * a0 + a1 * a1) + sqrt (a0 * a0 + a1 * a1 + a2 * a2)
  + n4 a0 a1 a2 a3 <= 4.749 * n4 a0 a1 a2 a3.
Proof.
  intros a0 a1 a2 a3 H0 H1 H2 H3.
  set (r1 := sqrt (a0 * a0 + a1 * a1)). set (r2 := sqrt (a0 * a0 + a1 * a1 + a2 * a2)).
  set (r3 := n4 a0 a1 a2 a3).
  assert (R1 : r1 * r1 = a0 * a0 + a1 * a1) by (apply sqrt_sqrt; nra).
  assert (R2 : r2 * r2 = r1 * r1 + a2 * a2) by (rewrite R1; apply sqrt_sqrt; nra).
  assert (R3 : r3 * r3 = r2 * r2 + a3 * a3) by (rewrite R2, R1; apply n4_sq).
  assert (P1 : 0 <= r1) by apply sqrt_pos. assert (P2 : 0 <= r2) by apply sqrt_pos.
  assert (P3 : 0 <= r3) by apply n4_pos.
  assert (S1 : a0 + a1 <= 1.41422 * r1).
  { assert ((a0 + a1) * (a0 + a1) <= (1.41422 * r1) * (1.41422 * r1)).
    { pose proof (Rle_0_sqr (a0 - a1)). unfold Rsqr in *. nra. }
    nra. }
  assert (S2 : 2.41422 * r1 + a2 <= 2.61314 * r2).
  { assert ((2.41422 * r1 + a2) * (2.41422 * r1 + a2) <= (2.61314 * r2) * (2.61314 * r2)).
    { pose proof (Rle_0_sqr (r1 - 2.41422 * a2)). unfold Rsqr in *. nra. }
    nra. }
  assert (S3 : 3.61314 * r2 + a3 <= 3.749 * r3).
  { assert ((3.61314 * r2 + a3) * (3.61314 * r2 + a3) <= (3.749 * r3) * (3.749 * r3)).
    { pose proof (Rle_0_sqr (r2 - 3.61314 * a3)). unfold Rsqr in *. nra. }
    nra. }
  lra.
Qed.

(* (x + y + z + t)^2 <= 4 (x^2 + y^2 + z^2 + t^2). *)
Lemma sq4 : forall x y z t, (x + y + z + t) * (x + y + z + t) <= 4 * (x * x + y * y + z * z + t * t).
Proof.
  intros. pose proof (Rle_0_sqr (x - y)); pose proof (Rle_0_sqr (x - z)); pose proof (Rle_0_sqr (x - t));
  pose proof (Rle_0_sqr (y - z)); pose proof (Rle_0_sqr (y - t)); pose proof (Rle_0_sqr (z - t)).
  unfold Rsqr in *. nra.
Qed.

(* The error's squared length from the components' bounds. *)
Lemma err_sq : forall e0 e1 e2 e3 M0 M1 M2 M3 w e,
  0 <= w <= 5.9605e-8 -> 0 <= e <= / 2 ^ 140 ->
  Rabs e0 <= w * M0 + 8 * e -> Rabs e1 <= w * M1 + 8 * e ->
  Rabs e2 <= w * M2 + 8 * e -> Rabs e3 <= w * M3 + 8 * e ->
  M0 * M0 + M1 * M1 + M2 * M2 + M3 * M3 <= 28.0001 ->
  e0 * e0 + e1 * e1 + e2 * e2 + e3 * e3 <= 5.2e-13.
Proof.
  intros e0 e1 e2 e3 M0 M1 M2 M3 w e Hw He H0 H1 H2 H3 HM.
  assert (Sq : forall x M, Rabs x <= w * M + 8 * e -> x * x <= 2 * (w * w) * (M * M) + 128 * (e * e)).
  { intros x M H. pose proof (Rabs_pos x). rewrite <- sq_abs.
    assert (Rabs x * Rabs x <= (w * M + 8 * e) * (w * M + 8 * e)) by (apply Rmult_le_compat; lra).
    pose proof (Rle_0_sqr (w * M - 8 * e)). unfold Rsqr in *. nra. }
  pose proof (Sq _ _ H0); pose proof (Sq _ _ H1); pose proof (Sq _ _ H2); pose proof (Sq _ _ H3).
  assert (Hww : w * w <= 5.9605e-8 * 5.9605e-8) by (apply Rmult_le_compat; lra).
  assert (Hee : e * e <= / 2 ^ 140) by (assert (/ 2 ^ 140 <= 1) by (simpl; lra); nra).
  assert (HM0 : 0 <= M0 * M0 + M1 * M1 + M2 * M2 + M3 * M3) by nra.
  assert (2 * (w * w) * (M0 * M0 + M1 * M1 + M2 * M2 + M3 * M3) <= 2 * (5.9605e-8 * 5.9605e-8) * 28.0001)
    by (apply Rmult_le_compat; nra).
  assert (/ 2 ^ 140 <= 1e-40) by (simpl; lra).
  nra.
Qed.

(* The last step: from the projection of the error on the product (dot)
   and the error's squared length (Ee) to the norm's relative error. *)
Lemma mul_final : forall N Sp dot Ee w e0,
  0 < N -> (1 - / 1048576) * (1 - / 1048576) <= N * N <= (1 + / 1048576) * (1 + / 1048576) ->
  0 <= w <= 5.9605e-8 -> 0 <= e0 <= / 2 ^ 140 ->
  Rabs dot <= w * (4.749 * (N * N)) + 16 * e0 * N ->
  0 <= Ee <= 5.2e-13 -> Sp = N * N + 2 * dot + Ee ->
  Rabs (sqrt Sp / N - 1) <= 2.84e-7.
Proof.
  intros N Sp dot Ee w e0 HNp HNb Hw He0 Hdot HEe HSp.
  assert (HN1 : N <= 1.001) by nra.
  assert (HNl : 0.999 <= N) by nra.
  assert (Heta : 16 * e0 * N <= 1e-40).
  { assert (16 * e0 * N <= 16 * e0 * 1.001) by (apply Rmult_le_compat_l; lra). lra. }
  assert (Hw2 : w * (4.749 * (N * N)) <= 5.9605e-8 * (4.749 * (N * N))) by (apply Rmult_le_compat_r; nra).
  apply abs_split in Hdot.
  assert (B : Rabs (Sp - N * N) <= 5.6613e-7 * (N * N)).
  { apply abs_join. rewrite HSp. split; lra. }
  set (X := sqrt Sp / N).
  assert (HSp0 : 0 <= Sp) by lra.
  assert (HX0 : 0 <= X) by (unfold X; apply Rmult_le_pos; [apply sqrt_pos|left; apply Rinv_0_lt_compat; lra]).
  assert (HX2 : X * X * (N * N) = Sp).
  { unfold X. replace (sqrt Sp / N * (sqrt Sp / N) * (N * N)) with (sqrt Sp * sqrt Sp * (N * / N) * (N * / N)) by (unfold Rdiv; ring).
    rewrite Rinv_r by lra. rewrite sqrt_sqrt by lra. ring. }
  rewrite <- HX2 in B.
  replace (X * X * (N * N) - N * N) with ((X * X - 1) * (N * N)) in B by ring.
  rewrite Rabs_mult, (Rabs_right (N * N)) in B by nra.
  assert (Hdev : Rabs (X * X - 1) <= 5.6614e-7).
  { apply Rmult_le_reg_r with (N * N); [nra|]. lra. }
  clear B HX2 HSp Hdot Hw2. fold X.
  apply abs_split in Hdev.
  assert (HXl : 1 - 5.6614e-7 <= X).
  { destruct (Rle_or_lt X 1); nra. }
  apply abs_join. split.
  - assert ((1 - X) * (1 + X) <= 5.6614e-7) by nra. nra.
  - assert ((X - 1) * (1 + X) <= 5.6614e-7) by nra. nra.
Qed.

(* One component's error is at most uu times the magnitudes of its terms
   and partial sums, plus 8 2^-150 (sum4_err). *)
Definition uu := u * (1 + 10 * u).

(* The law, on the terms of mul.g's certificate; 0 to 3 are w, x, y, z. *)
Theorem mul_norm : forall AW AX AY AZ BW BX BY BZ : R,
  let a0 := rnd AW in let a1 := rnd AX in let a2 := rnd AY in let a3 := rnd AZ in
  let b0 := rnd BW in let b1 := rnd BX in let b2 := rnd BY in let b3 := rnd BZ in
  1 - / 1048576 <= a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3 <= 1 + / 1048576 ->
  1 - / 1048576 <= b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3 <= 1 + / 1048576 ->
  let p0 := rnd (rnd (rnd (rnd (a0 * b0) - rnd (a1 * b1)) - rnd (a2 * b2)) - rnd (a3 * b3)) in
  let p1 := rnd (rnd (rnd (rnd (a0 * b1) + rnd (a1 * b0)) + rnd (a2 * b3)) - rnd (a3 * b2)) in
  let p2 := rnd (rnd (rnd (rnd (a0 * b2) - rnd (a1 * b3)) + rnd (a2 * b0)) + rnd (a3 * b1)) in
  let p3 := rnd (rnd (rnd (rnd (a0 * b3) + rnd (a1 * b2)) - rnd (a2 * b1)) + rnd (a3 * b0)) in
  Rabs (sqrt (p0 * p0 + p1 * p1 + p2 * p2 + p3 * p3)
        / (sqrt (a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3) * sqrt (b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3))
        - 1) <= 2.84e-7.
Proof.
  intros AW AX AY AZ BW BX BY BZ a0 a1 a2 a3 b0 b1 b2 b3 HA HB p0 p1 p2 p3.
  pose proof u_pos as Hu; pose proof eta_pos as He.
  assert (Hu1 : u = / 16777216) by reflexivity.
  assert (He1 : eta <= / 2 ^ 140) by (unfold eta; simpl; lra).
  (* The exact product, its components' terms and partial sums. *)
  set (P0 := a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3).
  set (P1 := a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2).
  set (P2 := a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1).
  set (P3 := a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0).
  (* Each component: four rounded terms summed left to right. *)
  assert (E0 : p0 = rnd (rnd (rnd (rnd (a0 * b0) + rnd (- (a1 * b1))) + rnd (- (a2 * b2))) + rnd (- (a3 * b3))))
    by (unfold p0; rewrite !rnd_opp; reflexivity).
  assert (E1 : p1 = rnd (rnd (rnd (rnd (a0 * b1) + rnd (a1 * b0)) + rnd (a2 * b3)) + rnd (- (a3 * b2))))
    by (unfold p1; rewrite !rnd_opp; reflexivity).
  assert (E2 : p2 = rnd (rnd (rnd (rnd (a0 * b2) + rnd (- (a1 * b3))) + rnd (a2 * b0)) + rnd (a3 * b1)))
    by (unfold p2; rewrite !rnd_opp; reflexivity).
  assert (E3 : p3 = rnd (rnd (rnd (rnd (a0 * b3) + rnd (a1 * b2)) + rnd (- (a2 * b1))) + rnd (a3 * b0)))
    by (unfold p3; rewrite !rnd_opp; reflexivity).
  set (s10 := a0 * b0 - a1 * b1); set (s11 := a0 * b1 + a1 * b0);
  set (s12 := a0 * b2 - a1 * b3); set (s13 := a0 * b3 + a1 * b2).
  set (s20 := a0 * b0 - a1 * b1 - a2 * b2); set (s21 := a0 * b1 + a1 * b0 + a2 * b3);
  set (s22 := a0 * b2 - a1 * b3 + a2 * b0); set (s23 := a0 * b3 + a1 * b2 - a2 * b1).
  pose proof (sum4_err (a0 * b0) (- (a1 * b1)) (- (a2 * b2)) (- (a3 * b3))) as F0; cbv zeta in F0.
  rewrite <- E0 in F0.
  replace (a0 * b0 + - (a1 * b1) + - (a2 * b2) + - (a3 * b3)) with P0 in F0 by (unfold P0; ring).
  replace (a0 * b0 + - (a1 * b1) + - (a2 * b2)) with s20 in F0 by (unfold s20; ring).
  replace (a0 * b0 + - (a1 * b1)) with s10 in F0 by (unfold s10; ring).
  pose proof (sum4_err (a0 * b1) (a1 * b0) (a2 * b3) (- (a3 * b2))) as F1; cbv zeta in F1.
  rewrite <- E1 in F1.
  replace (a0 * b1 + a1 * b0 + a2 * b3 + - (a3 * b2)) with P1 in F1 by (unfold P1; ring).
  replace (a0 * b1 + a1 * b0 + a2 * b3) with s21 in F1 by (unfold s21; ring).
  replace (a0 * b1 + a1 * b0) with s11 in F1 by (unfold s11; ring).
  pose proof (sum4_err (a0 * b2) (- (a1 * b3)) (a2 * b0) (a3 * b1)) as F2; cbv zeta in F2.
  rewrite <- E2 in F2.
  replace (a0 * b2 + - (a1 * b3) + a2 * b0 + a3 * b1) with P2 in F2 by (unfold P2; ring).
  replace (a0 * b2 + - (a1 * b3) + a2 * b0) with s22 in F2 by (unfold s22; ring).
  replace (a0 * b2 + - (a1 * b3)) with s12 in F2 by (unfold s12; ring).
  pose proof (sum4_err (a0 * b3) (a1 * b2) (- (a2 * b1)) (a3 * b0)) as F3; cbv zeta in F3.
  rewrite <- E3 in F3.
  replace (a0 * b3 + a1 * b2 + - (a2 * b1) + a3 * b0) with P3 in F3 by (unfold P3; ring).
  replace (a0 * b3 + a1 * b2 + - (a2 * b1)) with s23 in F3 by (unfold s23; ring).
  replace (a0 * b3 + a1 * b2) with s13 in F3 by (unfold s13; ring).
  repeat rewrite Rabs_Ropp in F0; repeat rewrite Rabs_Ropp in F1;
  repeat rewrite Rabs_Ropp in F2; repeat rewrite Rabs_Ropp in F3.
  repeat rewrite Rabs_mult in F0; repeat rewrite Rabs_mult in F1;
  repeat rewrite Rabs_mult in F2; repeat rewrite Rabs_mult in F3.
  clear E0 E1 E2 E3.
  set (A0 := Rabs a0) in *; set (A1 := Rabs a1) in *; set (A2 := Rabs a2) in *; set (A3 := Rabs a3) in *;
  set (B0 := Rabs b0) in *; set (B1 := Rabs b1) in *; set (B2 := Rabs b2) in *; set (B3 := Rabs b3) in *.
  set (T0 := A0 * B0 + A1 * B1 + A2 * B2 + A3 * B3); set (T1 := A0 * B1 + A1 * B0 + A2 * B3 + A3 * B2);
  set (T2 := A0 * B2 + A1 * B3 + A2 * B0 + A3 * B1); set (T3 := A0 * B3 + A1 * B2 + A2 * B1 + A3 * B0).
  set (M0 := T0 + Rabs s10 + Rabs s20 + Rabs P0); set (M1 := T1 + Rabs s11 + Rabs s21 + Rabs P1);
  set (M2 := T2 + Rabs s12 + Rabs s22 + Rabs P2); set (M3 := T3 + Rabs s13 + Rabs s23 + Rabs P3).
  assert (G0 : Rabs (p0 - P0) <= uu * M0 + 8 * eta) by (unfold uu, M0, T0; lra).
  assert (G1 : Rabs (p1 - P1) <= uu * M1 + 8 * eta) by (unfold uu, M1, T1; lra).
  assert (G2 : Rabs (p2 - P2) <= uu * M2 + 8 * eta) by (unfold uu, M2, T2; lra).
  assert (G3 : Rabs (p3 - P3) <= uu * M3 + 8 * eta) by (unfold uu, M3, T3; lra).
  clear F0 F1 F2 F3.
  pose proof (Rabs_pos a0) as PA0; pose proof (Rabs_pos a1) as PA1; pose proof (Rabs_pos a2) as PA2;
  pose proof (Rabs_pos a3) as PA3; pose proof (Rabs_pos b0) as PB0; pose proof (Rabs_pos b1) as PB1;
  pose proof (Rabs_pos b2) as PB2; pose proof (Rabs_pos b3) as PB3.
  fold A0 A1 A2 A3 B0 B1 B2 B3 in PA0, PA1, PA2, PA3, PB0, PB1, PB2, PB3.
  (* Lengths: |P| = |a| |b|, and the partial sums are products too. *)
  set (na := n4 a0 a1 a2 a3). set (nb := n4 b0 b1 b2 b3). set (N := n4 P0 P1 P2 P3).
  assert (Hna : na * na = a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3) by apply n4_sq.
  assert (Hnb : nb * nb = b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3) by apply n4_sq.
  pose proof (n4_pos a0 a1 a2 a3) as Pna; pose proof (n4_pos b0 b1 b2 b3) as Pnb;
  pose proof (n4_pos P0 P1 P2 P3) as PN. fold na in Pna; fold nb in Pnb; fold N in PN.
  assert (HN : N = na * nb).
  { unfold N, na, nb, n4. rewrite <- sqrt_mult by nra. f_equal. unfold P0, P1, P2, P3. ring. }
  assert (HS1 : n4 s10 s11 s12 s13 = sqrt (a0 * a0 + a1 * a1) * nb).
  { unfold nb, n4. rewrite <- sqrt_mult by nra. f_equal. unfold s10, s11, s12, s13. ring. }
  assert (HS2 : n4 s20 s21 s22 s23 = sqrt (a0 * a0 + a1 * a1 + a2 * a2) * nb).
  { unfold nb, n4. rewrite <- sqrt_mult by nra. f_equal. unfold s20, s21, s22, s23. ring. }
  assert (HT : n4 T0 T1 T2 T3 <= (A0 + A1 + A2 + A3) * nb).
  { replace nb with (n4 B0 B1 B2 B3). apply klein; assumption.
    unfold n4, nb, B0, B1, B2, B3. rewrite !sq_abs. reflexivity. }
  assert (HC : A0 + A1 + A2 + A3 + sqrt (a0 * a0 + a1 * a1) + sqrt (a0 * a0 + a1 * a1 + a2 * a2) + na
               <= 4.749 * na).
  { replace (sqrt (a0 * a0 + a1 * a1)) with (sqrt (A0 * A0 + A1 * A1)) by (unfold A0, A1; rewrite !sq_abs; reflexivity).
    replace (sqrt (a0 * a0 + a1 * a1 + a2 * a2)) with (sqrt (A0 * A0 + A1 * A1 + A2 * A2))
      by (unfold A0, A1, A2; rewrite !sq_abs; reflexivity).
    replace na with (n4 A0 A1 A2 A3) by (unfold n4, na, A0, A1, A2, A3; rewrite !sq_abs; reflexivity).
    apply chain; assumption. }
  (* Cauchy-Schwarz, four times: the weighted sum of the M_i. *)
  pose proof (cs4 P0 P1 P2 P3 T0 T1 T2 T3) as C1.
  pose proof (cs4 P0 P1 P2 P3 (Rabs s10) (Rabs s11) (Rabs s12) (Rabs s13)) as C2.
  pose proof (cs4 P0 P1 P2 P3 (Rabs s20) (Rabs s21) (Rabs s22) (Rabs s23)) as C3.
  assert (Ab : forall a b c d, n4 (Rabs a) (Rabs b) (Rabs c) (Rabs d) = n4 a b c d)
    by (intros; unfold n4; rewrite !sq_abs; reflexivity).
  rewrite Ab in C2, C3. rewrite HS1 in C2. rewrite HS2 in C3. fold N in C1, C2, C3.
  assert (C4 : Rabs P0 * Rabs P0 + Rabs P1 * Rabs P1 + Rabs P2 * Rabs P2 + Rabs P3 * Rabs P3 = N * N)
    by (rewrite !sq_abs; symmetry; apply n4_sq).
  assert (W : Rabs P0 * M0 + Rabs P1 * M1 + Rabs P2 * M2 + Rabs P3 * M3 <= 4.749 * (N * N)).
  { assert (N * n4 T0 T1 T2 T3 <= N * ((A0 + A1 + A2 + A3) * nb)) by (apply Rmult_le_compat_l; lra).
    assert (N * nb * (A0 + A1 + A2 + A3 + sqrt (a0 * a0 + a1 * a1) + sqrt (a0 * a0 + a1 * a1 + a2 * a2) + na)
            <= N * nb * (4.749 * na)) by (apply Rmult_le_compat_l; [apply Rmult_le_pos; lra|lra]).
    assert (E : Rabs P0 * M0 + Rabs P1 * M1 + Rabs P2 * M2 + Rabs P3 * M3
      = (Rabs P0 * T0 + Rabs P1 * T1 + Rabs P2 * T2 + Rabs P3 * T3)
      + (Rabs P0 * Rabs s10 + Rabs P1 * Rabs s11 + Rabs P2 * Rabs s12 + Rabs P3 * Rabs s13)
      + (Rabs P0 * Rabs s20 + Rabs P1 * Rabs s21 + Rabs P2 * Rabs s22 + Rabs P3 * Rabs s23)
      + (Rabs P0 * Rabs P0 + Rabs P1 * Rabs P1 + Rabs P2 * Rabs P2 + Rabs P3 * Rabs P3))
      by (unfold M0, M1, M2, M3; ring).
    rewrite E, C4.
    assert (N * N = N * nb * na) by (rewrite HN at 2; ring).
    assert (N * nb * (4.749 * na) = 4.749 * (N * N)) by lra.
    assert (N * nb * (A0 + A1 + A2 + A3 + sqrt (a0 * a0 + a1 * a1) + sqrt (a0 * a0 + a1 * a1 + a2 * a2) + na)
      = N * ((A0 + A1 + A2 + A3) * nb) + N * (sqrt (a0 * a0 + a1 * a1) * nb) + N * (sqrt (a0 * a0 + a1 * a1 + a2 * a2) * nb) + N * nb * na)
      by ring.
    lra. }
  (* The projection of the error on the product. *)
  assert (Huu : 0 <= uu <= 5.9605e-8) by (unfold uu; rewrite Hu1; lra).
  assert (Hdot : Rabs (P0 * (p0 - P0) + P1 * (p1 - P1) + P2 * (p2 - P2) + P3 * (p3 - P3))
                 <= uu * (4.749 * (N * N)) + 16 * eta * N).
  { pose proof (sum_abs_le P0 P1 P2 P3) as SA. fold (n4 P0 P1 P2 P3) in SA. fold N in SA.
    assert (K : forall P e M, Rabs e <= uu * M + 8 * eta -> Rabs (P * e) <= uu * (Rabs P * M) + 8 * eta * Rabs P).
    { intros P e0 M0' H. rewrite Rabs_mult.
      assert (Rabs P * Rabs e0 <= Rabs P * (uu * M0' + 8 * eta)) by (apply Rmult_le_compat_l; [apply Rabs_pos|lra]).
      lra. }
    pose proof (K P0 _ _ G0); pose proof (K P1 _ _ G1); pose proof (K P2 _ _ G2); pose proof (K P3 _ _ G3).
    pose proof (Rabs_triang (P0 * (p0 - P0) + P1 * (p1 - P1) + P2 * (p2 - P2)) (P3 * (p3 - P3)));
    pose proof (Rabs_triang (P0 * (p0 - P0) + P1 * (p1 - P1)) (P2 * (p2 - P2)));
    pose proof (Rabs_triang (P0 * (p0 - P0)) (P1 * (p1 - P1))).
    assert (uu * (Rabs P0 * M0 + Rabs P1 * M1 + Rabs P2 * M2 + Rabs P3 * M3) <= uu * (4.749 * (N * N)))
      by (apply Rmult_le_compat_l; lra).
    assert (8 * eta * (Rabs P0 + Rabs P1 + Rabs P2 + Rabs P3) <= 8 * eta * (2 * N))
      by (apply Rmult_le_compat_l; lra).
    lra. }
  (* The squared norm of the result. *)
  assert (HN2 : N * N = P0 * P0 + P1 * P1 + P2 * P2 + P3 * P3) by apply n4_sq.
  assert (HNb : (1 - / 1048576) * (1 - / 1048576) <= N * N <= (1 + / 1048576) * (1 + / 1048576)).
  { rewrite HN. replace (na * nb * (na * nb)) with ((na * na) * (nb * nb)) by ring. rewrite Hna, Hnb.
    assert (Pr : forall x y, 1 - / 1048576 <= x <= 1 + / 1048576 -> 1 - / 1048576 <= y <= 1 + / 1048576 ->
      (1 - / 1048576) * (1 - / 1048576) <= x * y <= (1 + / 1048576) * (1 + / 1048576)).
    { intros x y Hx Hy. split; apply Rmult_le_compat; lra. }
    apply Pr; assumption. }
  (* The error's squared length, second order: each component's error is
     at most uu M_i + 8 eta, and the M_i are at most 7 |a| |b| in squares
     (sq4, HT with |a_0| + ... + |a_3| <= 2 |a|, and the partial sums and
     P themselves products). *)
  assert (He2 : (p0 - P0) * (p0 - P0) + (p1 - P1) * (p1 - P1) + (p2 - P2) * (p2 - P2) + (p3 - P3) * (p3 - P3) <= 5.2e-13).
  { assert (HA2 : (A0 + A1 + A2 + A3) * (A0 + A1 + A2 + A3) <= 4 * (na * na)).
    { rewrite Hna. rewrite <- (sq_abs a0), <- (sq_abs a1), <- (sq_abs a2), <- (sq_abs a3).
      fold A0 A1 A2 A3. apply sq4. }
    assert (HTs : T0 * T0 + T1 * T1 + T2 * T2 + T3 * T3 <= 4 * (N * N)).
    { rewrite <- n4_sq. pose proof (n4_pos T0 T1 T2 T3).
      assert (n4 T0 T1 T2 T3 * n4 T0 T1 T2 T3 <= ((A0 + A1 + A2 + A3) * nb) * ((A0 + A1 + A2 + A3) * nb))
        by (apply Rmult_le_compat; lra).
      assert (((A0 + A1 + A2 + A3) * nb) * ((A0 + A1 + A2 + A3) * nb) <= 4 * (na * na) * (nb * nb))
        by (replace (((A0 + A1 + A2 + A3) * nb) * ((A0 + A1 + A2 + A3) * nb))
              with ((A0 + A1 + A2 + A3) * (A0 + A1 + A2 + A3) * (nb * nb)) by ring;
            apply Rmult_le_compat_r; [apply Rle_0_sqr | exact HA2]).
      rewrite HN. lra. }
    assert (HS1s : Rabs s10 * Rabs s10 + Rabs s11 * Rabs s11 + Rabs s12 * Rabs s12 + Rabs s13 * Rabs s13 <= N * N).
    { rewrite !sq_abs. rewrite HN.
      replace (s10 * s10 + s11 * s11 + s12 * s12 + s13 * s13) with ((a0 * a0 + a1 * a1) * (nb * nb))
        by (rewrite Hnb; unfold s10, s11, s12, s13; ring).
      replace (na * nb * (na * nb)) with ((na * na) * (nb * nb)) by ring.
      apply Rmult_le_compat_r; [apply Rle_0_sqr|].
      rewrite Hna. pose proof (Rle_0_sqr a2). pose proof (Rle_0_sqr a3). unfold Rsqr in *. lra. }
    assert (HS2s : Rabs s20 * Rabs s20 + Rabs s21 * Rabs s21 + Rabs s22 * Rabs s22 + Rabs s23 * Rabs s23 <= N * N).
    { rewrite !sq_abs. rewrite HN.
      replace (s20 * s20 + s21 * s21 + s22 * s22 + s23 * s23) with ((a0 * a0 + a1 * a1 + a2 * a2) * (nb * nb))
        by (rewrite Hnb; unfold s20, s21, s22, s23; ring).
      replace (na * nb * (na * nb)) with ((na * na) * (nb * nb)) by ring.
      apply Rmult_le_compat_r; [apply Rle_0_sqr|].
      rewrite Hna. pose proof (Rle_0_sqr a3). unfold Rsqr in *. lra. }
    assert (HPs : Rabs P0 * Rabs P0 + Rabs P1 * Rabs P1 + Rabs P2 * Rabs P2 + Rabs P3 * Rabs P3 = N * N)
      by (rewrite !sq_abs; symmetry; apply n4_sq).
    pose proof (sq4 T0 (Rabs s10) (Rabs s20) (Rabs P0)); pose proof (sq4 T1 (Rabs s11) (Rabs s21) (Rabs P1));
    pose proof (sq4 T2 (Rabs s12) (Rabs s22) (Rabs P2)); pose proof (sq4 T3 (Rabs s13) (Rabs s23) (Rabs P3)).
    assert (HM : M0 * M0 + M1 * M1 + M2 * M2 + M3 * M3 <= 28.0001).
    { unfold M0, M1, M2, M3. lra. }
    apply (err_sq _ _ _ _ M0 M1 M2 M3 uu eta Huu); [split; lra|assumption..]. }
  replace (sqrt (a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3) * sqrt (b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3)) with N
    by (rewrite HN; reflexivity).
  assert (He0 : 0 <= (p0 - P0) * (p0 - P0) + (p1 - P1) * (p1 - P1) + (p2 - P2) * (p2 - P2) + (p3 - P3) * (p3 - P3))
    by (pose proof (Rle_0_sqr (p0 - P0)); pose proof (Rle_0_sqr (p1 - P1));
        pose proof (Rle_0_sqr (p2 - P2)); pose proof (Rle_0_sqr (p3 - P3)); unfold Rsqr in *; lra).
  assert (HNp : 0 < N).
  { destruct (Req_dec N 0) as [Z|Z]; [rewrite Z in HNb; lra|lra]. }
  apply (mul_final N _ (P0 * (p0 - P0) + P1 * (p1 - P1) + P2 * (p2 - P2) + P3 * (p3 - P3))
    ((p0 - P0) * (p0 - P0) + (p1 - P1) * (p1 - P1) + (p2 - P2) * (p2 - P2) + (p3 - P3) * (p3 - P3)) uu eta); try lra.
Qed.
