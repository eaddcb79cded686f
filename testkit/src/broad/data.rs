//! Reading the recordings: BROAD trials (gyro, accelerometer, magnetometer
//! and optical ground truth at 2000/7 Hz) and x-io's Fusion sample log (no
//! ground truth), as plain or gzipped CSV. Errors name the file, the line
//! and the column.

use std::io::Read;
use std::path::Path;

use rigtform::Cvec3;

/// BROAD's sample period: the rate is exactly 2000/7 Hz.
pub const BROAD_DT: f32 = 0.0035;

/// BROAD's header row, as the CSV conversion of the trials writes it.
pub const BROAD_HEADER: &str =
    "gyr_x,gyr_y,gyr_z,acc_x,acc_y,acc_z,mag_x,mag_y,mag_z,quat_w,quat_x,quat_y,quat_z,movement";

/// x-io Fusion's sample log header.
pub const FUSION_HEADER: &str = "Time (s),Gyroscope X (deg/s),Gyroscope Y (deg/s),Gyroscope Z (deg/s),Accelerometer X (g),Accelerometer Y (g),Accelerometer Z (g),Magnetometer X (uT),Magnetometer Y (uT),Magnetometer Z (uT)";

/// One BROAD sample: rad/s, m/s², µT in the sensor frame; the ground truth
/// (sensor to ENU earth, scalar first; NaN where the markers were hidden);
/// whether the sample counts in the error metrics.
#[derive(Clone, Copy, Debug)]
pub struct BroadSample {
    /// Angular rate, rad/s.
    pub gyr: Cvec3,
    /// Specific force, m/s².
    pub acc: Cvec3,
    /// Magnetic field, µT.
    pub mag: Cvec3,
    /// Ground truth, sensor to ENU earth, `[w, x, y, z]`; NaN where the
    /// optical markers were hidden.
    pub truth: [f64; 4],
    /// Whether the sample is in the movement phase (the one scored).
    pub movement: bool,
}

/// One Fusion sample: seconds, deg/s, g, µT.
#[derive(Clone, Copy, Debug)]
pub struct FusionSample {
    /// Time stamp, s.
    pub time: f64,
    /// Angular rate, deg/s.
    pub gyr_deg: Cvec3,
    /// Specific force, g.
    pub acc_g: Cvec3,
    /// Magnetic field, µT.
    pub mag: Cvec3,
}

/// A recording, told apart by its header row.
pub enum Recording {
    /// A BROAD trial.
    Broad(Vec<BroadSample>),
    /// x-io's Fusion sample log.
    Fusion(Vec<FusionSample>),
}

/// Reads a file as text, gunzipping it if its name ends in `.gz`.
pub fn read_text(path: &Path) -> Result<String, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    if path.extension().is_some_and(|e| e == "gz") {
        let mut text = String::new();
        flate2::read::GzDecoder::new(&bytes[..])
            .read_to_string(&mut text)
            .map_err(|e| format!("{}: not a gzipped text file: {e}", path.display()))?;
        Ok(text)
    } else {
        String::from_utf8(bytes).map_err(|e| format!("{}: not a text file: {e}", path.display()))
    }
}

/// Reads and parses a recording; errors name the file and the line.
pub fn read(path: &Path) -> Result<Recording, String> {
    let text = read_text(path)?;
    parse(&text).map_err(|e| format!("{}: {e}", path.display()))
}

