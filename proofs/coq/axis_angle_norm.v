(* The norm of from_axis_angle(axis, angle) (src/quat/construction.rs) and
   of q.pow(alpha) for |alpha| <= f32::MAX / 4 (src/quat/power.rs, pow and
   polar): both are (c, k s), with the axis k = (x, y, z) / b through
   scale_for_squares (src/float/norm.rs: b the root of x x + y y + z z
   + 0 0, summed left to right, each component divided by b), (s, c) the
   sine and cosine kernel's results for one f32 argument (angle / 2, or
   alpha phi), and the vector part the rounded products k s. f32, round to
   nearest even. Within 3.483e-7 of 1.

   Domain: (x, y, z) scaled by an exact power of four so that its exact sum
   of squares lies in [1, 4], as for normalize (proofs/gappa/normalize.g
   says why the code's arithmetic commutes with that scaling, and
   normalize_scale.g proves the rescaled branches exact or within 2^-150).
   pow's pure real quaternions take the axis (1, 0, 0), which is in this
   domain; from_axis_angle's zero axis gives the identity, exactly unit.
   For |alpha| > f32::MAX / 4, pow ends with normalize, whose norm
   normalize_norm.v bounds within 2.391e-7.

   Taken as a hypothesis, not proven here: the sine and cosine kernel's
   relative errors, as the kernel (src/float/sin_cos.rs) puts its two
   polynomials together. Both are evaluated at one (r, t), the exact
   angle y = r + t; sin_poly_tail.g proves the sine polynomial within
   1.0e-7 of sin y and cos_poly_tail.g the cosine polynomial within 8e-8
   of cos y, relative. The kernel returns them either straight (s from
   sin_poly, c from cos_poly: |x| <= pi/4, or an even quadrant of the
   reduction) or swapped (s from cos_poly, c from sin_poly: pi/4 < |x|
   <= 3 pi/4, or an odd quadrant), with exact sign flips. So, with Sin
   and Cos the exact sine and cosine of one real angle (+-sin y and
   +-cos y straight, +-cos y and +-sin y swapped; Sin^2 + Cos^2 = 1, and
   which angle it is does not matter for the norm): either
   |s - Sin| <= 1.0e-7 |Sin|, |c - Cos| <= 8e-8 |Cos| and
   Sin^2 <= 0.5000001, or |s - Sin| <= 8e-8 |Sin|, |c - Cos| <= 1.0e-7
   |Cos| and Cos^2 <= 0.5000001. The square of the sine polynomial's
   exact value, sin(y)^2, is at most 0.5000001 because every (r, t) the
   kernel evaluates has |r| <= PIO4_HI (0.78539819, pi/4 + 2.2e-8) and
   |t| <= 2^-24 |r| (argued from the code and the reduction's range in
   docs/verification-proofs.md, the domain of sin_poly_tail.g), so
   |y| <= PIO4_HI (1 + 2^-24) < pi/4 + 7e-8 and sin(y)^2 = (1 +
   sin(2 |y| - pi/2)) / 2 <= 1/2 + (|y| - pi/4) < 0.50000007. The
   hypothesis is about the default backend's kernel; the libm backend's
   sinf/cosf are outside this law.

   Proven here, in Coq alone (no Gappa certificate): the axis's root b
   within 1.4902e-7 (2.5 2^-24 and a little) of the exact norm N, relative
   (axis_root: the three squares and the two additions each round within
   2^-24, relative, the partial sums at most the sum, so the sum is within
   3 2^-24 of it, its root within half that, and the root's rounding adds
   2^-24; normalize.g's interval bound is 0x1.81p-23, 3.008 2^-24); the
   quotients' and the products' roundings, each within 2^-24 relative
   plus 2^-150 (Common.v's norm4_upper and norm4_lower, so that their
   errors average, weighted by the components, rather than add up), which
   put |r|^2 between AL s^2 and AH s^2 (vector_part); and the last step:
   |q|^2 = c^2 + |r|^2 lies between Cos^2 Lc + Sin^2 Ls and
   Cos^2 Hc + Sin^2 Hs, with Lc, Hc the cosine's extreme factors and
   Ls, Hs those of the vector part, a weighted average with weights Cos^2
   and Sin^2 that sum to 1, not a sum. The sine polynomial's larger
   error weighs at most 0.5000001, so where Sin^2 is near 1 the sine
   carries the cosine polynomial's 8e-8. The terms are those of
   proofs/gappa/axis_angle.g (the correspondence test). *)
