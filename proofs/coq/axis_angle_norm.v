(* The norm of from_axis_angle(axis, angle) (src/quat/construction.rs) and
   of q.pow(alpha) for |alpha| <= f32::MAX / 4 (src/quat/power.rs, pow and
   polar): both are (c, k s), with the axis k = (x, y, z) / b through
   scale_for_squares (src/float/norm.rs: b the root of x x + y y + z z
   + 0 0, summed left to right, each component divided by b), (s, c) the
   sine and cosine kernel's results for one f32 argument (angle / 2, or
   alpha phi), and the vector part the rounded products k s. f32, round to
   nearest even. Within 4.035e-7 of 1.

   Domain: (x, y, z) scaled by an exact power of four so that its exact sum
   of squares lies in [1, 4], as for normalize (proofs/gappa/normalize.g
   says why the code's arithmetic commutes with that scaling, and
   normalize_scale.g proves the rescaled branches exact or within 2^-150).
   pow's pure real quaternions take the axis (1, 0, 0), which is in this
   domain; from_axis_angle's zero axis gives the identity, exactly unit.
   For |alpha| > f32::MAX / 4, pow ends with normalize, whose norm
   normalize_norm.v bounds within 2.391e-7.

   Hypothesis taken, not proven here: the sine and cosine kernel's
   relative errors, proven in sin_poly_*.g / cos_poly*.g: s = Sin (1 + es)
   and c = Cos (1 + ec) with |es|, |ec| <= 1.05e-7, Sin and Cos the exact
   sine and cosine of the kernel's f32 argument (so Sin^2 + Cos^2 = 1;
   which angle it is does not matter for the norm). This holds for the
   default backend's kernel (src/float/sin_cos.rs); the libm backend's
   sinf/cosf are outside this law.

   Proven here: the axis's root b within 0x1.81p-23 of the exact norm N,
   relative (normalize_norm.v's normalize_root, on normalize.g's
   certificate, with a fourth component 0); the quotients' and the
   products' roundings, each within 2^-24 relative plus 2^-150 (Common.v's
   norm4_upper and norm4_lower, so that their errors average, weighted by
   the components, rather than add up); and the last step: |q|^2 =
   c^2 + |r|^2 lies between Cos^2 lo + Sin^2 lo and Cos^2 hi + Sin^2 hi
   with lo, hi the extreme relative errors of each part, a weighted
   average with weights Cos^2 and Sin^2 that sum to 1, not a sum. *)
