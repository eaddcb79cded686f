(* The rotation of a vector, q * v (src/quat/ops.rs, Mul<Cvec3> for Quat):
   t = (u x v) * 2, then (v + t w) + u x t, with u = (x, y, z) the vector
   part of q, for q with |q|^2 within 2^-20 of 1 (every result of
   normalize, whose norm normalize_norm.v bounds within 2.391e-7 of 1) and
   v with |v|^2 in [1/4, 1] (every non-zero v after an exact power-of-two
   scaling, as in rotate.g): the error vector against the exact value of
   the same formula is at most 6.5e-7 |v| long. rotate_main, on which the
   law rests, holds for every v with |v|^2 at least 1/9, so that a vector
   an earlier rotation computed (rigtform_inverse.v) needs no rescaling.

   Proven here with vectors, on Flocq's rounding alone: the error is the
   sum of five vectors, each bounded by its length (triangle inequality):
   - the error of t (the first cross product's roundings, at most
     (1 + sqrt(4/3)) 2^-24 |u| |v| for u x v; the doubling is exact),
     turned by e -> w e + u x e, which does not lengthen it (|q| = 1);
   - the roundings of t w, at most 2^-24 |w| |t|;
   - the roundings of v + t w, at most 2^-24 |v + t w|, where v and t are
     orthogonal: |v + T w|^2 = |v|^2 + w^2 |T|^2;
   - the second cross product's roundings, at most
     (1 + sqrt(4/3)) 2^-24 |u| |t|;
   - the last sums' roundings, at most 2^-24 times the length of the sum
     they round, which is F(v) plus the four errors above (so within
     6.5e-7 |v| of |F(v)|, and |F(v)| within 4e-6 of |v| by the identity
     |F(v)|^2 = |v|^2 (1 + 4 |u|^2 (|q|^2 - 1)) + 4 (u . v)^2 (1 - |q|^2)).
   With s = |u| and c = |w| (s^2 + c^2 = |q|^2) the sum is at most
   (4.31 s + 2 c s + (1 + 2 c^2 s^2) + 4.31 s^2 + 1) 2^-24 |v| to first
   order, largest (10.83 2^-24) near s = 0.98 (rotate_scalar). The
   certificate of rotate.g (Gappa, 3.8e-6 |v| by intervals) is not
   needed. *)
(*! bound ROTATE_MAX_REL_ERROR rotate_error <= 6.5e-7 |q*v - F(v)| / |v|, F the exact formula, q within 2^-20 of unit norm *)
Require Import Reals Psatz.
Require Import Flocq.Core.Core.
Require Import Gappa.Gappa_library.
Require Import Laws.Common.

Open Scope R_scope.

(* The first-order factor as a function of s = |u| and c = |w|. *)
Lemma rotate_scalar : forall s c, 0 <= s -> 0 <= c -> s * s + c * c <= 1 + / 1048576 ->
  4.3097 * s + 2 * c * s + 2 + 2 * (c * s) * (c * s) + 4.3097 * (s * s) <= 10.87.
Proof.
  intros s c Hs Hc H.
  assert (AM : 2 * c * s <= 0.2 * (s * s) + 5 * (c * c)).
  { pose proof (Rle_0_sqr (0.2 * s - c)). unfold Rsqr in *. nra. }
  assert (0 <= c * c) by nra.
  assert (H4 : 2 * (c * s) * (c * s) <= 2 * (1 + / 1048576 - s * s) * (s * s)).
  { replace (2 * (c * s) * (c * s)) with (2 * (c * c) * (s * s)) by ring.
    apply Rmult_le_compat_r; [nra|lra]. }
  assert (s <= 1.001) by nra.
  pose proof (Rle_0_sqr (s - 0.967)). pose proof (Rle_0_sqr (s * s - 0.935)). unfold Rsqr in *.
  nra.
Qed.

(* A third of nv at least: a small absolute term is a multiple of nv. *)
Lemma third_le : forall nv k, / 3 <= nv -> 0 <= k -> k <= nv * (3 * k).
Proof. intros; nra. Qed.

(* The five lengths added, each bounded through the ones before it: a the
   first cross product's error, NT = |t|, Nmu the roundings of t w, Nsig
   those of v + m, Ngam the second cross product's, NL the error of t
   turned, Nrho the last sums', Nr the result's length. *)
