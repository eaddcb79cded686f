(* The projection of a onto the line of b (src/vec/template/lengths.rs,
   project_onto: u = b.try_normalize(), then u * a.dot(u)) and the
   rejection a - project_onto(a, b) (reject_from), for Cvec4
   (project3_bound.v: Cvec3): the error vector against the exact
   projection P = (a . b / |b|^2) b of the same f32 vectors, and against
   the exact rejection a - P, is at most 7.7584e-7 |a| and 7.8175e-7 |a|
   long (project4_main); the theorem project4 states the larger of the
   two, over |a|, at most 7.83e-7.
   The rounded terms are those of proofs/gappa/project4.g, which computes
   the code's bits (the correspondence test checks both).

   Domain: b's components scaled by an exact power of four so that
   |b|^2 lies in [1, 4], as in proofs/gappa/normalize.g (whose comment
   says how far the code's arithmetic commutes with that scaling, and
   normalize_scale.g the rescaled branches); a with |a| at least 2^-100
   (the absolute errors of roundings near underflow, 2^-150 each, are
   then below 2^-50 |a|). The quotient, the scaling and every sum are
   relative to |a| and |b| alike, so the law needs no other scaling.

   Proven here on Flocq's rounding, with the square root's error from the
   certificate of normalize.g (normalize_norm.v, normalize_root: the
   computed norm n is within 0x1.81p-23 of |b|, relative):
   - each component of u = rnd (b_i / n) is within 2.389e-7 |U_i| (plus
     2^-150) of U_i = b_i / |b|, the exact unit vector;
   - the dot product t (four rounded products summed left to right) is
     within ((1 + 2^-24)^4 - 1) sum |a_i u_i| of sum a_i u_i (Tracked.v),
     and with u's errors within 4.7733e-7 |a| of T = a . U (Cauchy-Schwarz:
     sum |a_i| |U_i| <= |a|);
   - each component of the projection, rnd (u_i t), is then within
     7.7584e-7 |a| |U_i| of T U_i = P_i, and the vector of those bounds is
     |U| = 1 times 7.7584e-7 |a| long (norm4_comb);
   - of that, 4.77331e-7 |a| |U_i| is the dot product's error and
     2.98505e-7 |T| |U_i| the roundings of u and of the product;
   - the rejection rounds a_i - p_i once more: within
     (1 + 2^-24) |p_i - P_i| + 2^-24 |R_i| of R_i = a_i - P_i, and |T| and
     |R| are the sides of a right angle (|T|^2 + |R|^2 = |a|^2), so the
     parts relative to them add to at most
     sqrt(((1 + 2^-24) 2.98505e-7)^2 + 2^-48) |a| <= 3.0441e-7 |a|
     (right_angle). *)
(*! bound PROJECT_MAX_REL_ERROR project4 <= 7.83e-7 the larger of |project_onto - P| / |a| and |reject_from - (a - P)| / |a|, Cvec4 *)
Require Import Reals Psatz.
Require Import Flocq.Core.Core.
Require Import Laws.Common Laws.Tracked.
Require Laws.normalize_norm.

Open Scope R_scope.

(* The length of a four-vector. *)
Definition n4 (a b c d : R) := sqrt (a * a + b * b + c * c + d * d).

Lemma n4_pos : forall a b c d, 0 <= n4 a b c d.
Proof. intros; apply sqrt_pos. Qed.

Lemma n4_sq : forall a b c d, n4 a b c d * n4 a b c d = a * a + b * b + c * c + d * d.
Proof. intros; unfold n4; apply sqrt_sqrt; nra. Qed.

Lemma sq_abs : forall t, Rabs t * Rabs t = t * t.
Proof. intro t. rewrite <- Rabs_mult. apply Rabs_right. nra. Qed.

Lemma sq_le : forall x c, Rabs x <= c -> x * x <= c * c.
Proof. intros x c H. rewrite <- sq_abs. pose proof (Rabs_pos x). nra. Qed.

(* Cauchy-Schwarz, on the magnitudes. *)
Lemma cs4 : forall a0 a1 a2 a3 x0 x1 x2 x3,
  Rabs a0 * Rabs x0 + Rabs a1 * Rabs x1 + Rabs a2 * Rabs x2 + Rabs a3 * Rabs x3
  <= n4 a0 a1 a2 a3 * n4 x0 x1 x2 x3.
