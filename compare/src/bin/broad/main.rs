//! Runs `rigtform`'s orientation filter on real IMU recordings and scores
//! it with the BROAD benchmark's metric, beside its peers run on the same
//! samples in the same run: VQF and x-io's Fusion from PyPI
//! (`tools/vqf_broad.py` and `tools/fusion_broad.py`, which need
//! `pip install vqf imufusion`), uf-ahrs's VQF, Mahony and Madgwick (in
//! process, [`uf_ahrs`]), and the published figures of Madgwick and Mahony;
//! writes a plot of the error over time.
//!
//! ```sh
//! cargo run --release -p rigtform-compare --bin broad -- ../shared/data/imu/broad_*.csv \
//!     ../shared/data/imu/xio_fusion_sensor_data.csv --plot docs/imu_errors.png
//! ```
//!
//! Accepts BROAD trials (as CSV, or gzipped like the one in the testkit's `data/`)
//! and x-io's Fusion sample log (no ground truth: a summary only). The data
//! and its origin are described in the README's IMU section.
//!
//! With `--hash`, it prints only a fingerprint of our estimates on each
//! BROAD trial ([`fingerprint`]), to show that a change of the code leaves
//! every estimate the same to the bit.

mod fingerprint;
mod plot;
mod pypi;
mod uf_ahrs;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::Parser;
use rigtform::attitude::{FilterParams, OrientationFilter};
use rigtform::{Cvec3, Quat};

use rigtform_testkit::broad::data::{self, BroadSample, FusionSample, Recording};
use rigtform_testkit::broad::metric::{self, Rmse, Run};

/// Evaluate rigtform's orientation filter on BROAD trials and x-io's Fusion log.
#[derive(Parser)]
struct Args {
    /// Recordings: BROAD trial CSVs (plain or .gz) and x-io Fusion logs.
    #[arg(required = true)]
    csv: Vec<PathBuf>,
    /// Where to write the PNG plot of the error over time (BROAD trials).
    #[arg(long)]
    plot: Option<PathBuf>,
    /// The Python interpreter that runs VQF and Fusion (it needs the `vqf`
    /// and `imufusion` packages).
    #[arg(long, default_value = "python3")]
    python: String,
    /// The folder that holds `vqf_broad.py` and `fusion_broad.py`: the
    /// repository's `tools/` (default: `tools` in the current folder, as
    /// when run from the repository's root).
    #[arg(long, default_value = "tools")]
    tools: PathBuf,
    /// The script that runs VQF, `tools/vqf_broad.py` of the repository
    /// (default: the file `RIGTFORM_VQF_SCRIPT` names, else `vqf_broad.py`
    /// in the `--tools` folder).
    #[arg(long)]
    vqf_script: Option<PathBuf>,
    /// The script that runs Fusion, `tools/fusion_broad.py` of the
    /// repository (found as the VQF script is, through
    /// `RIGTFORM_FUSION_SCRIPT`).
    #[arg(long)]
    fusion_script: Option<PathBuf>,
    /// `FilterParams::mag_delay` for every BROAD trial, in seconds: how
    /// long the magnetometer lags the gyroscope (default 0, as
    /// `FilterParams::DEFAULT`; BROAD's sensor: 0.011).
    #[arg(long, default_value_t = 0.0, value_parser = finite_seconds)]
    mag_delay: f32,
    /// Print only, for each BROAD trial, the FNV-1a hash of the bits of
    /// our every 6D and 9D estimate (no peers, no tables, no plot).
    #[arg(long, conflicts_with = "plot")]
    hash: bool,
}

/// A delay in seconds: a finite number.
fn finite_seconds(text: &str) -> Result<f32, String> {
    match text.parse::<f32>() {
        Ok(seconds) if seconds.is_finite() => Ok(seconds),
        _ => Err(format!("`{text}` is not a finite number of seconds")),
    }
}

/// Published RMSEs in degrees on a BROAD trial: Madgwick and Mahony with
/// the one parameter set best over all 39 trials (TAGP; inclination,
/// total), from the BROAD authors' `results_*_average_rmse.json`.
struct Published {
    trial: &'static str,
    madgwick: (f64, f64),
    mahony: (f64, f64),
}

