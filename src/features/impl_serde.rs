//! `serde::Serialize` and `serde::Deserialize` for every public type
//! (feature `serde`), derived: each type is written as a struct with the
//! field names of its Rust definition, so a `Quat` is `{x, y, z, w}`
//! (scalar last, as glam's; a format without names keeps that order) and a `Matrix4` is
//! `{cols: [c0, c1, c2, c3]}`, column-major; an [`EulerRot`](crate::EulerRot)
//! is its variant's name (`"ZYX"`). The attitude types
//! ([`OrientationFilter`](crate::attitude::OrientationFilter) with its
//! whole state, [`Smoother`](crate::attitude::Smoother),
//! [`FilterParams`](crate::attitude::FilterParams),
//! [`Diagnostics`](crate::attitude::Diagnostics), the mounting
//! [`AxesAlignment`](crate::attitude::AxesAlignment) and its
//! [`Axis`](crate::attitude::Axis), and the sensor calibrations
//! [`InertialCalibration`](crate::attitude::InertialCalibration) and
//! [`MagneticCalibration`](crate::attitude::MagneticCalibration)) are
//! included, so that a firmware can keep its calibration in a file and
//! save a learned gyro bias and restore the filter later.
//!
//! Deserializing takes the values as they come: a quaternion read from a
//! file is not normalized, and NaN stays NaN (formats without NaN, such as
//! JSON, write it as `null` and fail to read it back).
//!
//! ```
//! use rigtform::{Cvec3, Quat, RigTForm};
//! let a = RigTForm::new(Cvec3::new(1.0, 2.0, 3.0), Quat::from_rotation_z(0.5));
//! let json = serde_json::to_string(&a).unwrap();
//! assert!(json.starts_with(r#"{"t":{"x":1.0,"y":2.0,"z":3.0},"r":{"x":0.0,"y":0.0,"z":"#));
//! let b: RigTForm = serde_json::from_str(&json).unwrap();
//! assert_eq!(a, b);
//! ```

#[cfg(test)]
mod tests {
    use crate::attitude::{
        AxesAlignment, Axis, FilterParams, InertialCalibration, MagneticCalibration,
        OrientationFilter, Smoother,
    };
    use crate::{Cvec3, Cvec4, EulerRot, Matrix3, Matrix4, Quat, RigTForm};
    use serde::{de::DeserializeOwned, Serialize};

    /// Writes `value` to JSON, reads it back and returns both.
    fn round_trip<T: Serialize + DeserializeOwned>(value: &T) -> (std::string::String, T) {
        let json = serde_json::to_string(value).expect("finite values serialize");
        let back = serde_json::from_str(&json).expect("our own output parses");
        (json, back)
    }

