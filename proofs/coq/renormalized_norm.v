(* The norm of a.mul_renormalized(b) (src/quat.rs): p = a * b (the Hamilton
   product, src/quat/scalar.rs and sse2.rs), n2 = p.norm_squared()
   (Quat::dot: w w + x x + y y + z z, left to right), s = (3 - n2) * 0.5,
   and each component of p times s, every operation rounded to f32.

   Proven (renormalized_norm): for a and b with |a|^2 and |b|^2 within
   2^-20 of 1 (no hypothesis on their components), the result's norm is
   within 1.947e-7 of 1, whatever the inputs' norms in that domain. As
   an invariant: every a within 1.947e-7 of unit norm has |a|^2 within
   2^-20 of 1 (even with a component 1 + 2^-23, the others near 0), and
   so has every b within 2.391e-7 (every result of normalize,
   normalize_norm.v), so a chain of products started within 1.947e-7 of
   unit norm (the identity included) stays within it for every length.

   The steps: mul_norm.v puts |p| within 2.84e-7 of |a| |b|, relative,
   so |p|^2 lies within 2^-18 of 1. The certificate of renormalize.g
   bounds |p| s - 1 by 1.35e-7 on that domain (the Newton step takes
   |p|'s distance from 1 away to second order, and what is left is the
   step's own rounding), given the rounded squares' sum within 2^-24 of
   |p|^2, relative, which is proven here (each square's rounding is
   relative, and they are non-negative). Each component's last rounding
   c * s is relative too, so the result's length is within 2^-24 of
   |p| s (norm4_upper, norm4_lower, as in normalize_norm.v). *)
(*! bound RENORMALIZED_CHAIN_NORM_ERROR renormalized_norm <= 1.947e-7 | |a.mul_renormalized(b)| - 1 | for a, b with squared norms within 2^-20 of 1: one step, and so every chain started within it *)
Require Import Reals Psatz.
Require Import Flocq.Core.Core.
Require Import Gappa.Gappa_library.
Require Import Laws.Common.
Require Laws.renormalize.
Require Laws.mul_norm.

Open Scope R_scope.

(* The certificates write the code's 0.5 in decimal. *)
Lemma half : float10R (Float10 5 (-1)) = / 2.
Proof. unfold float10R, F2R. simpl. unfold Z.pow_pos. simpl. lra. Qed.

(* The scale against the product's norm: the certificate of renormalize.g,
   its hypotheses and hints proven. *)
Lemma renormalize_scale : forall PW PX PY PZ : R,
  let p0 := rnd PW in
  let p1 := rnd PX in
  let p2 := rnd PY in
  let p3 := rnd PZ in
  1 - / 262144 <= p0 * p0 + p1 * p1 + p2 * p2 + p3 * p3 <= 1 + / 262144 ->
  let n2 := rnd (rnd (rnd (rnd (p0 * p0) + rnd (p1 * p1)) + rnd (p2 * p2)) + rnd (p3 * p3)) in
  let s := rnd (rnd (3 - n2) * / 2) in
  -1.35e-7 <= sqrt (p0 * p0 + p1 * p1 + p2 * p2 + p3 * p3) * s - 1 <= 1.35e-7.
Proof.
  intros PW PX PY PZ p0 p1 p2 p3 HP n2 s.
  set (P := p0 * p0 + p1 * p1 + p2 * p2 + p3 * p3) in *.
  assert (HP0 : 0 < P) by lra.
  assert (HQ : sqrt P * sqrt P = P) by (apply sqrt_sqrt; lra).
  (* The rounded squares, in [0, 2]. *)
  assert (Sq : forall t, 0 <= t * t <= 2 -> 0 <= rnd (t * t) <= 2).
  { intros t Ht. replace 2 with (bpow radix2 1) by (simpl; lra).
    apply rnd_square_le; [lia | simpl; lra]. }
  assert (H0 : 0 <= p0 * p0 <= 2) by (split; [nra|unfold P in HP; nra]).
  assert (H1 : 0 <= p1 * p1 <= 2) by (split; [nra|unfold P in HP; nra]).
  assert (H2 : 0 <= p2 * p2 <= 2) by (split; [nra|unfold P in HP; nra]).
  assert (H3 : 0 <= p3 * p3 <= 2) by (split; [nra|unfold P in HP; nra]).
  (* Their sum is within 2^-24 P + 4 2^-150 of P. *)
  set (T := rnd (p0 * p0) + rnd (p1 * p1) + rnd (p2 * p2) + rnd (p3 * p3)).
  assert (HT : Rabs (T - P) <= u * P + 4 * eta) by (unfold T, P; apply squares_sum_err).
  assert (HTP : -(u + 8 * eta) <= (T - P) / P <= u + 8 * eta).
  { apply abs_split in HT. pose proof eta_pos. pose proof u_pos.
    set (r := (T - P) / P).
    assert (E : T - P = r * P) by (unfold r; field; lra).
    rewrite E in HT.
    assert (4 * eta <= 8 * eta * P) by nra.
    split; apply (Rmult_le_reg_r P); lra. }
  assert (Heta : 8 * eta <= / 2 ^ 48) by (unfold eta; simpl; lra).
  (* The certificate: |p| s - 1 within 1.35e-7. *)
  apply Classical_Prop.NNPP; intro Hn.
  refine (Laws.renormalize.l1 PW PX PY PZ _ _ _ _ _ _ _).
  - ring.
  - ring.
  - field. unfold P, p0, p1, p2, p3 in HP0. lra.
  - rewrite half. unfold Float1. unfold P, p0, p1, p2, p3 in HQ.
    set (Q := sqrt (rnd PW * rnd PW + rnd PX * rnd PX + rnd PY * rnd PY + rnd PZ * rnd PZ)) in *.
    rewrite <- HQ. field.
  - ring.
  - ring.
  - unfold Laws.renormalize.s1, Laws.renormalize.s2, Laws.renormalize.s3,
      Laws.renormalize.s4, Laws.renormalize.s5, Laws.renormalize.s6,
      Laws.renormalize.s7.
    unfold T in HTP. unfold u in HTP.
    pose proof (Sq p0 H0); pose proof (Sq p1 H1); pose proof (Sq p2 H2); pose proof (Sq p3 H3).
    unfold P, p0, p1, p2, p3 in *. gappa_nums. repeat split; try lra.
    intro Hg. apply Hn. unfold s, n2. rewrite half in Hg.
    change (IPR 3) with 3 in Hg. change (IPR 1) with 1 in Hg. lra.
Qed.

(* The step on any f32 p with |p|^2 within 2^-18 of 1: the result's length
   is within 2^-24 of |p| s (each c * s rounded, relative). *)
Lemma renormalize_norm : forall PW PX PY PZ : R,
  let p0 := rnd PW in
  let p1 := rnd PX in
  let p2 := rnd PY in
  let p3 := rnd PZ in
  1 - / 262144 <= p0 * p0 + p1 * p1 + p2 * p2 + p3 * p3 <= 1 + / 262144 ->
  let n2 := rnd (rnd (rnd (rnd (p0 * p0) + rnd (p1 * p1)) + rnd (p2 * p2)) + rnd (p3 * p3)) in
  let s := rnd (rnd (3 - n2) * / 2) in
  let r0 := rnd (p0 * s) in
  let r1 := rnd (p1 * s) in
  let r2 := rnd (p2 * s) in
  let r3 := rnd (p3 * s) in
  Rabs (sqrt (r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3) - 1) <= 1.947e-7.
Proof.
  intros PW PX PY PZ p0 p1 p2 p3 HP n2 s r0 r1 r2 r3.
  assert (Hs : -1.35e-7 <= sqrt (p0 * p0 + p1 * p1 + p2 * p2 + p3 * p3) * s - 1 <= 1.35e-7)
    by exact (renormalize_scale PW PX PY PZ HP).
  clearbody s.
  set (P := p0 * p0 + p1 * p1 + p2 * p2 + p3 * p3) in *.
  set (X := sqrt P * s) in Hs.
  assert (HP0 : 0 < sqrt P) by (apply sqrt_lt_R0; lra).
  assert (Hs0 : 0 < s).
  { destruct (Rle_or_lt s 0) as [H|H]; [|exact H].
    assert (sqrt P * s <= 0) by nra. unfold X in Hs. lra. }
  (* The exact scaled product's length is |p| s. *)
  assert (HQ : sqrt (p0 * s * (p0 * s) + p1 * s * (p1 * s) + p2 * s * (p2 * s) + p3 * s * (p3 * s)) = X).
  { replace (p0 * s * (p0 * s) + p1 * s * (p1 * s) + p2 * s * (p2 * s) + p3 * s * (p3 * s))
      with (s * s * P) by (unfold P; ring).
    rewrite sqrt_mult by (try apply Rle_0_sqr; lra).
    rewrite sqrt_square by lra. unfold X. ring. }
  (* Each component's rounding. *)
  assert (Hu : 0 <= u <= 1) by (unfold u; lra).
  pose proof eta_pos as He.
  pose proof (rnd_err (p0 * s)) as E0; pose proof (rnd_err (p1 * s)) as E1;
  pose proof (rnd_err (p2 * s)) as E2; pose proof (rnd_err (p3 * s)) as E3.
  pose proof (norm4_upper _ _ _ _ _ _ _ _ u eta (proj1 Hu) (Rlt_le _ _ He) E0 E1 E2 E3) as Up.
  pose proof (norm4_lower _ _ _ _ _ _ _ _ u eta Hu (Rlt_le _ _ He) E0 E1 E2 E3) as Lo.
  simpl in Lo. rewrite HQ in Up, Lo. fold r0 r1 r2 r3 in Up, Lo.
  assert (Heta : eta <= / 2 ^ 100) by (unfold eta; simpl; lra).
  apply abs_join. split.
  - (* The lower side, through the squares. *)
    set (L := (1 - u) * X).
    assert (HL : 1 - 1.947e-7 + 5e-11 <= L) by (unfold L, u; nra).
    assert (Hsq : (1 - 1.947e-7 + 5e-11) * (1 - 1.947e-7 + 5e-11) <= L * L).
    { assert (0 <= (L - (1 - 1.947e-7 + 5e-11)) * (L + (1 - 1.947e-7 + 5e-11)))
        by (apply Rmult_le_pos; lra).
      nra. }
    assert (4 * eta * X <= 8 * eta) by nra.
    assert (Lsq : L * L = (1 - u) * (1 - u) * (X * X)) by (unfold L; ring).
    assert (Hc2 : (1 - 1.947e-7) * (1 - 1.947e-7) <= r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3) by lra.
    assert (Hsr : sqrt ((1 - 1.947e-7) * (1 - 1.947e-7)) <= sqrt (r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3))
      by (apply sqrt_le_1_alt; exact Hc2).
    rewrite sqrt_square in Hsr by lra.
    lra.
  - (* The upper side. *)
    assert (u * X <= u * (1 + 1.35e-7)) by (apply Rmult_le_compat_l; unfold u; lra).
    unfold u in *. lra.
Qed.

(* The law: a and b with squared norms within 2^-20 of 1, p = a * b as the code rounds it
   (mul_norm.v's statement), then the scale and the four c * s. *)
Theorem renormalized_norm : forall AW AX AY AZ BW BX BY BZ : R,
  let a0 := rnd AW in let a1 := rnd AX in let a2 := rnd AY in let a3 := rnd AZ in
  let b0 := rnd BW in let b1 := rnd BX in let b2 := rnd BY in let b3 := rnd BZ in
  1 - / 1048576 <= a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3 <= 1 + / 1048576 ->
  1 - / 1048576 <= b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3 <= 1 + / 1048576 ->
  let p0 := rnd (rnd (rnd (rnd (a0 * b0) - rnd (a1 * b1)) - rnd (a2 * b2)) - rnd (a3 * b3)) in
  let p1 := rnd (rnd (rnd (rnd (a0 * b1) + rnd (a1 * b0)) + rnd (a2 * b3)) - rnd (a3 * b2)) in
  let p2 := rnd (rnd (rnd (rnd (a0 * b2) - rnd (a1 * b3)) + rnd (a2 * b0)) + rnd (a3 * b1)) in
  let p3 := rnd (rnd (rnd (rnd (a0 * b3) + rnd (a1 * b2)) - rnd (a2 * b1)) + rnd (a3 * b0)) in
  let n2 := rnd (rnd (rnd (rnd (p0 * p0) + rnd (p1 * p1)) + rnd (p2 * p2)) + rnd (p3 * p3)) in
  let s := rnd (rnd (3 - n2) * / 2) in
  let r0 := rnd (p0 * s) in
  let r1 := rnd (p1 * s) in
  let r2 := rnd (p2 * s) in
  let r3 := rnd (p3 * s) in
  Rabs (sqrt (r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3) - 1) <= 1.947e-7.
Proof.
  intros AW AX AY AZ BW BX BY BZ a0 a1 a2 a3 b0 b1 b2 b3 HA HB
    p0 p1 p2 p3 n2 s r0 r1 r2 r3.
  pose proof (Laws.mul_norm.mul_norm AW AX AY AZ BW BX BY BZ HA HB) as M.
  fold a0 a1 a2 a3 b0 b1 b2 b3 p0 p1 p2 p3 in M.
  (* |p|^2 within 2^-18 of 1: |p| = m |a| |b|, m within 2.84e-7 of 1. *)
  set (A := a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3) in *.
  set (B := b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3) in *.
  set (P := p0 * p0 + p1 * p1 + p2 * p2 + p3 * p3) in *.
  assert (HA0 : 0 < sqrt A) by (apply sqrt_lt_R0; lra).
  assert (HB0 : 0 < sqrt B) by (apply sqrt_lt_R0; lra).
  assert (M2 : Rabs (sqrt P / (sqrt A * sqrt B) - 1) <= 2.84e-7) by exact M.
  clear M. set (m := sqrt P / (sqrt A * sqrt B)) in M2.
  apply abs_split in M2.
  assert (Hm : sqrt P = m * (sqrt A * sqrt B))
    by (unfold m; field; split; apply Rgt_not_eq; assumption).
  assert (HPm : P = m * m * (A * B)).
  { rewrite <- (sqrt_sqrt P) by (unfold P; nra).
    rewrite Hm.
    replace (m * (sqrt A * sqrt B) * (m * (sqrt A * sqrt B)))
      with (m * m * ((sqrt A * sqrt A) * (sqrt B * sqrt B))) by ring.
    rewrite !sqrt_sqrt by lra. reflexivity. }
  assert (HP : 1 - / 262144 <= P <= 1 + / 262144).
  { assert (Hm2 : (1 - 2.84e-7) * (1 - 2.84e-7) <= m * m <= (1 + 2.84e-7) * (1 + 2.84e-7))
      by (split; apply Rmult_le_compat; lra).
    assert (HAB2 : (1 - / 1048576) * (1 - / 1048576) <= A * B <= (1 + / 1048576) * (1 + / 1048576))
      by (split; apply Rmult_le_compat; lra).
    assert (Lo : (1 - 2.84e-7) * (1 - 2.84e-7) * ((1 - / 1048576) * (1 - / 1048576)) <= m * m * (A * B))
      by (apply Rmult_le_compat; lra).
    assert (Up : m * m * (A * B) <= (1 + 2.84e-7) * (1 + 2.84e-7) * ((1 + / 1048576) * (1 + / 1048576)))
      by (apply Rmult_le_compat; nra).
    rewrite HPm. split; lra. }
  exact (renormalize_norm _ _ _ _ HP).
Qed.
