# q.inv().inv() (src/quat, Quat::inv: [w, -x, -y, -z]): negation only,
# exact in every format (a sign flip), so the inverse of the inverse is q
# itself, for every f32 q; w is returned as it is (the correspondence test compares the bits, NaN
# payloads and signed zeros included).
#
# Proven: each component of q.inv().inv() minus the same component of q
# is exactly 0, for every finite f32 component.
#
#! law - iix - x in [0, 0] q.inv().inv() = q exactly (each vector component; w is not touched)
@rnd = float<ieee_32, ne>;

x = rnd(X); y = rnd(Y); z = rnd(Z);

ix rnd= -x; iy rnd= -y; iz rnd= -z;
iix rnd= -ix; iiy rnd= -iy; iiz rnd= -iz;

{ |x| <= 0x1.fffffep127 /\ |y| <= 0x1.fffffep127 /\ |z| <= 0x1.fffffep127
  ->
  iix - x in [0, 0] /\ iiy - y in [0, 0] /\ iiz - z in [0, 0]
}

# Each negation is exact: its rounding error is 0.
iix - x -> (iix - (-ix)) - (ix - (-x));
iiy - y -> (iiy - (-iy)) - (iy - (-y));
iiz - z -> (iiz - (-iz)) - (iz - (-z));