    /// Every public type goes through JSON and comes back bit for bit
    /// (serde_json writes the shortest decimal that reads back exactly).
    #[test]
    fn every_public_type_round_trips_through_json_exactly() {
        let v = Cvec3::new(0.1, -2.5e-30, 3.4e38);
        let (json, back) = round_trip(&v);
        assert_eq!(back, v, "{json}");
        let v4 = Cvec4::new(1.0, -0.0, 1e-45, 7.25);
        let (json, back) = round_trip(&v4);
        assert_eq!(back, v4, "{json}");
        assert!(back.y.is_sign_negative(), "-0 keeps its sign: {json}");
        let q = Quat::from_rotation_x(0.3) * Quat::from_rotation_y(-1.1);
        let (json, back) = round_trip(&q);
        assert_eq!(back, q, "{json}");
        let r = RigTForm::new(v, q);
        assert_eq!(round_trip(&r).1, r);
        let m = Matrix4::from(r);
        let (json, back) = round_trip(&m);
        assert_eq!(back, m, "{json}");
        let m3 = Matrix3::from(m);
        let (json, back) = round_trip(&m3);
        assert_eq!(back, m3, "{json}");
        let p = FilterParams::DEFAULT;
        assert_eq!(round_trip(&p).1, p);
        let s = Smoother::new(q, 0.25);
        assert_eq!(round_trip(&s).1, s);
        for order in EulerRot::ALL {
            assert_eq!(round_trip(&order).1, order);
        }
        assert_eq!(round_trip(&EulerRot::ZYX).0, r#""ZYX""#);
        let mounting = AxesAlignment::new(Axis::PosY, Axis::NegX).expect("perpendicular");
        assert_eq!(round_trip(&mounting).1, mounting);
        let gyro = InertialCalibration {
            offset: Cvec3::new(0.01, -0.02, 0.005),
            ..InertialCalibration::IDENTITY
        };
        assert_eq!(round_trip(&gyro).1, gyro);
        let mag = MagneticCalibration {
            hard_iron: Cvec3::new(12.0, -3.0, 40.0),
            ..MagneticCalibration::IDENTITY
        };
        assert_eq!(round_trip(&mag).1, mag);
        let mut filter = OrientationFilter::new(FilterParams::DEFAULT);
        filter.update(Cvec3::ZERO, Cvec3::ZERO, 0.01);
        let d = filter.diagnostics();
        assert!(d.acc_ignored);
        assert_eq!(round_trip(&d).1, d);
    }

    /// The component order is the one of the Rust fields: scalar last for
    /// a `Quat`, columns for a `Matrix4`.
    #[test]
    fn fields_are_named_as_in_rust() {
        let (json, _) = round_trip(&Quat::from_wxyz(1.0, 2.0, 3.0, 4.0));
        assert_eq!(json, r#"{"x":2.0,"y":3.0,"z":4.0,"w":1.0}"#);
        let m = Matrix4::from_translation(Cvec3::new(5.0, 6.0, 7.0));
        let (json, _) = round_trip(&m);
        assert!(
            json.ends_with(r#"{"x":5.0,"y":6.0,"z":7.0,"w":1.0}]}"#),
            "the translation is the last column: {json}"
        );
    }

    /// A filter saved at any point reads back from JSON and carries on as
    /// the original: new, started from a known attitude, in 6D (no field
    /// ever), after bad samples and huge steps, and after a glitch as its
    /// first field.
    #[test]
    fn a_filter_saved_at_any_point_reads_back() {
        let p = FilterParams::DEFAULT;
        let (gyr, acc) = (Cvec3::new(0.01, -0.02, 0.005), Cvec3::new(0.3, -0.2, 9.8));
        let mag = Cvec3::new(20.0, 5.0, -40.0);
        let mut six = OrientationFilter::new(p);
        let mut glitched = OrientationFilter::new(p);
        let mut states = std::vec![
            OrientationFilter::new(p),
            OrientationFilter::with_attitude(p, Quat::from_rotation_y(0.3)),
            OrientationFilter::with_attitude(p, Quat::NAN),
        ];
        for i in 0..300 {
            six.update(gyr, acc, 0.01);
            if i % 100 == 0 {
                states.push(six);
            }
        }
        six.update(Cvec3::NAN, Cvec3::new(1e30, 0.0, 0.0), 0.01);
        six.update(gyr, acc, f32::MAX);
        six.update(gyr, acc, f32::NAN);
        states.push(six);
        glitched.update_with_mag(gyr, acc, Cvec3::new(1e30, -1e30, 0.0), 0.01);
        states.push(glitched);
        for state in states {
            let (json, mut g) = round_trip(&state);
            assert_eq!(g, state, "{json}");
            let mut f = state;
            for _ in 0..100 {
                f.update_with_mag(gyr, acc, mag, 0.01);
                g.update_with_mag(gyr, acc, mag, 0.01);
            }
            assert_eq!(g, f, "{json}");
        }
    }

    /// A filter saved mid-run and restored carries on exactly as the
    /// original: its whole state (bias, low-passes, rest timer, reference
    /// field) is written.
    #[test]
    fn a_restored_filter_continues_as_the_original() {
        let mut f = OrientationFilter::new(FilterParams::DEFAULT);
        let (gyr, acc) = (Cvec3::new(0.01, -0.02, 0.005), Cvec3::new(0.3, -0.2, 9.8));
        let mag = Cvec3::new(20.0, 5.0, -40.0);
        for _ in 0..300 {
            f.update_with_mag(gyr, acc, mag, 0.01);
        }
        let (json, mut g) = round_trip(&f);
        assert_eq!(g, f, "{json}");
        for _ in 0..300 {
            f.update_with_mag(gyr, acc, mag, 0.01);
            g.update_with_mag(gyr, acc, mag, 0.01);
        }
        assert_eq!(g, f);
        assert!(
            f.bias().norm() > 0.0,
            "the state that was saved is not the initial one"
        );
    }
}
