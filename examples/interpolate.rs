//! Prints the interpolation of two keyframes the notes' way, as a table:
//! the origin moves on a straight line at constant speed, and the frame turns
//! about one fixed axis at constant angular velocity, the short way.
//!
//! Run with `cargo run --example interpolate`.

use core::f32::consts::PI;
use rigtform::{Cvec3, Cvec4, Quat, RigTForm};

fn main() {
    // Keyframe 0: at the origin, turned 30 degrees about z.
    let k0 = RigTForm::new(Cvec3::new(0.0, 0.0, 0.0), Quat::from_rotation_z(PI / 6.0));
    // Keyframe 1: moved, and turned a further 200 degrees about the tilted
    // axis (1, 1, 0). That is 160 degrees the other way round: the transition
    // quaternion has w = cos(100 degrees) < 0, and slerp's conditional
    // negation must take the short way.
    let r1 = Quat::from_axis_angle(Cvec3::new(1.0, 1.0, 0.0), 200f32.to_radians()) * k0.r;
    let k1 = RigTForm::new(Cvec3::new(4.0, 2.0, -1.0), r1);

    let total = k0.r.angle_to(k1.r);
    let (axis, _) = (k1.r * k0.r.inv()).to_axis_angle();
    println!("keyframe 0: t = {}, r = {}", fmt_vec(k0.t), fmt_quat(k0.r));
    println!("keyframe 1: t = {}, r = {}", fmt_vec(k1.t), fmt_quat(k1.r));
    println!(
        "rotation between them: {:.3} degrees about {} (the short way; the long way is {:.3})",
        total.to_degrees(),
        fmt_vec(axis),
        360.0 - total.to_degrees()
    );
    println!();
    println!(
        "{:>6}  {:>26}  {:>38}  {:>12}  {:>13}  {:>11}",
        "alpha",
        "translation t",
        "rotation r (w, x, y, z)",
        "turned (deg)",
        "deg per alpha",
        "|r| - 1"
    );
    let tip = Cvec4::from_point(Cvec3::new(1.0, 0.0, 0.0));
    let mut tips = Vec::new();
    for step in -2..=12 {
        let alpha = step as f32 / 10.0;
        let frame = k0.interpolate(k1, alpha);
        let turned = k0.r.angle_to(frame.r);
        let per_alpha = if alpha != 0.0 {
            format!("{:13.4}", turned.to_degrees() / alpha.abs())
        } else {
            format!("{:>13}", "-")
        };
        println!(
            "{:>6.2}  {:>26}  {:>38}  {:>12.4}  {}  {:>11.2e}",
            alpha,
            fmt_vec(frame.t),
            fmt_quat(frame.r),
            turned.to_degrees(),
            per_alpha,
            frame.r.norm() - 1.0
        );
        tips.push((alpha, frame * tip));
    }
    println!();
    println!("(alpha outside [0, 1] extrapolates; 'turned' folds back past 180 degrees)");
    println!();
    println!("The point (1, 0, 0) of the object, carried by the interpolated frames:");
    for (alpha, p) in tips.iter().filter(|(a, _)| (0.0..=1.0).contains(a)) {
        println!("  alpha {alpha:>4.1}: {}", fmt_vec(p.xyz()));
    }
}

fn fmt_vec(v: Cvec3) -> String {
    format!("({:7.3}, {:7.3}, {:7.3})", v.x, v.y, v.z)
}

fn fmt_quat(q: Quat) -> String {
    format!("({:7.4}, {:7.4}, {:7.4}, {:7.4})", q.w, q.x, q.y, q.z)
}
