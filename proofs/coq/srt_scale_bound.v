(* The scale of Matrix4::to_scale_rotation_translation (src/matrix/
   transform.rs) for Matrix4::from_scale_rotation_translation(s, r, t):
   each column of from_quat(r) times its scale, and that column's norm.
   For every f32 quaternion r with |r|^2 within 1.2e-7 of 1 (every f32
   rounding of a unit quaternion) and every f32 scale with |s| >= 1e-3,
   the norm is within 7.92e-7 of |s|, relative.

   The rounded terms are those of proofs/gappa/srt_scale.g, which
   computes the code's bits (the correspondence test checks both): n for
   the first two columns, nz for the third, whose squares the code sums
   in another order. Argued from the code, in that model's header: the
   other columns are the first renamed, the padding's square and the
   division by the scale 1 are exact (the sum of squares lies in
   [2^-100, f32::MAX] for |s| <= 1e3), and the sign of the determinant
   multiplies the x scale by 1 or -1, exactly (and has the sign of the x
   scale where the y and z scales are positive, on paper in that header,
   from matrix3_determinant_bound.v). Flocq's rounding has no
   overflow; the code's has none while the sum of squares stays below
   f32::MAX, |s| below 1.8e19.

   The steps: the computed column is within (5, 2, 2) 2^-24 (plus
   second order) of the exact column of q's formula, entry by entry
   (diag_err, pair_err: each rounding relative to what it rounds), so
   within 3.4241e-7 in length; the exact column's squared length is
   1 + 4 (y^2 + z^2) (|q|^2 - 1) (column_length_sq), within 2.4001e-7 of
   1 in length; the products by the scale round each entry within 2^-24,
   relative, so the vector of the products is within 2^-24 of |s| times
   the column's length; the three rounded squares sum to within 3 2^-24
   of their exact sum, relative (squares_err), whose root is within half
   that (root_err); and the root rounds within 2^-24. *)
(*! bound SRT_SCALE_MAX_REL_ERROR srt_scale <= 7.92e-7 | |scale_i| of to_scale_rotation_translation against |s_i|, relative, for |r|^2 within 1.2e-7 of 1 and |s_i| >= 1e-3 *)
Require Import Reals Psatz.
Require Import Laws.Common.

Open Scope R_scope.

(* The exact first column of the rotation matrix of q (not divided by
   |q|^2): its squared length is 1 + 4 (y^2 + z^2) (|q|^2 - 1). *)
Lemma column_length_sq : forall w x y z,
  (1 - 2 * (y * y + z * z)) * (1 - 2 * (y * y + z * z))
  + (2 * (x * y + w * z)) * (2 * (x * y + w * z))
  + (2 * (x * z - w * y)) * (2 * (x * z - w * y))
  = 1 + 4 * (y * y + z * z) * (w * w + x * x + y * y + z * z - 1).
Proof. intros; ring. Qed.

Lemma eta_small : eta <= / 2 ^ 140.
Proof.
  unfold eta. apply Rinv_le_contravar; [apply pow_lt; lra|].
  replace 150%nat with (140 + 10)%nat by reflexivity. rewrite pow_add.
  assert (1 <= 2 ^ 10) by (simpl; lra).
  assert (0 < 2 ^ 140) by (apply pow_lt; lra). nra.
Qed.

Lemma eta_tiny : eta <= 1e-40.
Proof.
  eapply Rle_trans; [apply eta_small|].
  assert (H : 1e40 <= 2 ^ 140) by (simpl; lra).
  replace 1e-40 with (/ 1e40) by lra.
  apply Rinv_le_contravar; lra.
Qed.

(* A doubled float is exact. *)
Lemma double_exact : forall Y, rnd (rnd Y + rnd Y) = 2 * rnd Y.
Proof.
  intro Y. replace (rnd Y + rnd Y) with (rnd Y * 2) by ring.
  rewrite rnd_double. ring.
Qed.

