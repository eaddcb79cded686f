(* The inverse identities of RigTForm (src/rigtform.rs): a.inv() is
   (-(r^-1 t), r^-1) with r^-1 = [w, -x, -y, -z] (exact), and a * b is
   (a.t + a.r b.t, a.r b.r). With i = r^-1 t and g = r (-i), each the
   code's q * v (the computation of rotate_error.v; the lets are the
   terms of rigtform_inv.g, which the correspondence test compares), the
   translation of a * a.inv() is e = t + g, rounded component by
   component, and that of a.inv().inv() is -g (negations are exact);
   their rotations are r r^-1 and r exactly. For r with |r| within
   2.391e-7 of 1 (every result of normalize: normalize_norm.v) and t with
   |t|^2 at least 1/4 (every non-zero t after an exact power-of-two
   scaling), e is within 3.23e-6 |t| of 0 and -g within 3.22e-6 |t| of t.

   Proven here, with n = |r|^2 = 1 + delta, k the vector part of r and F
   the exact formula of q * v (rotate_error.v):
   - the exact formulas compose to t + 4 delta (|k|^2 t - (k . t) k)
     (compose_exact, by ring: F_q(v) = q v q* + (1 - n) v), at most
     4 |delta| |k|^2 |t| from t; it is 4 |delta| |t| where r is half a
     turn and t across its axis, the largest;
   - i is within 6.5e-7 |t| of F_{r^-1}(t) and g within 6.5e-7 |i| of
     F_r(-i) (rotate_main: |i|^2 is near |t|^2, and rotate_main takes
     every |v|^2 from 1/9 up), and F_r lengthens the first error by at
     most 1 + 4e-6 (formula_len);
   so |-g - t| <= (6.5e-7 (1 + 4e-6 + 6.5e-7) + 6.5e-7 (1 + 4e-6)
   + 4 4.782e-7 (1 + 2.391e-7)^2) |t| = 3.2129e-6 |t|, and t + g, which
   is -(-g - t), rounds once more (2^-24 of itself, besides 2 2^-150). *)
(*! law - rigtform_inverse_product <= 3.23e-6 |(a * a.inv()).t| / |t| for r a result of normalize *)
(*! law - rigtform_inverse_back <= 3.22e-6 |a.inv().inv().t - t| / |t| for r a result of normalize *)
Require Import Reals Psatz.
Require Import Flocq.Core.Core.
Require Import Gappa.Gappa_library.
Require Import Laws.Common.
Require Import Laws.rotate_error.

Open Scope R_scope.

(* The exact formula F_q(v) = v + 2 w (k x v) + 2 k x (k x v). *)
Definition F_x (w x y z vx vy vz : R) :=
  vx + (y * vz - z * vy) * 2 * w + (y * ((x * vy - y * vx) * 2) - z * ((z * vx - x * vz) * 2)).
Definition F_y (w x y z vx vy vz : R) :=
  vy + (z * vx - x * vz) * 2 * w + (z * ((y * vz - z * vy) * 2) - x * ((x * vy - y * vx) * 2)).
Definition F_z (w x y z vx vy vz : R) :=
  vz + (x * vy - y * vx) * 2 * w + (x * ((z * vx - x * vz) * 2) - y * ((y * vz - z * vy) * 2)).

(* rotate_main on these names: the error within 6.5e-7 |v|. *)
Lemma F_err : forall w x y z vx vy vz rx ry rz,
  1 - / 1048576 <= w * w + x * x + y * y + z * z <= 1 + / 1048576 ->
  / 9 <= vx * vx + vy * vy + vz * vz ->
  rx = rnd (rnd (vx + rnd (rnd (rnd (rnd (y * vz) - rnd (z * vy)) * 2) * w))
            + rnd (rnd (y * rnd (rnd (rnd (x * vy) - rnd (y * vx)) * 2))
                   - rnd (z * rnd (rnd (rnd (z * vx) - rnd (x * vz)) * 2)))) ->
  ry = rnd (rnd (vy + rnd (rnd (rnd (rnd (z * vx) - rnd (x * vz)) * 2) * w))
            + rnd (rnd (z * rnd (rnd (rnd (y * vz) - rnd (z * vy)) * 2))
                   - rnd (x * rnd (rnd (rnd (x * vy) - rnd (y * vx)) * 2)))) ->
  rz = rnd (rnd (vz + rnd (rnd (rnd (rnd (x * vy) - rnd (y * vx)) * 2) * w))
            + rnd (rnd (x * rnd (rnd (rnd (z * vx) - rnd (x * vz)) * 2))
                   - rnd (y * rnd (rnd (rnd (y * vz) - rnd (z * vy)) * 2)))) ->
  n3 (rx - F_x w x y z vx vy vz) (ry - F_y w x y z vx vy vz) (rz - F_z w x y z vx vy vz)
  <= 6.5e-7 * n3 vx vy vz.
