//! How serde writes an [`OrientationFilter`]: one flat struct of its whole
//! state, named and ordered as it always was, whatever estimator holds
//! each part, so that a filter saved by an earlier build reads back.

use super::bias::Bias;
use super::gyro::Gyro;
use super::hard_iron::HardIron;
use super::heading::Heading;
use super::inclination::Inclination;
use super::rest::RestDetector;
use super::OrientationFilter;
use crate::attitude::diagnostics::Flags;
use crate::attitude::params::FilterParams;
use crate::quat::Quat;
use crate::vec::Cvec3;

/// The saved form of an [`OrientationFilter`].
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "OrientationFilter")]
pub(super) struct Saved {
    params: FilterParams,
    strapdown: Quat,
    correction: Quat,
    acc_average: Cvec3,
    acc_rate: Cvec3,
    bias: Cvec3,
    last_rate: Cvec3,
    rest: RestDetector,
    hard_iron: Cvec3,
    mag_reference: [f32; 2],
    mag_shut: f32,
    bias_variance: f32,
    settling: f32,
    acc_error: f32,
    flags: Flags,
    axes_average: [Cvec3; 2],
    axes_rate: [Cvec3; 2],
}

impl From<OrientationFilter> for Saved {
    fn from(f: OrientationFilter) -> Self {
        Self {
            params: f.params,
            strapdown: f.strapdown,
            correction: f.correction,
            acc_average: f.inclination.average,
            acc_rate: f.inclination.rate,
            bias: f.bias.estimate,
            last_rate: f.gyro.last_rate,
            rest: f.rest,
            hard_iron: f.hard_iron.estimate,
            mag_reference: f.heading.reference,
            mag_shut: f.heading.shut,
            bias_variance: f.bias.variance,
            settling: f.settling,
            acc_error: f.acc_error,
            flags: f.flags,
            axes_average: f.bias.axes_average,
            axes_rate: f.bias.axes_rate,
        }
    }
}

impl From<Saved> for OrientationFilter {
    fn from(s: Saved) -> Self {
        Self {
            params: s.params,
            strapdown: s.strapdown,
            correction: s.correction,
            gyro: Gyro {
                last_rate: s.last_rate,
            },
            rest: s.rest,
            bias: Bias {
                estimate: s.bias,
                variance: s.bias_variance,
                axes_average: s.axes_average,
                axes_rate: s.axes_rate,
            },
            inclination: Inclination {
                average: s.acc_average,
                rate: s.acc_rate,
            },
            heading: Heading {
                reference: s.mag_reference,
                shut: s.mag_shut,
            },
            hard_iron: HardIron {
                estimate: s.hard_iron,
            },
            settling: s.settling,
            acc_error: s.acc_error,
            flags: s.flags,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A filter saved as JSON by the build before its estimators had a
    /// file each (9D, 30 s at 100 Hz: 5 s still, then turning with a
    /// magnet on the sensor and a burst of glitched fields), every part of
    /// the state set.
    const SAVED_BEFORE: &str = r#"{"params":{"gravity":9.81,"tau_acc":3.0,"tau_mag":10.0,"tau_bias":20.0,"bias_drift":0.000175,"bias_noise":0.01,"tau_bias_rest":3.0,"rest_gyro":0.035,"max_bias":0.035,"rest_acc":0.05,"rest_time":1.5,"acc_gate":0.1,"mag_gate":0.1,"gyro_range":3.4028235e+38,"mag_delay":0.0},"strapdown":{"x":0.14350033,"y":-0.20616578,"z":0.4729924,"w":-0.8445008},"correction":{"x":0.06759706,"y":0.0824176,"z":0.3791569,"w":0.91917247},"acc_average":{"x":-0.98346627,"y":1.8321514,"z":9.587002},"acc_rate":{"x":0.054189235,"y":-0.0024633058,"z":0.0059645153},"bias":{"x":0.008168868,"y":-0.016109223,"z":0.003908111},"last_rate":{"x":0.7664222,"y":0.48502067,"z":0.505},"rest":{"gyro":{"x":0.8352354,"y":0.4041094,"z":0.5049985},"acc":{"x":-1.0890298,"y":-6.5507197,"z":5.6090007},"time":0.0},"hard_iron":{"x":17.836637,"y":-8.830126,"z":1.9697634},"mag_reference":[19.27746,-38.991962],"mag_shut":13.530214,"bias_variance":0.00021897793,"settling":29.990591,"acc_error":0.00001855797,"flags":192,"axes_average":[{"x":0.3637255,"y":0.48498055,"z":0.061472297},{"x":0.13755128,"y":-0.07115615,"z":0.54370826}],"axes_rate":[{"x":0.47666967,"y":0.017313214,"z":0.2908148},{"x":-0.22510822,"y":0.08700525,"z":0.43921116}]}"#;

    /// It reads back, each value where it was (the bias, the hard-iron
    /// estimate, the reference and the attitude), and is written again
    /// exactly as it was read.
    #[test]
    fn a_filter_saved_by_an_earlier_build_reads_back() {
        let f: OrientationFilter =
            serde_json::from_str(SAVED_BEFORE).expect("the earlier format reads");
        assert_eq!(f.bias(), Cvec3::new(0.008168868, -0.016109223, 0.003908111));
        assert_eq!(
            f.hard_iron.estimate,
            Cvec3::new(17.836637, -8.830126, 1.9697634)
        );
        assert_eq!(f.heading.reference, [19.27746, -38.991962]);
        assert_eq!(f.heading.shut, 13.530214);
        assert_eq!(
            f.correction,
            Quat::from_xyzw(0.06759706, 0.0824176, 0.3791569, 0.91917247)
        );
        let written = serde_json::to_string(&f).expect("finite values serialize");
        assert_eq!(written, SAVED_BEFORE);
    }
}
