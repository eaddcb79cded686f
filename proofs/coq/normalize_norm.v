(* The norm after normalize (src/float/norm.rs, ScaledSquares::unit, the
   branch without rescaling), for components whose exact sum of squares S
   lies in [1, 4] (the code's arithmetic commutes with the exact
   power-of-four scaling that brings them there; proofs/gappa/normalize.g
   and normalize_scale.g say how far): within 2.391e-7 of 1.

   Certificate: normalize.g (Gappa), the sum of the rounded squares and its
   square root, n within 0x1.81p-23 of sqrt(S), relative, given that the
   rounded squares sum to within 2^-24 + 2^-48 of S, relative. Proven
   here: that hypothesis (each square's rounding is within 2^-24 of it,
   relative, plus 2^-150, so the errors of the squares, weighted by the
   squares, average to at most 2^-24), the certificate's rewriting hints
   (identities, by ring and field), and the last step: each quotient's
   rounding is relative too, so the result's length is within 2^-24 of
   the exact quotients' length sqrt(S) / n (norm4_upper, norm4_lower).
   The root's bound is a lemma of its own (normalize_root), on which the
   projections' laws (project4_bound.v) build. *)
(*! bound NORMALIZE_MAX_NORM_ERROR normalize_norm <= 2.391e-7 | |normalize(q)| - 1 | for every finite non-zero q *)
Require Import Reals Psatz.
Require Import Flocq.Core.Core.
Require Import Gappa.Gappa_library.
Require Import Laws.Common.
Require Laws.normalize.

Open Scope R_scope.

(* The square root of the sum of the rounded squares, against the exact
   norm: the certificate's goal, its hypothesis and hints proven. *)
Lemma normalize_root : forall A B C D : R,
  let a := rnd A in
  let b := rnd B in
  let c := rnd C in
  let d := rnd D in
  1 <= a * a + b * b + c * c + d * d <= 4 ->
  let s := rnd (rnd (rnd (rnd (a * a) + rnd (b * b)) + rnd (c * c)) + rnd (d * d)) in
  let n := rnd (sqrt s) in
  let N := sqrt (a * a + b * b + c * c + d * d) in
  -0x1.81p-23 <= (n - N) / N <= 0x1.81p-23.
Proof.
  intros A B C D a b c d HS s n N.
  set (S := a * a + b * b + c * c + d * d) in *.
  assert (HN : 1 <= N).
  { unfold N. rewrite <- sqrt_1. apply sqrt_le_1_alt. lra. }
  (* The rounded squares. *)
  assert (Sq : forall t, 0 <= t * t <= 4 -> 0 <= rnd (t * t) <= 4).
  { intros t Ht. replace 4 with (bpow radix2 2) by (simpl; lra).
    apply rnd_square_le; [lia | simpl; lra]. }
  assert (Ha : 0 <= a * a <= 4) by (split; [nra|unfold S in HS; nra]).
  assert (Hb : 0 <= b * b <= 4) by (split; [nra|unfold S in HS; nra]).
  assert (Hc : 0 <= c * c <= 4) by (split; [nra|unfold S in HS; nra]).
  assert (Hd : 0 <= d * d <= 4) by (split; [nra|unfold S in HS; nra]).
  (* Their sum is within 2^-24 S + 4 2^-150 of S. *)
  set (T := rnd (a * a) + rnd (b * b) + rnd (c * c) + rnd (d * d)).
  assert (HT : Rabs (T - S) <= u * S + 4 * eta) by (unfold T, S; apply squares_sum_err).
  (* The certificate: (n - N) / N within 0x1.81p-23. *)
  apply Classical_Prop.NNPP; intro Hn.
  refine (Laws.normalize.l1 A B C D _ _ _ _).
  - ring.
  - ring.
  - field. unfold S, a, b, c, d in HS. lra.
  - unfold Laws.normalize.s1, Laws.normalize.s2, Laws.normalize.s3,
      Laws.normalize.s4, Laws.normalize.s5, Laws.normalize.s6,
      Laws.normalize.s7.
    assert (HTS : -(u + 4 * eta) <= (T - S) / S <= u + 4 * eta).
    { apply abs_split in HT. pose proof eta_pos. pose proof u_pos.
      set (r := (T - S) / S).
      assert (E : T - S = r * S) by (unfold r; field; lra).
      rewrite E in HT. split; nra. }
    assert (Heta : 4 * eta <= / 2 ^ 48) by (unfold eta; simpl; lra).
    unfold T in HTS. unfold u in HTS.
    pose proof (Sq a Ha); pose proof (Sq b Hb); pose proof (Sq c Hc); pose proof (Sq d Hd).
    unfold S, a, b, c, d in *. gappa_nums. repeat split; try lra.
    intro Hg. apply Hn. unfold n, s, N. lra.
Qed.

Theorem normalize_norm : forall A B C D : R,
  let a := rnd A in
  let b := rnd B in
  let c := rnd C in
  let d := rnd D in
  1 <= a * a + b * b + c * c + d * d <= 4 ->
  let s := rnd (rnd (rnd (rnd (a * a) + rnd (b * b)) + rnd (c * c)) + rnd (d * d)) in
  let n := rnd (sqrt s) in
  let x := rnd (a / n) in
  let y := rnd (b / n) in
  let z := rnd (c / n) in
  let w := rnd (d / n) in
  Rabs (sqrt (x * x + y * y + z * z + w * w) - 1) <= 2.391e-7.
Proof.
  intros A B C D a b c d HS s n x y z w.
  set (S := a * a + b * b + c * c + d * d) in *.
  set (N := sqrt S).
  assert (HN : 1 <= N).
  { unfold N. rewrite <- sqrt_1. apply sqrt_le_1_alt. lra. }
  assert (Hroot : -0x1.81p-23 <= (n - N) / N <= 0x1.81p-23) by exact (normalize_root A B C D HS).
  (* The exact quotients' length is N / n = 1 / (1 + (n - N) / N). *)
  set (dl := (n - N) / N) in Hroot.
  assert (Hn : n = N * (1 + dl)) by (unfold dl; field; lra).
  assert (Hnp : 0 < n) by (rewrite Hn; apply Rmult_lt_0_compat; lra).
  set (Q := sqrt (a / n * (a / n) + b / n * (b / n) + c / n * (c / n) + d / n * (d / n))).
  assert (HQ : Q = N / n).
  { unfold Q. apply sqrt_lem_1.
    - assert (0 <= a / n * (a / n)) by nra. assert (0 <= b / n * (b / n)) by nra.
      assert (0 <= c / n * (c / n)) by nra. assert (0 <= d / n * (d / n)) by nra. lra.
    - unfold Rdiv. apply Rmult_le_pos; [lra|left; apply Rinv_0_lt_compat; lra].
    - unfold N. replace (sqrt S / n * (sqrt S / n)) with ((sqrt S * sqrt S) / (n * n))
        by (field; lra).
      rewrite sqrt_sqrt by lra. unfold S. field. lra. }
  assert (HQ1 : Q * (1 + dl) = 1) by (rewrite HQ, Hn; field; split; lra).
  assert (HQ0 : 0 <= Q) by apply sqrt_pos.
  (* Each quotient's rounding. *)
  assert (Hu : 0 <= u <= 1) by (unfold u; lra).
  pose proof eta_pos as He.
  pose proof (rnd_err (a / n)) as Ex; pose proof (rnd_err (b / n)) as Ey;
  pose proof (rnd_err (c / n)) as Ez; pose proof (rnd_err (d / n)) as Ew.
  pose proof (norm4_upper _ _ _ _ _ _ _ _ u eta (proj1 Hu) (Rlt_le _ _ He) Ex Ey Ez Ew) as Up.
  pose proof (norm4_lower _ _ _ _ _ _ _ _ u eta Hu (Rlt_le _ _ He) Ex Ey Ez Ew) as Lo.
  fold x y z w Q in Up, Lo. fold Q in Lo.
  assert (Hdl : -385 / 2147483648 <= dl <= 385 / 2147483648) by (simpl in Hroot; lra).
  assert (Heta : eta <= / 2 ^ 100) by (unfold eta; simpl; lra).
  assert (QB1 : 0 <= Q * (dl + 385 / 2147483648)) by (apply Rmult_le_pos; lra).
  assert (QB2 : 0 <= Q * (385 / 2147483648 - dl)) by (apply Rmult_le_pos; lra).
  apply abs_join. split.
  - (* The lower side, through the squares. *)
    set (L := (1 - u) * Q).
    assert (HL : 1 - 2.391e-7 + 5e-11 <= L) by (unfold L, u; lra).
    assert (Hsq : (1 - 2.391e-7 + 5e-11) * (1 - 2.391e-7 + 5e-11) <= L * L).
    { assert (0 <= (L - (1 - 2.391e-7 + 5e-11)) * (L + (1 - 2.391e-7 + 5e-11)))
        by (apply Rmult_le_pos; lra).
      nra. }
    assert (HQ2 : Q <= 2) by (unfold u in *; lra).
    assert (4 * eta * Q <= 8 * eta) by nra.
    assert (Lsq : L * L = (1 - u) * (1 - u) * (Q * Q)) by (unfold L; ring).
    assert (Hc2 : (1 - 2.391e-7) * (1 - 2.391e-7) <= x * x + y * y + z * z + w * w) by lra.
    assert (Hs : sqrt ((1 - 2.391e-7) * (1 - 2.391e-7)) <= sqrt (x * x + y * y + z * z + w * w))
      by (apply sqrt_le_1_alt; exact Hc2).
    rewrite sqrt_square in Hs by lra.
    lra.
  - (* The upper side. *)
    unfold u in Up. lra.
Qed.