Proof.
  intros w x y z vx vy vz rx ry rz HQ HV -> -> ->.
  exact (rotate_main w x y z vx vy vz HQ HV).
Qed.

Lemma F_len : forall w x y z vx vy vz,
  1 - / 1048576 <= w * w + x * x + y * y + z * z <= 1 + / 1048576 ->
  n3 (F_x w x y z vx vy vz) (F_y w x y z vx vy vz) (F_z w x y z vx vy vz) <= (1 + 4e-6) * n3 vx vy vz.
Proof. intros w x y z vx vy vz HQ. exact (formula_len w x y z vx vy vz HQ). Qed.

(* The exact formula shortens v by at most a tenth:
   |F(v)|^2 = |v|^2 (1 + 4 |k|^2 (n - 1)) + 4 (k . v)^2 (1 - n). *)
Lemma F_len_lower : forall w x y z vx vy vz,
  1 - / 1048576 <= w * w + x * x + y * y + z * z <= 1 + / 1048576 ->
  0.9 * n3 vx vy vz <= n3 (F_x w x y z vx vy vz) (F_y w x y z vx vy vz) (F_z w x y z vx vy vz).
Proof.
  intros w x y z vx vy vz HQ.
  pose proof (n3_pos vx vy vz) as Hnv.
  set (s2 := x * x + y * y + z * z). set (d := x * vx + y * vy + z * vz).
  set (V := vx * vx + vy * vy + vz * vz).
  assert (E : F_x w x y z vx vy vz * F_x w x y z vx vy vz + F_y w x y z vx vy vz * F_y w x y z vx vy vz
    + F_z w x y z vx vy vz * F_z w x y z vx vy vz
    = V * (1 + 4 * s2 * (w * w + s2 - 1)) + 4 * (d * d) * (1 - (w * w + s2)))
    by (unfold F_x, F_y, F_z, V, s2, d; ring).
  assert (Hd : d * d <= s2 * V).
  { unfold d, s2, V. pose proof (Rle_0_sqr (x * vy - y * vx)); pose proof (Rle_0_sqr (x * vz - z * vx));
    pose proof (Rle_0_sqr (y * vz - z * vy)). unfold Rsqr in *. nra. }
  assert (Hs : 0 <= s2 <= 1 + / 1048576) by (unfold s2 in *; split; nra).
  assert (HV : 0 <= V) by (unfold V; nra).
  assert (Hdd : 0 <= d * d) by nra.
  assert (Hnv2 : n3 vx vy vz * n3 vx vy vz = V) by apply n3_sq.
  rewrite <- (sqrt_square (0.9 * n3 vx vy vz)) by nra.
  unfold n3 at 3. apply sqrt_le_1_alt. rewrite E.
  assert (A1 : V * (4 * s2 * (w * w + s2 - 1)) >= - (V * (4 * (1 + / 1048576) * / 1048576))).
  { assert (0 <= V * (4 * s2 * / 1048576)) by (apply Rmult_le_pos; nra).
    assert (V * (4 * s2 * / 1048576) <= V * (4 * (1 + / 1048576) * / 1048576))
      by (apply Rmult_le_compat_l; nra).
    unfold s2 in *. nra. }
  assert (A2 : 4 * (d * d) * (1 - (w * w + s2)) >= - (4 * (s2 * V) * / 1048576)).
  { unfold s2 in *. nra. }
  assert (A3 : s2 * V <= (1 + / 1048576) * V) by nra.
  replace (0.9 * n3 vx vy vz * (0.9 * n3 vx vy vz)) with (0.81 * V) by (rewrite <- Hnv2; lra).
  replace (V * (1 + 4 * s2 * (w * w + s2 - 1))) with (V + V * (4 * s2 * (w * w + s2 - 1))) by ring.
  lra.
