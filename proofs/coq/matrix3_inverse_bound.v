(* An entry of the inverse of a 3x3 matrix (src/matrix/matrix3.rs,
   Matrix3::inverse: a cross product of two columns, the minor, times
   r = 1 / det, det = a . (b x c)), for entries in [-1, 1] (the code's
   arithmetic commutes with an exact power-of-two scaling of the matrix
   wherever nothing underflows or overflows) whose determinant's expansion
   cancels by at most 2^12 (T <= 4096 |det|) and whose determinant is at
   least 2^-100: within 3.585e-7 (Am + |M| T / |D|) / |D| of the exact
   entry M / D, with M the minor, Am the sum of its two products'
   magnitudes and T the sum of the six products' magnitudes of the
   determinant's expansion, besides 4 2^-150 (1 + 1 / |D|) from
   roundings near underflow.

   The rounded terms are those of proofs/gappa/matrix3_inverse.g, which
   computes the code's bits (the correspondence test checks both, and
   maps every entry onto the model's by the minor's four entries). The
   minor's two roundings and the product's are carried through with the
   computed r taken exactly (Tracked.v); r is within (2^-24 + the
   determinant's (1 + 2^-24)^5 - 1, matrix3_determinant_bound.v) T / D^2
   of 1 / D, which is the larger part: Tracked.v's inverse_entry. *)
(*! bound MATRIX3_INVERSE_MAX_REL_ERROR matrix3_inverse_entry <= 3.585e-7 |entry - exact| over (Am + |M| T / |det|) / |det| *)
Require Import Reals Psatz.
Require Import Laws.Common Laws.Tracked.
Require Laws.matrix3_determinant_bound.

Open Scope R_scope.

Theorem matrix3_inverse_entry : forall a0 a1 a2 b0 b1 b2 c0 c1 c2 f0 f1 g0 g1 : R,
  Rabs a0 <= 1 -> Rabs a1 <= 1 -> Rabs a2 <= 1 ->
  Rabs f0 <= 1 -> Rabs f1 <= 1 -> Rabs g0 <= 1 -> Rabs g1 <= 1 ->
  let x := rnd (rnd (b1 * c2) - rnd (b2 * c1)) in
  let y := rnd (rnd (b2 * c0) - rnd (b0 * c2)) in
  let z := rnd (rnd (b0 * c1) - rnd (b1 * c0)) in
  let d := rnd (rnd (rnd (a0 * x) + rnd (a1 * y)) + rnd (a2 * z)) in
  let r := rnd (1 / d) in
  let m := rnd (rnd (f0 * g1) - rnd (f1 * g0)) in
  let e := rnd (m * r) in
  let D := a0 * (b1 * c2 - b2 * c1) + a1 * (b2 * c0 - b0 * c2) + a2 * (b0 * c1 - b1 * c0) in
  let T := Rabs (a0 * b1 * c2) + Rabs (a0 * b2 * c1) + Rabs (a1 * b2 * c0)
         + Rabs (a1 * b0 * c2) + Rabs (a2 * b0 * c1) + Rabs (a2 * b1 * c0) in
  let M := f0 * g1 - f1 * g0 in
  let Am := Rabs (f0 * g1) + Rabs (f1 * g0) in
  / 2 ^ 100 <= Rabs D -> T <= 4096 * Rabs D -> 0 < Am ->
  (Rabs (e - M / D) - 4 * eta * (1 + / Rabs D)) / ((Am + Rabs M * T / Rabs D) / Rabs D)
    <= 3.585e-7.
Proof.
  intros a0 a1 a2 b0 b1 b2 c0 c1 c2 f0 f1 g0 g1 Ha0 Ha1 Ha2 Hf0 Hf1 Hg0 Hg1 x y z d r m e D T M Am HD HT HAp.
  pose proof u_pos as Hu. pose proof eta_pos as Heta.
  assert (HDp : 0 < Rabs D) by (assert (0 < / 2 ^ 100) by (apply Rinv_0_lt_compat; apply pow_lt; lra); lra).
  (* |D| <= T: the expansion's triangle inequality. *)
  assert (HDT : Rabs D <= T).
  { unfold D, T.
    replace (a0 * (b1 * c2 - b2 * c1) + a1 * (b2 * c0 - b0 * c2) + a2 * (b0 * c1 - b1 * c0))
      with (a0 * b1 * c2 + - (a0 * b2 * c1) + a1 * b2 * c0 + - (a1 * b0 * c2)
            + a2 * b0 * c1 + - (a2 * b1 * c0)) by ring.
    repeat (eapply Rle_trans; [apply Rabs_triang|apply Rplus_le_compat; [|rewrite ?Rabs_Ropp; apply Rle_refl]]).
    rewrite ?Rabs_Ropp. apply Rle_refl. }
  assert (HTp : 0 < T) by lra.
  (* The determinant, by its law. *)
  pose proof (Laws.matrix3_determinant_bound.matrix3_determinant a0 a1 a2 b0 b1 b2 c0 c1 c2) as Hdet.
  cbv zeta in Hdet. fold x y z d D T in Hdet. specialize (Hdet HTp).
  set (Ed := 8 * eta * (1 + Rabs a0 + Rabs a1 + Rabs a2)) in Hdet.
  assert (Hd : Rabs (d - D) <= 2.9803e-7 * T + Ed).
  { apply Rmult_le_compat_r with (r := T) in Hdet; [|lra].
    unfold Rdiv in Hdet. rewrite Rmult_assoc, Rinv_l in Hdet by lra. lra. }
  assert (HEd : 0 <= Ed <= 32 * eta).
  { unfold Ed. pose proof (Rabs_pos a0); pose proof (Rabs_pos a1); pose proof (Rabs_pos a2). nra. }
  assert (HEd2 : Ed <= / 2 ^ 40 * Rabs D).
  { assert (32 * eta <= / 2 ^ 40 * / 2 ^ 100) by (unfold eta; simpl; lra).
    assert (/ 2 ^ 40 * / 2 ^ 100 <= / 2 ^ 40 * Rabs D)
      by (apply Rmult_le_compat_l; [left; apply Rinv_0_lt_compat; apply pow_lt; lra|exact HD]).
    lra. }
  (* The minor times r, with r taken exactly. *)
  pose proof (near_sub _ _ _ _ _ _ u eta eta (Rlt_le _ _ Hu) (Rlt_le _ _ Heta) (Rlt_le _ _ Heta)
                (near_product f0 g1) (near_product f1 g0)) as Nm.
  fold m in Nm.
  set (k1 := u + u + u * u) in *.
  set (e1 := (1 + u) * (eta + eta) + eta) in *.
  assert (Hk1 : 0 <= k1) by (unfold k1; nra).
  assert (He1 : 0 <= e1) by (unfold e1; nra).
  pose proof (near_scale r _ _ _ _ _ Hk1 He1 Nm) as Ne.
  rewrite Rmult_comm in Ne. fold e in Ne.
  destruct Ne as [_ Ne].
  assert (HAm : Rabs f0 * Rabs g1 + Rabs f1 * Rabs g0 = Am) by (unfold Am; rewrite !Rabs_mult; ring).
  rewrite HAm in Ne.
  replace (r * (f0 * g1 - f1 * g0)) with (r * M) in Ne by reflexivity.
  assert (HMA : Rabs M <= Am).
  { unfold M, Am. unfold Rminus. eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_Ropp. lra. }
  set (k := u + k1 + u * k1) in *.
  set (e0 := (1 + u) * (Rabs r * e1) + eta) in *.
  assert (Hk : 0 <= k <= 4e-7) by (unfold k, k1, u; split; lra).
  assert (He0 : 0 <= e0).
  { unfold e0. apply Rplus_le_le_0_compat; [|lra].
    apply Rmult_le_pos; [lra|apply Rmult_le_pos; [apply Rabs_pos|exact He1]]. }
  assert (Ne' : Rabs (e - r * M) <= k * (Rabs r * Am) + (1 + u) * e1 * Rabs r + eta)
    by (unfold e0 in Ne; lra).
  assert (Hc : 0 <= (1 + u) * e1) by nra.
  pose proof (inverse_entry e M Am r d D T k ((1 + u) * e1) eta 2.9803e-7 Ed Hk ltac:(lra) Hc
                (Rlt_le _ _ Heta) (proj1 HEd) HMA Ne' eq_refl Hd HDp HDT HT HEd2) as H.
  (* The roundings near underflow, and the two parts under one bound. *)
  assert (HAm2 : Am <= 2).
  { unfold Am. rewrite !Rabs_mult.
    assert (Rabs f0 * Rabs g1 <= 1) by (pose proof (Rabs_pos f0); pose proof (Rabs_pos g1); nra).
    assert (Rabs f1 * Rabs g0 <= 1) by (pose proof (Rabs_pos f1); pose proof (Rabs_pos g0); nra).
    lra. }
  set (ia := / Rabs D) in *.
  assert (Hia : 0 < ia) by (unfold ia; apply Rinv_0_lt_compat; lra).
  assert (Hc1 : (1 + u) * e1 <= 3.0001 * eta) by (unfold e1, u; nra).
  assert (Heta1 : eta <= 1e-40) by (unfold eta; simpl; lra).
  assert (Heta2 : eta * eta <= 1e-40 * eta) by (apply Rmult_le_compat_r; lra).
  assert (HMp : 0 <= Rabs M) by apply Rabs_pos.
  assert (HE : (1 + u) * e1 * (1.0025 / Rabs D + eta) + eta + eta * (k * Am + Rabs M)
               <= 4 * eta * (1 + ia)).
  { replace (1.0025 / Rabs D) with (1.0025 * ia) by (unfold ia; field; lra).
    assert ((1 + u) * e1 * (1.0025 * ia + eta) <= 3.0001 * eta * (1.0025 * ia + eta))
      by (apply Rmult_le_compat_r; nra).
    assert (eta * (k * Am + Rabs M) <= eta * (4e-7 * 2 + 2)) by (apply Rmult_le_compat_l; nra).
    assert (3.0001 * eta * (1.0025 * ia + eta) = 3.0001 * 1.0025 * (eta * ia) + 3.0001 * (eta * eta))
      by ring.
    assert (4 * eta * (1 + ia) = 4 * eta + 4 * (eta * ia)) by ring.
    assert (0 <= eta * ia) by nra.
    lra. }
  set (R := (Am + Rabs M * T / Rabs D) / Rabs D).
  assert (HR : R = Am / Rabs D + Rabs M * T / (Rabs D * Rabs D)) by (unfold R; field; lra).
  assert (HR1 : 0 <= Am / Rabs D) by (unfold Rdiv; fold ia; apply Rmult_le_pos; lra).
  assert (HR2 : 0 <= Rabs M * T / (Rabs D * Rabs D))
    by (unfold Rdiv; apply Rmult_le_pos; [nra|left; apply Rinv_0_lt_compat; nra]).
  assert (HRp : 0 < R).
  { unfold R. unfold Rdiv. fold ia. apply Rmult_lt_0_compat; [|exact Hia].
    assert (0 <= Rabs M * T * ia) by (apply Rmult_le_pos; nra). lra. }
  assert (Hk2 : 1.0025 * k <= 3.585e-7) by (unfold k, k1, u; lra).
  assert (Hkd : 1.0021 * (u + 2.9803e-7 + / 2 ^ 40) <= 3.585e-7) by (unfold u; simpl; lra).
  assert (1.0025 * k * (Am / Rabs D) <= 3.585e-7 * (Am / Rabs D))
    by (apply Rmult_le_compat_r; lra).
  assert (1.0021 * (u + 2.9803e-7 + / 2 ^ 40) * (Rabs M * T / (Rabs D * Rabs D))
          <= 3.585e-7 * (Rabs M * T / (Rabs D * Rabs D)))
    by (apply Rmult_le_compat_r; lra).
  apply Rmult_le_reg_r with R; [exact HRp|].
  unfold Rdiv at 1. rewrite Rmult_assoc, Rinv_l by lra.
  rewrite HR. lra.
Qed.