Lemma rotate_combine : forall u0 k e s c nv a NT Nmu Nsig Ngam NL Nrho Nr,
  u0 = / 16777216 -> 0 <= e <= / 2 ^ 140 -> 0 <= k <= 2.15481 * u0 ->
  0 <= s -> 0 <= c -> s * s + c * c <= 1 + / 1048576 -> / 3 <= nv ->
  0 <= a <= k * (s * nv) + 8 * e ->
  NT <= 2 * (s * nv) + 2 * a ->
  Nmu <= u0 * c * NT + 2 * e ->
  Nsig <= u0 * (nv * (1 + 2 * (c * s) * (c * s)) + Nmu + 2 * c * a) + 2 * e ->
  Ngam <= k * (s * NT) + 8 * e ->
  NL <= (1 + / 1048576) * (2 * a) ->
  Nrho <= u0 * (Nr + Nrho) + 2 * e -> Nr <= (1 + 1e-5) * nv ->
  Nrho + Nsig + Nmu + Ngam + NL <= 6.5e-7 * nv.
Proof.
  intros u0 k e s c nv a NT Nmu Nsig Ngam NL Nrho Nr Hu He Hk Hs Hc Hq Hnv Ha HNT Hmu Hsig Hgam HL Hrho HNr.
  assert (Hs5 : s <= 1.00001) by nra.
  assert (Hs1 : s <= 1.001) by lra.
  assert (Hc1 : c <= 1.001) by nra.
  assert (Hcs : 0 <= c * s <= 1.001) by (split; nra).
  (* a / nv <= al, a small constant times... *)
  set (al := k * s + 24 * e).
  assert (Hal : a <= nv * al).
  { unfold al. assert (8 * e <= nv * (24 * e)) by nra. nra. }
  assert (Hks : k * s <= 2.15481 * u0 * s) by (apply Rmult_le_compat_r; lra).
  assert (Hal1 : al <= 2.1572 * u0).
  { unfold al. assert (2.15481 * u0 * s <= 2.15481 * u0 * 1.001) by (apply Rmult_le_compat_l; lra).
    rewrite Hu in *. lra. }
  assert (Ha1 : a <= nv * (2.1572 * u0)).
  { assert (nv * al <= nv * (2.1572 * u0)) by (apply Rmult_le_compat_l; lra). lra. }
  assert (HNT1 : NT <= nv * (2 * s + 2 * al)) by lra.
  assert (HNT2 : NT <= nv * 2.0001).
  { assert (nv * s <= nv * 1.00001) by (apply Rmult_le_compat_l; lra).
    assert (nv * al <= nv * (2.1572 * u0)) by (apply Rmult_le_compat_l; lra).
    rewrite Hu in *. lra. }

  (* The terms, each nv times a factor. *)
  assert (Hmu2 : Nmu <= nv * (2 * u0 * (c * s) + 2 * 1.001 * u0 * (2.1572 * u0) + 6 * e)).
  { assert (u0 * c * NT <= u0 * c * (nv * (2 * s + 2 * al))) by (apply Rmult_le_compat_l; nra).
    assert (u0 * c * al <= u0 * 1.001 * (2.1572 * u0)).
    { apply Rmult_le_compat; [apply Rmult_le_pos; lra|unfold al; apply Rplus_le_le_0_compat; [apply Rmult_le_pos|]; lra|
        apply Rmult_le_compat_l; lra|lra]. }
    assert (2 * e <= nv * (3 * (2 * e))) by (apply third_le; lra).
    assert (nv * (u0 * c * al) <= nv * (u0 * 1.001 * (2.1572 * u0))) by (apply Rmult_le_compat_l; lra).
    nra. }
  assert (Hmu3 : Nmu <= nv * (2 * u0 * 1.001 + 2 * 1.001 * u0 * (2.1572 * u0) + 6 * e)).
  { assert (nv * (2 * u0 * (c * s)) <= nv * (2 * u0 * 1.001)).
    { apply Rmult_le_compat_l; [lra|]. apply Rmult_le_compat_l; lra. }
    lra. }
  assert (Hsig2 : Nsig <= nv * (u0 * (1 + 2 * (c * s) * (c * s))
                   + u0 * (2 * u0 * 1.001 + 2 * 1.001 * u0 * (2.1572 * u0) + 6 * e + 2 * 1.001 * (2.1572 * u0)) + 6 * e)).
  { assert (c * a <= 1.001 * (nv * (2.1572 * u0))) by (apply Rmult_le_compat; nra).
    assert (2 * e <= nv * (3 * (2 * e))) by (apply third_le; lra).
    assert (u0 * (Nmu + 2 * c * a) <= u0 * (nv * (2 * u0 * 1.001 + 2 * 1.001 * u0 * (2.1572 * u0) + 6 * e) + 2 * (1.001 * (nv * (2.1572 * u0)))))
      by (apply Rmult_le_compat_l; lra).
    nra. }
  assert (Hgam2 : Ngam <= nv * (k * (2 * (s * s)) + 2 * 1.001 * (2.15481 * u0) * (2.1572 * u0) + 24 * e)).
  { assert (k * (s * NT) <= k * (s * (nv * (2 * s + 2 * al)))) by (apply Rmult_le_compat_l; [lra|]; apply Rmult_le_compat_l; lra).
    assert (k * s * al <= 2.15481 * u0 * 1.001 * (2.1572 * u0)).
    { apply Rmult_le_compat; [apply Rmult_le_pos; lra|unfold al; apply Rplus_le_le_0_compat; [apply Rmult_le_pos|]; lra| |lra].
      assert (2.15481 * u0 * s <= 2.15481 * u0 * 1.001) by (apply Rmult_le_compat_l; lra). lra. }
    assert (nv * (k * s * al) <= nv * (2.15481 * u0 * 1.001 * (2.1572 * u0))) by (apply Rmult_le_compat_l; lra).
    assert (8 * e <= nv * (3 * (8 * e))) by (apply third_le; lra).
    nra. }
  assert (HL2 : NL <= nv * ((1 + / 1048576) * 2 * al)) by nra.
  assert (Hrho2 : Nrho * (1 - u0) <= u0 * (1 + 1e-5) * nv + 2 * e).
  { assert (u0 * Nr <= u0 * ((1 + 1e-5) * nv)) by (apply Rmult_le_compat_l; lra). lra. }
  assert (Hrho3 : Nrho <= nv * (1.0000101 * u0)).
  { rewrite Hu in *. lra. }
  pose proof (rotate_scalar s c Hs Hc Hq) as Sc.
  assert (K2 : k * (s * s) <= 2.15481 * u0 * (s * s)) by (apply Rmult_le_compat_r; nra).
  set (B := 1.0000101 * u0
    + (u0 * (1 + 2 * (c * s) * (c * s)) + u0 * (2 * u0 * 1.001 + 2 * 1.001 * u0 * (2.1572 * u0) + 6 * e + 2 * 1.001 * (2.1572 * u0)) + 6 * e)
    + (2 * u0 * (c * s) + 2 * 1.001 * u0 * (2.1572 * u0) + 6 * e)
    + (k * (2 * (s * s)) + 2 * 1.001 * (2.15481 * u0) * (2.1572 * u0) + 24 * e)
    + (1 + / 1048576) * 2 * al).
  assert (HB : B <= 6.5e-7).
  { assert (0 <= s * s) by nra. assert (0 <= c * s) by nra.
    unfold B, al. rewrite Hu in *. lra. }
  assert (nv * B <= nv * 6.5e-7) by (apply Rmult_le_compat_l; lra).
  unfold B in *. lra.