(* A diagonal entry, 1 - (y (2 y) + z (2 z)) with each operation rounded:
   the two squares' roundings and the sum's, relative to y^2 + z^2 <= 1,
   and the difference's, relative to |1 - 2 (y^2 + z^2)| <= 1. *)
Lemma diag_err : forall y z,
  y * y + z * z <= 1.00000012 ->
  Rabs (rnd (1 - rnd (rnd (y * (2 * y)) + rnd (z * (2 * z))))
        - (1 - 2 * (y * y + z * z))) <= 2.9803e-7.
Proof.
  intros y z HS.
  pose proof eta_pos as He. pose proof eta_tiny as He2. pose proof u_pos as Hu.
  set (a := y * (2 * y)). set (b := z * (2 * z)).
  assert (Ha : 0 <= a) by (unfold a; nra).
  assert (Hb : 0 <= b) by (unfold b; nra).
  assert (Hab : a + b = 2 * (y * y + z * z)) by (unfold a, b; ring).
  pose proof (rnd_err a) as Ea. rewrite (Rabs_right a) in Ea by lra. apply abs_split in Ea.
  pose proof (rnd_err b) as Eb. rewrite (Rabs_right b) in Eb by lra. apply abs_split in Eb.
  set (t0 := rnd a + rnd b) in *.
  pose proof (rnd_err t0) as Et.
  assert (Ht0 : 0 <= t0).
  { unfold t0. pose proof (rnd_monotone 0 a Ha). pose proof (rnd_monotone 0 b Hb).
    rewrite rnd_0 in *. lra. }
  rewrite (Rabs_right t0) in Et by lra. apply abs_split in Et.
  set (t := rnd t0) in *.
  assert (Et0 : t0 = rnd a + rnd b) by reflexivity.
  clearbody t t0.
  pose proof (rnd_err (1 - t)) as Ed.
  assert (HS0 : 0 <= y * y + z * z) by nra.
  apply abs_join. apply abs_split in Ed.
  assert (HE : Rabs (a + b - t) <= (u + u + u * u) * (a + b) + 4 * eta).
  { apply abs_join. unfold u in *. split; lra. }
  apply abs_split in HE.
  assert (HR : Rabs (1 - t) <= 1.00000024 + (u + u + u * u) * (a + b) + 4 * eta).
  { apply Rabs_le. split; lra. }
  assert (u * Rabs (1 - t) <= u * (1.00000024 + (u + u + u * u) * (a + b) + 4 * eta))
    by (apply Rmult_le_compat_l; lra).
  assert (HS1 : a + b <= 2.00000024) by lra.
  assert (Hq : (u + u + u * u) * (a + b) <= (u + u + u * u) * 2.00000024)
    by (apply Rmult_le_compat_l; nra).
  unfold u in *. split; lra.
Qed.

(* An off-diagonal entry, a (2 b) + c (2 e) or a (2 b) - c (2 e) with each
   operation rounded: each rounding relative to what it rounds, and
   |2 a b| + |2 c e| <= a^2 + b^2 + c^2 + e^2. *)
Lemma pair_err : forall a b c e sg, (sg = 1 \/ sg = -1) ->
  a * a + b * b + c * c + e * e <= 1.00000012 ->
  Rabs (rnd (rnd (a * (2 * b)) + sg * rnd (c * (2 * e)))
        - 2 * (a * b + sg * (c * e))) <= 1.1921e-7.
Proof.
  intros a b c e sg Hsg HS.
  pose proof eta_pos as He. pose proof eta_tiny as He2. pose proof u_pos as Hu.
  set (P := a * (2 * b)). set (R := c * (2 * e)).
  assert (HP : Rabs P <= a * a + b * b).
  { apply Rabs_le. unfold P. pose proof (Rle_0_sqr (a + b)); pose proof (Rle_0_sqr (a - b)).
    unfold Rsqr in *. split; nra. }
  assert (HR : Rabs R <= c * c + e * e).
  { apply Rabs_le. unfold R. pose proof (Rle_0_sqr (c + e)); pose proof (Rle_0_sqr (c - e)).
    unfold Rsqr in *. split; nra. }
  pose proof (rnd_err P) as EP. pose proof (rnd_err R) as ER.
  assert (Hsg1 : Rabs sg = 1)
    by (destruct Hsg as [-> | ->]; unfold Rabs; destruct (Rcase_abs _); lra).
  assert (ET : Rabs ((rnd P - P) + sg * (rnd R - R)) <= u * (Rabs P + Rabs R) + 2 * eta).
  { eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_mult, Hsg1. lra. }
  set (T := rnd P + sg * rnd R).
  assert (HT : Rabs T <= (1 + u) * (Rabs P + Rabs R) + 2 * eta).
  { replace T with ((P + sg * R) + ((rnd P - P) + sg * (rnd R - R))) by (unfold T; ring).
    eapply Rle_trans; [apply Rabs_triang|].
    assert (Rabs (P + sg * R) <= Rabs P + Rabs R).
    { eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_mult, Hsg1. lra. }
    lra. }
  pose proof (rnd_err T) as ES.
  assert (u * Rabs T <= u * ((1 + u) * (Rabs P + Rabs R) + 2 * eta))
    by (apply Rmult_le_compat_l; lra).
  assert (Hk : (u + u + u * u) * (Rabs P + Rabs R) <= (u + u + u * u) * 1.00000012)
    by (apply Rmult_le_compat_l; nra).
  replace (2 * (a * b + sg * (c * e))) with (P + sg * R) by (unfold P, R; ring).
  replace (rnd T - (P + sg * R)) with ((rnd T - T) + ((rnd P - P) + sg * (rnd R - R)))
    by (unfold T; ring).
  eapply Rle_trans; [apply Rabs_triang|].
  unfold u in *. lra.
Qed.

Lemma sqrt_le_const : forall a b, 0 <= b -> a <= b * b -> sqrt a <= b.
Proof.
  intros a b Hb H. rewrite <- (sqrt_square b) by exact Hb.
  apply sqrt_le_1_alt. exact H.
Qed.

(* The sum of three rounded squares, left to right: within 3 2^-24 of
   the exact sum, relative, besides 8 2^-150. *)
Lemma squares_err : forall m0 m1 m2,
  let S := m0 * m0 + m1 * m1 + m2 * m2 in
  0 <= rnd (rnd (rnd (m0 * m0) + rnd (m1 * m1)) + rnd (m2 * m2)) /\
  Rabs (rnd (rnd (rnd (m0 * m0) + rnd (m1 * m1)) + rnd (m2 * m2)) - S)
  <= (u + u + u + u * u * 3 + u * u * u) * S + 8 * eta.
Proof.
  intros m0 m1 m2 S.
  pose proof eta_pos as He. pose proof u_pos as Hu.
  assert (Hu1 : u <= 1e-7) by (unfold u; lra).
  assert (Sq : forall m, 0 <= rnd (m * m) /\ Rabs (rnd (m * m) - m * m) <= u * (m * m) + eta).
  { intro m. assert (0 <= m * m) by nra. split.
    - rewrite <- rnd_0. apply rnd_monotone. lra.
    - pose proof (rnd_err (m * m)) as E. rewrite (Rabs_right (m * m)) in E by lra. exact E. }
  destruct (Sq m0) as [P0 E0]; destruct (Sq m1) as [P1 E1]; destruct (Sq m2) as [P2 E2].
  apply abs_split in E0; apply abs_split in E1; apply abs_split in E2.
  set (s0 := rnd (m0 * m0)) in *. set (s1 := rnd (m1 * m1)) in *.
  set (s2 := rnd (m2 * m2)) in *.
  assert (H0 : 0 <= m0 * m0) by nra. assert (H1 : 0 <= m1 * m1) by nra.
  assert (H2 : 0 <= m2 * m2) by nra.
  pose proof (rnd_err (s0 + s1)) as F. rewrite (Rabs_right (s0 + s1)) in F by lra. apply abs_split in F.
  assert (Pf : 0 <= rnd (s0 + s1)) by (rewrite <- rnd_0; apply rnd_monotone; lra).
  set (f := rnd (s0 + s1)) in *.
  pose proof (rnd_err (f + s2)) as G. rewrite (Rabs_right (f + s2)) in G by lra. apply abs_split in G.
  assert (Pg : 0 <= rnd (f + s2)) by (rewrite <- rnd_0; apply rnd_monotone; lra).
  set (g := rnd (f + s2)) in *.
  clearbody s0 s1 s2 f g.
  split; [exact Pg|]. apply Rabs_le. unfold S.
  assert (Heta : 0 <= eta) by lra.
  unfold u in *. split; lra.
Qed.

(* The root of a value within k N^2 of N^2 is within k (1 + k) / 2 N of
   N. *)
Lemma root_err : forall s N k, 0 <= s -> 0 <= N -> 0 <= k <= 1 / 2 ->
  Rabs (s - N * N) <= k * (N * N) ->
  Rabs (sqrt s - N) <= k * (1 + k) / 2 * N.
Proof.
  intros s N k Hs HN Hk H. apply abs_split in H.
  pose proof (sqrt_pos s) as Hr. pose proof (sqrt_sqrt s Hs) as Hrr.
  set (r := sqrt s) in *. clearbody r.
  destruct (Req_dec N 0) as [H0|H0].
  { subst N. assert (s = 0) by nra. subst s.
    assert (r = 0) by nra. subst r. rewrite Rminus_0_r, Rabs_R0. lra. }
  assert (HNp : 0 < N) by lra.
  assert (E : (r - N) * (r + N) = s - N * N) by (rewrite <- Hrr; ring).
  assert (Hlow : (1 - k) * N <= r).
  { destruct (Rle_or_lt ((1 - k) * N) r) as [Hl|Hl]; [exact Hl|].
    assert (0 <= (1 - k) * N) by nra.
    assert (r * r <= r * ((1 - k) * N)) by (apply Rmult_le_compat_l; lra).
    assert (r * ((1 - k) * N) < (1 - k) * N * ((1 - k) * N))
      by (apply Rmult_lt_compat_r; nra).
    assert ((1 - k) * N * ((1 - k) * N) <= (1 - k) * (N * N)) by nra.
    lra. }
  apply Rabs_le. split.
  - destruct (Rle_or_lt r N) as [Hl|Hl].
    + assert ((N - r) * ((2 - k) * N) <= k * (N * N)).
      { assert ((N - r) * ((2 - k) * N) <= (N - r) * (r + N))
          by (apply Rmult_le_compat_l; lra).
        lra. }
      assert (0 <= k * (1 + k) / 2 * N) by (apply Rmult_le_pos; nra).
      assert ((N - r) * (2 - k) <= k * N).
      { apply Rmult_le_reg_r with N; [exact HNp|]. nra. }
      assert (k * N <= k * (1 + k) / 2 * N * (2 - k)).
      { replace (k * (1 + k) / 2 * N * (2 - k)) with (k * N + k * N * (k - k * k) / 2) by field.
        assert (0 <= k * N) by nra. assert (0 <= k - k * k) by nra.
        assert (0 <= k * N * (k - k * k)) by (apply Rmult_le_pos; lra). lra. }
      assert (N - r <= k * (1 + k) / 2 * N).
      { apply Rmult_le_reg_r with (2 - k); [lra|]. nra. }
      lra.
    + assert (0 <= k * (1 + k) / 2 * N) by (apply Rmult_le_pos; nra). lra.
  - destruct (Rle_or_lt r N) as [Hl|Hl].
    + assert (0 <= k * (1 + k) / 2 * N) by (apply Rmult_le_pos; nra). lra.
    + assert ((r - N) * (2 * N) <= k * (N * N)).
      { assert ((r - N) * (2 * N) <= (r - N) * (r + N)) by (apply Rmult_le_compat_l; lra).
        lra. }
      nra.
Qed.

Theorem srt_scale : forall W X Y Z Sc : R,
  let w := rnd W in
  let x := rnd X in
  let y := rnd Y in
  let z := rnd Z in
  let s := rnd Sc in
  let y2 := rnd (y + y) in
  let z2 := rnd (z + z) in
  let yy := rnd (y * y2) in
  let zz := rnd (z * z2) in
  let xy := rnd (x * y2) in
  let xz := rnd (x * z2) in
  let wy := rnd (w * y2) in
  let wz := rnd (w * z2) in
  let d := rnd (1 - rnd (yy + zz)) in
  let o := rnd (xy + wz) in
  let p := rnd (xz - wy) in
  let m0 := rnd (d * s) in
  let m1 := rnd (o * s) in
  let m2 := rnd (p * s) in
  let q := rnd (rnd (rnd (m0 * m0) + rnd (m1 * m1)) + rnd (m2 * m2)) in
  let n := rnd (sqrt (q)) in
  let qz := rnd (rnd (rnd (m1 * m1) + rnd (m2 * m2)) + rnd (m0 * m0)) in
  let nz := rnd (sqrt (qz)) in
  Rabs (w * w + x * x + y * y + z * z - 1) <= 1.2e-7 ->
  1e-3 <= Rabs s ->
  Rmax (Rabs (n - Rabs s)) (Rabs (nz - Rabs s)) / Rabs s <= 7.92e-7.
Proof.
  intros W X Y Z Sc w x y z s y2 z2 yy zz xy xz wy wz d o p m0 m1 m2 q n qz nz HQ Hs.
  pose proof eta_pos as He. pose proof eta_tiny as He2. pose proof u_pos as Hu.
  apply abs_split in HQ.
  assert (Hy2 : y2 = 2 * y) by exact (double_exact Y).
  assert (Hz2 : z2 = 2 * z) by exact (double_exact Z).
  assert (Hw0 : 0 <= w * w) by nra. assert (Hx0 : 0 <= x * x) by nra.
  assert (Hy0 : 0 <= y * y) by nra. assert (Hz0 : 0 <= z * z) by nra.
  (* The computed column against the exact one of q. *)
  set (D0 := 1 - 2 * (y * y + z * z)).
  set (O0 := 2 * (x * y + 1 * (w * z))).
  set (P0 := 2 * (x * z + -1 * (w * y))).
  assert (Ed : Rabs (d - D0) <= 2.9803e-7).
  { unfold d, yy, zz, D0. rewrite Hy2, Hz2. apply diag_err. lra. }
  assert (Eo : Rabs (o - O0) <= 1.1921e-7).
  { unfold o, xy, wz, O0. rewrite Hy2, Hz2.
    replace (rnd (x * (2 * y)) + rnd (w * (2 * z)))
      with (rnd (x * (2 * y)) + 1 * rnd (w * (2 * z))) by ring.
    apply pair_err; [left; reflexivity|lra]. }
  assert (Ep : Rabs (p - P0) <= 1.1921e-7).
  { unfold p, xz, wy, P0. rewrite Hy2, Hz2.
    replace (rnd (x * (2 * z)) - rnd (w * (2 * y)))
      with (rnd (x * (2 * z)) + -1 * rnd (w * (2 * y))) by ring.
    apply pair_err; [right; reflexivity|lra]. }
  assert (HE : n3 (d - D0) (o - O0) (p - P0) <= 3.4241e-7).
  { eapply Rle_trans; [apply (n3_le _ _ _ 2.9803e-7 1.1921e-7 1.1921e-7); assumption|].
    apply sqrt_le_const; lra. }
  assert (HE' : n3 (D0 - d) (O0 - o) (P0 - p) <= 3.4241e-7).
  { eapply Rle_trans; [|exact HE]. right. unfold n3. f_equal. ring. }
  (* The exact column's length: 1 + 4 (y^2 + z^2) (|q|^2 - 1), squared. *)
  assert (HR2 : n3 D0 O0 P0 * n3 D0 O0 P0
                = 1 + 4 * (y * y + z * z) * (w * w + x * x + y * y + z * z - 1)).
  { rewrite n3_sq. unfold D0, O0, P0. ring. }
  assert (HRb : Rabs (4 * (y * y + z * z) * (w * w + x * x + y * y + z * z - 1)) <= 4.8001e-7).
  { rewrite !Rabs_mult. rewrite (Rabs_right 4) by lra.
    rewrite (Rabs_right (y * y + z * z)) by lra.
    assert (Rabs (w * w + x * x + y * y + z * z - 1) <= 1.2e-7) by (apply Rabs_le; lra).
    assert (y * y + z * z <= 1.00000012) by lra.
    assert (0 <= Rabs (w * w + x * x + y * y + z * z - 1)) by apply Rabs_pos.
    nra. }
  apply abs_split in HRb.
  pose proof (n3_pos D0 O0 P0) as HR0.
  assert (HR : Rabs (n3 D0 O0 P0 - 1) <= 2.4001e-7).
  { set (r := n3 D0 O0 P0) in *. apply Rabs_le. split.
    - destruct (Rle_or_lt (1 - 2.4001e-7) r) as [h|h]; [lra|].
      assert (r * r <= r * (1 - 2.4001e-7)) by (apply Rmult_le_compat_l; lra).
      assert (r * (1 - 2.4001e-7) <= (1 - 2.4001e-7) * (1 - 2.4001e-7))
        by (apply Rmult_le_compat_r; lra).
      lra.
    - destruct (Rle_or_lt r (1 + 2.4001e-7)) as [h|h]; [lra|].
      assert ((1 + 2.4001e-7) * (1 + 2.4001e-7) <= r * (1 + 2.4001e-7))
        by (apply Rmult_le_compat_r; lra).
      assert (r * (1 + 2.4001e-7) <= r * r) by (apply Rmult_le_compat_l; lra).
      lra. }
  apply abs_split in HR.
  set (L := n3 d o p).
  assert (HL : Rabs (L - 1) <= 5.8242e-7).
  { assert (U : L <= n3 D0 O0 P0 + n3 (d - D0) (o - O0) (p - P0)).
    { unfold L. eapply Rle_trans; [|apply n3_triang]. right. unfold n3. f_equal. ring. }
    assert (Lo : n3 D0 O0 P0 <= L + n3 (D0 - d) (O0 - o) (P0 - p)).
    { unfold L. eapply Rle_trans; [|apply n3_triang]. right. unfold n3. f_equal. ring. }
    apply Rabs_le. lra. }
  apply abs_split in HL.
  (* The column times the scale. *)
  set (C := n3 (d * s) (o * s) (p * s)).
  assert (HC : C = Rabs s * L).
  { unfold C, L. rewrite <- n3_scal. unfold n3. f_equal; ring. }
  assert (HCs : Rabs (C - Rabs s) <= 5.8242e-7 * Rabs s).
  { rewrite HC. replace (Rabs s * L - Rabs s) with (Rabs s * (L - 1)) by ring.
    rewrite Rabs_mult, Rabs_Rabsolu. rewrite Rmult_comm.
    apply Rmult_le_compat_r; [apply Rabs_pos|]. apply Rabs_le. lra. }
  apply abs_split in HCs.
  set (N := n3 m0 m1 m2).
  assert (Herr : n3 (m0 - d * s) (m1 - o * s) (m2 - p * s) <= u * C + 2 * eta).
  { eapply Rle_trans.
    { apply (n3_le _ _ _ (u * Rabs (d * s) + eta) (u * Rabs (o * s) + eta) (u * Rabs (p * s) + eta));
        apply rnd_err. }
    eapply Rle_trans; [apply n3_plus_const; lra|].
    rewrite n3_scal, n3_abs, (Rabs_right u) by lra. unfold C. lra. }
  assert (HN : Rabs (N - C) <= u * C + 2 * eta).
  { apply Rabs_le. split.
    - assert (C <= N + n3 (d * s - m0) (o * s - m1) (p * s - m2)).
      { unfold C, N. eapply Rle_trans; [|apply n3_triang]. right. unfold n3. f_equal. ring. }
      assert (n3 (d * s - m0) (o * s - m1) (p * s - m2) = n3 (m0 - d * s) (m1 - o * s) (m2 - p * s))
        by (unfold n3; f_equal; ring).
      lra.
    - assert (N <= C + n3 (m0 - d * s) (m1 - o * s) (m2 - p * s)).
      { unfold C, N. eapply Rle_trans; [|apply n3_triang]. right. unfold n3. f_equal. ring. }
      lra. }
  apply abs_split in HN.
  assert (HuC : u * C <= 5.9605e-8 * C) by (apply Rmult_le_compat_r; [unfold C; apply n3_pos|unfold u; lra]).
  assert (HNlow : 9.99e-4 <= N) by lra.
  (* The sum of the squares, in either order, and its root. *)
  assert (HN0 : 0 <= N) by (unfold N; apply n3_pos).
  assert (HNN : 9.98e-7 <= N * N) by nra.
  assert (Hs0 : 0 < Rabs s) by lra.
  assert (Root : forall q', 0 <= q' ->
            Rabs (q' - N * N) <= (u + u + u + u * u * 3 + u * u * u) * (N * N) + 8 * eta ->
            Rabs (rnd (sqrt q') - Rabs s) <= 7.92e-7 * Rabs s).
  { intros q' Hq0 Hq.
    assert (Hk : Rabs (q' - N * N) <= 1.78814e-7 * (N * N)).
    { apply Rabs_le. apply abs_split in Hq. unfold u in Hq. split; lra. }
    pose proof (root_err q' N 1.78814e-7 Hq0 HN0 ltac:(lra) Hk) as Hr.
    apply abs_split in Hr.
    pose proof (sqrt_pos q') as Hr0.
    pose proof (rnd_err (sqrt q')) as Hn.
    rewrite (Rabs_right (sqrt q')) in Hn by lra. apply abs_split in Hn.
    apply Rabs_le. unfold u in *. split; lra. }
  destruct (squares_err m0 m1 m2) as [Hq0 Hq]. fold q in Hq0, Hq.
  rewrite <- n3_sq in Hq. fold N in Hq.
  destruct (squares_err m1 m2 m0) as [Hqz0 Hz]. fold qz in Hqz0, Hz.
  replace (m1 * m1 + m2 * m2 + m0 * m0) with (m0 * m0 + m1 * m1 + m2 * m2) in Hz by ring.
  rewrite <- n3_sq in Hz. fold N in Hz.
  pose proof (Root q Hq0 Hq) as Rn. pose proof (Root qz Hqz0 Hz) as Rz. fold n in Rn. fold nz in Rz.
  apply Rmult_le_reg_r with (Rabs s); [exact Hs0|].
  unfold Rdiv. rewrite Rmult_assoc, Rinv_l by lra. rewrite Rmult_1_r.
  apply Rmax_lub; lra.
Qed.