Proof.
  intros.
  pose proof (n4_pos a0 a1 a2 a3); pose proof (n4_pos x0 x1 x2 x3).
  pose proof (n4_sq a0 a1 a2 a3) as Sa; pose proof (n4_sq x0 x1 x2 x3) as Sx.
  set (A := n4 a0 a1 a2 a3) in *; set (X := n4 x0 x1 x2 x3) in *.
  rewrite <- (sq_abs a0), <- (sq_abs a1), <- (sq_abs a2), <- (sq_abs a3) in Sa.
  rewrite <- (sq_abs x0), <- (sq_abs x1), <- (sq_abs x2), <- (sq_abs x3) in Sx.
  set (b0 := Rabs a0) in *; set (b1 := Rabs a1) in *; set (b2 := Rabs a2) in *;
  set (b3 := Rabs a3) in *; set (y0 := Rabs x0) in *; set (y1 := Rabs x1) in *;
  set (y2 := Rabs x2) in *; set (y3 := Rabs x3) in *.
  set (L := b0 * y0 + b1 * y1 + b2 * y2 + b3 * y3).
  assert (E : (A * X) * (A * X) - L * L
    = (b0 * y1 - b1 * y0) * (b0 * y1 - b1 * y0) + (b0 * y2 - b2 * y0) * (b0 * y2 - b2 * y0)
    + (b0 * y3 - b3 * y0) * (b0 * y3 - b3 * y0) + (b1 * y2 - b2 * y1) * (b1 * y2 - b2 * y1)
    + (b1 * y3 - b3 * y1) * (b1 * y3 - b3 * y1) + (b2 * y3 - b3 * y2) * (b2 * y3 - b3 * y2)).
  { replace ((A * X) * (A * X)) with ((A * A) * (X * X)) by ring. rewrite Sa, Sx. unfold L. ring. }
  assert (0 <= (A * X) * (A * X) - L * L).
  { rewrite E. pose proof (Rle_0_sqr (b0 * y1 - b1 * y0)); pose proof (Rle_0_sqr (b0 * y2 - b2 * y0));
    pose proof (Rle_0_sqr (b0 * y3 - b3 * y0)); pose proof (Rle_0_sqr (b1 * y2 - b2 * y1));
    pose proof (Rle_0_sqr (b1 * y3 - b3 * y1)); pose proof (Rle_0_sqr (b2 * y3 - b3 * y2)).
    unfold Rsqr in *. lra. }
  assert (0 <= A * X) by (apply Rmult_le_pos; lra).
  assert (0 <= L) by (unfold L, b0, b1, b2, b3, y0, y1, y2, y3;
    pose proof (Rabs_pos a0); pose proof (Rabs_pos a1); pose proof (Rabs_pos a2);
    pose proof (Rabs_pos a3); pose proof (Rabs_pos x0); pose proof (Rabs_pos x1);
    pose proof (Rabs_pos x2); pose proof (Rabs_pos x3); nra).
  nra.
Qed.

(* A vector whose components are each at most k |q_i| + m |w_i| + d in
   magnitude is at most k |q| + m |w| + 2 d long. *)
Lemma norm4_comb : forall x0 x1 x2 x3 q0 q1 q2 q3 w0 w1 w2 w3 k m d,
  0 <= k -> 0 <= m -> 0 <= d ->
  Rabs x0 <= k * Rabs q0 + m * Rabs w0 + d -> Rabs x1 <= k * Rabs q1 + m * Rabs w1 + d ->
  Rabs x2 <= k * Rabs q2 + m * Rabs w2 + d -> Rabs x3 <= k * Rabs q3 + m * Rabs w3 + d ->
  n4 x0 x1 x2 x3 <= k * n4 q0 q1 q2 q3 + m * n4 w0 w1 w2 w3 + 2 * d.
Proof.
  intros x0 x1 x2 x3 q0 q1 q2 q3 w0 w1 w2 w3 k m d Hk Hm Hd H0 H1 H2 H3.
  pose proof (n4_pos q0 q1 q2 q3) as PQ; pose proof (n4_pos w0 w1 w2 w3) as PW.
  pose proof (n4_sq q0 q1 q2 q3) as SQ; pose proof (n4_sq w0 w1 w2 w3) as SW.
  pose proof (cs4 q0 q1 q2 q3 w0 w1 w2 w3) as CS.
  pose proof (sum_abs_le q0 q1 q2 q3) as AQ; pose proof (sum_abs_le w0 w1 w2 w3) as AW.
  change (sqrt (q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)) with (n4 q0 q1 q2 q3) in AQ.
  change (sqrt (w0 * w0 + w1 * w1 + w2 * w2 + w3 * w3)) with (n4 w0 w1 w2 w3) in AW.
  set (Q := n4 q0 q1 q2 q3) in *; set (W := n4 w0 w1 w2 w3) in *.
  assert (HR : 0 <= k * Q + m * W + 2 * d) by nra.
  unfold n4 at 1. rewrite <- (sqrt_square (k * Q + m * W + 2 * d)) by exact HR.
  apply sqrt_le_1_alt.
  apply sq_le in H0; apply sq_le in H1; apply sq_le in H2; apply sq_le in H3.
  rewrite <- (sq_abs q0), <- (sq_abs q1), <- (sq_abs q2), <- (sq_abs q3) in SQ.
  rewrite <- (sq_abs w0), <- (sq_abs w1), <- (sq_abs w2), <- (sq_abs w3) in SW.
  set (c0 := Rabs q0) in *; set (c1 := Rabs q1) in *; set (c2 := Rabs q2) in *;
  set (c3 := Rabs q3) in *; set (v0 := Rabs w0) in *; set (v1 := Rabs w1) in *;
  set (v2 := Rabs w2) in *; set (v3 := Rabs w3) in *.
  assert (E : (k * c0 + m * v0 + d) * (k * c0 + m * v0 + d) + (k * c1 + m * v1 + d) * (k * c1 + m * v1 + d)
            + (k * c2 + m * v2 + d) * (k * c2 + m * v2 + d) + (k * c3 + m * v3 + d) * (k * c3 + m * v3 + d)
            = k * k * (c0 * c0 + c1 * c1 + c2 * c2 + c3 * c3) + m * m * (v0 * v0 + v1 * v1 + v2 * v2 + v3 * v3)
              + 4 * (d * d) + 2 * (k * m) * (c0 * v0 + c1 * v1 + c2 * v2 + c3 * v3)
              + 2 * (k * d) * (c0 + c1 + c2 + c3) + 2 * (m * d) * (v0 + v1 + v2 + v3)) by ring.
  rewrite <- SQ, <- SW in E.
  assert (2 * (k * m) * (c0 * v0 + c1 * v1 + c2 * v2 + c3 * v3) <= 2 * (k * m) * (Q * W))
    by (apply Rmult_le_compat_l; nra).
  assert (2 * (k * d) * (c0 + c1 + c2 + c3) <= 2 * (k * d) * (2 * Q))
    by (apply Rmult_le_compat_l; nra).
  assert (2 * (m * d) * (v0 + v1 + v2 + v3) <= 2 * (m * d) * (2 * W))
    by (apply Rmult_le_compat_l; nra).
  assert (F : (k * Q + m * W + 2 * d) * (k * Q + m * W + 2 * d)
            = k * k * (Q * Q) + m * m * (W * W) + 4 * (d * d) + 2 * (k * m) * (Q * W)
              + 2 * (k * d) * (2 * Q) + 2 * (m * d) * (2 * W)) by ring.
  lra.
