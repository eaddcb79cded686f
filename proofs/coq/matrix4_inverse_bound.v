(* An entry of the inverse of a 4x4 matrix (src/matrix/matrix4.rs,
   Matrix4::inverse: the 2x2 minors of the columns, each times r = 1 /
   det, and an entry the sum of three entries of the matrix times those
   scaled minors), for entries in [-1, 1] (the code's arithmetic commutes
   with an exact power-of-two scaling of the matrix wherever nothing
   underflows or overflows) whose determinant's expansion cancels by at
   most 2^12 (T <= 4096 |det|) and whose determinant is at least 2^-100:
   within 5.376e-7 (Ac + |C| T / |D|) / |D| of the exact entry C / D,
   with C = f0 M0 + f1 M1 + f2 M2 the cofactor, Ac the sum of its six
   products' magnitudes and T the sum of the 24 products' magnitudes of
   the determinant's expansion, besides 20 2^-150 (1 + 1 / |D|) from
   roundings near underflow.

   The rounded terms are those of proofs/gappa/matrix4_inverse.g, which
   computes the code's bits (the correspondence test checks both, and
   maps every entry onto the model's by its three entries and the four
   entries of each of its three minors). Each product of the cofactor
   passes through six roundings (two products and a difference in the
   minor, the product with r, the product with the entry, two sums at
   most), carried through with the computed r taken exactly (Tracked.v);
   r is within (2^-24 + the determinant's (1 + 2^-24)^8 - 1,
   matrix4_determinant_bound.v) T / D^2 of 1 / D, which is the larger
   part: Tracked.v's inverse_entry. *)
(*! bound INVERSE_MAX_REL_ERROR matrix4_inverse_entry <= 5.376e-7 |entry - exact| over (Ac + |C| T / |det|) / |det| *)
Require Import Reals Psatz.
Require Import Laws.Common Laws.Tracked.
Require Laws.matrix4_determinant_bound.

Open Scope R_scope.

(* The magnitude of a product of two differences of products. *)
Lemma pair_product_abs : forall p0 p1 p2 p3 q0 q1 q2 q3,
  Rabs ((p0 * p1 - p2 * p3) * (q0 * q1 - q2 * q3))
    <= (Rabs (p0 * p1) + Rabs (p2 * p3)) * (Rabs (q0 * q1) + Rabs (q2 * q3)).
Proof.
  intros. rewrite Rabs_mult.
  assert (H : forall a b, Rabs (a - b) <= Rabs a + Rabs b).
  { intros a b. unfold Rminus. eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_Ropp. lra. }
  apply Rmult_le_compat; try apply Rabs_pos; apply H.
Qed.

(* One product of the cofactor: an entry f times the minor p0 p1 - p2 p3
   times r, the minor rounded twice and its products once each, then the
   product with r and with f. *)
Lemma scaled_term : forall f r p0 p1 p2 p3, Rabs f <= 1 ->
  let k1 := u + u + u * u in
  let k2 := u + k1 + u * k1 in
  near (rnd (f * rnd (rnd (rnd (p0 * p1) - rnd (p2 * p3)) * r)))
       (f * (r * (p0 * p1 - p2 * p3)))
       (Rabs f * (Rabs r * (Rabs p0 * Rabs p1 + Rabs p2 * Rabs p3)))
       (u + k2 + u * k2) (3.001 * eta * Rabs r + 2.001 * eta).