const PUBLISHED: [Published; 3] = [
    Published {
        trial: "02",
        madgwick: (0.80, 1.50),
        mahony: (0.66, 2.97),
    },
    Published {
        trial: "07",
        madgwick: (2.50, 5.00),
        mahony: (1.84, 5.23),
    },
    Published {
        trial: "16",
        madgwick: (3.09, 4.82),
        mahony: (10.01, 20.28),
    },
];

/// One evaluated BROAD trial.
pub struct Trial {
    pub name: String,
    pub samples: Vec<BroadSample>,
    pub six: Run,
    pub nine: Run,
    /// VQF's 6D and 9D runs over the same samples.
    pub vqf_six: Run,
    pub vqf_nine: Run,
    /// Fusion's 6D and 9D runs.
    pub fusion_six: Run,
    pub fusion_nine: Run,
    /// uf-ahrs's runs, in the order of [`uf_ahrs::NAMES`].
    pub uf: [uf_ahrs::Runs; 3],
}

impl Trial {
    /// One run of each filter (`which` of its 6D and its 9D run), in the
    /// order of the tables' columns: ours, VQF, uf-ahrs's three, Fusion.
    fn runs<'t>(&'t self, which: fn(&'t Run, &'t Run) -> &'t Run) -> [&'t Run; 6] {
        let [a, b, c] = &self.uf;
        [
            which(&self.six, &self.nine),
            which(&self.vqf_six, &self.vqf_nine),
            which(&a.six, &a.nine),
            which(&b.six, &b.nine),
            which(&c.six, &c.nine),
            which(&self.fusion_six, &self.fusion_nine),
        ]
    }
}