/// Parses the text of a recording: a header row, then one row per sample.
/// A UTF-8 byte-order mark before the header and blank lines are skipped
/// (as `tools/vqf_broad.py` skips them).
pub fn parse(text: &str) -> Result<Recording, String> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = text.lines().enumerate();
    let header = lines.next().map(|(_, l)| l.trim_end()).unwrap_or_default();
    let rows = lines.filter(|(_, l)| !l.trim().is_empty());
    match header {
        BROAD_HEADER => rows
            .map(|(i, line)| {
                let [gx, gy, gz, ax, ay, az, mx, my, mz, w, x, y, z, m] = fields(line, i + 1)?;
                let movement = match m {
                    0.0 => false,
                    1.0 => true,
                    _ => return Err(format!("line {}: movement must be 0 or 1, got {m}", i + 1)),
                };
                Ok(BroadSample {
                    gyr: vec3(gx, gy, gz),
                    acc: vec3(ax, ay, az),
                    mag: vec3(mx, my, mz),
                    truth: [w, x, y, z],
                    movement,
                })
            })
            .collect::<Result<_, _>>()
            .map(Recording::Broad),
        FUSION_HEADER => rows
            .map(|(i, line)| {
                let [t, gx, gy, gz, ax, ay, az, mx, my, mz] = fields(line, i + 1)?;
                Ok(FusionSample {
                    time: t,
                    gyr_deg: vec3(gx, gy, gz),
                    acc_g: vec3(ax, ay, az),
                    mag: vec3(mx, my, mz),
                })
            })
            .collect::<Result<_, _>>()
            .map(Recording::Fusion),
        _ => Err(format!(
            "line 1: unknown header {header:?}; expected a BROAD trial ({BROAD_HEADER}) or x-io's Fusion log"
        )),
    }
}

/// The `N` comma-separated numbers of a row (`line_number` counts from 1).
fn fields<const N: usize>(line: &str, line_number: usize) -> Result<[f64; N], String> {
    let mut out = [0.0; N];
    let mut parts = line.split(',');
    for (i, slot) in out.iter_mut().enumerate() {
        let part = parts
            .next()
            .ok_or_else(|| format!("line {line_number}: {N} columns expected, found {i}"))?;
        *slot = part.trim().parse().map_err(|_| {
            format!(
                "line {line_number}, column {}: not a number: {part:?}",
                i + 1
            )
        })?;
    }
    if parts.next().is_some() {
        return Err(format!("line {line_number}: more than {N} columns"));
    }
    Ok(out)
}

fn vec3(x: f64, y: f64, z: f64) -> Cvec3 {
    Cvec3::new(x as f32, y as f32, z as f32)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_rows_are_reported_with_their_line_number() {
        let header = BROAD_HEADER;
        let good = "0.1,0,0,0,0,9.81,0,16,-41,1,0,0,0,1";
        let cases = [
            (
                format!("{header}\n{good}\n0.1,0,0,x,0,9.81,0,16,-41,1,0,0,0,1\n"),
                "line 3, column 4",
            ),
            (
                format!("{header}\n{good}\n0.1,0,0\n"),
                "line 3: 14 columns expected, found 3",
            ),
            (
                format!("{header}\n{good},7\n"),
                "line 2: more than 14 columns",
            ),
            (
                format!("{header}\n0.1,0,0,0,0,9.81,0,16,-41,1,0,0,0,2\n"),
                "line 2: movement must be 0 or 1",
            ),
            ("a,b\n1,2\n".to_string(), "line 1: unknown header"),
        ];
        for (text, want) in cases {
            match parse(&text) {
                Err(e) => assert!(e.contains(want), "{e:?} should say {want:?}"),
                Ok(_) => panic!("{text:?} parsed"),
            }
        }
        assert!(
            matches!(parse(&format!("{header}\n{good}\n")), Ok(Recording::Broad(s)) if s.len() == 1)
        );
    }

    #[test]
    fn byte_order_mark_and_blank_lines_are_skipped() {
        let header = BROAD_HEADER;
        let good = "0.1,0,0,0,0,9.81,0,16,-41,1,0,0,0,1";
        for text in [
            format!("\u{feff}{header}\n{good}\n{good}\n"),
            format!("{header}\r\n\r\n{good}\r\n  \r\n{good}\r\n\r\n"),
        ] {
            match parse(&text) {
                Ok(Recording::Broad(s)) => assert_eq!(s.len(), 2, "{text:?}"),
                Ok(Recording::Fusion(_)) => panic!("{text:?} read as a Fusion log"),
                Err(e) => panic!("{text:?}: {e}"),
            }
        }
    }
}