Qed.

(* w e + k x e has length at most |q| |e|: w e and k x e are orthogonal,
   and |k x e| <= |k| |e|. *)
Lemma turn_len : forall w k1 k2 k3 e1 e2 e3,
  n3 (w * e1 + (k2 * e3 - k3 * e2)) (w * e2 + (k3 * e1 - k1 * e3)) (w * e3 + (k1 * e2 - k2 * e1))
  <= sqrt (w * w + k1 * k1 + k2 * k2 + k3 * k3) * n3 e1 e2 e3.
Proof.
  intros. unfold n3. rewrite <- sqrt_mult by nra. apply sqrt_le_1_alt.
  pose proof (Rle_0_sqr (k1 * e1 + k2 * e2 + k3 * e3)). unfold Rsqr in *. nra.
Qed.

(* v + T w with T = 2 k x v: v and T are orthogonal, |T| <= 2 |k| |v|. *)
Lemma first_sum_len : forall w x y z vx vy vz,
  n3 (vx + (y * vz - z * vy) * 2 * w) (vy + (z * vx - x * vz) * 2 * w) (vz + (x * vy - y * vx) * 2 * w)
  <= n3 vx vy vz * (1 + 2 * (Rabs w * n3 x y z) * (Rabs w * n3 x y z)).