fn main() -> ExitCode {
    let args = Args::parse();
    match evaluate(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn evaluate(args: &Args) -> Result<(), String> {
    // Read everything first, so that a bad file stops the run before any output.
    let mut trials = Vec::new();
    let mut fusion = Vec::new();
    for path in &args.csv {
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_else(|| path.display().to_string());
        match data::read(path)? {
            Recording::Broad(samples) if samples.is_empty() => {
                return Err(format!("{}: no samples", path.display()))
            }
            Recording::Broad(samples) => trials.push((name, path, samples)),
            Recording::Fusion(samples) if samples.len() < 2 => {
                return Err(format!("{}: fewer than two samples", path.display()))
            }
            Recording::Fusion(samples) => fusion.push((name, samples)),
        }
    }
    let params = FilterParams {
        mag_delay: args.mag_delay,
        ..FilterParams::DEFAULT
    };
    if args.hash {
        for (name, _, samples) in &trials {
            println!("{}", fingerprint::line(name, samples, params));
        }
        return Ok(());
    }
    let scripts = if trials.is_empty() {
        None
    } else {
        Some((
            pypi::VQF.find_script(args.vqf_script.as_deref(), &args.tools)?,
            pypi::FUSION.find_script(args.fusion_script.as_deref(), &args.tools)?,
        ))
    };
    let trials: Vec<Trial> = trials
        .into_iter()
        .map(|(name, path, samples)| {
            let six = metric::run(&samples, params, false);
            if six.rmse.samples == 0 {
                return Err(format!(
                    "{}: no sample is scored (none is in the movement phase with ground truth)",
                    path.display()
                ));
            }
            let nine = metric::run(&samples, params, true);
            let (vqf_script, fusion_script) = match &scripts {
                Some((vqf, fusion)) => (vqf.as_path(), fusion.as_path()),
                None => (Path::new(""), Path::new("")),
            };
            let (vqf_six, vqf_nine) = pypi::VQF.run(&args.python, vqf_script, path, &samples)?;
            let (fusion_six, fusion_nine) =
                pypi::FUSION.run(&args.python, fusion_script, path, &samples)?;
            let trial = Trial {
                six,
                nine,
                vqf_six,
                vqf_nine,
                fusion_six,
                fusion_nine,
                uf: uf_ahrs::run_all(&samples),
                name,
                samples,
            };
            let runs = [&trial.six, &trial.nine, &trial.vqf_six, &trial.vqf_nine];
            if let Some(run) = runs.iter().find(|r| !rmse_is_finite(r.rmse)) {
                let bad = run.estimates.iter().filter(|q| !q.is_finite()).count();
                return Err(format!(
                    "{}: an RMSE is not finite ({:?}; {bad} non-finite estimates), no verdict",
                    path.display(),
                    run.rmse
                ));
            }
            Ok(trial)
        })
        .collect::<Result<_, String>>()?;
    if !trials.is_empty() {
        print_table(&trials, params.mag_delay);
        print_peers(&trials, params.mag_delay);
    }
    for (name, samples) in &fusion {
        print_fusion_summary(name, samples);
    }
    if let Some(path) = &args.plot {
        if trials.is_empty() {
            return Err("--plot needs at least one BROAD trial".into());
        }
        plot::write(path, &trials)?;
        println!("\nplot written to {}", path.display());
    }
    Ok(())
}

/// Whether every error of `rmse` is a number (not NaN, not infinite).
fn rmse_is_finite(rmse: Rmse) -> bool {
    [rmse.inclination, rmse.heading, rmse.total]
        .iter()
        .all(|e| e.is_finite())
}

/// The two digits after `broad_` in a file name: the BROAD trial number.
fn trial_number(name: &str) -> Option<&str> {
    let rest = &name[name.find("broad_")? + 6..];
    rest.get(..2)
        .filter(|n| n.bytes().all(|b| b.is_ascii_digit()))
}

fn print_table(trials: &[Trial], mag_delay: f32) {
    if mag_delay == 0.0 {
        println!("BROAD trials: RMSE in degrees over the movement phase, FilterParams::DEFAULT for every trial.");
    } else {
        println!("BROAD trials: RMSE in degrees over the movement phase, FilterParams::DEFAULT with mag_delay {mag_delay} s for every trial.");
    }
    println!("VQF: the `vqf` package from PyPI (VQF(Ts).updateBatch, default parameters), run on the same CSVs in this run.");
    println!("Madgwick and Mahony: the BROAD authors' 9D runs with the one parameter set best over all 39 trials (TAGP).\n");
    println!("| trial | ours 6D incl. | VQF 6D incl. | ours 9D incl. | VQF 9D incl. | ours 9D heading | VQF 9D heading | ours 9D total | VQF 9D total | Madgwick incl. / total | Mahony incl. / total |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
    for t in trials {
        let (six, nine) = (t.six.rmse, t.nine.rmse);
        let (vqf_six, vqf_nine) = (t.vqf_six.rmse, t.vqf_nine.rmse);
        let published = trial_number(&t.name).and_then(|n| PUBLISHED.iter().find(|p| p.trial == n));
        let (madgwick, mahony) = match published {
            Some(p) => (
                format!("{:.2} / {:.2}", p.madgwick.0, p.madgwick.1),
                format!("{:.2} / {:.2}", p.mahony.0, p.mahony.1),
            ),
            None => ("-".into(), "-".into()),
        };
        println!(
            "| {} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {madgwick} | {mahony} |",
            t.name,
            six.inclination,
            vqf_six.inclination,
            nine.inclination,
            vqf_nine.inclination,
            nine.heading,
            vqf_nine.heading,
            nine.total,
            vqf_nine.total
        );
        let nan = t
            .six
            .estimates
            .iter()
            .chain(&t.nine.estimates)
            .filter(|q| !q.is_finite())
            .count();
        if nan > 0 {
            println!("  ({nan} non-finite estimates in {})", t.name);
        }
    }
    println!("\nAgainst VQF, measured in this run (ours / VQF's):");
    for t in trials {
        let (six, nine) = (t.six.rmse, t.nine.rmse);
        let (vqf_six, vqf_nine) = (t.vqf_six.rmse, t.vqf_nine.rmse);
        println!(
            "  {}: 6D inclination {:.3} against {:.3} ({:.2}); 9D total {:.3} against {:.3} ({:.2})",
            t.name,
            six.inclination,
            vqf_six.inclination,
            six.inclination / vqf_six.inclination,
            nine.total,
            vqf_nine.total,
            nine.total / vqf_nine.total,
        );
    }
    let check = |ok: bool| if ok { "met" } else { "MISSED" };
    if trials.len() > 1 {
        type Pair = fn(&Trial) -> (f64, f64);
        let metrics: [(&str, Pair); 2] = [
            ("6D inclination", |t| {
                (t.six.rmse.inclination, t.vqf_six.rmse.inclination)
            }),
            ("9D total", |t| (t.nine.rmse.total, t.vqf_nine.rmse.total)),
        ];
        for (title, pair) in metrics {
            let n = trials.len() as f64;
            let ours = trials.iter().map(|t| pair(t).0).sum::<f64>() / n;
            let vqf = trials.iter().map(|t| pair(t).1).sum::<f64>() / n;
            let (worst, ratio) = trials.iter().map(|t| (t, pair(t).0 / pair(t).1)).fold(
                (&trials[0], f64::NEG_INFINITY),
                |a, b| if b.1 > a.1 { b } else { a },
            );
            println!(
                "  {title}: mean of {} trials {ours:.3} against VQF's {vqf:.3}, at or below: {}; \
                 worst ratio {ratio:.2} ({}), within 1.2: {}",
                trials.len(),
                check(ours <= vqf),
                worst.name,
                check(ratio <= 1.2),
            );
        }
    }
    let verdicts: Vec<_> = trials
        .iter()
        .filter_map(|t| {
            let n = trial_number(&t.name)?;
            Some((t, PUBLISHED.iter().find(|p| p.trial == n)?))
        })
        .collect();
    if !verdicts.is_empty() {
        println!("\nAgainst the published figures of Madgwick and Mahony:");
    }
    for (t, p) in verdicts {
        let (six, nine) = (t.six.rmse, t.nine.rmse);
        let best_incl = p.madgwick.0.min(p.mahony.0);
        println!(
            "  {}: 6D and 9D inclination below Madgwick and Mahony ({best_incl:.2}): {}; 9D total below Madgwick ({:.2}): {}",
            t.name,
            check(six.inclination < best_incl && nine.inclination < best_incl),
            p.madgwick.1,
            check(nine.total < p.madgwick.1),
        );
    }
    for t in trials {
        let Rmse { samples, .. } = t.six.rmse;
        println!(
            "  {}: {} samples, {samples} scored",
            t.name,
            t.samples.len()
        );
    }
}

/// How the filters of [`print_peers`] other than ours run.
const SETTINGS: &str = "\
- VQF (PyPI): `vqf` VQF(0.0035).updateBatch, default parameters (tools/vqf_broad.py).
- uf-ahrs 0.2.2: Vqf / Mahony / Madgwick ::new(3.5 ms, *Params::default()) (Mahony kp 0.74, ki 0.0012; \
Madgwick beta 0.05), Ahrs::update (9D) and update_imu (6D); its north-west-up estimates turned to east-north-up.
- Fusion (PyPI): `imufusion` Ahrs with gain 0.5, gyroscope range 2000 deg/s, acceleration and magnetic rejection \
10 deg, rejection timeout 5 s, sample rate 2000/7 Hz, ENU, its gyroscope bias (offset) algorithm in front, \
as its README recommends; deg/s and g in (tools/fusion_broad.py).
Every filter starts at the first sample, without warm-up or alignment; the scored samples are the movement phase's.";

/// `rmse` of `run`, with the count of non-finite estimates if any.
fn cell(run: &Run, rmse: f64) -> String {
    let bad = run.estimates.iter().filter(|q| !q.is_finite()).count();
    if bad == 0 && rmse.is_finite() {
        format!("{rmse:.2}")
    } else {
        format!("{rmse:.2} ({bad} non-finite)")
    }
}

/// Every filter's 6D inclination and 9D total error, trial by trial, and
/// their means over the trials.
fn print_peers(trials: &[Trial], mag_delay: f32) {
    println!("\nAll filters on the same samples, the same metric (RMSE in degrees over the movement phase):");
    if mag_delay == 0.0 {
        println!("- ours: OrientationFilter::new(FilterParams::DEFAULT), dt 3.5 ms.");
    } else {
        println!(
            "- ours: OrientationFilter::new(FilterParams::DEFAULT with mag_delay {mag_delay} s), dt 3.5 ms \
             (the other filters get the magnetometer readings as recorded)."
        );
    }
    println!("{SETTINGS}");
    let names: Vec<&str> = ["ours", pypi::VQF.name]
        .into_iter()
        .chain(uf_ahrs::NAMES)
        .chain([pypi::FUSION.name])
        .collect();
    type Pick = fn(&Trial) -> [&Run; 6];
    let six: Pick = |t| t.runs(|six, _| six);
    let nine: Pick = |t| t.runs(|_, nine| nine);
    type Metric = fn(&Run) -> f64;
    let tables: [(&str, Pick, Metric); 2] = [
        ("6D inclination", six, |r| r.rmse.inclination),
        ("9D total", nine, |r| r.rmse.total),
    ];
    for (title, pick, metric) in tables {
        println!("\n{title}:\n");
        println!("| trial | {} |", names.join(" | "));
        println!("| --- |{}", " ---: |".repeat(names.len()));
        let mut sums = [0.0; 6];
        for t in trials {
            let runs = pick(t);
            let cells: Vec<String> = runs.iter().map(|r| cell(r, metric(r))).collect();
            for (sum, r) in sums.iter_mut().zip(runs) {
                *sum += metric(r);
            }
            println!("| {} | {} |", t.name, cells.join(" | "));
        }
        if trials.len() > 1 {
            let means: Vec<String> = sums
                .iter()
                .map(|s| format!("{:.2}", s / trials.len() as f64))
                .collect();
            println!(
                "| mean of {} trials | {} |",
                trials.len(),
                means.join(" | ")
            );
            // Each filter's largest ratio to VQF (PyPI) over the trials.
            let worst: Vec<String> = (0..names.len())
                .map(|k| {
                    let ratio = trials
                        .iter()
                        .map(|t| metric(pick(t)[k]) / metric(pick(t)[1]))
                        .fold(f64::NEG_INFINITY, f64::max);
                    format!("{ratio:.2}")
                })
                .collect();
            println!("| worst ratio to VQF (PyPI) | {} |", worst.join(" | "));
        }
    }
}

/// Roll, pitch and yaw (z-y-x Euler angles) of `q`, in degrees.
fn euler_degrees(q: Quat) -> [f64; 3] {
    let [w, x, y, z] = q.to_wxyz().map(f64::from);
    let roll = (2.0 * (w * x + y * z)).atan2(1.0 - 2.0 * (x * x + y * y));
    let pitch = (2.0 * (w * y - z * x)).clamp(-1.0, 1.0).asin();
    let yaw = (2.0 * (w * z + x * y)).atan2(1.0 - 2.0 * (y * y + z * z));
    [roll, pitch, yaw].map(f64::to_degrees)
}

fn print_fusion_summary(name: &str, samples: &[FusionSample]) {
    // The log is in deg/s and g: gravity is 1 in the accelerometer's unit.
    let params = FilterParams {
        gravity: 1.0,
        ..FilterParams::DEFAULT
    };
    let mut six = OrientationFilter::new(params);
    let mut nine = OrientationFilter::new(params);
    let (mut non_finite, mut resting, mut max_tilt) = (0usize, 0usize, 0.0f64);
    let (mut dt_min, mut dt_max) = (f64::INFINITY, 0.0f64);
    let mut previous = samples[0].time - (samples[1].time - samples[0].time);
    for s in samples {
        let dt = s.time - previous;
        previous = s.time;
        dt_min = dt_min.min(dt);
        dt_max = dt_max.max(dt);
        let gyr = s.gyr_deg * core::f32::consts::PI / 180.0;
        let q6 = six.update(gyr, s.acc_g, dt as f32);
        let q9 = nine.update_with_mag(gyr, s.acc_g, s.mag, dt as f32);
        non_finite += usize::from(!q6.is_finite()) + usize::from(!q9.is_finite());
        resting += usize::from(nine.is_resting());
        let up = q9.inv() * Cvec3::Z; // earth's up in the sensor frame
        max_tilt = max_tilt.max(f64::from(up.z.clamp(-1.0, 1.0)).acos().to_degrees());
    }
    let duration = samples[samples.len() - 1].time - samples[0].time;
    let [roll, pitch, yaw] = euler_degrees(nine.attitude());
    let [roll6, pitch6, yaw6] = euler_degrees(six.attitude());
    let bias = nine.bias() * 180.0 / core::f32::consts::PI;
    println!("\n{name}: x-io Fusion sample log, no ground truth");
    println!(
        "  {} samples over {duration:.1} s, dt from {:.1} to {:.1} ms",
        samples.len(),
        dt_min * 1e3,
        dt_max * 1e3
    );
    println!("  non-finite estimates: {non_finite} (6D and 9D together)");
    println!(
        "  at rest: {:.1} % of samples",
        100.0 * resting as f64 / samples.len() as f64
    );
    println!("  largest tilt from level (9D): {max_tilt:.1} deg");
    println!("  final attitude, roll / pitch / yaw (ENU, deg): 9D {roll:.1} / {pitch:.1} / {yaw:.1}, 6D {roll6:.1} / {pitch6:.1} / {yaw6:.1}");
    println!(
        "  final gyro bias estimate (9D): [{:.3}, {:.3}, {:.3}] deg/s",
        bias.x, bias.y, bias.z
    );
}
