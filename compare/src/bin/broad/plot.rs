//! The error-over-time plot of the `broad` binary: one panel per BROAD
//! trial, 6D inclination error and 9D total error in degrees, ours and
//! VQF's (measured in the same run).

use std::path::Path;

use plotters::prelude::*;

use crate::Trial;
use rigtform_testkit::broad::metric::sample_error;

/// Where the binary looks for a font for the plot's labels (the plot is
/// drawn without text if none is found): `RIGTFORM_FONT`, else DejaVu Sans
/// where Debian and Ubuntu install it.
const FONT_PATHS: [&str; 2] = [
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
];

fn register_font() -> bool {
    let from_env = std::env::var("RIGTFORM_FONT").ok();
    for path in from_env.iter().map(String::as_str).chain(FONT_PATHS) {
        if let Ok(bytes) = std::fs::read(path) {
            let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
            if plotters::style::register_font("sans-serif", FontStyle::Normal, bytes).is_ok() {
                return true;
            }
        }
    }
    false
}

/// Samples per plotted point: the largest error of each run of this many
/// samples, so that peaks survive.
const BUCKET: usize = 35;

/// Writes the plot to `path` (PNG): to a temporary file first, renamed at
/// the end, so that no half-written plot is left behind.
pub fn write(path: &Path, trials: &[Trial]) -> Result<(), String> {
    let labels = register_font();
    if !labels {
        eprintln!("note: no font found (set RIGTFORM_FONT to a .ttf file); the plot has no labels");
    }
    let temporary = path.with_extension("partial.png");
    draw(&temporary, trials, labels).map_err(|e| {
        let _ = std::fs::remove_file(&temporary);
        format!("{}: {e}", path.display())
    })?;
    std::fs::rename(&temporary, path).map_err(|e| {
        let _ = std::fs::remove_file(&temporary);
        format!("{}: {e}", path.display())
    })
}

/// Per bucket of samples: time (s), then the largest 6D inclination error
/// and the largest 9D total error (degrees), ours and VQF's, over the
/// samples with ground truth.
fn series(t: &Trial) -> Vec<(f64, [f64; 4])> {
    let dt = f64::from(rigtform_testkit::broad::data::BROAD_DT);
    let mut points = Vec::new();
    for (k, chunk) in t.samples.chunks(BUCKET).enumerate() {
        let mut worst: Option<[f64; 4]> = None;
        for (i, s) in chunk.iter().enumerate() {
            if s.truth.iter().any(|c| c.is_nan()) {
                continue;
            }
            let j = k * BUCKET + i;
            let errors = [
                sample_error(t.six.estimates[j], s.truth).inclination,
                sample_error(t.nine.estimates[j], s.truth).total,
                sample_error(t.vqf_six.estimates[j], s.truth).inclination,
                sample_error(t.vqf_nine.estimates[j], s.truth).total,
            ];
            let w = worst.unwrap_or([0.0; 4]);
            worst = Some(core::array::from_fn(|c| w[c].max(errors[c])));
        }
        if let Some(w) = worst {
            points.push(((k * BUCKET) as f64 * dt, w));
        }
    }
    points
}

fn draw(path: &Path, trials: &[Trial], labels: bool) -> Result<(), Box<dyn std::error::Error>> {
    let (width, height) = (800u32, 220 * trials.len() as u32);
    let mut rgb = vec![0u8; (width * height * 3) as usize];
    plot_into(&mut rgb, (width, height), trials, labels)?;
    encode_png(path, &rgb, (width, height))
}