Proof.
  intros f r p0 p1 p2 p3 Hf k1 k2.
  pose proof u_pos as Hu. pose proof eta_pos as He.
  pose proof (near_sub _ _ _ _ _ _ u eta eta (Rlt_le _ _ Hu) (Rlt_le _ _ He) (Rlt_le _ _ He)
                (near_product p0 p1) (near_product p2 p3)) as Nm.
  fold k1 in Nm.
  set (e1 := (1 + u) * (eta + eta) + eta) in *.
  assert (Hk1 : 0 <= k1) by (unfold k1; nra).
  assert (He1 : 0 <= e1) by (unfold e1; nra).
  pose proof (near_scale r _ _ _ _ _ Hk1 He1 Nm) as Nn.
  rewrite Rmult_comm in Nn. fold k2 in Nn.
  assert (Hk2 : 0 <= k2) by (unfold k2; nra).
  assert (Hr : 0 <= Rabs r) by apply Rabs_pos.
  assert (He2 : 0 <= (1 + u) * (Rabs r * e1) + eta).
  { assert (0 <= Rabs r * e1) by (apply Rmult_le_pos; lra). nra. }
  pose proof (near_scale f _ _ _ _ _ Hk2 He2 Nn) as Nf.
  apply (near_weaken _ _ _ _ _ _ _ Nf).
  - apply Rmult_le_pos; [apply Rabs_pos|].
    apply Rmult_le_pos; [exact Hr|].
    apply Rplus_le_le_0_compat; apply Rmult_le_pos; apply Rabs_pos.
  - lra.
  - set (X := (1 + u) * (Rabs r * e1) + eta).
    assert (HX0 : 0 <= X) by (unfold X; lra).
    assert (HX : Rabs f * X <= X).
    { assert (Rabs f * X <= 1 * X) by (apply Rmult_le_compat_r; lra). lra. }
    assert (He1b : e1 <= 3.0001 * eta) by (unfold e1, u; lra).
    assert (Hu1 : u <= 1e-7) by (unfold u; lra).
    assert (HX2 : X <= 3.0004 * eta * Rabs r + eta).
    { unfold X.
      assert (H1 : Rabs r * e1 <= Rabs r * (3.0001 * eta)) by (apply Rmult_le_compat_l; lra).
      assert (H2 : 0 <= Rabs r * e1) by (apply Rmult_le_pos; lra).
      assert (H3 : u * (Rabs r * e1) <= 1e-7 * (Rabs r * (3.0001 * eta)))
        by (apply Rmult_le_compat; lra).
      assert (0 <= eta * Rabs r) by (apply Rmult_le_pos; lra).
      lra. }
    assert (H4 : (1 + u) * (Rabs f * X) <= (1 + u) * X) by (apply Rmult_le_compat_l; lra).
    assert (H5 : u * X <= 1e-7 * (3.0004 * eta * Rabs r + eta)) by (apply Rmult_le_compat; lra).
    assert (0 <= eta * Rabs r) by (apply Rmult_le_pos; lra).
    lra.
Qed.

(* The absolute parts of the sum of the three products, under one bound. *)
Lemma sum_absolute : forall a E E', 0 <= a ->
  E = 3.001 * eta * a + 2.001 * eta -> E' = (1 + u) * (E + E) + eta ->
  (1 + u) * (E' + E') + eta <= 13 * eta * a + 12 * eta.
Proof.
  intros a E E' Ha HE HE'. subst E' E.
  pose proof u_pos as Hu. pose proof eta_pos as He.
  assert (Hu1 : u <= 1e-7) by (unfold u; lra).
  assert (0 <= eta * a) by nra.
  assert (u * (eta * a) <= 1e-7 * (eta * a)) by (apply Rmult_le_compat_r; lra).
  assert (u * eta <= 1e-7 * eta) by (apply Rmult_le_compat_r; lra).
  assert (u * (u * (eta * a)) <= 1e-7 * (eta * a)) by nra.
  assert (u * (u * eta) <= 1e-7 * eta) by nra.
  nra.
Qed.

Lemma product3_le_1 : forall p q s, Rabs p <= 1 -> Rabs q <= 1 -> Rabs s <= 1 ->
  Rabs p * Rabs q * Rabs s <= 1.
Proof.
  intros p q s Hp Hq Hs. pose proof (Rabs_pos p); pose proof (Rabs_pos q); pose proof (Rabs_pos s).
  assert (Rabs p * Rabs q <= 1) by nra. nra.
Qed.