Proof.
  intros.
  pose proof (n3_pos vx vy vz); pose proof (n3_pos x y z); pose proof (Rabs_pos w).
  assert (Hw2 : Rabs w * Rabs w = w * w) by (rewrite <- Rabs_mult; apply Rabs_right; nra).
  pose proof (cross_len x y z vx vy vz) as HC.
  pose proof (n3_pos (y * vz - z * vy) (z * vx - x * vz) (x * vy - y * vx)).
  assert (HC2 : n3 (y * vz - z * vy) (z * vx - x * vz) (x * vy - y * vx) * n3 (y * vz - z * vy) (z * vx - x * vz) (x * vy - y * vx)
                <= (n3 x y z * n3 vx vy vz) * (n3 x y z * n3 vx vy vz)) by nra.
  rewrite n3_sq in HC2.
  set (C2 := (y * vz - z * vy) * (y * vz - z * vy) + (z * vx - x * vz) * (z * vx - x * vz) + (x * vy - y * vx) * (x * vy - y * vx)) in *.
  set (s := n3 x y z) in *. set (nv := n3 vx vy vz) in *. set (c := Rabs w) in *.
  unfold n3 at 1. rewrite <- (sqrt_square (nv * (1 + 2 * (c * s) * (c * s)))) by (apply Rmult_le_pos; nra).
  apply sqrt_le_1_alt.
  assert (E : (vx + (y * vz - z * vy) * 2 * w) * (vx + (y * vz - z * vy) * 2 * w)
    + (vy + (z * vx - x * vz) * 2 * w) * (vy + (z * vx - x * vz) * 2 * w)
    + (vz + (x * vy - y * vx) * 2 * w) * (vz + (x * vy - y * vx) * 2 * w)
    = nv * nv + 4 * (c * c) * C2) by (unfold nv, C2; rewrite Hw2, n3_sq; ring).
  rewrite E.
  assert (c * c * C2 <= c * c * ((s * nv) * (s * nv))) by (apply Rmult_le_compat_l; nra).
  assert (0 <= (c * s) * (c * s) * (c * s) * (c * s) * (nv * nv)) by
    (repeat apply Rmult_le_pos; nra).
  nra.
Qed.

(* The exact formula's length: |F(v)|^2 = |v|^2 (1 + 4 |k|^2 (|q|^2 - 1))
   + 4 (k . v)^2 (1 - |q|^2), so |F(v)| is |v| up to 4 2^-20 (1 + 2^-20). *)
Lemma formula_len : forall w x y z vx vy vz,
  1 - / 1048576 <= w * w + x * x + y * y + z * z <= 1 + / 1048576 ->
  let Tx := (y * vz - z * vy) * 2 in
  let Ty := (z * vx - x * vz) * 2 in
  let Tz := (x * vy - y * vx) * 2 in
  n3 (vx + Tx * w + (y * Tz - z * Ty)) (vy + Ty * w + (z * Tx - x * Tz)) (vz + Tz * w + (x * Ty - y * Tx))
  <= (1 + 4e-6) * n3 vx vy vz.
Proof.
  intros w x y z vx vy vz HQ Tx Ty Tz.
  pose proof (n3_pos vx vy vz) as Hnv.
  set (n := x * x + y * y + z * z). set (d := x * vx + y * vy + z * vz).
  set (V := vx * vx + vy * vy + vz * vz).
  assert (E : (vx + Tx * w + (y * Tz - z * Ty)) * (vx + Tx * w + (y * Tz - z * Ty))
    + (vy + Ty * w + (z * Tx - x * Tz)) * (vy + Ty * w + (z * Tx - x * Tz))
    + (vz + Tz * w + (x * Ty - y * Tx)) * (vz + Tz * w + (x * Ty - y * Tx))
    = V * (1 + 4 * n * (w * w + n - 1)) + 4 * (d * d) * (1 - (w * w + n)))
    by (unfold Tx, Ty, Tz, V, n, d; ring).
  assert (Hd : d * d <= n * V).
  { unfold d, n, V. pose proof (Rle_0_sqr (x * vy - y * vx)); pose proof (Rle_0_sqr (x * vz - z * vx));
    pose proof (Rle_0_sqr (y * vz - z * vy)). unfold Rsqr in *. nra. }
  assert (Hn : 0 <= n <= 1 + / 1048576) by (unfold n in *; split; nra).
  assert (HV : 0 <= V) by (unfold V; nra).
  assert (Hdd : 0 <= d * d) by nra.
  assert (Hnv2 : n3 vx vy vz * n3 vx vy vz = V) by apply n3_sq.
  unfold n3 at 1. rewrite <- (sqrt_square ((1 + 4e-6) * n3 vx vy vz)) by nra.
  apply sqrt_le_1_alt. rewrite E.
  assert (A1 : V * (4 * n * (w * w + n - 1)) <= V * (4 * (1 + / 1048576) * / 1048576)).
  { apply Rmult_le_compat_l; [lra|]. unfold n in *. nra. }
  assert (A2 : 4 * (d * d) * (1 - (w * w + n)) <= 4 * (n * V) * / 1048576).
  { unfold n in *. nra. }
  assert (A3 : n * V <= (1 + / 1048576) * V) by nra.
  nra.
Qed.

