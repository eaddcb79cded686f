//! Per-pixel shading, the CS175 model: for each of two point lights a
//! diffuse term `max(0, n . l)` and a specular term `max(0, n . h)^64`
//! with the halfway vector `h = normalize(l + v)`, plus a little ambient
//! light; all in eye coordinates, from the interpolated normal.

use rigtform::{Cvec3, RigTForm};

use crate::vertex::ATTRIBUTES;

/// Ambient light, as a fraction of the surface colour.
pub const AMBIENT: f32 = 0.12;
/// Brightness of the white specular highlight.
pub const SPECULAR: f32 = 0.35;

/// Two point lights in eye coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lighting {
    /// Light positions in eye coordinates.
    pub lights: [Cvec3; 2],
    /// Diffuse intensity of each light.
    pub intensity: [f32; 2],
}

impl Lighting {
    /// Lights at the world positions `lights`, seen from `eye` (the notes
    /// send `inv(eyeRbt) * light` to the shaders).
    ///
    /// ```
    /// use rigtform::{Cvec3, RigTForm};
    /// use rigtform_render::Lighting;
    /// let eye = RigTForm::from_translation(Cvec3::new(0.0, 0.0, 5.0));
    /// let l = Lighting::new(eye, [Cvec3::ZERO, Cvec3::Y], [1.0, 0.5]);
    /// assert_eq!(l.lights[0], Cvec3::new(0.0, 0.0, -5.0));
    /// ```
    #[must_use]
    pub fn new(eye: RigTForm, lights: [Cvec3; 2], intensity: [f32; 2]) -> Self {
        let to_eye = eye.inv();
        Self {
            lights: lights.map(|p| to_eye.transform_point(p)),
            intensity,
        }
    }

    /// The linear RGB colour of a surface point from its interpolated
    /// attributes: eye-space position, normal (any length) and colour.
    /// A zero normal gets only the ambient term.
    ///
    /// ```
    /// use rigtform::{Cvec3, RigTForm};
    /// use rigtform_render::Lighting;
    /// // A light straight in front of a surface facing the eye.
    /// let l = Lighting::new(RigTForm::IDENTITY, [Cvec3::ZERO; 2], [0.5, 0.5]);
    /// let c = l.shade(&[0.0, 0.0, -2.0, 0.0, 0.0, 1.0, 0.5, 0.5, 0.5]);
    /// assert!(c[0] > 0.5);
    /// ```
    #[must_use]
    #[inline]
    pub fn shade(&self, a: &[f32; ATTRIBUTES]) -> [f32; 3] {
        let p = Cvec3::new(a[0], a[1], a[2]);
        let n = unit(Cvec3::new(a[3], a[4], a[5]));
        let base = [a[6], a[7], a[8]];
        let mut diffuse = AMBIENT;
        let mut specular = 0.0;
        if let Some(n) = n {
            let v = unit(-p).unwrap_or(Cvec3::Z);
            for (light, intensity) in self.lights.iter().zip(self.intensity) {
                let Some(l) = unit(*light - p) else {
                    continue;
                };
                diffuse += intensity * n.dot(l).max(0.0);
                if let Some(h) = unit(l + v) {
                    specular += intensity * pow64(n.dot(h).max(0.0));
                }
            }
        }
        base.map(|c| c * diffuse + SPECULAR * specular)
    }
}

/// `v` scaled to unit length, or `None` for a zero, subnormal-squared or
/// non-finite `v`. Plainly `v / sqrt(v . v)`: the fragment stage runs this
/// four times per pixel, and its inputs are eye-space lengths of ordinary
/// size, so the library's scale-safe `try_normalize` is not needed here.
fn unit(v: Cvec3) -> Option<Cvec3> {
    let n2 = v.dot(v);
    (n2.is_normal()).then(|| v * (1.0 / n2.sqrt()))
}

/// `x^64` by six squarings.
fn pow64(x: f32) -> f32 {
    let mut y = x;
    for _ in 0..6 {
        y *= y;
    }
    y
}

#[cfg(test)]
mod tests {
    use super::*;

    fn attrs(p: Cvec3, n: Cvec3) -> [f32; ATTRIBUTES] {
        [p.x, p.y, p.z, n.x, n.y, n.z, 1.0, 1.0, 1.0]
    }

    #[test]
    fn unit_has_unit_length_and_refuses_zero() {
        let u = unit(Cvec3::new(3.0, -4.0, 12.0)).unwrap();
        assert!((u.norm() - 1.0).abs() < 1e-6);
        assert!((u.x - 3.0 / 13.0).abs() < 1e-7);
        assert_eq!(unit(Cvec3::ZERO), None);
        assert_eq!(unit(Cvec3::new(f32::NAN, 0.0, 0.0)), None);
        assert_eq!(unit(Cvec3::new(f32::INFINITY, 0.0, 0.0)), None);
    }

    #[test]
    fn pow64_matches_powi() {
        for x in [0.0f32, 0.5, 0.9, 0.99, 1.0] {
            assert!((pow64(x) - x.powi(64)).abs() <= 1e-6 * x.powi(64).max(1e-30));
        }
    }

    #[test]
    fn surface_facing_away_from_lights_gets_only_ambient() {
        let l = Lighting::new(
            RigTForm::IDENTITY,
            [Cvec3::new(0.0, 5.0, 0.0); 2],
            [0.6, 0.6],
        );
        let lit = l.shade(&attrs(Cvec3::new(0.0, 0.0, -3.0), Cvec3::Y));
        let dark = l.shade(&attrs(Cvec3::new(0.0, 0.0, -3.0), -Cvec3::Y));
        assert_eq!(dark, [AMBIENT; 3]);
        assert!(lit[0] > dark[0] + 0.5);
    }

    #[test]
    fn diffuse_follows_lamberts_cosine() {
        let light = Cvec3::new(0.0, 0.0, 100.0);
        let l = Lighting::new(RigTForm::IDENTITY, [light; 2], [0.5, 0.0]);
        let p = Cvec3::ZERO;
        let tilted = Cvec3::new(0.0, 1.0, 1.0); // 45 degrees from the light
        let c = l.shade(&attrs(p, tilted))[0] - AMBIENT;
        // The eye looks along the light, so the highlight is 45 degrees off
        // the normal: cos(45)^64 = 2^-32, far below the tolerance.
        assert!(
            (c - 0.5 * core::f32::consts::FRAC_1_SQRT_2).abs() < 1e-5,
            "{c}"
        );
    }

    #[test]
    fn specular_peaks_at_the_mirror_direction() {
        let l = Lighting::new(
            RigTForm::IDENTITY,
            [Cvec3::new(0.0, 0.0, 0.0); 2],
            [0.5, 0.5],
        );
        let p = Cvec3::new(0.0, 0.0, -4.0);
        let facing = l.shade(&attrs(p, Cvec3::Z))[0];
        let off = l.shade(&attrs(p, Cvec3::new(0.3, 0.0, 1.0)))[0];
        assert!(facing - off > 0.3, "{facing} {off}");
    }

    #[test]
    fn zero_normal_gets_only_ambient() {
        let l = Lighting::new(RigTForm::IDENTITY, [Cvec3::Z; 2], [1.0, 1.0]);
        assert_eq!(l.shade(&attrs(-Cvec3::Z, Cvec3::ZERO)), [AMBIENT; 3]);
    }
}