Theorem matrix4_inverse_entry : forall a0 a1 a2 b0 b1 b2 c0 c1 c2 d0 d1 d2 x y z w
    f0 f1 f2 g0 g1 g2 g3 h0 h1 h2 h3 k0 k1 k2 k3 : R,
  Rabs a0 <= 1 -> Rabs a1 <= 1 -> Rabs a2 <= 1 -> Rabs b0 <= 1 -> Rabs b1 <= 1 ->
  Rabs b2 <= 1 -> Rabs c0 <= 1 -> Rabs c1 <= 1 -> Rabs c2 <= 1 -> Rabs d0 <= 1 ->
  Rabs d1 <= 1 -> Rabs d2 <= 1 -> Rabs x <= 1 -> Rabs y <= 1 -> Rabs z <= 1 -> Rabs w <= 1 ->
  Rabs f0 <= 1 -> Rabs f1 <= 1 -> Rabs f2 <= 1 ->
  Rabs g0 <= 1 -> Rabs g1 <= 1 -> Rabs g2 <= 1 -> Rabs g3 <= 1 ->
  Rabs h0 <= 1 -> Rabs h1 <= 1 -> Rabs h2 <= 1 -> Rabs h3 <= 1 ->
  Rabs k0 <= 1 -> Rabs k1 <= 1 -> Rabs k2 <= 1 -> Rabs k3 <= 1 ->
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
  let r := rnd (1 / det) in
  let m0 := rnd (rnd (g0 * g1) - rnd (g2 * g3)) in
  let m1 := rnd (rnd (h0 * h1) - rnd (h2 * h3)) in
  let m2 := rnd (rnd (k0 * k1) - rnd (k2 * k3)) in
  let n0 := rnd (m0 * r) in
  let n1 := rnd (m1 * r) in
  let n2 := rnd (m2 * r) in
  let e := rnd (rnd (rnd (f0 * n0) + rnd (f1 * n1)) + rnd (f2 * n2)) in
  let D := (a1 * b2 - a2 * b1) * (c0 * w - d0 * z) + (a2 * b0 - a0 * b2) * (c1 * w - d1 * z)
         + (a0 * b1 - a1 * b0) * (c2 * w - d2 * z) + (c1 * d2 - c2 * d1) * (a0 * y - b0 * x)
         + (c2 * d0 - c0 * d2) * (a1 * y - b1 * x) + (c0 * d1 - c1 * d0) * (a2 * y - b2 * x) in
  let T := (Rabs (a1 * b2) + Rabs (a2 * b1)) * (Rabs (c0 * w) + Rabs (d0 * z))
         + (Rabs (a2 * b0) + Rabs (a0 * b2)) * (Rabs (c1 * w) + Rabs (d1 * z))
         + (Rabs (a0 * b1) + Rabs (a1 * b0)) * (Rabs (c2 * w) + Rabs (d2 * z))
         + (Rabs (c1 * d2) + Rabs (c2 * d1)) * (Rabs (a0 * y) + Rabs (b0 * x))
         + (Rabs (c2 * d0) + Rabs (c0 * d2)) * (Rabs (a1 * y) + Rabs (b1 * x))
         + (Rabs (c0 * d1) + Rabs (c1 * d0)) * (Rabs (a2 * y) + Rabs (b2 * x)) in
  let C := f0 * (g0 * g1 - g2 * g3) + f1 * (h0 * h1 - h2 * h3) + f2 * (k0 * k1 - k2 * k3) in
  let Ac := Rabs (f0 * g0 * g1) + Rabs (f0 * g2 * g3) + Rabs (f1 * h0 * h1)
          + Rabs (f1 * h2 * h3) + Rabs (f2 * k0 * k1) + Rabs (f2 * k2 * k3) in
  / 2 ^ 100 <= Rabs D -> T <= 4096 * Rabs D -> 0 < Ac ->
  (Rabs (e - C / D) - 20 * eta * (1 + / Rabs D)) / ((Ac + Rabs C * T / Rabs D) / Rabs D)
    <= 5.376e-7.
