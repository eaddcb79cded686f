//! The notes' comparison: one pair of keyframes interpolated by lerping
//! the 4x4 matrices (bad idea 1), by lerping Euler angles (bad idea 2) and
//! by `RigTForm::interpolate`, and by Euler angles and slerp again in a
//! turned world frame (left invariance). Each panel's caption measures what
//! its method does: the volume of a lerped matrix, how far Euler angles
//! are off slerp, how far a turned world moves the result.

use rigtform::{Cvec3, Cvec4, Quat, RigTForm};

use crate::demo::interpolation::Method;
use crate::vertex::Placement;

/// Which panels a demo frame shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum Comparison {
    /// All five panels.
    #[default]
    All,
    /// Matrix lerp, Euler lerp and slerp.
    Interpolation,
    /// Euler lerp and slerp, each in the world frame and in a rotated one.
    Invariance,
    /// Slerp alone.
    Slerp,
}

/// One panel: a method, the world frame it interpolates in, and the
/// keyframes it interpolates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Panel {
    /// The title drawn above the panel.
    pub title: &'static str,
    /// The interpolation method.
    pub method: Method,
    /// `G` of the world frame `w' = w G` the method works in.
    pub world: RigTForm,
    /// The keyframes at `alpha = 0` and 1.
    pub keyframes: (RigTForm, RigTForm),
}

/// The rotated world frame of the invariance panels: tipped 90 degrees
/// about the z axis, then turned 60 degrees about the new vertical.
#[must_use]
pub fn rotated_world() -> RigTForm {
    RigTForm::from_rotation(
        Quat::from_rotation_z(core::f32::consts::FRAC_PI_2) * Quat::from_rotation_x(1.0),
    )
}

/// The two keyframes: the second is moved across the ground and turned a
/// further 150 degrees about a tilted axis.
///
/// ```
/// let (k0, k1) = rigtform_render::demo::keyframes();
/// assert!((k0.r.angle_to(k1.r).to_degrees() - 150.0).abs() < 1e-3);
/// ```
#[must_use]
pub fn keyframes() -> (RigTForm, RigTForm) {
    let r0 = Quat::from_rotation_y(0.4) * Quat::from_rotation_x(-0.25);
    let k0 = RigTForm::new(Cvec3::new(-1.9, 1.2, 0.3), r0);
    let turn = Quat::from_axis_angle(Cvec3::new(0.3, 1.0, 0.9), 150f32.to_radians());
    let k1 = RigTForm::new(Cvec3::new(1.9, 1.2, -0.6), turn * r0);
    (k0, k1)
}

impl Comparison {
    /// The panels, left to right, each interpolating [`keyframes`].
    #[must_use]
    pub fn panels(self) -> Vec<Panel> {
        let keyframes = keyframes();
        let panel = |title, method, world| Panel {
            title,
            method,
            world,
            keyframes,
        };
        let (w, g) = (RigTForm::IDENTITY, rotated_world());
        let matrix = panel("MATRIX LERP", Method::MatrixLerp, w);
        let euler = panel("EULER LERP", Method::EulerLerp, w);
        let slerp = panel("SLERP", Method::Slerp, w);
        let euler_g = panel("EULER, WORLD TURNED", Method::EulerLerp, g);
        let slerp_g = panel("SLERP, WORLD TURNED", Method::Slerp, g);
        match self {
            Comparison::All => vec![matrix, euler, slerp, euler_g, slerp_g],
            Comparison::Interpolation => vec![matrix, euler, slerp],
            Comparison::Invariance => vec![euler, euler_g, slerp, slerp_g],
            Comparison::Slerp => vec![slerp],
        }
    }
}

impl Panel {
    /// Where the panel's method places the body at `alpha`.
    ///
    /// ```
    /// use rigtform_render::demo::{keyframes, Comparison};
    /// use rigtform_render::Placement;
    /// let slerp = Comparison::Slerp.panels()[0];
    /// assert_eq!(slerp.placement(0.0), Placement::Rigid(keyframes().0));
    /// ```
    #[must_use]
    pub fn placement(&self, alpha: f32) -> Placement {
        let (k0, k1) = self.keyframes;
        self.method.placement(k0, k1, self.world, alpha)
    }

    /// The second label line of the panel at `alpha`: a measure of what the
    /// method does there.
    ///
    /// ```
    /// use rigtform_render::demo::Comparison;
    /// let panels = Comparison::Interpolation.panels();
    /// assert_eq!(panels[2].caption(1.0), "turned 150.0 deg");
    /// ```
    #[must_use]
    pub fn caption(&self, alpha: f32) -> String {
        let rotation = |p: &Panel| match p.placement(alpha) {
            Placement::Rigid(r) => Some(r.r),
            Placement::Matrix(_) => None,
        };
        let degrees_between = |a: &Panel, b: &Panel| {
            rotation(a)
                .zip(rotation(b))
                .map_or(0.0, |(a, b)| a.angle_to(b).to_degrees())
        };
        if self.world != RigTForm::IDENTITY {
            // The same method in the untouched world frame.
            let in_world = Panel {
                world: RigTForm::IDENTITY,
                ..*self
            };
            return format!("{:5.1} deg off world's", degrees_between(self, &in_world));
        }
        match (self.method, self.placement(alpha)) {
            (Method::MatrixLerp, Placement::Matrix(m)) => {
                let [a, b, c, _] = m.cols.map(Cvec4::xyz);
                format!("volume x{:.2}", a.dot(b.cross(c)))
            }
            (Method::EulerLerp, _) => {
                let slerp = Panel {
                    method: Method::Slerp,
                    ..*self
                };
                format!("{:5.1} deg off slerp", degrees_between(self, &slerp))
            }
            (_, Placement::Rigid(r)) => {
                let k0 = self.keyframes.0;
                format!("turned {:5.1} deg", r.r.angle_to(k0.r).to_degrees())
            }
            (_, Placement::Matrix(_)) => String::new(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matrix_lerp_panel_shrinks_halfway() {
        let panels = Comparison::Interpolation.panels();
        let caption = panels[0].caption(0.5);
        // cos(75 degrees)^2 = 0.067: the plane of the turn collapses.
        assert_eq!(caption, "volume x0.07");
        assert_eq!(panels[0].caption(0.0), "volume x1.00");
    }

    #[test]
    fn rotated_world_changes_euler_but_not_slerp() {
        let panels = Comparison::Invariance.panels();
        let titles: Vec<_> = panels.iter().map(|p| p.title).collect();
        assert_eq!(titles[1], "EULER, WORLD TURNED");
        let euler_g = panels[1].caption(0.5);
        let slerp_g = panels[3].caption(0.5);
        assert_eq!(slerp_g, "  0.0 deg off world's");
        let euler_off: f32 = euler_g.split_whitespace().next().unwrap().parse().unwrap();
        assert!(euler_off > 10.0, "{euler_g}");
    }
}
