(* slerp's f32 evaluation in the plane (src/quat/slerp/in_f32.rs,
   slerp_f32 then slerp_in_plane, alpha in (0, 1), the branch phi > 2^-12):
   two pieces of the norm of its result, proven here; the law that joins
   them to the kernels' errors is not (docs/verification-proofs.md says
   what it lacks).

   The shares of the angle (slerp_plane_shares): far = rnd(alpha phi) and
   near = rnd(phi - far), for f32 alpha in [0, 1] and phi >= 2^-12, lie in
   [0, phi] (rounding is monotone and phi is an f32); where far >= phi / 2
   (alpha about 1/2 and above), phi - far is an f32 (Sterbenz's lemma,
   Flocq's sterbenz), so near + far = phi exactly; elsewhere (far <
   phi / 2) near + far differs from phi by the rounding of phi - far
   alone, which is not 0 where far has bits below the ulp of phi - far, at
   most 2^-24 (phi - far) <= 2^-24 phi (and 2^-150 below the normal range, which
   phi >= 2^-12 makes at most 4e-42 relative): | near + far - phi | / phi
   <= 5.961e-8 in every case.

   The exact combination at the computed angle
   (slerp_plane_exact_norm): for unit a and b at the exact angle theta
   (a . b = cos theta) and shares n, f >= 0 of an angle n + f in (0, pi/2]
   (the code's near and far; phi' = n + f is the angle they make, phi's
   f32 shares), the coefficients C0 = sin(n) / sin(phi') and C1 = sin(f) /
   sin(phi') make |C0 a + C1 b|^2 = C0^2 + C1^2 + 2 C0 C1 cos(theta), and
   as sin^2 n + sin^2 f + 2 sin n sin f cos(n + f) = sin^2(n + f)
   (shares_identity, from sin_plus and cos_plus), that is 1 + 2 C0 C1
   (cos theta - cos phi'). With 2 sin n sin f = cos(n - f) - cos(phi')
   <= 1 - cos(phi') <= sin^2(phi') (cos phi' >= 0), 2 C0 C1 <= 1, and
   |cos theta - cos phi'| <= |theta - phi'| (form2 and |sin x| <= |x|):
   the squared norm of the exact combination moves from 1 by at most the
   angle's error, | |C0 a + C1 b|^2 - 1 | / |theta - phi'| <= 1 (to
   first order the factor is tan(phi' / 2), which reaches 1 at pi/2).

   Assumed: nothing beyond the theorems' hypotheses; no certificate. *)
(*! law - slerp_plane_shares <= 5.961e-8 | near + far - phi | / phi, slerp's f32 shares of the angle, phi >= 2^-12, alpha in [0, 1]; 0 where far >= phi / 2 *)
(*! law - slerp_plane_exact_norm <= 1.0 | |C0 a + C1 b|^2 - 1 | / |theta - (n + f)|, unit a, b at the angle theta, coefficients sin(n) / sin(n + f), sin(f) / sin(n + f), n + f in (0, pi/2] *)
Require Import Reals Psatz.
Require Import Flocq.Core.Core Flocq.Prop.Sterbenz.
Require Import Laws.Common.

Open Scope R_scope.

Lemma rnd_format : forall x, generic_format radix2 (FLT_exp (-149) 24) (rnd x).
Proof.
  intro x. apply generic_format_round; [apply FLT_exp_valid; reflexivity|unfold rndNE; apply valid_rnd_N].
Qed.

Lemma shares : forall A P : R,
  let alpha := rnd A in let phi := rnd P in
  0 <= alpha <= 1 -> 0 < phi ->
  let far := rnd (alpha * phi) in
  let near := rnd (phi - far) in
  0 <= far <= phi /\ 0 <= near <= phi /\
  (phi / 2 <= far -> near + far = phi) /\
  Rabs (near + far - phi) <= u * phi + eta.
Proof.
  intros A P alpha phi Ha Hp far near.
  assert (Rphi : rnd phi = phi).
  { apply round_generic; [unfold rndNE; apply valid_rnd_N|apply rnd_format]. }
  assert (Hf : 0 <= far <= phi).
  { split.
    - rewrite <- rnd_0. apply rnd_monotone. nra.
    - apply Rle_trans with (rnd phi); [apply rnd_monotone; nra|lra]. }
  assert (Hn : 0 <= near <= phi).
  { split.
    - rewrite <- rnd_0. apply rnd_monotone. lra.
    - apply Rle_trans with (rnd phi); [apply rnd_monotone; lra|lra]. }
  assert (E : near + far - phi = near - (phi - far)) by ring.
  split; [exact Hf|]. split; [exact Hn|]. split.
  - intro H. assert (F : generic_format radix2 (FLT_exp (-149) 24) (phi - far)).
    { apply sterbenz; [apply FLT_exp_valid; reflexivity|apply FLT_exp_monotone|apply rnd_format|apply rnd_format|lra]. }
    assert (near = phi - far) by (apply round_generic; [unfold rndNE; apply valid_rnd_N|exact F]).
    lra.
  - rewrite E. pose proof (rnd_err (phi - far)) as R. fold near in R.
    rewrite (Rabs_right (phi - far)) in R by lra.
    pose proof u_pos. assert (u * (phi - far) <= u * phi) by (apply Rmult_le_compat_l; lra). lra.
Qed.

(* The law of the shares, for phi >= 2^-12 (slerp's branch), relative. *)
Theorem slerp_plane_shares : forall A P : R,
  let alpha := rnd A in let phi := rnd P in
  0 <= alpha <= 1 -> / 4096 <= phi ->
  let far := rnd (alpha * phi) in
  let near := rnd (phi - far) in
  (phi / 2 <= far -> near + far = phi) /\
  Rabs (near + far - phi) / phi <= 5.961e-8.
Proof.
  intros A P alpha phi Ha Hp far near.
  assert (Hp0 : 0 < phi) by lra.
  destruct (shares A P Ha Hp0) as (_ & _ & Ex & B).
  fold alpha phi far near in Ex, B.
  split; [exact Ex|].
  pose proof eta_pos as He.
  assert (Heta : eta <= / 1000000000000000000000000000000) by (unfold eta; simpl; lra).
  apply (Rmult_le_reg_r phi); [lra|]. unfold Rdiv. rewrite Rmult_assoc, Rinv_l, Rmult_1_r by lra.
  unfold u in B. nra.
Qed.

(* sin^2 n + sin^2 f + 2 sin n sin f cos (n + f) = sin^2 (n + f). *)
Lemma shares_identity : forall n f,
  sin n * sin n + sin f * sin f + 2 * sin n * sin f * cos (n + f)
  = sin (n + f) * sin (n + f).
Proof.
  intros n f. rewrite sin_plus, cos_plus.
  pose proof (sin2_cos2 n) as Pn. pose proof (sin2_cos2 f) as Pf. unfold Rsqr in *.
  assert (E : (sin n * cos f + cos n * sin f) * (sin n * cos f + cos n * sin f)
    = sin n * sin n * (cos f * cos f) + sin f * sin f * (cos n * cos n)
      + 2 * sin n * sin f * (cos n * cos f)) by ring.
  rewrite E. replace (cos n * cos n) with (1 - sin n * sin n) by lra.
  replace (cos f * cos f) with (1 - sin f * sin f) by lra. ring.
Qed.

(* | sin t | <= | t |. *)
Lemma sin_abs_le : forall t, Rabs (sin t) <= Rabs t.
Proof.
  assert (P : forall t, 0 <= t -> Rabs (sin t) <= t).
  { intros t H. pose proof (SIN_bound t) as B.
    destruct (Req_dec t 0) as [Z|Z].
    { rewrite Z, sin_0, Rabs_R0. lra. }
    pose proof (sin_lt_x t ltac:(lra)) as L.
    destruct (Rle_dec t 1) as [T|T].
    - pose proof PI2_1. rewrite Rabs_right; [lra|].
      apply Rle_ge, sin_ge_0; lra.
    - apply Rabs_le. lra. }
  intro t. destruct (Rle_dec 0 t) as [G|G].
  - rewrite (Rabs_right t) by lra. apply P. exact G.
  - replace (sin t) with (- sin (- t)) by (rewrite sin_neg; ring).
    rewrite Rabs_Ropp, (Rabs_left t) by lra. apply P. lra.
Qed.

(* | cos x - cos y | <= | x - y |. *)
Lemma cos_lipschitz : forall x y, Rabs (cos x - cos y) <= Rabs (x - y).
Proof.
  intros x y. rewrite form2.
  rewrite !Rabs_mult.
  pose proof (sin_abs_le ((x - y) / 2)) as A.
  pose proof (SIN_bound ((x + y) / 2)) as B.
  assert (B' : Rabs (sin ((x + y) / 2)) <= 1) by (apply Rabs_le; lra).
  replace (Rabs ((x - y) / 2)) with (Rabs (x - y) / 2) in A
    by (unfold Rdiv; rewrite Rabs_mult, (Rabs_right (/ 2)) by lra; ring).
  assert (M2 : Rabs (-2) = 2) by (rewrite Rabs_left; lra). rewrite M2.
  pose proof (Rabs_pos (sin ((x - y) / 2))). pose proof (Rabs_pos (sin ((x + y) / 2))).
  assert (Rabs (sin ((x - y) / 2)) * Rabs (sin ((x + y) / 2)) <= Rabs (x - y) / 2 * 1)
    by (apply Rmult_le_compat; lra).
  lra.
Qed.

Theorem slerp_plane_exact_norm : forall a0 a1 a2 a3 b0 b1 b2 b3 theta n f : R,
  a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3 = 1 ->
  b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3 = 1 ->
  a0 * b0 + a1 * b1 + a2 * b2 + a3 * b3 = cos theta ->
  0 <= n -> 0 <= f -> 0 < n + f <= PI / 2 -> theta <> n + f ->
  let C0 := sin n / sin (n + f) in
  let C1 := sin f / sin (n + f) in
  let r0 := C0 * a0 + C1 * b0 in let r1 := C0 * a1 + C1 * b1 in
  let r2 := C0 * a2 + C1 * b2 in let r3 := C0 * a3 + C1 * b3 in
  Rabs (r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3 - 1) / Rabs (theta - (n + f)) <= 1.0.
Proof.
  intros a0 a1 a2 a3 b0 b1 b2 b3 theta n f QA QB D Hn Hf Hp Hne C0 C1 r0 r1 r2 r3.
  replace 1.0 with 1 by lra.
  pose proof PI_RGT_0 as Hpi.
  set (p := n + f) in *.
  assert (Ep : p = n + f) by reflexivity.
  assert (HS : 0 < sin p) by (apply sin_gt_0; lra).
  assert (Hsn : 0 <= sin n) by (apply sin_ge_0; lra).
  assert (Hsf : 0 <= sin f) by (apply sin_ge_0; lra).
  assert (Hcp : 0 <= cos p) by (apply cos_ge_0; lra).
  assert (N2 : r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3
    = C0 * C0 * (a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3)
      + C1 * C1 * (b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3)
      + 2 * C0 * C1 * (a0 * b0 + a1 * b1 + a2 * b2 + a3 * b3))
    by (unfold r0, r1, r2, r3; ring).
  rewrite QA, QB, D in N2.
  assert (One : C0 * C0 + C1 * C1 + 2 * C0 * C1 * cos p = 1).
  { pose proof (shares_identity n f) as I. fold p in I.
    assert (E0 : C0 * sin p = sin n) by (unfold C0; field; lra).
    assert (E1 : C1 * sin p = sin f) by (unfold C1; field; lra).
    assert (Z : (C0 * C0 + C1 * C1 + 2 * C0 * C1 * cos p - 1) * (sin p * sin p) = 0).
    { replace ((C0 * C0 + C1 * C1 + 2 * C0 * C1 * cos p - 1) * (sin p * sin p))
        with ((C0 * sin p) * (C0 * sin p) + (C1 * sin p) * (C1 * sin p)
          + 2 * (C0 * sin p) * (C1 * sin p) * cos p - sin p * sin p) by ring.
      rewrite E0, E1, <- I. ring. }
    apply Rmult_integral in Z. destruct Z as [Z|Z]; nra. }
  assert (Diff : r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3 - 1 = 2 * C0 * C1 * (cos theta - cos p))
    by (rewrite N2; lra).
  (* 2 sin n sin f <= 1 - cos p <= sin^2 p: 2 C0 C1 <= 1. *)
  assert (K : 0 <= 2 * C0 * C1 <= 1).
  { assert (Cm : cos (n - f) = cos n * cos f + sin n * sin f) by apply cos_minus.
    assert (Cp : cos p = cos n * cos f - sin n * sin f) by (unfold p; apply cos_plus).
    pose proof (COS_bound (n - f)).
    pose proof (sin2_cos2 p) as P2. unfold Rsqr in P2.
    assert (T : 2 * sin n * sin f <= sin p * sin p) by nra.
    assert (E : 2 * C0 * C1 = 2 * sin n * sin f / (sin p * sin p)) by (unfold C0, C1; field; lra).
    rewrite E. split.
    - apply Rmult_le_pos; [nra|]. left. apply Rinv_0_lt_compat. nra.
    - apply (Rmult_le_reg_r (sin p * sin p)); [nra|]. unfold Rdiv.
      rewrite Rmult_assoc, Rinv_l by nra. lra. }
  assert (Hd : 0 < Rabs (theta - p)) by (apply Rabs_pos_lt; lra).
  apply (Rmult_le_reg_r (Rabs (theta - p))); [exact Hd|].
  unfold Rdiv. rewrite Rmult_assoc, Rinv_l, Rmult_1_r, Rmult_1_l by lra.
  rewrite Diff, Rabs_mult, (Rabs_right (2 * C0 * C1)) by lra.
  pose proof (cos_lipschitz theta p). pose proof (Rabs_pos (cos theta - cos p)).
  assert (2 * C0 * C1 * Rabs (cos theta - cos p) <= 1 * Rabs (theta - p)) by (apply Rmult_le_compat; lra).
  lra.
Qed.