Qed.

(* 2^-24 + the bound of normalize_root, over 1 minus that bound. *)
Definition theta := 2.389e-7.

(* A component of the computed unit vector: rnd (b / n) against b / N,
   with n within dl of N, relative. *)
Lemma unit_comp : forall b N n dl, 0 < N -> n = N * (1 + dl) ->
  -0x1.81p-23 <= dl <= 0x1.81p-23 ->
  Rabs (rnd (b / n) - b / N) <= theta * Rabs (b / N) + eta.
Proof.
  intros b N n dl HN Hn Hdl.
  assert (Hd : -385 / 2147483648 <= dl <= 385 / 2147483648) by (simpl in Hdl; lra).
  set (U := b / N). set (g := / (1 + dl)).
  assert (Hg1 : g * (1 + dl) = 1) by (unfold g; field; lra).
  assert (Hg0 : 0 < g) by (unfold g; apply Rinv_0_lt_compat; lra).
  assert (Hbn : b / n = U * g) by (unfold U, g; rewrite Hn; field; split; lra).
  assert (Hg2 : g <= 1.00000018).
  { assert (1 <= 1.00000018 * (1 + dl)) by lra. nra. }
  assert (Hgm : Rabs (g - 1) <= 385 / 2147483648 * g).
  { replace (g - 1) with (- (dl * g)) by lra.
    rewrite Rabs_Ropp, Rabs_mult, (Rabs_right g) by lra.
    apply Rmult_le_compat_r; [lra|]. apply Rabs_le. lra. }
  pose proof (rnd_err (b / n)) as E. rewrite Hbn in E |- *.
  rewrite Rabs_mult, (Rabs_right g) in E by lra.
  replace (rnd (U * g) - U) with ((rnd (U * g) - U * g) + U * (g - 1)) by ring.
  eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_mult.
  pose proof (Rabs_pos U). pose proof u_pos.
  assert (Rabs U * Rabs (g - 1) <= Rabs U * (385 / 2147483648 * g))
    by (apply Rmult_le_compat_l; lra).
  assert ((u + 385 / 2147483648) * g <= theta) by (unfold theta, u; nra).
  assert (Rabs U * ((u + 385 / 2147483648) * g) <= Rabs U * theta)
    by (apply Rmult_le_compat_l; lra).
  nra.
Qed.

(* Two lengths at a right angle, x^2 + y^2 <= z^2, weighted: at most
   sqrt(c1^2 + c2^2) z (Cauchy-Schwarz in the plane). *)
Lemma right_angle : forall c1 c2 x y z C, 0 <= c1 -> 0 <= c2 -> 0 <= C ->
  c1 * c1 + c2 * c2 <= C * C -> 0 <= x -> 0 <= y -> 0 <= z -> x * x + y * y <= z * z ->
  c1 * x + c2 * y <= C * z.
Proof.
  intros c1 c2 x y z C H1 H2 HC HCC Hx Hy Hz Hxy.
  assert (L : (c1 * x + c2 * y) * (c1 * x + c2 * y) <= (C * z) * (C * z)).
  { pose proof (Rle_0_sqr (c1 * y - c2 * x)). unfold Rsqr in *.
    assert ((c1 * c1 + c2 * c2) * (x * x + y * y) <= (C * C) * (z * z)).
    { apply Rmult_le_compat; nra. }
    nra. }
  assert (0 <= C * z) by nra.
  nra.
