//! Reading the recordings the `broad` example evaluates: BROAD trials
//! (gyro, accelerometer, magnetometer and optical ground truth at 2000/7 Hz)
//! and x-io's Fusion sample log (no ground truth), as plain or gzipped CSV.
//! Shared with `tests/broad.rs`.

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
    pub gyr: Cvec3,
    pub acc: Cvec3,
    pub mag: Cvec3,
    pub truth: [f64; 4],
    pub movement: bool,
}

/// One Fusion sample: seconds, deg/s, g, µT.
#[derive(Clone, Copy, Debug)]
pub struct FusionSample {
    pub time: f64,
    pub gyr_deg: Cvec3,
    pub acc_g: Cvec3,
    pub mag: Cvec3,
}

/// A recording, told apart by its header row.
pub enum Recording {
    Broad(Vec<BroadSample>),
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

/// Parses the text of a recording.
pub fn parse(text: &str) -> Result<Recording, String> {
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