Proof.
  intros a0 a1 a2 b0 b1 b2 c0 c1 c2 d0 d1 d2 x y z w f0 f1 f2 g0 g1 g2 g3 h0 h1 h2 h3 k0 k1 k2 k3
    Ha0 Ha1 Ha2 Hb0 Hb1 Hb2 Hc0 Hc1 Hc2 Hd0 Hd1 Hd2 Hx Hy Hz Hw Hf0 Hf1 Hf2
    Hg0 Hg1 Hg2 Hg3 Hh0 Hh1 Hh2 Hh3 Hk0 Hk1 Hk2 Hk3
    s0 s1 s2 t0 t1 t2 u0 u1 u2 v0 v1 v2 det r m0 m1 m2 n0 n1 n2 e D T C Ac HD HT HAp.
  pose proof u_pos as Hu. pose proof eta_pos as Heta.
  assert (HDp : 0 < Rabs D) by (assert (0 < / 2 ^ 100) by (apply Rinv_0_lt_compat; apply pow_lt; lra); lra).
  (* |D| <= T: the expansion's triangle inequality. *)
  assert (HDT : Rabs D <= T).
  { unfold D, T.
    pose proof (pair_product_abs a1 b2 a2 b1 c0 w d0 z).
    pose proof (pair_product_abs a2 b0 a0 b2 c1 w d1 z).
    pose proof (pair_product_abs a0 b1 a1 b0 c2 w d2 z).
    pose proof (pair_product_abs c1 d2 c2 d1 a0 y b0 x).
    pose proof (pair_product_abs c2 d0 c0 d2 a1 y b1 x).
    pose proof (pair_product_abs c0 d1 c1 d0 a2 y b2 x).
    repeat (eapply Rle_trans; [apply Rabs_triang|apply Rplus_le_compat; [|eassumption]]).
    eassumption. }
  assert (HTp : 0 < T) by lra.
  (* The determinant, by its law. *)
  pose proof (Laws.matrix4_determinant_bound.matrix4_determinant 1 a0 a1 a2 b0 b1 b2 c0 c1 c2
                d0 d1 d2 x y z w Ha0 Ha1 Ha2 Hb0 Hb1 Hb2 Hc0 Hc1 Hc2 Hd0 Hd1 Hd2 Hx Hy Hz Hw) as Hdet.
  cbv zeta in Hdet. fold s0 s1 s2 t0 t1 t2 u0 u1 u2 v0 v1 v2 in Hdet. fold det D T in Hdet.
  specialize (Hdet HTp).
  set (Ed := 112 * eta * (1 + 1 * 1)) in Hdet.
  assert (Hd : Rabs (det - D) <= 4.7684e-7 * T + Ed).
  { apply Rmult_le_compat_r with (r := T) in Hdet; [|lra].
    unfold Rdiv in Hdet. rewrite Rmult_assoc, Rinv_l in Hdet by lra. lra. }
  assert (HEd : 0 <= Ed) by (unfold Ed; lra).
  assert (HEd2 : Ed <= / 2 ^ 40 * Rabs D).
  { assert (Ed <= / 2 ^ 40 * / 2 ^ 100) by (unfold Ed, eta; simpl; lra).
    assert (/ 2 ^ 40 * / 2 ^ 100 <= / 2 ^ 40 * Rabs D)
      by (apply Rmult_le_compat_l; [left; apply Rinv_0_lt_compat; apply pow_lt; lra|exact HD]).
    lra. }
  (* The three products of the cofactor, with r taken exactly, and their sum. *)
  pose proof (scaled_term f0 r g0 g1 g2 g3 Hf0) as P0.
  pose proof (scaled_term f1 r h0 h1 h2 h3 Hf1) as P1.
  pose proof (scaled_term f2 r k0 k1 k2 k3 Hf2) as P2.
  cbv zeta in P0, P1, P2. fold m0 m1 m2 in P0, P1, P2. fold n0 n1 n2 in P0, P1, P2.
  set (q1 := u + u + u * u) in *.
  set (q2 := u + q1 + u * q1) in *.
  set (q3 := u + q2 + u * q2) in *.
  set (E := 3.001 * eta * Rabs r + 2.001 * eta) in *.
  assert (Hr0 : 0 <= Rabs r) by apply Rabs_pos.
  assert (Hq3 : 0 <= q3) by (unfold q3, q2, q1, u; lra).
  assert (HEr0 : 0 <= eta * Rabs r) by (apply Rmult_le_pos; lra).
  assert (HE : 0 <= E) by (unfold E; lra).
  pose proof (near_add _ _ _ _ _ _ _ _ _ Hq3 HE HE P0 P1) as S01.
  set (q4 := u + q3 + u * q3) in *.
  set (E' := (1 + u) * (E + E) + eta) in *.
  assert (Hq34 : q3 <= q4) by (unfold q4, q3, q2, q1, u; lra).
  assert (Hq4 : 0 <= q4) by lra.
  assert (HuE : 0 <= u * E) by (apply Rmult_le_pos; lra).
  assert (HEE : E <= E') by (unfold E'; lra).
  assert (HE' : 0 <= E') by lra.
  assert (Pos : forall p0 p1 p2 p3 : R, 0 <= Rabs p0 * Rabs p1 + Rabs p2 * Rabs p3)
    by (intros; apply Rplus_le_le_0_compat; apply Rmult_le_pos; apply Rabs_pos).
  assert (HA2 : 0 <= Rabs f2 * (Rabs r * (Rabs k0 * Rabs k1 + Rabs k2 * Rabs k3))).
  { apply Rmult_le_pos; [apply Rabs_pos|apply Rmult_le_pos; [exact Hr0|apply Pos]]. }
  pose proof (near_weaken _ _ _ _ _ _ _ P2 HA2 Hq34 HEE) as P2'.
  pose proof (near_add _ _ _ _ _ _ _ _ _ Hq4 HE' HE' S01 P2') as N.
  fold e in N. destruct N as [_ N].
  set (k := u + q4 + u * q4) in *.
  replace (f0 * (r * (g0 * g1 - g2 * g3)) + f1 * (r * (h0 * h1 - h2 * h3))
           + f2 * (r * (k0 * k1 - k2 * k3))) with (r * C) in N by (unfold C; ring).
  assert (HAc : Rabs f0 * (Rabs r * (Rabs g0 * Rabs g1 + Rabs g2 * Rabs g3))
              + Rabs f1 * (Rabs r * (Rabs h0 * Rabs h1 + Rabs h2 * Rabs h3))
              + Rabs f2 * (Rabs r * (Rabs k0 * Rabs k1 + Rabs k2 * Rabs k3)) = Rabs r * Ac)
    by (unfold Ac; rewrite !Rabs_mult; ring).
  rewrite HAc in N.
  assert (HCA : Rabs C <= Ac).
  { unfold C, Ac.
    assert (Hm : forall f p0 p1 p2 p3,
               Rabs (f * (p0 * p1 - p2 * p3)) <= Rabs (f * p0 * p1) + Rabs (f * p2 * p3)).
    { intros f p0 p1 p2 p3.
      replace (f * (p0 * p1 - p2 * p3)) with (f * p0 * p1 + - (f * p2 * p3)) by ring.
      eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_Ropp. lra. }
    pose proof (Hm f0 g0 g1 g2 g3). pose proof (Hm f1 h0 h1 h2 h3). pose proof (Hm f2 k0 k1 k2 k3).
    eapply Rle_trans; [apply Rabs_triang|].
    pose proof (Rabs_triang (f0 * (g0 * g1 - g2 * g3)) (f1 * (h0 * h1 - h2 * h3))). lra. }
  assert (Hk : 0 <= k <= 4e-7) by (unfold k, q4, q3, q2, q1, u; split; lra).
  set (c := 13 * eta).
  set (e0 := 12 * eta).
  assert (HEr : (1 + u) * (E' + E') + eta <= c * Rabs r + e0)
    by (unfold c, e0; apply (sum_absolute (Rabs r) E E' Hr0 eq_refl eq_refl)).
  assert (Ne : Rabs (e - r * C) <= k * (Rabs r * Ac) + c * Rabs r + e0) by lra.
  assert (Hc : 0 <= c) by (unfold c; lra).
  assert (He0 : 0 <= e0) by (unfold e0; lra).
  pose proof (inverse_entry e C Ac r det D T k c e0 4.7684e-7 Ed Hk ltac:(lra) Hc He0 HEd HCA Ne
                eq_refl Hd HDp HDT HT HEd2) as H.
  (* The roundings near underflow, and the two parts under one bound. *)
  assert (HAc6 : Ac <= 6).
  { unfold Ac. rewrite !Rabs_mult.
    pose proof product3_le_1 as Hp.
    pose proof (Hp f0 g0 g1 Hf0 Hg0 Hg1). pose proof (Hp f0 g2 g3 Hf0 Hg2 Hg3).
    pose proof (Hp f1 h0 h1 Hf1 Hh0 Hh1). pose proof (Hp f1 h2 h3 Hf1 Hh2 Hh3).
    pose proof (Hp f2 k0 k1 Hf2 Hk0 Hk1). pose proof (Hp f2 k2 k3 Hf2 Hk2 Hk3). lra. }
  set (ia := / Rabs D) in *.
  assert (Hia : 0 < ia) by (unfold ia; apply Rinv_0_lt_compat; lra).
  assert (Heta1 : eta <= 1e-40) by (unfold eta; simpl; lra).
  assert (HCp : 0 <= Rabs C) by apply Rabs_pos.
  assert (HE2 : c * (1.0025 / Rabs D + eta) + e0 + eta * (k * Ac + Rabs C)
               <= 20 * eta * (1 + ia)).
  { replace (1.0025 / Rabs D) with (1.0025 * ia) by (unfold ia; field; lra).
    unfold c, e0.
    assert (k * Ac <= 4e-7 * 6) by (apply Rmult_le_compat; lra).
    assert (eta * (k * Ac + Rabs C) <= eta * (4e-7 * 6 + 6)) by (apply Rmult_le_compat_l; lra).
    assert (eta * eta <= 1e-40 * eta) by (apply Rmult_le_compat_r; lra).
    assert (0 <= eta * ia) by (apply Rmult_le_pos; lra).
    lra. }
  set (R := (Ac + Rabs C * T / Rabs D) / Rabs D).
  assert (HR : R = Ac / Rabs D + Rabs C * T / (Rabs D * Rabs D)) by (unfold R; field; lra).
  assert (HR1 : 0 <= Ac / Rabs D) by (unfold Rdiv; fold ia; apply Rmult_le_pos; lra).
  assert (HR2 : 0 <= Rabs C * T / (Rabs D * Rabs D))
    by (unfold Rdiv; apply Rmult_le_pos; [apply Rmult_le_pos; lra|
        left; apply Rinv_0_lt_compat; apply Rmult_lt_0_compat; lra]).
  assert (HRp : 0 < R).
  { unfold R. unfold Rdiv. fold ia. apply Rmult_lt_0_compat; [|exact Hia].
    assert (0 <= Rabs C * T * ia) by (apply Rmult_le_pos; [apply Rmult_le_pos|]; lra). lra. }
  assert (Hkb : 1.0025 * k <= 5.376e-7) by (unfold k, q4, q3, q2, q1, u; lra).
  assert (Hkdb : 1.0021 * (u + 4.7684e-7 + / 2 ^ 40) <= 5.376e-7) by (unfold u; simpl; lra).
  assert (1.0025 * k * (Ac / Rabs D) <= 5.376e-7 * (Ac / Rabs D))
    by (apply Rmult_le_compat_r; lra).
  assert (1.0021 * (u + 4.7684e-7 + / 2 ^ 40) * (Rabs C * T / (Rabs D * Rabs D))
          <= 5.376e-7 * (Rabs C * T / (Rabs D * Rabs D)))
    by (apply Rmult_le_compat_r; lra).
  apply Rmult_le_reg_r with R; [exact HRp|].
  unfold Rdiv at 1. rewrite Rmult_assoc, Rinv_l by lra.
  rewrite HR. lra.
Qed.