Qed.

(* The whole computation for Cvec4, its error vectors bounded by |a|:
   the projection's first, the rejection's second. *)
Lemma project4_main : forall a0 a1 a2 a3 B0 B1 B2 B3 : R,
  let b0 := rnd B0 in
  let b1 := rnd B1 in
  let b2 := rnd B2 in
  let b3 := rnd B3 in
  1 <= b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3 <= 4 ->
  / 2 ^ 100 <= n4 a0 a1 a2 a3 ->
  let s := rnd (rnd (rnd (rnd (b0 * b0) + rnd (b1 * b1)) + rnd (b2 * b2)) + rnd (b3 * b3)) in
  let n := rnd (sqrt (s)) in
  let u0 := rnd (b0 / n) in
  let u1 := rnd (b1 / n) in
  let u2 := rnd (b2 / n) in
  let u3 := rnd (b3 / n) in
  let t := rnd (rnd (rnd (rnd (a0 * u0) + rnd (a1 * u1)) + rnd (a2 * u2)) + rnd (a3 * u3)) in
  let p0 := rnd (u0 * t) in
  let p1 := rnd (u1 * t) in
  let p2 := rnd (u2 * t) in
  let p3 := rnd (u3 * t) in
  let T := (a0 * b0 + a1 * b1 + a2 * b2 + a3 * b3) / (b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3) in
  n4 (p0 - T * b0) (p1 - T * b1) (p2 - T * b2) (p3 - T * b3) <= 7.7584e-7 * n4 a0 a1 a2 a3 /\
  n4 (rnd (a0 - p0) - (a0 - T * b0)) (rnd (a1 - p1) - (a1 - T * b1))
     (rnd (a2 - p2) - (a2 - T * b2)) (rnd (a3 - p3) - (a3 - T * b3))
  <= 7.8175e-7 * n4 a0 a1 a2 a3.