(* A cross product's rounding, relative to |p| |q| (cross_err). *)
Definition kap := u * (1 + u) * 1.1548 + u.

(* The error against the formula, split into the five vectors above, for
   any v with |v|^2 at least 1/9 (the exact power-of-two scalings of v
   overlap, so a v computed by an earlier step needs no rescaling). The
   last sums round the sum before them, within F(v) and the four other
   errors, so at most (1 + 1e-5) |v| long. *)
Lemma rotate_main : forall w x y z vx vy vz : R,
  1 - / 1048576 <= w * w + x * x + y * y + z * z <= 1 + / 1048576 ->
  / 9 <= vx * vx + vy * vy + vz * vz ->
  let tx := rnd (rnd (rnd (y * vz) - rnd (z * vy)) * 2) in
  let ty := rnd (rnd (rnd (z * vx) - rnd (x * vz)) * 2) in
  let tz := rnd (rnd (rnd (x * vy) - rnd (y * vx)) * 2) in
  let sx := rnd (vx + rnd (tx * w)) in
  let sy := rnd (vy + rnd (ty * w)) in
  let sz := rnd (vz + rnd (tz * w)) in
  let gx := rnd (rnd (y * tz) - rnd (z * ty)) in
  let gy := rnd (rnd (z * tx) - rnd (x * tz)) in
  let gz := rnd (rnd (x * ty) - rnd (y * tx)) in
  let Tx := (y * vz - z * vy) * 2 in
  let Ty := (z * vx - x * vz) * 2 in
  let Tz := (x * vy - y * vx) * 2 in
  n3 (rnd (sx + gx) - (vx + Tx * w + (y * Tz - z * Ty)))
     (rnd (sy + gy) - (vy + Ty * w + (z * Tx - x * Tz)))
     (rnd (sz + gz) - (vz + Tz * w + (x * Ty - y * Tx))) <= 6.5e-7 * n3 vx vy vz.
Proof.
  intros w x y z vx vy vz HQ HV tx ty tz sx sy sz gx gy gz Tx Ty Tz.
  pose proof u_pos as Hu; pose proof eta_pos as He.
  assert (Hu1 : u = / 16777216) by reflexivity.
  assert (He1 : 0 <= eta <= / 2 ^ 140) by (unfold eta; simpl; lra).
  assert (Hnv2 : n3 vx vy vz * n3 vx vy vz = vx * vx + vy * vy + vz * vz) by apply n3_sq.
  assert (Hs2 : n3 x y z * n3 x y z = x * x + y * y + z * z) by apply n3_sq.
  pose proof (n3_pos vx vy vz) as Hnv0; pose proof (n3_pos x y z) as Hs0.
  assert (Hnv : / 3 <= n3 vx vy vz) by nra.
  assert (Hw2 : Rabs w * Rabs w = w * w) by (rewrite <- Rabs_mult; apply Rabs_right; nra).
  pose proof (Rabs_pos w) as Hcw.
  assert (Hq : n3 x y z * n3 x y z + Rabs w * Rabs w <= 1 + / 1048576) by lra.
  assert (Hkap : 0 <= kap <= 2.15481 * u) by (unfold kap; rewrite Hu1; lra).
  (* The first cross product: c = k x v, and t = 2 c exactly. *)
  assert (Etx : tx = rnd (rnd (y * vz) - rnd (z * vy)) * 2) by apply rnd_double.
  assert (Ety : ty = rnd (rnd (z * vx) - rnd (x * vz)) * 2) by apply rnd_double.
  assert (Etz : tz = rnd (rnd (x * vy) - rnd (y * vx)) * 2) by apply rnd_double.
  set (ex := rnd (rnd (y * vz) - rnd (z * vy)) - (y * vz - z * vy)) in *.
  set (ey := rnd (rnd (z * vx) - rnd (x * vz)) - (z * vx - x * vz)) in *.
  set (ez := rnd (rnd (x * vy) - rnd (y * vx)) - (x * vy - y * vx)) in *.
  assert (Etx' : tx = 2 * ((y * vz - z * vy) + ex)) by (rewrite Etx; unfold ex; ring).
  assert (Ety' : ty = 2 * ((z * vx - x * vz) + ey)) by (rewrite Ety; unfold ey; ring).
  assert (Etz' : tz = 2 * ((x * vy - y * vx) + ez)) by (rewrite Etz; unfold ez; ring).
  clear Etx Ety Etz.
  assert (Ha : n3 ex ey ez <= kap * (n3 x y z * n3 vx vy vz) + 8 * eta) by apply cross_err.
  pose proof (n3_pos ex ey ez) as Ha0.
  pose proof (cross_len x y z vx vy vz) as HC.
  (* |t| *)
  assert (HNT : n3 tx ty tz <= 2 * (n3 x y z * n3 vx vy vz) + 2 * n3 ex ey ez).
  { rewrite Etx', Ety', Etz', n3_scal, Rabs_right by lra.
    pose proof (n3_triang (y * vz - z * vy) (z * vx - x * vz) (x * vy - y * vx) ex ey ez). lra. }
  (* The products t w. *)
  set (mx := rnd (tx * w)) in *; set (my := rnd (ty * w)) in *; set (mz := rnd (tz * w)) in *.
  assert (Hmu : n3 (mx - tx * w) (my - ty * w) (mz - tz * w) <= u * Rabs w * n3 tx ty tz + 2 * eta).
  { eapply Rle_trans; [apply n3_le; apply rnd_err|].
    eapply Rle_trans; [apply n3_plus_const; lra|].
    rewrite !Rabs_mult.
    replace (u * (Rabs tx * Rabs w)) with ((u * Rabs w) * Rabs tx) by ring.
    replace (u * (Rabs ty * Rabs w)) with ((u * Rabs w) * Rabs ty) by ring.
    replace (u * (Rabs tz * Rabs w)) with ((u * Rabs w) * Rabs tz) by ring.
    rewrite n3_scal, n3_abs, (Rabs_right (u * Rabs w)) by nra. lra. }
  (* The sums v + m. *)
  assert (Hsig : n3 (sx - (vx + mx)) (sy - (vy + my)) (sz - (vz + mz))
                 <= u * (n3 vx vy vz * (1 + 2 * (Rabs w * n3 x y z) * (Rabs w * n3 x y z))
                         + n3 (mx - tx * w) (my - ty * w) (mz - tz * w) + 2 * Rabs w * n3 ex ey ez) + 2 * eta).
  { eapply Rle_trans; [apply n3_le; apply rnd_err|].
    eapply Rle_trans; [apply n3_plus_const; lra|].
    rewrite n3_scal, n3_abs, (Rabs_right u) by lra.
    apply Rplus_le_compat_r. apply Rmult_le_compat_l; [lra|].
    replace (vx + mx) with ((vx + (y * vz - z * vy) * 2 * w) + ((mx - tx * w) + (2 * w) * ex)) by (rewrite Etx'; ring).
    replace (vy + my) with ((vy + (z * vx - x * vz) * 2 * w) + ((my - ty * w) + (2 * w) * ey)) by (rewrite Ety'; ring).
    replace (vz + mz) with ((vz + (x * vy - y * vx) * 2 * w) + ((mz - tz * w) + (2 * w) * ez)) by (rewrite Etz'; ring).
    eapply Rle_trans; [apply n3_triang|].
    pose proof (first_sum_len w x y z vx vy vz).
    pose proof (n3_triang (mx - tx * w) (my - ty * w) (mz - tz * w) ((2 * w) * ex) ((2 * w) * ey) ((2 * w) * ez)) as Tri.
    rewrite n3_scal, Rabs_mult, (Rabs_right 2) in Tri by lra. lra. }
  (* The second cross product, k x t. *)
  assert (Hgam : n3 (gx - (y * tz - z * ty)) (gy - (z * tx - x * tz)) (gz - (x * ty - y * tx))
                 <= kap * (n3 x y z * n3 tx ty tz) + 8 * eta) by apply cross_err.
  (* The error of t, turned by w + k x. *)
  assert (HL : n3 (w * (2 * ex) + (y * (2 * ez) - z * (2 * ey))) (w * (2 * ey) + (z * (2 * ex) - x * (2 * ez)))
                  (w * (2 * ez) + (x * (2 * ey) - y * (2 * ex))) <= (1 + / 1048576) * (2 * n3 ex ey ez)).
  { eapply Rle_trans; [apply turn_len|].
    rewrite n3_scal, (Rabs_right 2) by lra.
    apply Rmult_le_compat_r; [lra|].
    rewrite <- (sqrt_square (1 + / 1048576)) by lra. apply sqrt_le_1_alt. nra. }
  (* The four errors before the last sums, within 6.5e-7 |v| (the five
     with none from the last sums). *)
  set (Sig := n3 (sx - (vx + mx)) (sy - (vy + my)) (sz - (vz + mz))) in *.
  set (Mu := n3 (mx - tx * w) (my - ty * w) (mz - tz * w)) in *.
  set (Gam := n3 (gx - (y * tz - z * ty)) (gy - (z * tx - x * tz)) (gz - (x * ty - y * tx))) in *.
  set (L := n3 (w * (2 * ex) + (y * (2 * ez) - z * (2 * ey))) (w * (2 * ey) + (z * (2 * ex) - x * (2 * ez)))
                (w * (2 * ez) + (x * (2 * ey) - y * (2 * ex)))) in *.
  assert (H4 : 0 + Sig + Mu + Gam + L <= 6.5e-7 * n3 vx vy vz).
  { eapply (rotate_combine u kap eta (n3 x y z) (Rabs w) (n3 vx vy vz) (n3 ex ey ez) (n3 tx ty tz) _ _ _ _ 0 0);
      eauto; lra. }
  (* So the sum the last sums round is at most (1 + 1e-5) |v| long. *)
  assert (HSG : n3 (sx + gx) (sy + gy) (sz + gz) <= (1 + 1e-5) * n3 vx vy vz).
  { pose proof (formula_len w x y z vx vy vz HQ) as HF. cbv zeta in HF.
    assert (Tri4 : forall p1 p2 p3 q1 q2 q3 r1 r2 r3 o1 o2 o3 l1 l2 l3,
      n3 (p1 + (q1 + r1 + o1 + l1)) (p2 + (q2 + r2 + o2 + l2)) (p3 + (q3 + r3 + o3 + l3))
      <= n3 p1 p2 p3 + (n3 q1 q2 q3 + n3 r1 r2 r3 + n3 o1 o2 o3 + n3 l1 l2 l3)).
    { intros. eapply Rle_trans; [apply n3_triang|]. apply Rplus_le_compat_l.
      eapply Rle_trans; [apply n3_triang|]. apply Rplus_le_compat_r.
      eapply Rle_trans; [apply n3_triang|]. apply Rplus_le_compat_r. apply n3_triang. }
    assert (Fx : sx + gx = (vx + (y * vz - z * vy) * 2 * w + (y * ((x * vy - y * vx) * 2) - z * ((z * vx - x * vz) * 2)))
        + ((sx - (vx + mx)) + (mx - tx * w) + (gx - (y * tz - z * ty)) + (w * (2 * ex) + (y * (2 * ez) - z * (2 * ey)))))
      by (rewrite Etx', Ety', Etz'; ring).
    assert (Fy : sy + gy = (vy + (z * vx - x * vz) * 2 * w + (z * ((y * vz - z * vy) * 2) - x * ((x * vy - y * vx) * 2)))
        + ((sy - (vy + my)) + (my - ty * w) + (gy - (z * tx - x * tz)) + (w * (2 * ey) + (z * (2 * ex) - x * (2 * ez)))))
      by (rewrite Etx', Ety', Etz'; ring).
    assert (Fz : sz + gz = (vz + (x * vy - y * vx) * 2 * w + (x * ((z * vx - x * vz) * 2) - y * ((y * vz - z * vy) * 2)))
        + ((sz - (vz + mz)) + (mz - tz * w) + (gz - (x * ty - y * tx)) + (w * (2 * ez) + (x * (2 * ey) - y * (2 * ex)))))
      by (rewrite Etx', Ety', Etz'; ring).
    rewrite Fx, Fy, Fz. eapply Rle_trans; [apply Tri4|]. fold Sig Mu Gam L. lra. }
  (* The last sum. *)
  assert (Hrho : n3 (rnd (sx + gx) - (sx + gx)) (rnd (sy + gy) - (sy + gy)) (rnd (sz + gz) - (sz + gz))
                 <= u * (n3 (sx + gx) (sy + gy) (sz + gz)
                         + n3 (rnd (sx + gx) - (sx + gx)) (rnd (sy + gy) - (sy + gy)) (rnd (sz + gz) - (sz + gz))) + 2 * eta).
  { eapply Rle_trans; [apply n3_le; apply rnd_err|].
    eapply Rle_trans; [apply n3_plus_const; lra|].
    rewrite n3_scal, n3_abs, (Rabs_right u) by lra.
    pose proof (n3_pos (rnd (sx + gx) - (sx + gx)) (rnd (sy + gy) - (sy + gy)) (rnd (sz + gz) - (sz + gz))).
    nra. }
  (* The whole error, as the sum of the five. *)
  assert (Split : forall p1 p2 p3 q1 q2 q3 r1 r2 r3 o1 o2 o3 l1 l2 l3,
    n3 (p1 + q1 + r1 + o1 + l1) (p2 + q2 + r2 + o2 + l2) (p3 + q3 + r3 + o3 + l3)
    <= n3 p1 p2 p3 + n3 q1 q2 q3 + n3 r1 r2 r3 + n3 o1 o2 o3 + n3 l1 l2 l3).
  { intros. eapply Rle_trans; [apply n3_triang|].
    apply Rplus_le_compat_r. eapply Rle_trans; [apply n3_triang|].
    apply Rplus_le_compat_r. eapply Rle_trans; [apply n3_triang|].
    apply Rplus_le_compat_r. apply n3_triang. }
  assert (Ex : rnd (sx + gx) - (vx + Tx * w + (y * Tz - z * Ty)) = (rnd (sx + gx) - (sx + gx)) + (sx - (vx + mx)) + (mx - tx * w)
            + (gx - (y * tz - z * ty)) + (w * (2 * ex) + (y * (2 * ez) - z * (2 * ey))))
    by (unfold Tx, Ty, Tz; rewrite Etx', Ety', Etz'; ring).
  assert (Ey : rnd (sy + gy) - (vy + Ty * w + (z * Tx - x * Tz)) = (rnd (sy + gy) - (sy + gy)) + (sy - (vy + my)) + (my - ty * w)
            + (gy - (z * tx - x * tz)) + (w * (2 * ey) + (z * (2 * ex) - x * (2 * ez))))
    by (unfold Tx, Ty, Tz; rewrite Etx', Ety', Etz'; ring).
  assert (Ez : rnd (sz + gz) - (vz + Tz * w + (x * Ty - y * Tx)) = (rnd (sz + gz) - (sz + gz)) + (sz - (vz + mz)) + (mz - tz * w)
            + (gz - (x * ty - y * tx)) + (w * (2 * ez) + (x * (2 * ey) - y * (2 * ex))))
    by (unfold Tx, Ty, Tz; rewrite Etx', Ety', Etz'; ring).
  rewrite Ex, Ey, Ez. eapply Rle_trans; [apply Split|].
  eapply (rotate_combine u kap eta (n3 x y z) (Rabs w) (n3 vx vy vz) (n3 ex ey ez) (n3 tx ty tz)); eauto; lra.
Qed.

(* The law, on the terms of rotate.g. *)
Theorem rotate_error : forall W X Y Z VX VY VZ : R,
  let w := rnd W in let x := rnd X in let y := rnd Y in let z := rnd Z in
  let vx := rnd VX in let vy := rnd VY in let vz := rnd VZ in
  1 - / 1048576 <= w * w + x * x + y * y + z * z <= 1 + / 1048576 ->
  / 4 <= vx * vx + vy * vy + vz * vz <= 1 ->
  let tx := rnd (rnd (rnd (y * vz) - rnd (z * vy)) * 2) in
  let ty := rnd (rnd (rnd (z * vx) - rnd (x * vz)) * 2) in
  let tz := rnd (rnd (rnd (x * vy) - rnd (y * vx)) * 2) in
  let rx := rnd (rnd (vx + rnd (tx * w)) + rnd (rnd (y * tz) - rnd (z * ty))) in
  let ry := rnd (rnd (vy + rnd (ty * w)) + rnd (rnd (z * tx) - rnd (x * tz))) in
  let rz := rnd (rnd (vz + rnd (tz * w)) + rnd (rnd (x * ty) - rnd (y * tx))) in
  let Tx := (y * vz - z * vy) * 2 in
  let Ty := (z * vx - x * vz) * 2 in
  let Tz := (x * vy - y * vx) * 2 in
  let Rx := vx + Tx * w + (y * Tz - z * Ty) in
  let Ry := vy + Ty * w + (z * Tx - x * Tz) in
  let Rz := vz + Tz * w + (x * Ty - y * Tx) in
  sqrt ((rx - Rx) * (rx - Rx) + (ry - Ry) * (ry - Ry) + (rz - Rz) * (rz - Rz))
    / sqrt (vx * vx + vy * vy + vz * vz) <= 6.5e-7.
Proof.
  intros W X Y Z VX VY VZ w x y z vx vy vz HQ HV tx ty tz rx ry rz Tx Ty Tz Rx Ry Rz.
  change (sqrt ((rx - Rx) * (rx - Rx) + (ry - Ry) * (ry - Ry) + (rz - Rz) * (rz - Rz)))
    with (n3 (rx - Rx) (ry - Ry) (rz - Rz)).
  change (sqrt (vx * vx + vy * vy + vz * vz)) with (n3 vx vy vz).
  pose proof (n3_pos vx vy vz) as Hnv0.
  assert (Hnv2 : n3 vx vy vz * n3 vx vy vz = vx * vx + vy * vy + vz * vz) by apply n3_sq.
  assert (Hnv : 0 < n3 vx vy vz) by nra.
  assert (HV9 : / 9 <= vx * vx + vy * vy + vz * vz) by lra.
  pose proof (rotate_main w x y z vx vy vz HQ HV9) as Main.
  apply Rmult_le_reg_r with (n3 vx vy vz); [lra|].
  unfold Rdiv. rewrite Rmult_assoc, Rinv_l by lra. rewrite Rmult_1_r. exact Main.
Qed.
