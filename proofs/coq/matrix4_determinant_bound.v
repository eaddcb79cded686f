(* The determinant of a 4x4 matrix (src/matrix/matrix4.rs,
   Matrix4::determinant, s . v + t . u of the cofactors' 2x2 minors), for
   entries at most M in magnitude, where nothing overflows: within
   (1 + 2^-24)^8 - 1 of the exact determinant, relative to the sum T of
   the magnitudes of the 24 products of four entries of its expansion,
   besides at most 112 2^-150 (1 + M^2) from roundings near underflow.

   The rounded terms are those of proofs/gappa/matrix4_determinant.g,
   which computes the code's bits (the correspondence test checks both).
   Each product of four entries passes through eight roundings: two
   products of entries and their difference in each minor, the product
   of the two minors, two sums in its dot product at most and the last
   sum. *)
(*! bound DETERMINANT_MAX_REL_ERROR matrix4_determinant <= 4.7684e-7 |det - exact| over the sum of the 24 products' magnitudes *)
Require Import Reals Psatz.
Require Import Laws.Common Laws.Tracked.

Open Scope R_scope.

(* The magnitude of a 2x2 minor's two products, for entries at most M. *)
Lemma pair_magnitude : forall M p0 p1 p2 p3,
  Rabs p0 <= M -> Rabs p1 <= M -> Rabs p2 <= M -> Rabs p3 <= M ->
  0 <= Rabs p0 * Rabs p1 + Rabs p2 * Rabs p3 <= 2 * (M * M).
Proof.
  intros M p0 p1 p2 p3 H0 H1 H2 H3.
  pose proof (Rabs_pos p0); pose proof (Rabs_pos p1);
  pose proof (Rabs_pos p2); pose proof (Rabs_pos p3).
  assert (Rabs p0 * Rabs p1 <= M * M) by (apply Rmult_le_compat; lra).
  assert (Rabs p2 * Rabs p3 <= M * M) by (apply Rmult_le_compat; lra).
  split; [apply Rplus_le_le_0_compat; apply Rmult_le_pos|]; lra.
Qed.

(* One product of two 2x2 minors, each the rounded difference of two
   rounded products, for entries at most M in magnitude. *)
Lemma minor_product : forall M p0 p1 p2 p3 q0 q1 q2 q3,
  Rabs p0 <= M -> Rabs p1 <= M -> Rabs p2 <= M -> Rabs p3 <= M ->
  Rabs q0 <= M -> Rabs q1 <= M -> Rabs q2 <= M -> Rabs q3 <= M ->
  near (rnd (rnd (rnd (p0 * p1) - rnd (p2 * p3)) * rnd (rnd (q0 * q1) - rnd (q2 * q3))))
       ((p0 * p1 - p2 * p3) * (q0 * q1 - q2 * q3))
       ((Rabs p0 * Rabs p1 + Rabs p2 * Rabs p3) * (Rabs q0 * Rabs q1 + Rabs q2 * Rabs q3))
       (5.000001 * u) (13 * eta * (1 + M * M)).
Proof.
  intros M p0 p1 p2 p3 q0 q1 q2 q3 H0 H1 H2 H3 K0 K1 K2 K3.
  pose proof u_pos as Hu. pose proof eta_pos as He.
  pose proof (near_sub _ _ _ _ _ _ u eta eta (Rlt_le _ _ Hu) (Rlt_le _ _ He) (Rlt_le _ _ He)
                (near_product p0 p1) (near_product p2 p3)) as Np.
  pose proof (near_sub _ _ _ _ _ _ u eta eta (Rlt_le _ _ Hu) (Rlt_le _ _ He) (Rlt_le _ _ He)
                (near_product q0 q1) (near_product q2 q3)) as Nq.
  set (k1 := u + u + u * u) in *.
  set (e1 := (1 + u) * (eta + eta) + eta) in *.
  assert (Hk1 : 0 <= k1) by (unfold k1; nra).
  assert (He1 : 0 <= e1) by (unfold e1; nra).
  pose proof (near_mul _ _ _ _ _ _ _ _ _ Hk1 He1 He1 Np Nq) as N.
  set (A := Rabs p0 * Rabs p1 + Rabs p2 * Rabs p3) in *.
  set (B := Rabs q0 * Rabs q1 + Rabs q2 * Rabs q3) in *.
  pose proof (pair_magnitude M p0 p1 p2 p3 H0 H1 H2 H3) as HA.
  pose proof (pair_magnitude M q0 q1 q2 q3 K0 K1 K2 K3) as HB.
  fold A in HA. fold B in HB.
  apply (near_weaken _ _ _ _ _ _ _ N).
  - apply Rmult_le_pos; lra.
  - unfold k1, u; lra.
  - assert (Hsum : A * e1 + B * e1 <= 4 * (M * M) * e1) by nra.
    assert (He14 : 0 <= e1 <= 4 * eta) by (unfold e1, u; lra).
    assert (Heta : eta <= / 16) by (unfold eta; simpl; lra).
    assert (Hee : e1 * e1 <= eta) by nra.
    assert (HMM : 0 <= M * M) by nra.
    assert (Hk : (1 + k1) <= 1.0001) by (unfold k1, u; lra).
    assert (HAB : 0 <= A * e1 + B * e1) by nra.
    assert ((1 + k1) * (A * e1 + B * e1) <= 1.0001 * (4 * (M * M) * e1)) by nra.
    assert (He1b : e1 <= 3.0001 * eta) by (unfold e1, u; lra).
    assert (4 * (M * M) * e1 <= 4 * (M * M) * (3.0001 * eta)) by nra.
    unfold u in *. nra.
Qed.

Theorem matrix4_determinant : forall M a0 a1 a2 b0 b1 b2 c0 c1 c2 d0 d1 d2 x y z w : R,
  Rabs a0 <= M -> Rabs a1 <= M -> Rabs a2 <= M -> Rabs b0 <= M -> Rabs b1 <= M ->
  Rabs b2 <= M -> Rabs c0 <= M -> Rabs c1 <= M -> Rabs c2 <= M -> Rabs d0 <= M ->
  Rabs d1 <= M -> Rabs d2 <= M -> Rabs x <= M -> Rabs y <= M -> Rabs z <= M -> Rabs w <= M ->
  let s0 := rnd (rnd (a1 * b2) - rnd (a2 * b1)) in
  let s1 := rnd (rnd (a2 * b0) - rnd (a0 * b2)) in
  let s2 := rnd (rnd (a0 * b1) - rnd (a1 * b0)) in
  let t0 := rnd (rnd (c1 * d2) - rnd (c2 * d1)) in
  let t1 := rnd (rnd (c2 * d0) - rnd (c0 * d2)) in
  let t2 := rnd (rnd (c0 * d1) - rnd (c1 * d0)) in
  let u0 := rnd (rnd (a0 * y) - rnd (b0 * x)) in
  let u1 := rnd (rnd (a1 * y) - rnd (b1 * x)) in
  let u2 := rnd (rnd (a2 * y) - rnd (b2 * x)) in
  let v0 := rnd (rnd (c0 * w) - rnd (d0 * z)) in
  let v1 := rnd (rnd (c1 * w) - rnd (d1 * z)) in
  let v2 := rnd (rnd (c2 * w) - rnd (d2 * z)) in
  let det := rnd (rnd (rnd (rnd (s0 * v0) + rnd (s1 * v1)) + rnd (s2 * v2))
                + rnd (rnd (rnd (t0 * u0) + rnd (t1 * u1)) + rnd (t2 * u2))) in
  let D := (a1 * b2 - a2 * b1) * (c0 * w - d0 * z) + (a2 * b0 - a0 * b2) * (c1 * w - d1 * z)
         + (a0 * b1 - a1 * b0) * (c2 * w - d2 * z) + (c1 * d2 - c2 * d1) * (a0 * y - b0 * x)
         + (c2 * d0 - c0 * d2) * (a1 * y - b1 * x) + (c0 * d1 - c1 * d0) * (a2 * y - b2 * x) in
  let T := (Rabs (a1 * b2) + Rabs (a2 * b1)) * (Rabs (c0 * w) + Rabs (d0 * z))
         + (Rabs (a2 * b0) + Rabs (a0 * b2)) * (Rabs (c1 * w) + Rabs (d1 * z))
         + (Rabs (a0 * b1) + Rabs (a1 * b0)) * (Rabs (c2 * w) + Rabs (d2 * z))
         + (Rabs (c1 * d2) + Rabs (c2 * d1)) * (Rabs (a0 * y) + Rabs (b0 * x))
         + (Rabs (c2 * d0) + Rabs (c0 * d2)) * (Rabs (a1 * y) + Rabs (b1 * x))
         + (Rabs (c0 * d1) + Rabs (c1 * d0)) * (Rabs (a2 * y) + Rabs (b2 * x)) in
  0 < T ->
  (Rabs (det - D) - 112 * eta * (1 + M * M)) / T <= 4.7684e-7.
Proof.
  intros M a0 a1 a2 b0 b1 b2 c0 c1 c2 d0 d1 d2 x y z w
    Ha0 Ha1 Ha2 Hb0 Hb1 Hb2 Hc0 Hc1 Hc2 Hd0 Hd1 Hd2 Hx Hy Hz Hw
    s0 s1 s2 t0 t1 t2 u0 u1 u2 v0 v1 v2 det D T HT.
  pose proof u_pos as Hu. pose proof eta_pos as He.
  pose proof (minor_product M _ _ _ _ _ _ _ _ Ha1 Hb2 Ha2 Hb1 Hc0 Hw Hd0 Hz) as P0.
  pose proof (minor_product M _ _ _ _ _ _ _ _ Ha2 Hb0 Ha0 Hb2 Hc1 Hw Hd1 Hz) as P1.
  pose proof (minor_product M _ _ _ _ _ _ _ _ Ha0 Hb1 Ha1 Hb0 Hc2 Hw Hd2 Hz) as P2.
  pose proof (minor_product M _ _ _ _ _ _ _ _ Hc1 Hd2 Hc2 Hd1 Ha0 Hy Hb0 Hx) as Q0.
  pose proof (minor_product M _ _ _ _ _ _ _ _ Hc2 Hd0 Hc0 Hd2 Ha1 Hy Hb1 Hx) as Q1.
  pose proof (minor_product M _ _ _ _ _ _ _ _ Hc0 Hd1 Hc1 Hd0 Ha2 Hy Hb2 Hx) as Q2.
  fold s0 s1 s2 t0 t1 t2 u0 u1 u2 v0 v1 v2 in P0, P1, P2, Q0, Q1, Q2.
  set (k := 5.000001 * u) in *.
  set (e := 13 * eta * (1 + M * M)) in *.
  assert (Hk : 0 <= k) by (unfold k; lra).
  assert (HM : 0 <= M * M) by nra.
  assert (Hep : 0 <= e) by (unfold e; nra).
  (* The two dot products, left to right. *)
  pose proof (near_add _ _ _ _ _ _ _ _ _ Hk Hep Hep P0 P1) as SP.
  pose proof (near_add _ _ _ _ _ _ _ _ _ Hk Hep Hep Q0 Q1) as SQ.
  set (k' := u + k + u * k) in *.
  set (e' := (1 + u) * (e + e) + eta) in *.
  assert (Hkk : k <= k') by (unfold k'; nra).
  assert (Hk' : 0 <= k') by lra.
  assert (He' : e <= e') by (unfold e'; nra).
  assert (He'p : 0 <= e') by lra.
  assert (Pos : forall p q r s : R, 0 <= Rabs p * Rabs q + Rabs r * Rabs s)
    by (intros; apply Rplus_le_le_0_compat; apply Rmult_le_pos; apply Rabs_pos).
  pose proof (near_weaken _ _ _ _ _ _ _ P2 (Rmult_le_pos _ _ (Pos _ _ _ _) (Pos _ _ _ _)) Hkk He') as P2'.
  pose proof (near_weaken _ _ _ _ _ _ _ Q2 (Rmult_le_pos _ _ (Pos _ _ _ _) (Pos _ _ _ _)) Hkk He') as Q2'.
  pose proof (near_add _ _ _ _ _ _ _ _ _ Hk' He'p He'p SP P2') as DP.
  pose proof (near_add _ _ _ _ _ _ _ _ _ Hk' He'p He'p SQ Q2') as DQ.
  set (k'' := u + k' + u * k') in *.
  set (e'' := (1 + u) * (e' + e') + eta) in *.
  assert (Hk'' : 0 <= k'') by (unfold k''; nra).
  assert (He'' : 0 <= e'') by (unfold e''; nra).
  pose proof (near_add _ _ _ _ _ _ _ _ _ Hk'' He'' He'' DP DQ) as N.
  destruct N as [_ N]. fold det in N.
  assert (HD : (a1 * b2 - a2 * b1) * (c0 * w - d0 * z) + (a2 * b0 - a0 * b2) * (c1 * w - d1 * z)
      + (a0 * b1 - a1 * b0) * (c2 * w - d2 * z) + ((c1 * d2 - c2 * d1) * (a0 * y - b0 * x)
      + (c2 * d0 - c0 * d2) * (a1 * y - b1 * x) + (c0 * d1 - c1 * d0) * (a2 * y - b2 * x)) = D)
    by (unfold D; ring).
  rewrite HD in N.
  assert (HTT : (Rabs a1 * Rabs b2 + Rabs a2 * Rabs b1) * (Rabs c0 * Rabs w + Rabs d0 * Rabs z)
      + (Rabs a2 * Rabs b0 + Rabs a0 * Rabs b2) * (Rabs c1 * Rabs w + Rabs d1 * Rabs z)
      + (Rabs a0 * Rabs b1 + Rabs a1 * Rabs b0) * (Rabs c2 * Rabs w + Rabs d2 * Rabs z)
      + ((Rabs c1 * Rabs d2 + Rabs c2 * Rabs d1) * (Rabs a0 * Rabs y + Rabs b0 * Rabs x)
      + (Rabs c2 * Rabs d0 + Rabs c0 * Rabs d2) * (Rabs a1 * Rabs y + Rabs b1 * Rabs x)
      + (Rabs c0 * Rabs d1 + Rabs c1 * Rabs d0) * (Rabs a2 * Rabs y + Rabs b2 * Rabs x)) = T)
    by (unfold T; rewrite !Rabs_mult; ring).
  rewrite HTT in N.
  assert (Hk3 : u + k'' + u * k'' <= 4.7684e-7) by (unfold k'', k', k, u; lra).
  assert (He3 : (1 + u) * (e'' + e'') + eta <= 112 * eta * (1 + M * M))
    by (unfold e'', e', e, u; nra).
  assert ((u + k'' + u * k'') * T <= 4.7684e-7 * T) by (apply Rmult_le_compat_r; lra).
  apply Rmult_le_reg_r with T; [exact HT|].
  unfold Rdiv. rewrite Rmult_assoc, Rinv_l by lra. lra.
Qed.