Proof.
  intros a0 a1 a2 a3 B0 B1 B2 B3 b0 b1 b2 b3 HS Ha s n u0 u1 u2 u3 t p0 p1 p2 p3 T.
  pose proof u_pos as Hu. pose proof eta_pos as He.
  assert (Hu1 : u = / 16777216) by reflexivity.
  set (S := b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3) in *.
  set (N := sqrt S).
  assert (HN : 1 <= N).
  { unfold N. rewrite <- sqrt_1. apply sqrt_le_1_alt. lra. }
  assert (HNN : N * N = S) by (unfold N; apply sqrt_sqrt; lra).
  pose proof (Laws.normalize_norm.normalize_root B0 B1 B2 B3 HS) as Hroot.
  change (-0x1.81p-23 <= (n - N) / N <= 0x1.81p-23) in Hroot.
  set (dl := (n - N) / N) in Hroot.
  assert (Hn : n = N * (1 + dl)) by (unfold dl; field; lra).
  (* The exact unit vector, and the computed one. *)
  set (U0 := b0 / N); set (U1 := b1 / N); set (U2 := b2 / N); set (U3 := b3 / N).
  assert (HU : n4 U0 U1 U2 U3 = 1).
  { unfold n4. replace (U0 * U0 + U1 * U1 + U2 * U2 + U3 * U3) with (S / (N * N))
      by (unfold U0, U1, U2, U3, S; field; lra).
    rewrite HNN. replace (S / S) with 1 by (field; lra). apply sqrt_1. }
  assert (Hv0 : Rabs (u0 - U0) <= theta * Rabs U0 + eta) by (apply (unit_comp b0 N n dl); lra).
  assert (Hv1 : Rabs (u1 - U1) <= theta * Rabs U1 + eta) by (apply (unit_comp b1 N n dl); lra).
  assert (Hv2 : Rabs (u2 - U2) <= theta * Rabs U2 + eta) by (apply (unit_comp b2 N n dl); lra).
  assert (Hv3 : Rabs (u3 - U3) <= theta * Rabs U3 + eta) by (apply (unit_comp b3 N n dl); lra).
  assert (Mag : forall v V, Rabs (v - V) <= theta * Rabs V + eta ->
                  Rabs v <= (1 + theta) * Rabs V + eta).
  { intros v V H. pose proof (Rabs_triang_inv v V). lra. }
  pose proof (Mag _ _ Hv0) as Hm0; pose proof (Mag _ _ Hv1) as Hm1;
  pose proof (Mag _ _ Hv2) as Hm2; pose proof (Mag _ _ Hv3) as Hm3.
  (* |a| and the magnitudes it bounds. *)
  set (al := n4 a0 a1 a2 a3) in *.
  assert (Hal : 0 < al) by (assert (0 < / 2 ^ 100) by (apply Rinv_0_lt_compat; apply pow_lt; lra); lra).
  assert (Heta : eta <= 1e-15 * al).
  { assert (eta = / 2 ^ 50 * / 2 ^ 100) by (unfold eta; simpl; field).
    assert (/ 2 ^ 50 * / 2 ^ 100 <= / 2 ^ 50 * al) by (apply Rmult_le_compat_l; [simpl; lra|exact Ha]).
    assert (/ 2 ^ 50 * al <= 1e-15 * al) by (apply Rmult_le_compat_r; [lra|]; simpl; lra).
    lra. }
  pose proof (cs4 a0 a1 a2 a3 U0 U1 U2 U3) as CS. rewrite HU, Rmult_1_r in CS. fold al in CS.
  pose proof (sum_abs_le a0 a1 a2 a3) as SA.
  change (sqrt (a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3)) with al in SA.
  pose proof (Rabs_pos a0); pose proof (Rabs_pos a1); pose proof (Rabs_pos a2);
  pose proof (Rabs_pos a3); pose proof (Rabs_pos U0); pose proof (Rabs_pos U1);
  pose proof (Rabs_pos U2); pose proof (Rabs_pos U3).
  (* The exact dot product with U, and T U_i = P_i. *)
  set (TT := a0 * U0 + a1 * U1 + a2 * U2 + a3 * U3).
  assert (HT : T = TT / N) by (unfold T, TT, U0, U1, U2, U3; fold S; rewrite <- HNN; field; lra).
  assert (HP : forall b, T * b = TT * (b / N)) by (intro b; rewrite HT; field; lra).
  assert (HTT : Rabs TT <= al).
  { unfold TT.
    pose proof (Rabs_triang (a0 * U0 + a1 * U1 + a2 * U2) (a3 * U3)).
    pose proof (Rabs_triang (a0 * U0 + a1 * U1) (a2 * U2)).
    pose proof (Rabs_triang (a0 * U0) (a1 * U1)).
    rewrite !Rabs_mult in *. lra. }
  (* The dot product: its roundings (Tracked.v), then u's errors. *)
  pose proof (near_add _ _ _ _ _ _ u eta eta (Rlt_le _ _ Hu) (Rlt_le _ _ He) (Rlt_le _ _ He)
                (near_product a0 u0) (near_product a1 u1)) as D1.
  set (k2 := u + u + u * u) in D1.
  assert (Hk2 : u <= k2) by (unfold k2; nra).
  pose proof (near_weaken _ _ _ _ _ _ _ (near_product a2 u2)
                (Rmult_le_pos _ _ (Rabs_pos a2) (Rabs_pos u2)) Hk2 (Rle_refl eta)) as M2.
  assert (He2 : 0 <= (1 + u) * (eta + eta) + eta)
    by (pose proof u_pos; pose proof eta_pos; apply Rplus_le_le_0_compat; [apply Rmult_le_pos|]; lra).
  pose proof (near_add _ _ _ _ _ _ _ _ _ (Rle_trans _ _ _ (Rlt_le _ _ Hu) Hk2) He2
                (Rlt_le _ _ He) D1 M2) as D2.
  set (k3 := u + k2 + u * k2) in D2.
  assert (Hk3 : u <= k3) by (unfold k3; nra).
  pose proof (near_weaken _ _ _ _ _ _ _ (near_product a3 u3)
                (Rmult_le_pos _ _ (Rabs_pos a3) (Rabs_pos u3)) Hk3 (Rle_refl eta)) as M3.
  set (e3 := (1 + u) * ((1 + u) * (eta + eta) + eta + eta) + eta) in D2.
  assert (He3 : 0 <= e3) by (unfold e3; nra).
  pose proof (near_add _ _ _ _ _ _ _ _ _ (Rle_trans _ _ _ (Rlt_le _ _ Hu) Hk3) He3
                (Rlt_le _ _ He) D2 M3) as D3.
  destruct D3 as [_ D3]. fold t in D3.
  set (k4 := u + k3 + u * k3) in D3.
  assert (Hk4 : 0 <= k4 <= 2.3842e-7) by (unfold k4, k3, k2; rewrite Hu1; split; nra).
  set (e4 := (1 + u) * (e3 + eta) + eta) in D3.
  assert (He4 : e4 <= 8 * eta) by (unfold e4, e3; rewrite Hu1; nra).
  set (Au := Rabs a0 * Rabs u0 + Rabs a1 * Rabs u1 + Rabs a2 * Rabs u2 + Rabs a3 * Rabs u3) in D3.
  assert (HAu : Au <= (1 + theta) * al + 2 * eta * al).
  { unfold Au.
    assert (Rabs a0 * Rabs u0 <= Rabs a0 * ((1 + theta) * Rabs U0 + eta)) by (apply Rmult_le_compat_l; lra).
    assert (Rabs a1 * Rabs u1 <= Rabs a1 * ((1 + theta) * Rabs U1 + eta)) by (apply Rmult_le_compat_l; lra).
    assert (Rabs a2 * Rabs u2 <= Rabs a2 * ((1 + theta) * Rabs U2 + eta)) by (apply Rmult_le_compat_l; lra).
    assert (Rabs a3 * Rabs u3 <= Rabs a3 * ((1 + theta) * Rabs U3 + eta)) by (apply Rmult_le_compat_l; lra).
    assert ((1 + theta) * (Rabs a0 * Rabs U0 + Rabs a1 * Rabs U1 + Rabs a2 * Rabs U2 + Rabs a3 * Rabs U3)
            <= (1 + theta) * al) by (apply Rmult_le_compat_l; unfold theta; lra).
    assert (eta * (Rabs a0 + Rabs a1 + Rabs a2 + Rabs a3) <= eta * (2 * al))
      by (apply Rmult_le_compat_l; lra).
    nra. }
  assert (Hdu : Rabs ((a0 * u0 + a1 * u1 + a2 * u2 + a3 * u3) - TT) <= theta * al + 2 * eta * al).
  { unfold TT.
    replace (a0 * u0 + a1 * u1 + a2 * u2 + a3 * u3 - (a0 * U0 + a1 * U1 + a2 * U2 + a3 * U3))
      with (a0 * (u0 - U0) + a1 * (u1 - U1) + a2 * (u2 - U2) + a3 * (u3 - U3)) by ring.
    assert (Rabs (a0 * (u0 - U0)) <= Rabs a0 * (theta * Rabs U0 + eta))
      by (rewrite Rabs_mult; apply Rmult_le_compat_l; lra).
    assert (Rabs (a1 * (u1 - U1)) <= Rabs a1 * (theta * Rabs U1 + eta))
      by (rewrite Rabs_mult; apply Rmult_le_compat_l; lra).
    assert (Rabs (a2 * (u2 - U2)) <= Rabs a2 * (theta * Rabs U2 + eta))
      by (rewrite Rabs_mult; apply Rmult_le_compat_l; lra).
    assert (Rabs (a3 * (u3 - U3)) <= Rabs a3 * (theta * Rabs U3 + eta))
      by (rewrite Rabs_mult; apply Rmult_le_compat_l; lra).
    assert (theta * (Rabs a0 * Rabs U0 + Rabs a1 * Rabs U1 + Rabs a2 * Rabs U2 + Rabs a3 * Rabs U3)
            <= theta * al) by (apply Rmult_le_compat_l; unfold theta; lra).
    assert (eta * (Rabs a0 + Rabs a1 + Rabs a2 + Rabs a3) <= eta * (2 * al))
      by (apply Rmult_le_compat_l; lra).
    pose proof (Rabs_triang (a0 * (u0 - U0) + a1 * (u1 - U1) + a2 * (u2 - U2)) (a3 * (u3 - U3))).
    pose proof (Rabs_triang (a0 * (u0 - U0) + a1 * (u1 - U1)) (a2 * (u2 - U2))).
    pose proof (Rabs_triang (a0 * (u0 - U0)) (a1 * (u1 - U1))).
    nra. }
  set (tau := 4.7733e-7).
  assert (Htau : Rabs (t - TT) <= tau * al).
  { replace (t - TT) with ((t - (a0 * u0 + a1 * u1 + a2 * u2 + a3 * u3))
                           + ((a0 * u0 + a1 * u1 + a2 * u2 + a3 * u3) - TT)) by ring.
    eapply Rle_trans; [apply Rabs_triang|].
    assert (0 <= Au) by (unfold Au; pose proof (Rabs_pos u0); pose proof (Rabs_pos u1);
      pose proof (Rabs_pos u2); pose proof (Rabs_pos u3); nra).
    assert (k4 * Au <= 2.3842e-7 * ((1 + theta) * al + 2 * eta * al)).
    { apply Rmult_le_compat; lra. }
    assert (Hea : eta * al <= 1e-44 * al) by (apply Rmult_le_compat_r; [lra|]; unfold eta; simpl; lra).
    unfold tau, theta in *. lra. }
  assert (Ht : Rabs t <= Rabs TT + tau * al).
  { pose proof (Rabs_triang_inv t TT). unfold tau in *. lra. }
  (* Each component of the projection: a part relative to |a|, the
     dot product's error, and a part relative to |T|, u's and the
     product's roundings. *)
  pose proof (Rabs_pos TT) as HT0.
  set (A := 4.77331e-7). set (B := 2.98505e-7).
  set (kk := A * al + B * Rabs TT).
  assert (Hp : forall v V, Rabs (v - V) <= theta * Rabs V + eta ->
                 Rabs (rnd (v * t) - TT * V) <= kk * Rabs V + 3 * eta * al + eta).
  { intros v V Hvv.
    pose proof (Mag _ _ Hvv) as Hm. pose proof (Rabs_pos V).
    pose proof (rnd_err (v * t)) as R. rewrite Rabs_mult in R.
    replace (rnd (v * t) - TT * V)
      with ((rnd (v * t) - v * t) + v * (t - TT) + (v - V) * TT) by ring.
    pose proof (Rabs_triang ((rnd (v * t) - v * t) + v * (t - TT)) ((v - V) * TT)).
    pose proof (Rabs_triang (rnd (v * t) - v * t) (v * (t - TT))).
    rewrite Rabs_mult in *.
    assert (Rabs v * Rabs t <= ((1 + theta) * Rabs V + eta) * (Rabs TT + tau * al))
      by (apply Rmult_le_compat; try apply Rabs_pos; lra).
    assert (Rabs v * Rabs (t - TT) <= ((1 + theta) * Rabs V + eta) * (tau * al))
      by (apply Rmult_le_compat; try apply Rabs_pos; lra).
    assert (Rabs (v - V) * Rabs TT <= (theta * Rabs V + eta) * Rabs TT)
      by (apply Rmult_le_compat; try apply Rabs_pos; lra).
    assert (0 <= Rabs V * al) by (apply Rmult_le_pos; [apply Rabs_pos | lra]).
    assert (0 <= Rabs V * Rabs TT) by (apply Rmult_le_pos; apply Rabs_pos).
    assert (0 <= eta * al) by (apply Rmult_le_pos; [pose proof eta_pos | ]; lra).
    assert (eta * Rabs TT <= eta * al) by (apply Rmult_le_compat_l; lra).
    unfold kk, A, B, theta, tau in *. rewrite Hu1 in *. lra. }
  assert (HP0 : Rabs (p0 - T * b0) <= kk * Rabs U0 + 3 * eta * al + eta) by (rewrite HP; apply Hp; exact Hv0).
  assert (HP1 : Rabs (p1 - T * b1) <= kk * Rabs U1 + 3 * eta * al + eta) by (rewrite HP; apply Hp; exact Hv1).
  assert (HP2 : Rabs (p2 - T * b2) <= kk * Rabs U2 + 3 * eta * al + eta) by (rewrite HP; apply Hp; exact Hv2).
  assert (HP3 : Rabs (p3 - T * b3) <= kk * Rabs U3 + 3 * eta * al + eta) by (rewrite HP; apply Hp; exact Hv3).
  assert (Hd : 0 <= 3 * eta * al + eta)
    by (pose proof eta_pos; assert (0 <= eta * al) by (apply Rmult_le_pos; lra); lra).
  assert (HK : 0 <= kk) by (unfold kk, A, B; nra).
  assert (HBT : B * Rabs TT <= B * al) by (apply Rmult_le_compat_l; [unfold B; lra|exact HTT]).
  assert (Hsmall : 2 * (3 * eta * al + eta) <= 1e-14 * al).
  { assert (eta * al <= 1e-44 * al) by (apply Rmult_le_compat_r; [lra|]; unfold eta; simpl; lra).
    lra. }
  split.
  - assert (Z : forall x V, Rabs x <= kk * Rabs V + 3 * eta * al + eta ->
                Rabs x <= kk * Rabs V + 0 * Rabs V + (3 * eta * al + eta)) by (intros; lra).
    pose proof (norm4_comb _ _ _ _ U0 U1 U2 U3 U0 U1 U2 U3 kk 0 _ HK (Rle_refl 0) Hd
                  (Z _ _ HP0) (Z _ _ HP1) (Z _ _ HP2) (Z _ _ HP3)) as N4.
    rewrite HU in N4.
    unfold kk, A, B in *. lra.
  - (* The rejection: one more rounding, of a_i - p_i. Its part relative
       to |T| and its rounding relative to |R| add as the sides of a
       right angle: |T|^2 + |R|^2 = |a|^2. *)
    set (R0 := a0 - T * b0); set (R1 := a1 - T * b1); set (R2 := a2 - T * b2); set (R3 := a3 - T * b3).
    assert (HR : Rabs TT * Rabs TT + n4 R0 R1 R2 R3 * n4 R0 R1 R2 R3 <= al * al).
    { assert (E : R0 * R0 + R1 * R1 + R2 * R2 + R3 * R3
                  = (a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3) - TT * TT).
      { unfold R0, R1, R2, R3. rewrite !HP. fold U0 U1 U2 U3.
        pose proof (n4_sq U0 U1 U2 U3) as SU. rewrite HU in SU.
        assert (SU' : U0 * U0 + U1 * U1 + U2 * U2 + U3 * U3 = 1) by lra.
        replace ((a0 - TT * U0) * (a0 - TT * U0) + (a1 - TT * U1) * (a1 - TT * U1)
                 + (a2 - TT * U2) * (a2 - TT * U2) + (a3 - TT * U3) * (a3 - TT * U3))
          with ((a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3) - 2 * TT * (a0 * U0 + a1 * U1 + a2 * U2 + a3 * U3)
                + TT * TT * (U0 * U0 + U1 * U1 + U2 * U2 + U3 * U3)) by ring.
        rewrite SU'. change (a0 * U0 + a1 * U1 + a2 * U2 + a3 * U3) with TT. ring. }
      rewrite n4_sq, E, sq_abs. unfold al. rewrite n4_sq. lra. }
    assert (Hr : forall a p P Ub, Rabs (p - P) <= kk * Rabs Ub + 3 * eta * al + eta ->
                   Rabs (rnd (a - p) - (a - P))
                   <= ((1 + u) * kk) * Rabs Ub + u * Rabs (a - P)
                      + ((1 + u) * (3 * eta * al + eta) + eta)).
    { intros a p P Ub Hpp.
      pose proof (rnd_err (a - p)) as R.
      replace (rnd (a - p) - (a - P)) with ((rnd (a - p) - (a - p)) + - (p - P)) by ring.
      pose proof (Rabs_triang (rnd (a - p) - (a - p)) (- (p - P))). rewrite Rabs_Ropp in *.
      assert (Rabs (a - p) <= Rabs (a - P) + Rabs (p - P)).
      { replace (a - p) with ((a - P) + - (p - P)) by ring.
        pose proof (Rabs_triang (a - P) (- (p - P))). rewrite Rabs_Ropp in *. lra. }
      assert (u * Rabs (a - p) <= u * (Rabs (a - P) + (kk * Rabs Ub + 3 * eta * al + eta)))
        by (apply Rmult_le_compat_l; lra).
      pose proof (Rabs_pos Ub). lra. }
    assert (Hd2 : 0 <= (1 + u) * (3 * eta * al + eta) + eta)
      by (pose proof u_pos; pose proof eta_pos; apply Rplus_le_le_0_compat; [apply Rmult_le_pos|]; lra).
    assert (HK2 : 0 <= (1 + u) * kk) by (pose proof u_pos; apply Rmult_le_pos; lra).
    pose proof (norm4_comb _ _ _ _ U0 U1 U2 U3 R0 R1 R2 R3 _ _ _ HK2 (Rlt_le _ _ Hu) Hd2
                  (Hr a0 p0 (T * b0) U0 HP0) (Hr a1 p1 (T * b1) U1 HP1)
                  (Hr a2 p2 (T * b2) U2 HP2) (Hr a3 p3 (T * b3) U3 HP3)) as N4.
    rewrite HU in N4.
    assert (Hright : (1 + u) * B * Rabs TT + u * n4 R0 R1 R2 R3 <= 3.0441e-7 * al).
    { apply right_angle; try (unfold B; rewrite Hu1; lra); try apply n4_pos; lra. }
    assert (2 * ((1 + u) * (3 * eta * al + eta) + eta) <= 1e-13 * al).
    { assert (eta * al <= 1e-44 * al) by (apply Rmult_le_compat_r; [lra|]; unfold eta; simpl; lra).
      rewrite Hu1. lra. }
    unfold kk, A, R0, R1, R2, R3 in *. rewrite Hu1 in *. lra.
Qed.

Lemma ratio : forall x al c, 0 < al -> x <= c * al -> x / al <= c.
Proof.
  intros x al c H1 H2. apply Rmult_le_reg_r with al; [exact H1|].
  unfold Rdiv. rewrite Rmult_assoc, Rinv_l by lra. lra.
Qed.

Theorem project4 : forall a0 a1 a2 a3 B0 B1 B2 B3 : R,
  let b0 := rnd B0 in
  let b1 := rnd B1 in
  let b2 := rnd B2 in
  let b3 := rnd B3 in
  1 <= b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3 <= 4 ->
  / 2 ^ 100 <= n4 a0 a1 a2 a3 ->
  let s := rnd (rnd (rnd (rnd (b0 * b0) + rnd (b1 * b1)) + rnd (b2 * b2)) + rnd (b3 * b3)) in
  let n := rnd (sqrt (s)) in
  let u0 := rnd (b0 / n) in
  let u1 := rnd (b1 / n) in
  let u2 := rnd (b2 / n) in
  let u3 := rnd (b3 / n) in
  let t := rnd (rnd (rnd (rnd (a0 * u0) + rnd (a1 * u1)) + rnd (a2 * u2)) + rnd (a3 * u3)) in
  let p0 := rnd (u0 * t) in
  let p1 := rnd (u1 * t) in
  let p2 := rnd (u2 * t) in
  let p3 := rnd (u3 * t) in
  let r0 := rnd (a0 - p0) in
  let r1 := rnd (a1 - p1) in
  let r2 := rnd (a2 - p2) in
  let r3 := rnd (a3 - p3) in
  let T := (a0 * b0 + a1 * b1 + a2 * b2 + a3 * b3) / (b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3) in
  Rmax (n4 (p0 - T * b0) (p1 - T * b1) (p2 - T * b2) (p3 - T * b3) / n4 a0 a1 a2 a3)
       (n4 (r0 - (a0 - T * b0)) (r1 - (a1 - T * b1))
           (r2 - (a2 - T * b2)) (r3 - (a3 - T * b3)) / n4 a0 a1 a2 a3) <= 7.83e-7.
Proof.
  intros a0 a1 a2 a3 B0 B1 B2 B3 b0 b1 b2 b3 HS Ha.
  assert (Hpos : 0 < n4 a0 a1 a2 a3)
    by (assert (0 < / 2 ^ 100) by (apply Rinv_0_lt_compat, pow_lt; lra); lra).
  pose proof (project4_main a0 a1 a2 a3 B0 B1 B2 B3 HS Ha) as M. cbv zeta in M |- *. unfold b0, b1, b2, b3 in *.
  destruct M as [Hp Hr].
  apply Rmax_lub; apply ratio; try assumption; lra.
Qed.