(*! given sin_poly_tail.g sine <= 1.0e-7 the sine polynomial's relative error with its tail *)
(*! given cos_poly_tail.g cosine <= 8e-8 the cosine polynomial's relative error with its tail *)
(*! looser UNIT_NORM_ERROR axis_angle_norm <= 3.483e-7 | |from_axis_angle(axis, angle)| - 1 | and | |q.pow(alpha)| - 1 | for |alpha| <= f32::MAX / 4, given the sine polynomial's relative error within 1.0e-7 (sin_poly_tail.g) and the cosine polynomial's within 8e-8 (cos_poly_tail.g), the sine polynomial's exact value squared at most 0.5000001 *)
Require Import Reals Psatz.
Require Import Flocq.Core.Core.
Require Import Gappa.Gappa_library.
Require Import Laws.Common.
Open Scope R_scope.

(* Rounding a rounded value leaves it. *)
Lemma rnd_idem : forall t, rnd (rnd t) = rnd t.
Proof.
  intro t. unfold rnd. apply round_generic.
  - apply valid_rnd_N.
  - apply generic_format_round; [apply FLT_exp_valid; reflexivity|apply valid_rnd_N].
Qed.

(* A root of t within D of 1: within D / 2 of 1 above, D / 2 + D^2 below. *)
Lemma sqrt_bounds : forall r t D, 0 <= r -> r * r = t -> 1 - D <= t <= 1 + D -> 0 <= D <= 1e-6 ->
  1 - D / 2 - D * D <= r <= 1 + D / 2.
Proof.
  intros r t D Hr Ht [Hl Hh] HD. subst t. split.
  - destruct (Rle_or_lt (1 - D / 2 - D * D) r) as [H|H]; [exact H|].
    assert (0 <= 1 - D / 2 - D * D) by nra.
    assert (r * r < (1 - D / 2 - D * D) * (1 - D / 2 - D * D)) by (apply Rmult_le_0_lt_compat; lra).
    nra.
  - destruct (Rle_or_lt r (1 + D / 2)) as [H|H]; [exact H|].
    assert ((1 + D / 2) * (1 + D / 2) < r * r) by (apply Rmult_le_0_lt_compat; lra).
    nra.
Qed.

(* The axis's root, tighter than normalize.g's interval bound: the three
   squares and two additions each round within 2^-24, relative (weighted by
   the partial sums, at most S), so the sum is within 3 2^-24 + 4 2^-48 of
   S, the root within half that, and its own rounding adds 2^-24. *)
Lemma axis_root : forall X Y Z,
  let x := rnd X in
  let y := rnd Y in
  let z := rnd Z in
  1 <= x * x + y * y + z * z <= 4 ->
  let q := rnd (rnd (rnd (rnd (x * x) + rnd (y * y)) + rnd (z * z)) + rnd (0 * 0)) in
  let b := rnd (sqrt (q)) in
  let N := sqrt (x * x + y * y + z * z + 0 * 0) in
  -1.4902e-7 <= (b - N) / N <= 1.4902e-7.
Proof.
  intros X Y Z x y z HS q b N.
  assert (Hq : q = rnd (rnd (rnd (x * x) + rnd (y * y)) + rnd (z * z))).
  { unfold q. rewrite Rmult_0_l, rnd_0, Rplus_0_r. apply rnd_idem. }
  assert (HN2 : x * x + y * y + z * z + 0 * 0 = x * x + y * y + z * z) by ring.
  unfold N. rewrite HN2. clear N HN2.
  set (S := x * x + y * y + z * z) in *.
  assert (Hxx : 0 <= x * x) by apply Rle_0_sqr.
  assert (Hyy : 0 <= y * y) by apply Rle_0_sqr.
  assert (Hzz : 0 <= z * z) by apply Rle_0_sqr.
  pose proof (rnd_err (x * x)) as Ea; rewrite (Rabs_right (x * x)) in Ea by lra.
  pose proof (rnd_err (y * y)) as Eb; rewrite (Rabs_right (y * y)) in Eb by lra.
  pose proof (rnd_err (z * z)) as Ec; rewrite (Rabs_right (z * z)) in Ec by lra.
  assert (Pa : 0 <= rnd (x * x)) by (rewrite <- rnd_0; apply rnd_monotone; lra).
  assert (Pb : 0 <= rnd (y * y)) by (rewrite <- rnd_0; apply rnd_monotone; lra).
  assert (Pc : 0 <= rnd (z * z)) by (rewrite <- rnd_0; apply rnd_monotone; lra).
  set (t1 := rnd (x * x) + rnd (y * y)).
  assert (Pt1 : 0 <= t1) by (unfold t1; lra).
  pose proof (rnd_err t1) as E1; rewrite (Rabs_right t1) in E1 by lra.
  set (s1 := rnd t1) in *.
  assert (Ps1 : 0 <= s1) by (unfold s1; rewrite <- rnd_0; apply rnd_monotone; lra).
  set (t2 := s1 + rnd (z * z)).
  assert (Pt2 : 0 <= t2) by (unfold t2; lra).
  pose proof (rnd_err t2) as E2; rewrite (Rabs_right t2) in E2 by lra.
  assert (Hq' : q = rnd t2) by (rewrite Hq; reflexivity).
  rewrite <- Hq' in E2. clear Hq'.
  pose proof eta_pos as He.
  assert (Heta : eta <= 1e-45) by (unfold eta; simpl; lra).
  assert (Hu : u = / 16777216) by reflexivity.
  apply abs_split in Ea; apply abs_split in Eb; apply abs_split in Ec;
  apply abs_split in E1; apply abs_split in E2.
  clearbody s1. clear Hq.
  (* The sum: q within (3 u + 4 u^2) S + 6 eta of S, below 1.7882e-7 S. *)
  assert (Hd : (1 - 1.7882e-7) * S <= q <= (1 + 1.7882e-7) * S).
  { unfold t2, t1 in *. rewrite Hu in *.
    assert (x * x + y * y <= S) by (unfold S; lra).
    unfold S in *. split; lra. }
  assert (HSp : 0 < S) by lra.
  set (r := sqrt q / sqrt S).
  assert (HsS : 1 <= sqrt S) by (rewrite <- sqrt_1; apply sqrt_le_1_alt; lra).
  assert (Hq0 : 0 <= q) by lra.
  assert (Hr2 : r * r = q / S).
  { unfold r. replace (sqrt q / sqrt S * (sqrt q / sqrt S)) with ((sqrt q * sqrt q) / (sqrt S * sqrt S)) by (field; lra).
    rewrite !sqrt_sqrt by lra. reflexivity. }
  assert (Hr0 : 0 <= r) by (unfold r, Rdiv; apply Rmult_le_pos; [apply sqrt_pos|left; apply Rinv_0_lt_compat; lra]).
  assert (Hqs : 1 - 1.7882e-7 <= q / S <= 1 + 1.7882e-7).
  { split; apply Rmult_le_reg_r with S; try lra; unfold Rdiv; rewrite Rmult_assoc, Rinv_l, Rmult_1_r by lra; lra. }
  rewrite <- Hr2 in Hqs.
  destruct (sqrt_bounds r (r * r) 1.7882e-7 Hr0 eq_refl Hqs) as [Hrl Hrh]; [lra|].
  (* Its rounding. *)
  pose proof (rnd_err (sqrt q)) as Eb'. rewrite (Rabs_right (sqrt q)) in Eb' by (apply Rle_ge; apply sqrt_pos).
  apply abs_split in Eb'. fold b in Eb'.
  assert (Hsq : sqrt q = r * sqrt S) by (unfold r; field; lra).
  assert (Hbr : (b - sqrt S) / sqrt S = (b / sqrt S - r) + (r - 1)) by (field; lra).
  rewrite Hbr.
  assert (Ee : eta / sqrt S <= eta).
  { apply Rmult_le_reg_r with (sqrt S); [lra|]. unfold Rdiv. rewrite Rmult_assoc, Rinv_l by lra.
    assert (eta * 1 <= eta * sqrt S) by (apply Rmult_le_compat_l; lra). lra. }
  assert (Ee0 : 0 <= eta / sqrt S) by (unfold Rdiv; apply Rmult_le_pos; [lra|left; apply Rinv_0_lt_compat; lra]).
  rewrite Hsq in Eb'.
  assert (E4 : (r * sqrt S - (u * (r * sqrt S) + eta)) / sqrt S <= b / sqrt S).
  { unfold Rdiv. apply Rmult_le_compat_r; [left; apply Rinv_0_lt_compat; lra|lra]. }
  assert (E5 : b / sqrt S <= (r * sqrt S + (u * (r * sqrt S) + eta)) / sqrt S).
  { unfold Rdiv. apply Rmult_le_compat_r; [left; apply Rinv_0_lt_compat; lra|lra]. }
  replace ((r * sqrt S - (u * (r * sqrt S) + eta)) / sqrt S) with (r - u * r - eta / sqrt S) in E4 by (field; lra).
  replace ((r * sqrt S + (u * (r * sqrt S) + eta)) / sqrt S) with (r + u * r + eta / sqrt S) in E5 by (field; lra).
  assert (Hur : u * r <= u * (1 + 1.7882e-7 / 2)) by (apply Rmult_le_compat_l; [rewrite Hu; lra|lra]).
  assert (Hur2 : u * (1 - 1.7882e-7 / 2 - 1.7882e-7 * 1.7882e-7) <= u * r) by (apply Rmult_le_compat_l; [rewrite Hu; lra|lra]).
  rewrite Hu in Hur, Hur2, E4, E5. split; lra.
Qed.


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

(* The vector part, on its parts' bounds: the rounded products' squared
   length R2 lies between AL s^2 and AH s^2, up to 1e-28, with AL and AH
   the extreme factors of the axis's length and the two roundings. *)
Lemma vector_part : forall uu et s Q K P R R2,
  uu = / 16777216 -> 0 < et <= / 2 ^ 100 ->
  s * s <= 1.000001 ->
  1 - 1.4903e-7 <= Q <= 1 + 1.4903e-7 ->
  0 <= K -> K <= (1 + uu) * Q + 2 * et -> (1 - uu) * (1 - uu) * (Q * Q) - 4 * et * Q <= K * K ->
  0 <= P -> P * P = s * s * (K * K) ->
  0 <= R -> R * R = R2 -> R <= (1 + uu) * P + 2 * et -> (1 - uu) * (1 - uu) * (P * P) - 4 * et * P <= R2 ->
  (1 - / 16777216) * (1 - / 16777216) * ((1 - / 16777216) * (1 - / 16777216) * ((1 - 1.4903e-7) * (1 - 1.4903e-7)))
    * (s * s) - 1e-28 <= R2 <=
  (1 + / 16777216) * (1 + / 16777216)
    * (((1 + / 16777216) * (1 + 1.4903e-7) + 2e-30) * ((1 + / 16777216) * (1 + 1.4903e-7) + 2e-30))
    * (s * s) + 1e-28.
Proof.
  intros uu et s Q K P R R2 Hu He Hss [QLo QUp] HK0 KUp KLo HP0 HP2 HR0 HR RUp RLo.
  subst uu.
  assert (Het : et <= 1e-30) by (simpl in He; lra).
  assert (Hs0 : 0 <= s * s) by apply Rle_0_sqr.
  (* The axis's length. *)
  set (Kh := (1 + / 16777216) * (1 + 1.4903e-7) + 2e-30).
  assert (HKh : K <= Kh).
  { assert ((1 + / 16777216) * Q <= (1 + / 16777216) * (1 + 1.4903e-7)) by (apply Rmult_le_compat_l; lra).
    unfold Kh. lra. }
  assert (HK2h : K * K <= Kh * Kh) by (apply Rmult_le_compat; lra).
  assert (HQ2 : (1 - 1.4903e-7) * (1 - 1.4903e-7) <= Q * Q) by (apply Rmult_le_compat; lra).
  set (Kl2 := (1 - / 16777216) * (1 - / 16777216) * ((1 - 1.4903e-7) * (1 - 1.4903e-7)) - 8e-30).
  assert (HK2l : Kl2 <= K * K).
  { assert ((1 - / 16777216) * (1 - / 16777216) * ((1 - 1.4903e-7) * (1 - 1.4903e-7))
            <= (1 - / 16777216) * (1 - / 16777216) * (Q * Q)) by (apply Rmult_le_compat_l; lra).
    assert (4 * et * Q <= 8e-30).
    { assert (et * Q <= 1e-30 * 2) by (apply Rmult_le_compat; lra). lra. }
    unfold Kl2. lra. }
  (* The products' exact length. *)
  assert (HP2h : P * P <= s * s * (Kh * Kh)).
  { rewrite HP2. apply Rmult_le_compat_l; lra. }
  assert (HP2l : s * s * Kl2 <= P * P).
  { rewrite HP2. apply Rmult_le_compat_l; lra. }
  assert (HP1 : P <= 2).
  { assert (P * P <= 1.01).
    { assert (Kh * Kh <= 1.000001) by (unfold Kh; lra).
      assert (0 <= Kh * Kh) by apply Rle_0_sqr.
      assert (s * s * (Kh * Kh) <= 1.000001 * 1.000001) by (apply Rmult_le_compat; lra).
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
  unfold Kh, Kl2 in *. split; lra.
Qed.

(* A root of n2 between (1 - D)^2 and (1 + D)^2 is within D of 1. *)
Lemma root_near_one : forall n2 D, 0 <= D <= 1 -> (1 - D) * (1 - D) <= n2 <= (1 + D) * (1 + D) ->
  Rabs (sqrt n2 - 1) <= D.
Proof.
  intros n2 D HD [Lo Hi]. apply abs_join. split.
  - assert (Hsq : sqrt ((1 - D) * (1 - D)) <= sqrt n2) by (apply sqrt_le_1_alt; exact Lo).
    rewrite sqrt_square in Hsq by lra. lra.
  - assert (Hsq : sqrt n2 <= sqrt ((1 + D) * (1 + D))) by (apply sqrt_le_1_alt; exact Hi).
    rewrite sqrt_square in Hsq by lra. lra.
Qed.

Theorem axis_angle_norm : forall X Y Z Sin Cos s c : R,
  let x := rnd X in
  let y := rnd Y in
  let z := rnd Z in
  1 <= x * x + y * y + z * z <= 4 ->
  Sin * Sin + Cos * Cos = 1 ->
  (Rabs (s - Sin) <= 1.0e-7 * Rabs Sin /\ Rabs (c - Cos) <= 8e-8 * Rabs Cos /\ Sin * Sin <= 0.5000001)
  \/ (Rabs (s - Sin) <= 8e-8 * Rabs Sin /\ Rabs (c - Cos) <= 1.0e-7 * Rabs Cos /\ Cos * Cos <= 0.5000001) ->
  let q := rnd (rnd (rnd (rnd (x * x) + rnd (y * y)) + rnd (z * z)) + rnd (0 * 0)) in
  let b := rnd (sqrt (q)) in
  let kx := rnd (x / b) in
  let ky := rnd (y / b) in
  let kz := rnd (z / b) in
  let rx := rnd (kx * s) in
  let ry := rnd (ky * s) in
  let rz := rnd (kz * s) in
  Rabs (sqrt (c * c + rx * rx + ry * ry + rz * rz) - 1) <= 3.483e-7.
Proof.
  intros X Y Z Sin Cos s c x y z HS Hunit Hsc q b kx ky kz rx ry rz.
  pose proof u_pos as Hu0; pose proof eta_pos as He0.
  assert (Heta : 0 < eta <= / 2 ^ 100) by (split; [lra|unfold eta; simpl; lra]).
  (* The root (axis_root). *)
  set (N := sqrt (x * x + y * y + z * z + 0 * 0)).
  assert (Hroot : -1.4902e-7 <= (b - N) / N <= 1.4902e-7) by exact (axis_root X Y Z HS).
  assert (HN : 1 <= N).
  { unfold N. rewrite <- sqrt_1. apply sqrt_le_1_alt. lra. }
  set (dl := (b - N) / N) in Hroot.
  assert (Hb : b = N * (1 + dl)) by (unfold dl; field; lra).
  assert (Hdl : -1.4902e-7 <= dl <= 1.4902e-7) by exact Hroot.
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
  assert (HQh : Q <= 1 + 1.4903e-7).
  { assert (Q * (1 - 1.4902e-7) <= 1).
    { assert (Q * (- 1.4902e-7) <= Q * dl) by (apply Rmult_le_compat_l; lra). lra. }
    lra. }
  assert (HQl : 1 - 1.4903e-7 <= Q).
  { assert (1 <= Q * (1 + 1.4902e-7)).
    { assert (Q * dl <= Q * (1.4902e-7)) by (apply Rmult_le_compat_l; lra). lra. }
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
  (* The kernel's hypothesis, squared: in either case s within 1.0e-7 of
     Sin, relative, so s^2 <= 1.000001, which the vector part takes. *)
  assert (Hs : Rabs (s - Sin) <= 1.0e-7 * Rabs Sin).
  { assert (0 <= Rabs Sin) by apply Rabs_pos. destruct Hsc as [[Hk _]|[Hk _]]; lra. }
  assert (HSin : 0 <= Sin * Sin) by apply Rle_0_sqr.
  assert (HCos : 0 <= Cos * Cos) by apply Rle_0_sqr.
  assert (Hss : s * s <= 1.000001).
  { pose proof (sq_rel s Sin 1.0e-7 ltac:(lra) Hs) as [_ Hk]. lra. }
  pose proof (vector_part u eta s Q K P (sqrt R2) R2 eq_refl Heta Hss (conj HQl HQh) (sqrt_pos _) KUp KLo
                (sqrt_pos _) HP2 (sqrt_pos _) HR RUp RLo) as [VLo VUp].
  (* The last step: c^2 + R2 lies between Cos^2 Lc + Sin^2 Ls and
     Cos^2 Hc + Sin^2 Hs, a weighted average (Cos^2 + Sin^2 = 1) in which
     the sine polynomial's larger error weighs at most 0.5000001. *)
  apply root_near_one; [lra|].
  destruct Hsc as [[Hs' [Hc Hw]]|[Hs' [Hc Hw]]].
  - pose proof (sq_rel s Sin 1.0e-7 ltac:(lra) Hs') as [SLo SUp].
    pose proof (sq_rel c Cos 8e-8 ltac:(lra) Hc) as [CLo CUp].
    split; lra.
  - pose proof (sq_rel s Sin 8e-8 ltac:(lra) Hs') as [SLo SUp].
    pose proof (sq_rel c Cos 1.0e-7 ltac:(lra) Hc) as [CLo CUp].
    split; lra.
Qed.