Qed.

(* The exact formulas of r and r^-1 composed: F_r(F_{r^-1}(t)) = t + 4 (n - 1)
   (|k|^2 t - (k . t) k), since F_q(v) = q v q* + (1 - n) v and
   r t r* + r* t r = 2 (w^2 - |k|^2) t + 4 (k . t) k. *)
Lemma compose_exact : forall w x y z t1 t2 t3 i1 i2 i3,
  i1 = F_x w (-x) (-y) (-z) t1 t2 t3 -> i2 = F_y w (-x) (-y) (-z) t1 t2 t3 ->
  i3 = F_z w (-x) (-y) (-z) t1 t2 t3 ->
  F_x w x y z i1 i2 i3 - t1
    = 4 * (w * w + x * x + y * y + z * z - 1) * ((x * x + y * y + z * z) * t1 - (x * t1 + y * t2 + z * t3) * x) /\
  F_y w x y z i1 i2 i3 - t2
    = 4 * (w * w + x * x + y * y + z * z - 1) * ((x * x + y * y + z * z) * t2 - (x * t1 + y * t2 + z * t3) * y) /\
  F_z w x y z i1 i2 i3 - t3
    = 4 * (w * w + x * x + y * y + z * z - 1) * ((x * x + y * y + z * z) * t3 - (x * t1 + y * t2 + z * t3) * z).
Proof. intros w x y z t1 t2 t3 i1 i2 i3 -> -> ->. unfold F_x, F_y, F_z. repeat split; ring. Qed.

(* |(|k|^2 t - (k . t) k)| = |k| |k x t| <= |k|^2 |t|. *)
Lemma across_len : forall x y z t1 t2 t3 s2 d,
  s2 = x * x + y * y + z * z -> d = x * t1 + y * t2 + z * t3 ->
  n3 (s2 * t1 - d * x) (s2 * t2 - d * y) (s2 * t3 - d * z) <= s2 * n3 t1 t2 t3.
Proof.
  intros x y z t1 t2 t3 s2 d Hs2 Hd.
  pose proof (n3_pos t1 t2 t3). pose proof (n3_sq t1 t2 t3) as Ht.
  assert (Hs : 0 <= s2) by (rewrite Hs2; nra).
  unfold n3 at 1. rewrite <- (sqrt_square (s2 * n3 t1 t2 t3)) by nra.
  apply sqrt_le_1_alt.
  replace (s2 * n3 t1 t2 t3 * (s2 * n3 t1 t2 t3)) with (s2 * s2 * (n3 t1 t2 t3 * n3 t1 t2 t3)) by ring.
  rewrite Ht.
  assert (E : (s2 * t1 - d * x) * (s2 * t1 - d * x) + (s2 * t2 - d * y) * (s2 * t2 - d * y)
              + (s2 * t3 - d * z) * (s2 * t3 - d * z)
              = s2 * s2 * (t1 * t1 + t2 * t2 + t3 * t3) - s2 * (d * d)) by (rewrite Hs2, Hd; ring).
  rewrite E. assert (0 <= s2 * (d * d)) by (apply Rmult_le_pos; nra). lra.
Qed.

Lemma n3_opp : forall a b c, n3 (- a) (- b) (- c) = n3 a b c.
Proof.
  intros. replace (- a) with (-1 * a) by ring. replace (- b) with (-1 * b) by ring.
  replace (- c) with (-1 * c) by ring. rewrite n3_scal, (Rabs_left (-1)) by lra. ring.
Qed.

(* A quotient of lengths bounded through the numerator. *)
Lemma rel_le : forall a b k, 0 < b -> a <= k * b -> a / b <= k.
Proof.
  intros a b k Hb H. apply Rmult_le_reg_r with b; [exact Hb|].
  unfold Rdiv. rewrite Rmult_assoc, Rinv_l by lra. lra.