(*! looser UNIT_NORM_ERROR axis_angle_norm <= 4.035e-7 | |from_axis_angle(axis, angle)| - 1 | and | |q.pow(alpha)| - 1 | for |alpha| <= f32::MAX / 4, given the sine and cosine kernel's relative errors within 1.05e-7 (proven in sin_poly_*.g / cos_poly*.g) *)
Require Import Reals Psatz.
Require Import Flocq.Core.Core.
Require Import Gappa.Gappa_library.
Require Import Laws.Common.
Require Laws.normalize_norm.
Open Scope R_scope.

Lemma sq_rel : forall a A e, 0 <= e <= 1 -> Rabs (a - A) <= e * Rabs A ->
  (1 - e) * (1 - e) * (A * A) <= a * a <= (1 + e) * (1 + e) * (A * A).
Proof.
  intros a A e He H.
  pose proof (Rabs_triang_inv a A) as T1.
  pose proof (Rabs_triang_inv A a) as T2. rewrite Rabs_minus_sym in T2.
  assert (Ea : a * a = Rabs a * Rabs a) by (rewrite <- Rabs_mult; rewrite Rabs_right; nra).
  assert (EA : A * A = Rabs A * Rabs A) by (rewrite <- Rabs_mult; rewrite Rabs_right; nra).
  pose proof (Rabs_pos a); pose proof (Rabs_pos A).
  rewrite Ea, EA.
  assert (Up : Rabs a <= (1 + e) * Rabs A) by lra.
  assert (Lo : (1 - e) * Rabs A <= Rabs a) by lra.
  assert (0 <= (1 - e) * Rabs A) by (apply Rmult_le_pos; lra).
  clear H T1 T2 Ea EA.
  split.
  - replace ((1 - e) * (1 - e) * (Rabs A * Rabs A)) with (((1 - e) * Rabs A) * ((1 - e) * Rabs A)) by ring.
    apply Rmult_le_compat; lra.
  - replace ((1 + e) * (1 + e) * (Rabs A * Rabs A)) with (((1 + e) * Rabs A) * ((1 + e) * Rabs A)) by ring.
    apply Rmult_le_compat; lra.
Qed.

(* The last step, on the parts' bounds: the squared norm c^2 + |r|^2 lies
   between Cos^2 L + Sin^2 L and Cos^2 H + Sin^2 H, with L and H the
   extreme factors of the parts, and Cos^2 + Sin^2 = 1. *)
Lemma last_step : forall uu et Sin Cos s c Q K P R R2,
  uu = / 16777216 -> 0 < et <= / 2 ^ 100 ->
  Sin * Sin + Cos * Cos = 1 ->
  (1 - 1.05e-7) * (1 - 1.05e-7) * (Sin * Sin) <= s * s <= (1 + 1.05e-7) * (1 + 1.05e-7) * (Sin * Sin) ->
  (1 - 1.05e-7) * (1 - 1.05e-7) * (Cos * Cos) <= c * c <= (1 + 1.05e-7) * (1 + 1.05e-7) * (Cos * Cos) ->
  1 - 1.7928e-7 <= Q <= 1 + 1.7928e-7 ->
  0 <= K -> K <= (1 + uu) * Q + 2 * et -> (1 - uu) * (1 - uu) * (Q * Q) - 4 * et * Q <= K * K ->
  0 <= P -> P * P = s * s * (K * K) ->
  0 <= R -> R * R = R2 -> R <= (1 + uu) * P + 2 * et -> (1 - uu) * (1 - uu) * (P * P) - 4 * et * P <= R2 ->
  Rabs (sqrt (c * c + R2) - 1) <= 4.035e-7.
Proof.
  intros uu et Sin Cos s c Q K P R R2 Hu He Hunit [SLo SUp] [CLo CUp] [QLo QUp] HK0 KUp KLo HP0 HP2 HR0 HR RUp RLo.
  subst uu.
  assert (Het : et <= 1e-30) by (simpl in He; lra).
  assert (HSin : 0 <= Sin * Sin) by apply Rle_0_sqr.
  assert (HCos : 0 <= Cos * Cos) by apply Rle_0_sqr.
  assert (HSin1 : Sin * Sin <= 1) by lra.
  assert (Hss : s * s <= 1.000001) by lra.
  assert (Hs0 : 0 <= s * s) by apply Rle_0_sqr.
  assert (Hc0 : 0 <= c * c) by apply Rle_0_sqr.
  (* The axis's length. *)
  set (Kh := (1 + / 16777216) * (1 + 1.7928e-7) + 2e-30).
  assert (HKh : K <= Kh).
  { assert ((1 + / 16777216) * Q <= (1 + / 16777216) * (1 + 1.7928e-7)) by (apply Rmult_le_compat_l; lra).
    unfold Kh. lra. }
  assert (HK2h : K * K <= Kh * Kh) by (apply Rmult_le_compat; lra).
  assert (HQ2 : (1 - 1.7928e-7) * (1 - 1.7928e-7) <= Q * Q) by (apply Rmult_le_compat; lra).
  set (Kl2 := (1 - / 16777216) * (1 - / 16777216) * ((1 - 1.7928e-7) * (1 - 1.7928e-7)) - 8e-30).
  assert (HK2l : Kl2 <= K * K).
  { assert ((1 - / 16777216) * (1 - / 16777216) * ((1 - 1.7928e-7) * (1 - 1.7928e-7))
            <= (1 - / 16777216) * (1 - / 16777216) * (Q * Q)) by (apply Rmult_le_compat_l; lra).
    assert (4 * et * Q <= 8e-30).
    { assert (et * Q <= 1e-30 * 2) by (apply Rmult_le_compat; lra). lra. }
    unfold Kl2. lra. }
  (* The products' exact length. *)
  assert (HP2h : P * P <= (1 + 1.05e-7) * (1 + 1.05e-7) * (Sin * Sin) * (Kh * Kh)).
  { rewrite HP2. assert (0 <= K * K) by apply Rle_0_sqr. apply Rmult_le_compat; lra. }
  assert (HP2l : (1 - 1.05e-7) * (1 - 1.05e-7) * (Sin * Sin) * Kl2 <= P * P).
  { rewrite HP2. assert (0 <= Kl2) by (unfold Kl2; lra). apply Rmult_le_compat; lra. }
  assert (HP1 : P <= 2).
  { assert (P * P <= 1.01).
    { assert ((1 + 1.05e-7) * (1 + 1.05e-7) * (Sin * Sin) <= 1.000001) by lra.
      assert (Kh * Kh <= 1.000001) by (unfold Kh; lra).
      assert ((1 + 1.05e-7) * (1 + 1.05e-7) * (Sin * Sin) * (Kh * Kh) <= 1.000001 * 1.000001)
        by (apply Rmult_le_compat; try lra; apply Rmult_le_pos; lra).
      lra. }
    nra. }
  (* The rounded products' length. *)
  assert (HetP : et * P <= 2e-30) by (replace 2e-30 with (1e-30 * 2) by lra; apply Rmult_le_compat; lra).
  assert (HR2h : R2 <= (1 + / 16777216) * (1 + / 16777216) * (P * P) + 20e-30).
  { rewrite <- HR.
    assert (R * R <= ((1 + / 16777216) * P + 2 * et) * ((1 + / 16777216) * P + 2 * et))
      by (apply Rmult_le_compat; lra).
    assert (et * et <= 1e-30) by (assert (et * et <= 1e-30 * 1) by (apply Rmult_le_compat; lra); lra).
    lra. }
  assert (HR2l : (1 - / 16777216) * (1 - / 16777216) * (P * P) - 8e-30 <= R2) by lra.
  apply abs_join. split.
  - set (L := (1 - / 16777216) * (1 - / 16777216) * ((1 - 1.05e-7) * (1 - 1.05e-7))
              * ((1 - / 16777216) * (1 - / 16777216) * ((1 - 1.7928e-7) * (1 - 1.7928e-7)))).
    assert (HLS : L * (Sin * Sin) - 20e-30 <= R2).
    { assert (E : (1 - / 16777216) * (1 - / 16777216) * ((1 - 1.05e-7) * (1 - 1.05e-7) * (Sin * Sin) * Kl2)
                 = L * (Sin * Sin) - (1 - / 16777216) * (1 - / 16777216) * ((1 - 1.05e-7) * (1 - 1.05e-7)) * 8e-30 * (Sin * Sin))
        by (unfold L, Kl2; ring).
      assert ((1 - / 16777216) * (1 - / 16777216) * ((1 - 1.05e-7) * (1 - 1.05e-7) * (Sin * Sin) * Kl2)
              <= (1 - / 16777216) * (1 - / 16777216) * (P * P)) by (apply Rmult_le_compat_l; lra).
      lra. }
    assert (HLC : L * (Cos * Cos) <= c * c).
    { assert (L * (Cos * Cos) <= (1 - 1.05e-7) * (1 - 1.05e-7) * (Cos * Cos))
        by (apply Rmult_le_compat_r; [lra|unfold L; lra]).
      lra. }
    assert (HL : (1 - 4.035e-7) * (1 - 4.035e-7) + 1e-20 <= L) by (unfold L; lra).
    assert (Hsum : (1 - 4.035e-7) * (1 - 4.035e-7) <= c * c + R2).
    { assert (L * (Cos * Cos) + L * (Sin * Sin) = L) by (rewrite <- Rmult_plus_distr_l; rewrite Rplus_comm, Hunit; ring).
      lra. }
    assert (Hsq : sqrt ((1 - 4.035e-7) * (1 - 4.035e-7)) <= sqrt (c * c + R2))
      by (apply sqrt_le_1_alt; exact Hsum).
    rewrite sqrt_square in Hsq by lra. lra.
  - set (H := (1 + / 16777216) * (1 + / 16777216) * ((1 + 1.05e-7) * (1 + 1.05e-7)) * (Kh * Kh)).
    assert (HHS : R2 <= H * (Sin * Sin) + 20e-30).
    { assert ((1 + / 16777216) * (1 + / 16777216) * (P * P)
              <= (1 + / 16777216) * (1 + / 16777216) * ((1 + 1.05e-7) * (1 + 1.05e-7) * (Sin * Sin) * (Kh * Kh)))
        by (apply Rmult_le_compat_l; lra).
      assert (E : (1 + / 16777216) * (1 + / 16777216) * ((1 + 1.05e-7) * (1 + 1.05e-7) * (Sin * Sin) * (Kh * Kh))
                  = H * (Sin * Sin)) by (unfold H; ring).
      lra. }
    assert (HHC : c * c <= H * (Cos * Cos)).
    { assert ((1 + 1.05e-7) * (1 + 1.05e-7) * (Cos * Cos) <= H * (Cos * Cos))
        by (apply Rmult_le_compat_r; [lra|unfold H, Kh; lra]).
      lra. }
    assert (HH : H + 1e-20 <= (1 + 4.035e-7) * (1 + 4.035e-7)) by (unfold H, Kh; lra).
    assert (Hsum : c * c + R2 <= (1 + 4.035e-7) * (1 + 4.035e-7)).
    { assert (H * (Cos * Cos) + H * (Sin * Sin) = H) by (rewrite <- Rmult_plus_distr_l; rewrite Rplus_comm, Hunit; ring).
      lra. }
    assert (Hsq : sqrt (c * c + R2) <= sqrt ((1 + 4.035e-7) * (1 + 4.035e-7)))
      by (apply sqrt_le_1_alt; exact Hsum).
    rewrite sqrt_square in Hsq by lra. lra.
Qed.

Theorem axis_angle_norm : forall X Y Z Sin Cos s c : R,
  let x := rnd X in
  let y := rnd Y in
  let z := rnd Z in
  1 <= x * x + y * y + z * z <= 4 ->
  Sin * Sin + Cos * Cos = 1 ->
  Rabs (s - Sin) <= 1.05e-7 * Rabs Sin ->
  Rabs (c - Cos) <= 1.05e-7 * Rabs Cos ->
  let q := rnd (rnd (rnd (rnd (x * x) + rnd (y * y)) + rnd (z * z)) + rnd (0 * 0)) in
  let b := rnd (sqrt (q)) in
  let kx := rnd (x / b) in
  let ky := rnd (y / b) in
  let kz := rnd (z / b) in
  let rx := rnd (kx * s) in
  let ry := rnd (ky * s) in
  let rz := rnd (kz * s) in
  Rabs (sqrt (c * c + rx * rx + ry * ry + rz * rz) - 1) <= 4.035e-7.
Proof.
  intros X Y Z Sin Cos s c x y z HS Hunit Hs Hc q b kx ky kz rx ry rz.
  pose proof u_pos as Hu0; pose proof eta_pos as He0.
  assert (Heta : 0 < eta <= / 2 ^ 100) by (split; [lra|unfold eta; simpl; lra]).
  (* The root, from normalize.g's certificate with a fourth component 0. *)
  set (N := sqrt (x * x + y * y + z * z + 0 * 0)).
  assert (Hroot : -0x1.81p-23 <= (b - N) / N <= 0x1.81p-23).
  { pose proof (Laws.normalize_norm.normalize_root X Y Z 0) as R.
    cbv zeta in R. rewrite !rnd_0 in R.
    apply R. fold x y z. lra. }
  assert (HN : 1 <= N).
  { unfold N. rewrite <- sqrt_1. apply sqrt_le_1_alt. lra. }
  set (dl := (b - N) / N) in Hroot.
  assert (Hb : b = N * (1 + dl)) by (unfold dl; field; lra).
  assert (Hdl : -385 / 2147483648 <= dl <= 385 / 2147483648) by (simpl in Hroot; lra).
  assert (Hbp : 0 < b) by (rewrite Hb; apply Rmult_lt_0_compat; lra).
  (* The exact quotients' length Q = N / b = 1 / (1 + dl). *)
  set (Q := sqrt (x / b * (x / b) + y / b * (y / b) + z / b * (z / b) + 0 * 0)).
  assert (HQ : Q = N / b).
  { unfold Q. apply sqrt_lem_1.
    - assert (0 <= x / b * (x / b)) by apply Rle_0_sqr. assert (0 <= y / b * (y / b)) by apply Rle_0_sqr.
      assert (0 <= z / b * (z / b)) by apply Rle_0_sqr. lra.
    - unfold Rdiv. apply Rmult_le_pos; [unfold N; apply sqrt_pos|left; apply Rinv_0_lt_compat; lra].
    - unfold N. replace (sqrt (x * x + y * y + z * z + 0 * 0) / b * (sqrt (x * x + y * y + z * z + 0 * 0) / b))
        with ((sqrt (x * x + y * y + z * z + 0 * 0) * sqrt (x * x + y * y + z * z + 0 * 0)) / (b * b))
        by (field; lra).
      rewrite sqrt_sqrt by lra. field. lra. }
  assert (HQ1 : Q * (1 + dl) = 1) by (rewrite HQ, Hb; field; split; lra).
  assert (HQ0 : 0 <= Q) by apply sqrt_pos.
  assert (HQh : Q <= 1 + 1.7928e-7).
  { assert (Q * (1 - 385 / 2147483648) <= 1).
    { assert (Q * (- 385 / 2147483648) <= Q * dl) by (apply Rmult_le_compat_l; lra). lra. }
    lra. }
  assert (HQl : 1 - 1.7928e-7 <= Q).
  { assert (1 <= Q * (1 + 385 / 2147483648)).
    { assert (Q * dl <= Q * (385 / 2147483648)) by (apply Rmult_le_compat_l; lra). lra. }
    lra. }
  (* The axis: each quotient's rounding. *)
  assert (Hu1 : 0 <= u <= 1) by (unfold u; lra).
  assert (E0 : Rabs (0 - 0) <= u * Rabs 0 + eta) by (rewrite Rminus_0_r, Rabs_R0; lra).
  pose proof (rnd_err (x / b)) as Ex; pose proof (rnd_err (y / b)) as Ey;
  pose proof (rnd_err (z / b)) as Ez.
  pose proof (norm4_upper _ _ _ _ _ _ _ _ u eta (proj1 Hu1) (Rlt_le _ _ He0) Ex Ey Ez E0) as KUp.
  pose proof (norm4_lower _ _ _ _ _ _ _ _ u eta Hu1 (Rlt_le _ _ He0) Ex Ey Ez E0) as KLo.
  cbv zeta in KLo. fold kx ky kz Q in KUp, KLo.
  set (K := sqrt (kx * kx + ky * ky + kz * kz + 0 * 0)) in KUp.
  assert (HK2 : K * K = kx * kx + ky * ky + kz * kz + 0 * 0).
  { unfold K. apply sqrt_sqrt.
    assert (0 <= kx * kx) by apply Rle_0_sqr. assert (0 <= ky * ky) by apply Rle_0_sqr.
    assert (0 <= kz * kz) by apply Rle_0_sqr. lra. }
  rewrite <- HK2 in KLo.
  (* The products k s: each rounding relative, their exact length |s| K. *)
  pose proof (rnd_err (kx * s)) as Px; pose proof (rnd_err (ky * s)) as Py;
  pose proof (rnd_err (kz * s)) as Pz.
  pose proof (norm4_upper _ _ _ _ _ _ _ _ u eta (proj1 Hu1) (Rlt_le _ _ He0) Px Py Pz E0) as RUp.
  pose proof (norm4_lower _ _ _ _ _ _ _ _ u eta Hu1 (Rlt_le _ _ He0) Px Py Pz E0) as RLo.
  cbv zeta in RLo. fold rx ry rz in RUp, RLo.
  set (P := sqrt (kx * s * (kx * s) + ky * s * (ky * s) + kz * s * (kz * s) + 0 * 0)) in RUp, RLo.
  assert (HP2 : P * P = s * s * (K * K)).
  { unfold P. rewrite sqrt_sqrt.
    - rewrite HK2. ring.
    - assert (0 <= kx * s * (kx * s)) by apply Rle_0_sqr. assert (0 <= ky * s * (ky * s)) by apply Rle_0_sqr.
      assert (0 <= kz * s * (kz * s)) by apply Rle_0_sqr. lra. }
  set (R2 := rx * rx + ry * ry + rz * rz + 0 * 0) in RUp, RLo.
  assert (HR : sqrt R2 * sqrt R2 = R2).
  { apply sqrt_sqrt. unfold R2.
    assert (0 <= rx * rx) by apply Rle_0_sqr. assert (0 <= ry * ry) by apply Rle_0_sqr.
    assert (0 <= rz * rz) by apply Rle_0_sqr. lra. }
  assert (Hq : c * c + rx * rx + ry * ry + rz * rz = c * c + R2) by (unfold R2; ring).
  rewrite Hq.
  (* The kernel's hypothesis, squared, and the last step. *)
  assert (He : 0 <= 1.05e-7 <= 1) by lra.
  apply (last_step u eta Sin Cos s c Q K P (sqrt R2) R2); try easy.
  - apply sq_rel; assumption.
  - apply sq_rel; assumption.
  - apply sqrt_pos.
  - apply sqrt_pos.
  - apply sqrt_pos.
Qed.
