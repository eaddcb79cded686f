//! From one rotation towards another, besides [`Quat::slerp`]:
//! [`Quat::slerp_long`], along the arc the signs give, and
//! [`Quat::rotate_towards`], a step of at most a given angle (glam's names
//! and meanings).

use super::Quat;

impl Quat {
    /// Spherical linear interpolation along the arc from `self` to `other`
    /// as their signs give it, without taking the short way: the notes'
    /// slerp without `cn`, `pow(other * self.inv(), alpha) * self`. Where
    /// `self.dot(other) >= 0` this is [`slerp`](Self::slerp); where it is
    /// negative the result turns the long way, through more than pi, which
    /// keeps the direction of turning that keyframes' signs encode (glam's
    /// `slerp_long`).
    ///
    /// # Preconditions
    ///
    /// Unit quaternions. For `other = -self` (the same rotation, a whole
    /// turn apart) the turn is about the x axis, the axis
    /// [`pow`](Self::pow) gives a pure real quaternion with `w < 0`. NaN or
    /// infinite input gives [`Quat::NAN`].
    ///
    /// # Accuracy
    ///
    /// That of two products and one [`pow`](Self::pow), whose error
    /// ([`accuracy::POW_MAX_ANGLE_ERROR`](crate::accuracy::POW_MAX_ANGLE_ERROR))
    /// is per radian turned, and the long way turns up to 2 pi. No bound of
    /// its own is measured: the tests hold it to glam's `slerp_long` within
    /// 2e-5 rad, and its turn to `alpha` of the long angle within 2e-5 rad,
    /// on 10,000 draws.
    ///
    /// ```
    /// use core::f32::consts::PI;
    /// use rigtform::Quat;
    /// let (a, b) = (Quat::IDENTITY, Quat::from_rotation_z(PI / 2.0));
    /// // The same rotation b, with the other sign: the long way round.
    /// let half = a.slerp_long(-b, 0.5);
    /// assert!(half.angle_to(Quat::from_rotation_z(-3.0 * PI / 4.0)) < 1e-6);
    /// // With b's own sign, the short way, as slerp.
    /// assert!(a.slerp_long(b, 0.5).angle_to(a.slerp(b, 0.5)) < 1e-6);
    /// ```
    #[must_use]
    pub fn slerp_long(self, other: Self, alpha: f32) -> Self {
        (other * self.inv()).pow(alpha) * self
    }