/// Encodes an RGB image as an indexed PNG: the 256 most frequent colours
/// form the palette, and the rare others (anti-aliasing shades) take the
/// nearest of them. A third of the size of the RGB file, with no visible
/// change.
fn encode_png(
    path: &Path,
    rgb: &[u8],
    (width, height): (u32, u32),
) -> Result<(), Box<dyn std::error::Error>> {
    let pixels: Vec<[u8; 3]> = rgb.chunks_exact(3).map(|p| [p[0], p[1], p[2]]).collect();
    let mut counts = std::collections::HashMap::new();
    for &p in &pixels {
        *counts.entry(p).or_insert(0u32) += 1;
    }
    let mut by_count: Vec<([u8; 3], u32)> = counts.into_iter().collect();
    by_count.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    let palette: Vec<[u8; 3]> = by_count.iter().take(256).map(|&(c, _)| c).collect();
    let distance = |a: [u8; 3], b: [u8; 3]| -> i32 {
        (0..3)
            .map(|i| (i32::from(a[i]) - i32::from(b[i])).pow(2))
            .sum()
    };
    let mut index_of = std::collections::HashMap::new();
    let indices: Vec<u8> = pixels
        .iter()
        .map(|&p| {
            *index_of.entry(p).or_insert_with(|| {
                (0..palette.len())
                    .min_by_key(|&i| distance(p, palette[i]))
                    .unwrap_or(0) as u8
            })
        })
        .collect();
    let file = std::io::BufWriter::new(std::fs::File::create(path)?);
    let mut encoder = png::Encoder::new(file, width, height);
    encoder.set_compression(png::Compression::High);
    encoder.set_color(png::ColorType::Indexed);
    encoder.set_palette(palette.concat());
    encoder.write_header()?.write_image_data(&indices)?;
    Ok(())
}

fn plot_into(
    rgb: &mut [u8],
    size: (u32, u32),
    trials: &[Trial],
    labels: bool,
) -> Result<(), Box<dyn std::error::Error>> {
    let root = BitMapBackend::with_buffer(rgb, size).into_drawing_area();
    root.fill(&WHITE)?;
    let six_colour = RGBColor(31, 119, 180);
    let nine_colour = RGBColor(214, 39, 40);
    let vqf_six_colour = RGBColor(140, 190, 230);
    let vqf_nine_colour = RGBColor(240, 150, 150);
    for (panel, t) in root.split_evenly((trials.len(), 1)).iter().zip(trials) {
        let points = series(t);
        let end = points.last().map_or(1.0, |p| p.0);
        // Up to the 99.5th percentile of both curves, so one spike does not flatten the rest.
        let mut values: Vec<f64> = points.iter().flat_map(|p| p.1).collect();
        values.sort_by(f64::total_cmp);
        let top = values
            .get(values.len() * 995 / 1000)
            .copied()
            .unwrap_or(1.0)
            .max(1.0)
            * 1.2;
        let mut builder = ChartBuilder::on(panel);
        builder.margin(8);
        if labels {
            builder
                .caption(
                    format!("{}: error over time (deg)", t.name),
                    ("sans-serif", 18),
                )
                .x_label_area_size(30)
                .y_label_area_size(40);
        }
        let mut chart = builder.build_cartesian_2d(0.0..end, 0.0..top)?;
        let mut mesh = chart.configure_mesh();
        mesh.light_line_style(WHITE.mix(0.0));
        if labels {
            mesh.x_desc("time (s)");
        } else {
            mesh.x_labels(0).y_labels(0);
        }
        mesh.draw()?;
        let clip = |v: f64| v.min(top);
        // VQF's curves first, in lighter colours, so ours stay on top.
        let curves = [
            ("VQF 6D inclination", vqf_six_colour, 2),
            ("VQF 9D total", vqf_nine_colour, 3),
            ("ours 6D inclination", six_colour, 0),
            ("ours 9D total", nine_colour, 1),
        ];
        for (name, colour, column) in curves {
            let line = points.iter().map(|p| (p.0, clip(p.1[column])));
            let series = chart.draw_series(LineSeries::new(line, colour))?;
            if labels {
                series
                    .label(name)
                    .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], colour));
            }
        }
        if labels {
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .position(SeriesLabelPosition::UpperRight)
                .draw()?;
        }
    }
    root.present()?;
    Ok(())
}