Qed.

(* a.inv().inv(): its translation -g within 3.22e-6 |t| of t (3.2129e-6). *)
Theorem rigtform_inverse_back : forall W X Y Z T1 T2 T3 : R,
  let w := rnd W in let x := rnd X in let y := rnd Y in let z := rnd Z in
  let t1 := rnd T1 in let t2 := rnd T2 in let t3 := rnd T3 in
  Rabs (sqrt (w * w + x * x + y * y + z * z) - 1) <= 2.391e-7 ->
  / 4 <= t1 * t1 + t2 * t2 + t3 * t3 ->
  let ax := rnd (rnd (rnd ((-y) * t3) - rnd ((-z) * t2)) * 2) in
  let ay := rnd (rnd (rnd ((-z) * t1) - rnd ((-x) * t3)) * 2) in
  let az := rnd (rnd (rnd ((-x) * t2) - rnd ((-y) * t1)) * 2) in
  let ix := rnd (rnd (t1 + rnd (ax * w)) + rnd (rnd ((-y) * az) - rnd ((-z) * ay))) in
  let iy := rnd (rnd (t2 + rnd (ay * w)) + rnd (rnd ((-z) * ax) - rnd ((-x) * az))) in
  let iz := rnd (rnd (t3 + rnd (az * w)) + rnd (rnd ((-x) * ay) - rnd ((-y) * ax))) in
  let cx := rnd (rnd (rnd (y * (-iz)) - rnd (z * (-iy))) * 2) in
  let cy := rnd (rnd (rnd (z * (-ix)) - rnd (x * (-iz))) * 2) in
  let cz := rnd (rnd (rnd (x * (-iy)) - rnd (y * (-ix))) * 2) in
  let gx := rnd (rnd ((-ix) + rnd (cx * w)) + rnd (rnd (y * cz) - rnd (z * cy))) in
  let gy := rnd (rnd ((-iy) + rnd (cy * w)) + rnd (rnd (z * cx) - rnd (x * cz))) in
  let gz := rnd (rnd ((-iz) + rnd (cz * w)) + rnd (rnd (x * cy) - rnd (y * cx))) in
  sqrt ((- gx - t1) * (- gx - t1) + (- gy - t2) * (- gy - t2) + (- gz - t3) * (- gz - t3))
    / sqrt (t1 * t1 + t2 * t2 + t3 * t3) <= 3.22e-6.