    /// `self` turned towards `other` by at most `max_angle` radians, along
    /// the short way, never past `other`: `other`'s rotation once it is
    /// within reach. A negative `max_angle` turns away from `other`, by at
    /// most the angle that makes it the opposite rotation (pi away).
    ///
    /// # Preconditions
    ///
    /// Unit quaternions. NaN or infinite input or `max_angle` gives
    /// [`Quat::NAN`]. `max_angle = 0` gives `self` exactly.
    ///
    /// # Accuracy
    ///
    /// The angle turned is `max_angle` (or the whole angle between them, or
    /// what is left to pi when turning away) up to the errors of
    /// [`angle_to`](Self::angle_to) and [`slerp`](Self::slerp): within
    /// 1e-5 rad, and within 2e-5 rad of glam's `rotate_towards`, on 10,000
    /// draws in the tests (no bound of its own is measured).
    ///
    /// ```
    /// use rigtform::Quat;
    /// let (a, b) = (Quat::IDENTITY, Quat::from_rotation_y(1.0));
    /// let step = a.rotate_towards(b, 0.25);
    /// assert!(step.angle_to(Quat::from_rotation_y(0.25)) < 1e-6);
    /// assert!(a.rotate_towards(b, 5.0).angle_to(b) < 1e-6); // no overshoot
    /// ```
    #[must_use]
    pub fn rotate_towards(self, other: Self, max_angle: f32) -> Self {
        if !max_angle.is_finite() {
            return Self::NAN;
        }
        if max_angle == 0.0 {
            return if self.is_finite() && other.is_finite() {
                self
            } else {
                Self::NAN
            };
        }
        let angle = self.angle_to(other);
        if !angle.is_finite() {
            return Self::NAN;
        }
        // Turning away: the farthest is the rotation pi from `other`.
        let reach = if max_angle > 0.0 {
            angle
        } else {
            core::f32::consts::PI - angle
        };
        if max_angle.abs() >= reach {
            return if max_angle > 0.0 {
                other
            } else if angle > 0.0 {
                self.slerp(other, -reach / angle)
            } else {
                // `other` itself: any axis leads pi away; take slerp's own
                // choice for the opposite of a point, a half turn about x.
                Self::from_rotation_x(core::f32::consts::PI) * other
            };
        }
        if angle == 0.0 {
            // Turning away from `other` by less than pi, from `other`
            // itself: about x, as above.
            return Self::from_rotation_x(-max_angle) * self;
        }
        self.slerp(other, max_angle / angle)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f32::consts::PI;
    use rand::{Rng, SeedableRng};

    use crate::test_draws::unit_quat as random_unit;

    /// glam's `slerp_long` on the same pairs, of either sign: the arc the
    /// signs give, the long way where the dot product is negative.
    #[test]
    fn slerp_long_follows_the_signs_as_glam_does() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(27);
        let mut long_ways = 0;
        for _ in 0..10_000 {
            let (a, b) = (random_unit(&mut rng), random_unit(&mut rng));
            let b = if rng.random() { b } else { -b };
            if a.dot(b).abs() > 1.0 - 1e-3 {
                continue;
            }
            let alpha = rng.random_range(-0.5..1.5);
            let ours = a.slerp_long(b, alpha);
            let theirs: Quat = glam::Quat::from_array(a.to_array())
                .slerp_long(glam::Quat::from_array(b.to_array()), alpha)
                .to_array()
                .into();
            assert!((ours.norm() - 1.0).abs() < 1e-6);
            assert!(ours.angle_to(theirs) < 2e-5, "{a:?} {b:?} {alpha}");
            if a.dot(b) < 0.0 && (0.0..=1.0).contains(&alpha) {
                long_ways += 1;
                // Through more than pi in all: alpha of it so far.
                let whole = 2.0 * PI - a.angle_to(b);
                let turned = a.angle_to(ours);
                let want = (alpha * whole).min(2.0 * PI - alpha * whole);
                assert!((turned - want).abs() < 2e-5, "{turned} {want}");
            }
        }
        assert!(long_ways > 2_000, "{long_ways}");
    }

    #[test]
    fn rotate_towards_agrees_with_glam() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(28);
        for _ in 0..10_000 {
            let (a, b) = (random_unit(&mut rng), random_unit(&mut rng));
            let max = rng.random_range(-4.0f32..4.0);
            let ours = a.rotate_towards(b, max);
            let theirs: Quat = glam::Quat::from_array(a.to_array())
                .rotate_towards(glam::Quat::from_array(b.to_array()), max)
                .to_array()
                .into();
            let angle = a.angle_to(b);
            // glam snaps to `other` within 1e-4 rad, also when turning away.
            if angle <= 1e-4 {
                continue;
            }
            assert!(ours.angle_to(theirs) < 2e-5, "{a:?} {b:?} {max}");
            let turned = a.angle_to(ours);
            let want = if max >= 0.0 {
                max.min(angle)
            } else {
                (-max).min(PI - angle)
            };
            assert!((turned - want).abs() < 1e-5, "{turned} {want}");
            assert!(ours.angle_to(b) <= angle + 1e-5 || max < 0.0);
        }
    }

    #[test]
    fn rotate_towards_edges() {
        let a = Quat::from_rotation_x(0.5);
        assert_eq!(a.rotate_towards(Quat::IDENTITY, 0.0), a);
        assert!(a.rotate_towards(a, 1.0).angle_to(a) < 1e-6);
        assert!(a.rotate_towards(a, -1.0).angle_to(a) > 0.999);
        assert!(a.rotate_towards(a, -4.0).angle_to(a) > PI - 1e-5);
        assert!(a.rotate_towards(Quat::IDENTITY, f32::NAN).is_nan());
        assert!(a.rotate_towards(Quat::NAN, 1.0).is_nan());
        assert!(Quat::NAN.rotate_towards(a, 0.0).is_nan());
        assert!(a.rotate_towards(a, f32::INFINITY).is_nan());
        assert!(Quat::NAN.slerp_long(a, 0.5).is_nan());
        // The same rotation, a whole turn apart: half way is a half turn.
        assert!(a.slerp_long(-a, 0.5).angle_to(a) > PI - 1e-5);
        assert!(a.slerp_long(a, 0.5).angle_to(a) < 1e-6);
    }
}
