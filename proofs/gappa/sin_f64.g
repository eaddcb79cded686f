# slerp's f64 sine (src/quat/slerp/kernels_f64.rs, sin_to_quarter_turn):
# s = x x; p = (S0 + s S1) + (s s) (S2 + s S3); y = x + (x s) p.
# f64, round to nearest even, every operation rounded.
#
# Sin stands for sin(x). The hypothesis on it is the approximation error
# of the exact polynomial Y, which Sollya's supnorm bounds
# (sin_f64.sollya: 6.0554e-9, rounded up here to 6.056e-9).
#
# Proven: the evaluation is within 5.01e-16 of the exact polynomial
# (relative), and the result within 6.057e-9 of sin(x) (relative), for
# every f64 x in [9.29e-10, 1.5708] (every f32 from 2^-30 to pi/2).
#
#! sollya sin_f64.sollya 6.056e-9
#! bound SIN_F64_MAX_REL_ERROR 6.057e-9 relative error of sin_to_quarter_turn against sin
@rnd = float<ieee_64, ne>;

x = rnd(X);

s rnd= x * x;
p rnd= (-0x1.55554bc836424p-3 + s * 0x1.110ed38056595p-7) + (s * s) * (-0x1.9f6ffeed2e992p-13 + s * 0x1.5dbdf10fb3356p-19);
m rnd= x * s;
q rnd= m * p;
y rnd= x + q;

S = x * x;
P = (-0x1.55554bc836424p-3 + S * 0x1.110ed38056595p-7) + (S * S) * (-0x1.9f6ffeed2e992p-13 + S * 0x1.5dbdf10fb3356p-19);
M = x * S;
T = S * P;
Q = M * P;
Y = x + Q;

{ x in [9.29e-10, 1.5708] /\ (Y - Sin) / Sin in [-6.056e-9, 6.056e-9]
  ->
  (y - Y) / Y in [-5.01e-16, 5.01e-16] /\
  (y - Sin) / Sin in [-6.057e-9, 6.057e-9]
}

(y - Sin) / Sin -> (y - Y) / Y + (Y - Sin) / Sin + ((y - Y) / Y) * ((Y - Sin) / Sin);
(y - Y) / Y -> (y - (x + q)) / (x + q) * (1 + (q - Q) / Y) + (q - Q) / Y;
(q - Q) / Y -> ((q - Q) / Q) * (T / (1 + T));
Y -> x * (1 + T);
x + q -> Y * (1 + (q - Q) / Y);