Proof.
  intros W X Y Z T1 T2 T3 w x y z t1 t2 t3 HN HT ax ay az ix iy iz cx cy cz gx gy gz.
  apply rel_le; [change (0 < n3 t1 t2 t3); pose proof (n3_pos t1 t2 t3); pose proof (n3_sq t1 t2 t3); nra|].
  change (n3 (- gx - t1) (- gy - t2) (- gz - t3) <= 3.22e-6 * n3 t1 t2 t3).
  apply Rle_trans with (3.2129e-6 * n3 t1 t2 t3); [|pose proof (n3_pos t1 t2 t3); lra].
  set (n := w * w + x * x + y * y + z * z) in *.
  set (s2 := x * x + y * y + z * z).
  pose proof (n3_pos t1 t2 t3) as Ht0. pose proof (n3_sq t1 t2 t3) as Ht2.
  assert (Ht : / 2 <= n3 t1 t2 t3) by nra.
  (* n within (1 +- 2.391e-7)^2. *)
  assert (Hn0 : 0 <= n) by (unfold n; nra).
  assert (Hsq : sqrt n * sqrt n = n) by (apply sqrt_sqrt; lra).
  apply abs_split in HN.
  assert (Hn : (1 - 2.391e-7) * (1 - 2.391e-7) <= n <= (1 + 2.391e-7) * (1 + 2.391e-7))
    by (pose proof (sqrt_pos n); split; nra).
  assert (HQ : 1 - / 1048576 <= n <= 1 + / 1048576) by lra.
  assert (HQ' : 1 - / 1048576 <= w * w + (- x) * (- x) + (- y) * (- y) + (- z) * (- z) <= 1 + / 1048576)
    by (unfold n in HQ; split; nra).
  assert (Hs2 : 0 <= s2 <= n) by (unfold s2, n; split; nra).
  (* The first rotation: i = F_{r^-1}(t) + e1. *)
  set (Ix := F_x w (-x) (-y) (-z) t1 t2 t3). set (Iy := F_y w (-x) (-y) (-z) t1 t2 t3).
  set (Iz := F_z w (-x) (-y) (-z) t1 t2 t3).
  assert (E1 : n3 (ix - Ix) (iy - Iy) (iz - Iz) <= 6.5e-7 * n3 t1 t2 t3)
    by (apply (F_err w (-x) (-y) (-z) t1 t2 t3 ix iy iz HQ'); [lra|reflexivity..]).
  assert (HI : n3 Ix Iy Iz <= (1 + 4e-6) * n3 t1 t2 t3) by (apply F_len; exact HQ').
  assert (HI' : 0.9 * n3 t1 t2 t3 <= n3 Ix Iy Iz) by (apply F_len_lower; exact HQ').
  pose proof (n3_triang Ix Iy Iz (ix - Ix) (iy - Iy) (iz - Iz)) as Tri.
  replace (Ix + (ix - Ix)) with ix in Tri by ring. replace (Iy + (iy - Iy)) with iy in Tri by ring.
  replace (Iz + (iz - Iz)) with iz in Tri by ring.
  assert (Hi : n3 ix iy iz <= (1 + 4e-6 + 6.5e-7) * n3 t1 t2 t3) by lra.
  assert (Hi' : 0.8 * n3 t1 t2 t3 <= n3 ix iy iz).
  { pose proof (n3_triang ix iy iz (- (ix - Ix)) (- (iy - Iy)) (- (iz - Iz))) as Tri2.
    rewrite n3_opp in Tri2.
    replace (ix + - (ix - Ix)) with Ix in Tri2 by ring. replace (iy + - (iy - Iy)) with Iy in Tri2 by ring.
    replace (iz + - (iz - Iz)) with Iz in Tri2 by ring. lra. }
  (* The second rotation: g = F_r(-i) + e2. *)
  assert (HV2 : / 9 <= (- ix) * (- ix) + (- iy) * (- iy) + (- iz) * (- iz)).
  { rewrite <- (n3_sq (- ix) (- iy) (- iz)), n3_opp. nra. }
  assert (E2 : n3 (gx - F_x w x y z (- ix) (- iy) (- iz)) (gy - F_y w x y z (- ix) (- iy) (- iz))
                  (gz - F_z w x y z (- ix) (- iy) (- iz)) <= 6.5e-7 * n3 ix iy iz).
  { rewrite <- (n3_opp ix iy iz). apply (F_err w x y z (-ix) (-iy) (-iz) gx gy gz HQ HV2); reflexivity. }
  (* F_r of the first error. *)
  assert (HF1 : n3 (F_x w x y z (ix - Ix) (iy - Iy) (iz - Iz)) (F_y w x y z (ix - Ix) (iy - Iy) (iz - Iz))
                   (F_z w x y z (ix - Ix) (iy - Iy) (iz - Iz)) <= (1 + 4e-6) * (6.5e-7 * n3 t1 t2 t3)).
  { eapply Rle_trans; [apply F_len; exact HQ|]. apply Rmult_le_compat_l; lra. }
  (* The exact formulas composed. *)
  set (d := x * t1 + y * t2 + z * t3).
  destruct (compose_exact w x y z t1 t2 t3 Ix Iy Iz eq_refl eq_refl eq_refl) as (C1 & C2 & C3).
  fold n s2 d in C1, C2, C3.
  assert (HC : n3 (4 * (n - 1) * (s2 * t1 - d * x)) (4 * (n - 1) * (s2 * t2 - d * y)) (4 * (n - 1) * (s2 * t3 - d * z))
               <= 4 * 4.7820006e-7 * ((1 + 2.391e-7) * (1 + 2.391e-7)) * n3 t1 t2 t3).
  { rewrite n3_scal, Rabs_mult, (Rabs_right 4) by lra.
    pose proof (across_len x y z t1 t2 t3 s2 d eq_refl eq_refl) as A.
    assert (Hd : Rabs (n - 1) <= 4.7820006e-7) by (apply Rabs_le; split; lra).
    assert (0 <= n3 (s2 * t1 - d * x) (s2 * t2 - d * y) (s2 * t3 - d * z)) by apply n3_pos.
    assert (Rabs (n - 1) * n3 (s2 * t1 - d * x) (s2 * t2 - d * y) (s2 * t3 - d * z)
            <= 4.7820006e-7 * (s2 * n3 t1 t2 t3))
      by (apply Rmult_le_compat; [apply Rabs_pos|lra|lra|lra]).
    assert (s2 * n3 t1 t2 t3 <= (1 + 2.391e-7) * (1 + 2.391e-7) * n3 t1 t2 t3)
      by (apply Rmult_le_compat_r; lra).
    nra. }
  (* -g - t = -e2 + F_r(e1) + (F_r(F_{r^-1}(t)) - t). *)
  assert (Nx : - gx - t1 = - (gx - F_x w x y z (- ix) (- iy) (- iz)) + F_x w x y z (ix - Ix) (iy - Iy) (iz - Iz)
                          + 4 * (n - 1) * (s2 * t1 - d * x))
    by (rewrite <- C1; unfold F_x; ring).
  assert (Ny : - gy - t2 = - (gy - F_y w x y z (- ix) (- iy) (- iz)) + F_y w x y z (ix - Ix) (iy - Iy) (iz - Iz)
                          + 4 * (n - 1) * (s2 * t2 - d * y))
    by (rewrite <- C2; unfold F_y; ring).
  assert (Nz : - gz - t3 = - (gz - F_z w x y z (- ix) (- iy) (- iz)) + F_z w x y z (ix - Ix) (iy - Iy) (iz - Iz)
                          + 4 * (n - 1) * (s2 * t3 - d * z))
    by (rewrite <- C3; unfold F_z; ring).
  rewrite Nx, Ny, Nz.
  eapply Rle_trans; [apply n3_triang|].
  pose proof (n3_triang (- (gx - F_x w x y z (- ix) (- iy) (- iz))) (- (gy - F_y w x y z (- ix) (- iy) (- iz)))
    (- (gz - F_z w x y z (- ix) (- iy) (- iz))) (F_x w x y z (ix - Ix) (iy - Iy) (iz - Iz))
    (F_y w x y z (ix - Ix) (iy - Iy) (iz - Iz)) (F_z w x y z (ix - Ix) (iy - Iy) (iz - Iz))) as Tr2.
  rewrite n3_opp in Tr2.
  assert (6.5e-7 * n3 ix iy iz <= 6.5e-7 * ((1 + 4e-6 + 6.5e-7) * n3 t1 t2 t3))
    by (apply Rmult_le_compat_l; lra).
  lra.
Qed.

(* a * a.inv(): its translation t + g, rounded, within 3.23e-6 |t| of 0. *)
Theorem rigtform_inverse_product : forall W X Y Z T1 T2 T3 : R,
  let w := rnd W in let x := rnd X in let y := rnd Y in let z := rnd Z in
  let t1 := rnd T1 in let t2 := rnd T2 in let t3 := rnd T3 in
  Rabs (sqrt (w * w + x * x + y * y + z * z) - 1) <= 2.391e-7 ->
  / 4 <= t1 * t1 + t2 * t2 + t3 * t3 ->
  let ax := rnd (rnd (rnd ((-y) * t3) - rnd ((-z) * t2)) * 2) in
  let ay := rnd (rnd (rnd ((-z) * t1) - rnd ((-x) * t3)) * 2) in
  let az := rnd (rnd (rnd ((-x) * t2) - rnd ((-y) * t1)) * 2) in
  let ix := rnd (rnd (t1 + rnd (ax * w)) + rnd (rnd ((-y) * az) - rnd ((-z) * ay))) in
  let iy := rnd (rnd (t2 + rnd (ay * w)) + rnd (rnd ((-z) * ax) - rnd ((-x) * az))) in
  let iz := rnd (rnd (t3 + rnd (az * w)) + rnd (rnd ((-x) * ay) - rnd ((-y) * ax))) in
  let cx := rnd (rnd (rnd (y * (-iz)) - rnd (z * (-iy))) * 2) in
  let cy := rnd (rnd (rnd (z * (-ix)) - rnd (x * (-iz))) * 2) in
  let cz := rnd (rnd (rnd (x * (-iy)) - rnd (y * (-ix))) * 2) in
  let gx := rnd (rnd ((-ix) + rnd (cx * w)) + rnd (rnd (y * cz) - rnd (z * cy))) in
  let gy := rnd (rnd ((-iy) + rnd (cy * w)) + rnd (rnd (z * cx) - rnd (x * cz))) in
  let gz := rnd (rnd ((-iz) + rnd (cz * w)) + rnd (rnd (x * cy) - rnd (y * cx))) in
  let ex := rnd (t1 + gx) in let ey := rnd (t2 + gy) in let ez := rnd (t3 + gz) in
  sqrt (ex * ex + ey * ey + ez * ez) / sqrt (t1 * t1 + t2 * t2 + t3 * t3) <= 3.23e-6.
Proof.
  intros W X Y Z T1 T2 T3 w x y z t1 t2 t3 HN HT ax ay az ix iy iz cx cy cz gx gy gz ex ey ez.
  pose proof (rigtform_inverse_back W X Y Z T1 T2 T3 HN HT) as B. cbv zeta in B.
  pose proof (n3_pos t1 t2 t3). pose proof (n3_sq t1 t2 t3).
  assert (Ht : / 2 <= n3 t1 t2 t3) by nra.
  change (n3 (- gx - t1) (- gy - t2) (- gz - t3) / n3 t1 t2 t3 <= 3.22e-6) in B.
  assert (B' : n3 (- gx - t1) (- gy - t2) (- gz - t3) <= 3.22e-6 * n3 t1 t2 t3).
  { apply Rmult_le_reg_r with (/ n3 t1 t2 t3); [apply Rinv_0_lt_compat; lra|].
    rewrite Rmult_assoc, Rinv_r by lra. unfold Rdiv in B. lra. }
  pose proof u_pos as Hu; pose proof eta_pos as He.
  assert (Hu1 : u = / 16777216) by reflexivity.
  assert (He1 : eta <= / 2 ^ 140) by (unfold eta; simpl; lra).
  (* t + g is -(-g - t). *)
  assert (S : n3 (t1 + gx) (t2 + gy) (t3 + gz) <= 3.22e-6 * n3 t1 t2 t3).
  { rewrite <- n3_opp. replace (- (t1 + gx)) with (- gx - t1) by ring.
    replace (- (t2 + gy)) with (- gy - t2) by ring. replace (- (t3 + gz)) with (- gz - t3) by ring.
    exact B'. }
  (* The last sums' roundings. *)
  assert (R : n3 (ex - (t1 + gx)) (ey - (t2 + gy)) (ez - (t3 + gz)) <= u * n3 (t1 + gx) (t2 + gy) (t3 + gz) + 2 * eta).
  { eapply Rle_trans; [apply n3_le; apply rnd_err|].
    eapply Rle_trans; [apply n3_plus_const; lra|].
    rewrite n3_scal, n3_abs, (Rabs_right u) by lra. lra. }
  pose proof (n3_triang (t1 + gx) (t2 + gy) (t3 + gz) (ex - (t1 + gx)) (ey - (t2 + gy)) (ez - (t3 + gz))) as Tri.
  replace (t1 + gx + (ex - (t1 + gx))) with ex in Tri by ring.
  replace (t2 + gy + (ey - (t2 + gy))) with ey in Tri by ring.
  replace (t3 + gz + (ez - (t3 + gz))) with ez in Tri by ring.
  apply rel_le; [change (0 < n3 t1 t2 t3); lra|].
  change (n3 ex ey ez <= 3.23e-6 * n3 t1 t2 t3).
  assert (u * n3 (t1 + gx) (t2 + gy) (t3 + gz) <= u * (3.22e-6 * n3 t1 t2 t3)) by (apply Rmult_le_compat_l; lra).
  rewrite Hu1 in *. lra.
Qed.
