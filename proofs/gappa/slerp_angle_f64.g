# The angle of slerp's f64 evaluation (src/quat/slerp/in_f64.rs: Pair::checked,
# Pair::near, Pair::far, Pair::quotient) against the angle between its
# inputs: from f32 a and b (b with the sign that makes a . b >= 0, the
# notes' cn, which the code takes exactly as |a . b|), the squared norms
# n2, on2 and the dot product in f64, each product of two f32 exact and
# the sums rounded in the code's order ((x x' + z z') + (y y' + w w')),
# sum = n2 + on2, near = sum - 2 dot, far = sum + 2 dot, t2 = near / far.
# f64, round to nearest even.
#
# The arc of arc_f64.g and the coefficients of coefficient_f64.g and
# coefficient_rest_f64.g are those of the angle phi with tan^2(phi / 2) =
# t2, whose cosine is Cos = (1 - t2) / (1 + t2). For the exact values of
# the same f32 inputs, (1 - T) / (1 + T) with T = Near / Far is
# 2 (a . b) / (|a|^2 + |b|^2) (Mean), the cosine of the angle between a
# and b up to the inputs' norms, which proofs/coq/slerp_norm_f64.v takes
# exactly.
#
# Domain: a and b within 2^-20 of unit norm (squared; every result of
# normalize, whose norm proofs/coq/normalize_norm.v bounds within 2.391e-7
# of 1), components in [-1, 1], a . b >= 0.
#
# Proven: t2 within 2e-15 of T (absolute: near cancels as the angle
# shrinks, so its error is not relative to it), and Cos within 4e-15 of
# Mean. proofs/coq/slerp_norm_f64.v takes this goal as its hypothesis on
# the angle.
#
# The side conditions' factorizations (`#! side`): Far, far Far and
# |a|^2 + |b|^2 as Gappa expands them, where interval arithmetic on the
# expanded terms loses that they are near 2 and 4.
#
#! law - Cos - Mean in [-4e-15, 4e-15] the cosine of slerp's f64 angle against 2 (a . b) / (|a|^2 + |b|^2), for a, b within 2^-20 of unit norm
#! side 2 * (ax) * (bx) * (far) + ((bw) * (bw)) * (far) + ((aw) * (aw)) * (far) + ((bx) * (bx)) * (far) + 2 * (ay) * (by) * (far) + ((ax) * (ax)) * (far) + ((by) * (by)) * (far) + 2 * (az) * (bz) * (far) + ((ay) * (ay)) * (far) + ((bz) * (bz)) * (far) + 2 * (aw) * (bw) * (far) + ((az) * (az)) * (far) -> Far * far;
#! side 2 * (ay) * (by) + ((aw) * (aw)) + ((ax) * (ax)) + 2 * (az) * (bz) + ((ay) * (ay)) + ((az) * (az)) + ((bw) * (bw)) + ((bx) * (bx)) + ((by) * (by)) + ((bz) * (bz)) + 2 * (aw) * (bw) + 2 * (ax) * (bx) -> Far;
#! side 2 * ((ax) * (ax)) * (t2) + 2 * ((by) * (by)) * (t2) + 2 * ((ay) * (ay)) * (t2) + 2 * ((bz) * (bz)) * (t2) + 2 * ((aw) * (aw)) + 2 * ((az) * (az)) * (t2) + 2 * ((ax) * (ax)) + 2 * ((ay) * (ay)) + 2 * ((az) * (az)) + 2 * ((bw) * (bw)) + 2 * ((bx) * (bx)) + 2 * ((bw) * (bw)) * (t2) + 2 * ((by) * (by)) + 2 * ((bz) * (bz)) + 2 * ((aw) * (aw)) * (t2) + 2 * ((bx) * (bx)) * (t2) -> (Far + Near) * (1 + t2);
#! side ((az) * (az)) + ((ay) * (ay)) + ((bz) * (bz)) + ((ax) * (ax)) + ((by) * (by)) + ((aw) * (aw)) + ((bx) * (bx)) + ((bw) * (bw)) -> QA + QB;
@rnd = float<ieee_64, ne>;
@f32 = float<ieee_32, ne>;

aw = f32(Aw); ax = f32(Ax); ay = f32(Ay); az = f32(Az);
bw = f32(Bw); bx = f32(Bx); by = f32(By); bz = f32(Bz);

n2 rnd= (ax * ax + az * az) + (ay * ay + aw * aw);
on2 rnd= (bx * bx + bz * bz) + (by * by + bw * bw);
dot rnd= (ax * bx + az * bz) + (ay * by + aw * bw);
sum rnd= n2 + on2;
near rnd= sum - 2 * dot;
far rnd= sum + 2 * dot;
t2 rnd= near / far;

QA = (ax * ax + az * az) + (ay * ay + aw * aw);
QB = (bx * bx + bz * bz) + (by * by + bw * bw);
Dot = (ax * bx + az * bz) + (ay * by + aw * bw);
Near = QA + QB - 2 * Dot;
Far = QA + QB + 2 * Dot;
T = Near / Far;
Cos = (1 - t2) / (1 + t2);
Mean = 2 * Dot / (QA + QB);

{ QA in [0.99999904632568359375, 1.00000095367431640625] /\
  QB in [0.99999904632568359375, 1.00000095367431640625] /\
  Dot in [0, 1.00000095367431640625] /\
  |aw| <= 1 /\ |ax| <= 1 /\ |ay| <= 1 /\ |az| <= 1 /\
  |bw| <= 1 /\ |bx| <= 1 /\ |by| <= 1 /\ |bz| <= 1
  ->
  t2 - T in [-2e-15, 2e-15] /\ Cos - Mean in [-4e-15, 4e-15]
}

t2 - T -> (t2 - near / far) + (near - Near) / far - Near * (far - Far) / (far * Far);
Cos - Mean -> -2 * (t2 - T) / ((1 + t2) * (1 + T));
