(* The determinant of a 3x3 matrix (src/matrix/matrix3.rs,
   Matrix3::determinant, a . (b x c)), for any entries where nothing
   overflows: within (1 + 2^-24)^5 - 1 of the exact determinant, relative
   to the sum T of the magnitudes of the six products of its expansion,
   besides at most 8 2^-150 (1 + |a0| + |a1| + |a2|) from roundings near
   underflow.

   The rounded terms x, y, z and d are those of
   proofs/gappa/matrix3_determinant.g, which computes the code's bits
   (the correspondence test checks both). Each term of the expansion
   passes through five roundings (a product, the cross product's
   difference, the product with a, two sums at most), and each rounding
   is relative to what it rounds: Tracked.v carries the bound through. *)
(*! bound MATRIX3_DETERMINANT_MAX_REL_ERROR matrix3_determinant <= 2.9803e-7 |det - exact| over the sum of the six products' magnitudes *)
Require Import Reals Psatz.
Require Import Laws.Common Laws.Tracked.

Open Scope R_scope.

Theorem matrix3_determinant : forall a0 a1 a2 b0 b1 b2 c0 c1 c2 : R,
  let x := rnd (rnd (b1 * c2) - rnd (b2 * c1)) in
  let y := rnd (rnd (b2 * c0) - rnd (b0 * c2)) in
  let z := rnd (rnd (b0 * c1) - rnd (b1 * c0)) in
  let d := rnd (rnd (rnd (a0 * x) + rnd (a1 * y)) + rnd (a2 * z)) in
  let D := a0 * (b1 * c2 - b2 * c1) + a1 * (b2 * c0 - b0 * c2) + a2 * (b0 * c1 - b1 * c0) in
  let T := Rabs (a0 * b1 * c2) + Rabs (a0 * b2 * c1) + Rabs (a1 * b2 * c0)
         + Rabs (a1 * b0 * c2) + Rabs (a2 * b0 * c1) + Rabs (a2 * b1 * c0) in
  0 < T ->
  (Rabs (d - D) - 8 * eta * (1 + Rabs a0 + Rabs a1 + Rabs a2)) / T <= 2.9803e-7.
Proof.
  intros a0 a1 a2 b0 b1 b2 c0 c1 c2 x y z d D T HT.
  pose proof u_pos as Hu. pose proof eta_pos as He.
  assert (Hk1 : 0 <= u + u + u * u) by nra.
  set (k1 := u + u + u * u) in *.
  set (e1 := (1 + u) * (eta + eta) + eta).
  assert (He1 : 0 <= e1) by (unfold e1; nra).
  (* The cross product's components. *)
  pose proof (near_sub _ _ _ _ _ _ u eta eta (Rlt_le _ _ Hu) (Rlt_le _ _ He) (Rlt_le _ _ He)
                (near_product b1 c2) (near_product b2 c1)) as Nx.
  pose proof (near_sub _ _ _ _ _ _ u eta eta (Rlt_le _ _ Hu) (Rlt_le _ _ He) (Rlt_le _ _ He)
                (near_product b2 c0) (near_product b0 c2)) as Ny.
  pose proof (near_sub _ _ _ _ _ _ u eta eta (Rlt_le _ _ Hu) (Rlt_le _ _ He) (Rlt_le _ _ He)
                (near_product b0 c1) (near_product b1 c0)) as Nz.
  fold x y z k1 e1 in Nx, Ny, Nz.
  (* Each times an entry of the first column. *)
  pose proof (near_scale a0 _ _ _ _ _ Hk1 He1 Nx) as Mx.
  pose proof (near_scale a1 _ _ _ _ _ Hk1 He1 Ny) as My.
  pose proof (near_scale a2 _ _ _ _ _ Hk1 He1 Nz) as Mz.
  set (k2 := u + k1 + u * k1) in *.
  assert (Hk2 : 0 <= k2) by (unfold k2; nra).
  assert (Hex : 0 <= (1 + u) * (Rabs a0 * e1) + eta)
    by (pose proof (Rabs_pos a0); assert (0 <= Rabs a0 * e1) by nra; nra).
  assert (Hey : 0 <= (1 + u) * (Rabs a1 * e1) + eta)
    by (pose proof (Rabs_pos a1); assert (0 <= Rabs a1 * e1) by nra; nra).
  assert (Hez : 0 <= (1 + u) * (Rabs a2 * e1) + eta)
    by (pose proof (Rabs_pos a2); assert (0 <= Rabs a2 * e1) by nra; nra).
  (* The two sums, left to right. *)
  pose proof (near_add _ _ _ _ _ _ _ _ _ Hk2 Hex Hey Mx My) as S1.
  set (k3 := u + k2 + u * k2) in *.
  assert (Hk3 : k2 <= k3) by (unfold k3; nra).
  assert (Hk3p : 0 <= k3) by lra.
  assert (HAz : 0 <= Rabs a2 * (Rabs b0 * Rabs c1 + Rabs b1 * Rabs c0))
    by (apply Rmult_le_pos; [|apply Rplus_le_le_0_compat; apply Rmult_le_pos]; apply Rabs_pos).
  pose proof (near_weaken _ _ _ _ _ _ _ Mz HAz Hk3 (Rle_refl _)) as Mz'.
  assert (He3 : 0 <= (1 + u) * ((1 + u) * (Rabs a0 * e1) + eta + ((1 + u) * (Rabs a1 * e1) + eta)) + eta)
    by (apply Rplus_le_le_0_compat; [apply Rmult_le_pos|]; lra).
  pose proof (near_add _ _ _ _ _ _ _ _ _ Hk3p He3 Hez S1 Mz') as S2.
  destruct S2 as [_ S2].
  fold d in S2.
  (* The magnitudes are the six terms'. *)
  assert (HA : Rabs a0 * (Rabs b1 * Rabs c2 + Rabs b2 * Rabs c1)
             + Rabs a1 * (Rabs b2 * Rabs c0 + Rabs b0 * Rabs c2)
             + Rabs a2 * (Rabs b0 * Rabs c1 + Rabs b1 * Rabs c0) = T).
  { unfold T. rewrite !Rabs_mult. ring. }
  replace (a0 * (b1 * c2 - b2 * c1) + a1 * (b2 * c0 - b0 * c2) + a2 * (b0 * c1 - b1 * c0))
    with D in S2 by reflexivity.
  rewrite HA in S2.
  set (k4 := u + k3 + u * k3) in *.
  assert (Hk4 : k4 <= 2.9803e-7) by (unfold k4, k3, k2, k1, u; lra).
  set (E := (1 + u) * ((1 + u) * ((1 + u) * (Rabs a0 * e1) + eta + ((1 + u) * (Rabs a1 * e1) + eta)) + eta
              + ((1 + u) * (Rabs a2 * e1) + eta)) + eta) in S2.
  assert (HE : E <= 8 * eta * (1 + Rabs a0 + Rabs a1 + Rabs a2)).
  { unfold E, e1.
    pose proof (Rabs_pos a0); pose proof (Rabs_pos a1); pose proof (Rabs_pos a2).
    assert (0 <= Rabs a0 * eta) by nra. assert (0 <= Rabs a1 * eta) by nra.
    assert (0 <= Rabs a2 * eta) by nra.
    unfold u. nra. }
  assert (k4 * T <= 2.9803e-7 * T) by (apply Rmult_le_compat_r; lra).
  apply Rmult_le_reg_r with T; [exact HT|].
  unfold Rdiv. rewrite Rmult_assoc, Rinv_l by lra. lra.
Qed.
