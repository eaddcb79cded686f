//! `rigtform-render`: renders the demo into a folder of PNG frames, an
//! animated GIF and a contact sheet.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use clap::Parser;
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use rigtform_render::demo::gltf::{self, GltfDemo};
use rigtform_render::demo::spline::{self, Keyed, SplineDemo};
use rigtform_render::demo::{
    contact_sheet, gif_sequence, labelled_contact_sheet, load_body, sheet_frames, Comparison, Demo,
};
use rigtform_render::gltf_scene::GltfScene;
use rigtform_render::output::{replace_outputs, write_gif, write_png, OutputSet};
use rigtform_render::{Cull, Image, Msaa, Settings};

/// Renders keyframe animations of RigTForms: slerp side by side with
/// lerping matrices and lerping Euler angles, and the same keyframes seen
/// from a turned world frame.
#[derive(Debug, Parser)]
#[command(version)]
struct Args {
    /// Folder to write into (created if missing): frames/frame_NNN.png,
    /// animation.gif, contact_sheet.png.
    #[arg(short, long, default_value = "out")]
    out: PathBuf,

    /// Size of each panel in pixels, WIDTHxHEIGHT (16 to 4096 each).
    #[arg(short, long, default_value = "320x240", value_parser = parse_size)]
    size: (u32, u32),

    /// Number of frames from the first keyframe to the second (2 to 1000);
    /// with 4k + 1 frames the contact sheet shows alpha = 0, 1/4, 1/2, 3/4, 1.
    #[arg(short, long, default_value_t = 49, value_parser = clap::value_parser!(u32).range(2..=1000))]
    frames: u32,

    /// Which panels to show.
    #[arg(short, long, value_enum, default_value_t = Comparison::All)]
    comparison: Comparison,

    /// An OBJ file to animate instead of the axes body (scaled to fit).
    #[arg(long)]
    obj: Option<PathBuf>,

    /// Samples per pixel: 1, or 4 for multisample anti-aliasing.
    #[arg(long, default_value_t = 4, value_parser = parse_msaa)]
    msaa: u32,

    /// Worker threads (default: one per core). The images do not depend on it.
    #[arg(short, long, value_parser = clap::value_parser!(u32).range(1..=256))]
    threads: Option<u32>,

    /// Rows of the contact sheet: evenly spaced frames, first and last
    /// included (2 to the frame count; default 5, or the frame count if
    /// fewer).
    #[arg(long, value_parser = clap::value_parser!(u32).range(2..=1000))]
    sheet_rows: Option<u32>,

    /// The most memory the run may need, in MiB: settings that would need
    /// more (frames kept for the GIF and the contact sheet, one
    /// framebuffer per thread) are refused before anything is rendered.
    #[arg(long, default_value_t = 4096, value_parser = clap::value_parser!(u64).range(64..))]
    memory_limit: u64,

    /// Play a glTF 2.0 file's animation instead (.gltf with its buffers
    /// inline or beside it, or .glb): every channel of every animation on
    /// one clock, from the earliest key to the latest, through rigtform's
    /// samplers. Skins and morph targets are not played (a note says so).
    #[arg(long, value_name = "FILE", conflicts_with_all = ["comparison", "spline", "obj"])]
    gltf: Option<PathBuf>,

    /// Skip the GIF (it is the slowest file to encode).
    #[arg(long)]
    no_gif: bool,

    /// Render the keyframe comparison instead: five keyframes by slerp key
    /// to key beside the Catmull-Rom spline, over 4 s, and a plot of their
    /// angular speed (angular_speed.png).
    #[arg(long, conflicts_with = "comparison")]
    spline: bool,
}

fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("expected WIDTHxHEIGHT such as 320x240, got {s:?}"))?;
    let parse = |v: &str, what: &str| -> Result<u32, String> {
        let n: u32 = v
            .trim()
            .parse()
            .map_err(|_| format!("{what} {v:?} is not a whole number"))?;
        if (16..=4096).contains(&n) {
            Ok(n)
        } else {
            Err(format!("{what} {n} is outside 16 to 4096"))
        }
    };
    Ok((parse(w, "width")?, parse(h, "height")?))
}

fn parse_msaa(s: &str) -> Result<u32, String> {
    match s {
        "1" => Ok(1),
        "4" => Ok(4),
        _ => Err(format!("samples per pixel must be 1 or 4, got {s:?}")),
    }
}

/// Gap between panels, in pixels (the demo's layout).
const PANEL_GAP: u64 = 4;
/// The contact sheet's margin and gap, in pixels (its layout).
const SHEET_MARGIN: u64 = 8 * 11 + 8;

/// An upper estimate of the bytes a run needs at its peak, the largest of
/// its three phases: rendering (`threads` frames at a time, each with its
/// framebuffer, panel and frame images and the PNG's bytes, beside the
/// frames kept), the contact sheet, and the GIF (one palette image per
/// frame, and per thread the quantizer's copies of a frame).
fn memory_needed(args: &Args, panels: u64, sheet_rows: u64, threads: u64) -> u64 {
    let (w, h) = (u64::from(args.size.0), u64::from(args.size.1));
    let samples = if args.msaa == 4 { 4 } else { 1 };
    let frames = u64::from(args.frames);
    let frame_pixels =
        (panels * w + (panels - 1) * PANEL_GAP) * (h + u64::from(rigtform_render::demo::LABEL_BAR));
    let frame = 3 * frame_pixels;
    let kept = if args.no_gif { sheet_rows } else { frames } * frame;
    let in_flight = threads.min(frames);
    let rendering = kept + in_flight * (16 * samples * w * h + 3 * w * h + 3 * frame);
    let sheet = kept + 2 * 3 * sheet_rows * (frame_pixels + (SHEET_MARGIN + PANEL_GAP) * h);
    let gif = if args.no_gif {
        0
    } else {
        kept + frames * frame_pixels + in_flight * 7 * frame_pixels + frame_pixels
    };
    rendering.max(sheet).max(gif)
}

/// The outputs of a run, staged and swapped in whole.
const OUTPUTS: OutputSet<'static> = OutputSet {
    files: &["contact_sheet.png", "animation.gif", "angular_speed.png"],
    frames: "frames",
};

/// `--gltf`: loads and checks the whole file before anything is written,
/// then renders its animation into frames, a contact sheet and a GIF,
/// staged and swapped in whole as the demo's.
fn run_gltf(
    args: &Args,
    path: &Path,
    sheet_rows: u32,
    pool: &rayon::ThreadPool,
    start: Instant,
) -> Result<String, String> {
    let scene = GltfScene::load(path)?;
    for note in &scene.unsupported {
        eprintln!("note: {}: {note}", path.display());
    }
    let title = path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let demo = GltfDemo::new(scene, title);
    let (t0, t1) = demo.scene().span();
    let settings = Settings {
        width: args.size.0,
        height: args.size.1,
        msaa: if args.msaa == 4 { Msaa::X4 } else { Msaa::Off },
        cull: Cull::Back,
    };
    let mut written = String::new();
    replace_outputs(&args.out, OUTPUTS, |stage| {
        let frames_dir = stage.join(OUTPUTS.frames);
        let images: Vec<Image> = pool.install(|| {
            (0..args.frames)
                .into_par_iter()
                .map(|i| {
                    let image = demo.render_frame(demo.time(i, args.frames), &settings);
                    write_png(&frames_dir.join(format!("frame_{i:03}.png")), &image)
                        .map_err(|e| e.to_string())?;
                    Ok(image)
                })
                .collect::<Result<_, String>>()
        })?;
        let rows: Vec<(f32, &Image)> = sheet_frames(args.frames, sheet_rows)
            .into_iter()
            .map(|i| (demo.time(i, args.frames), &images[i as usize]))
            .collect();
        write_png(
            &stage.join("contact_sheet.png"),
            &labelled_contact_sheet(&rows, "t (s)"),
        )
        .map_err(|e| e.to_string())?;
        written = format!(
            "{} frames of {} channel(s), {t0:.3} s to {t1:.3} s, in {}, {}",
            args.frames,
            demo.scene().channels.len(),
            args.out.join(OUTPUTS.frames).display(),
            args.out.join("contact_sheet.png").display()
        );
        if !args.no_gif {
            let sequence = gltf::gif_sequence(args.frames, t1 - t0);
            pool.install(|| write_gif(&stage.join("animation.gif"), &images, &sequence))
                .map_err(|e| e.to_string())?;
            written += &format!(", {}", args.out.join("animation.gif").display());
        }
        Ok(())
    })?;
    Ok(format!(
        "wrote {written} in {:.2} s",
        start.elapsed().as_secs_f64()
    ))
}

fn run(args: &Args) -> Result<String, String> {
    let start = Instant::now();
    let sheet_rows = args.sheet_rows.unwrap_or(args.frames.min(5));
    if sheet_rows > args.frames {
        return Err(format!(
            "--sheet-rows {sheet_rows} is more than --frames {}",
            args.frames
        ));
    }
    let threads = match args.threads {
        Some(n) => u64::from(n),
        None => std::thread::available_parallelism().map_or(1, |n| n.get() as u64),
    };
    let panels = if args.gltf.is_some() {
        1
    } else if args.spline {
        Keyed::BOTH.len()
    } else {
        args.comparison.panels().len()
    } as u64;
    let needed = memory_needed(args, panels, u64::from(sheet_rows), threads);
    if needed > args.memory_limit << 20 {
        return Err(format!(
            "--size {}x{} with --frames {} needs about {} MiB, more than --memory-limit {} MiB: \
             use a smaller --size, fewer --frames, --no-gif or fewer --threads, \
             or raise --memory-limit if the machine has the memory",
            args.size.0,
            args.size.1,
            args.frames,
            needed.div_ceil(1 << 20),
            args.memory_limit
        ));
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads as usize)
        .build()
        .map_err(|e| format!("cannot start threads: {e}"))?;
    if let Some(path) = &args.gltf {
        return run_gltf(args, path, sheet_rows, &pool, start);
    }
    let body = args.obj.as_deref().map(load_body).transpose()?;
    let spline_demo = args.spline.then(|| SplineDemo::new(body.clone()));
    let demo = Demo::new(args.comparison, body);
    let settings = Settings {
        width: args.size.0,
        height: args.size.1,
        msaa: if args.msaa == 4 { Msaa::X4 } else { Msaa::Off },
        cull: Cull::Back,
    };
    let set = OUTPUTS;
    let mut render_time = start.elapsed();
    let mut written = String::new();
    replace_outputs(&args.out, set, |stage| {
        let frames_dir = stage.join(set.frames);
        let bar = ProgressBar::new(u64::from(args.frames)).with_style(
            ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} frames, {elapsed}")
                .map_err(|e| e.to_string())?
                .progress_chars("=> "),
        );
        bar.set_message("rendering");
        let on_sheet = sheet_frames(args.frames, sheet_rows);
        // Frames in parallel (and bands in parallel inside each): every frame is
        // a pure function of its alpha, so the files do not depend on the order.
        // Only the frames the GIF or the contact sheet shows are kept.
        let images: Vec<Option<Image>> = pool.install(|| {
            (0..args.frames)
                .into_par_iter()
                .map(|i| {
                    let alpha = Demo::alpha(i, args.frames);
                    let image = match &spline_demo {
                        Some(s) => s.render_frame(alpha, &settings),
                        None => demo.render_frame(alpha, &settings),
                    };
                    write_png(&frames_dir.join(format!("frame_{i:03}.png")), &image)
                        .map_err(|e| e.to_string())?;
                    bar.inc(1);
                    Ok((!args.no_gif || on_sheet.contains(&i)).then_some(image))
                })
                .collect::<Result<_, String>>()
        })?;
        bar.finish_and_clear();
        render_time = start.elapsed();

        let rows: Vec<(f32, &Image)> = on_sheet
            .iter()
            .filter_map(|&i| Some((Demo::alpha(i, args.frames), images[i as usize].as_ref()?)))
            .collect();
        write_png(&stage.join("contact_sheet.png"), &contact_sheet(&rows))
            .map_err(|e| e.to_string())?;
        let out = &args.out;
        written = format!(
            "{} frames in {}, {}",
            args.frames,
            out.join(set.frames).display(),
            out.join("contact_sheet.png").display()
        );
        if let Some(s) = &spline_demo {
            write_png(
                &stage.join("angular_speed.png"),
                &spline::speed_plot(s.keys(), 640, 320),
            )
            .map_err(|e| e.to_string())?;
            written += &format!(", {}", out.join("angular_speed.png").display());
        }
        if !args.no_gif {
            let images: Vec<Image> = images.into_iter().flatten().collect();
            let there_and_back = gif_sequence(args.frames);
            pool.install(|| write_gif(&stage.join("animation.gif"), &images, &there_and_back))
                .map_err(|e| e.to_string())?;
            written += &format!(", {}", out.join("animation.gif").display());
        }
        Ok(())
    })?;
    if let Some(s) = &spline_demo {
        for method in Keyed::BOTH {
            let (jump, key) = spline::largest_jump(method, s.keys());
            println!(
                "{}: largest angular velocity jump at a key {jump:.3e} rad/s (key {key})",
                method.title()
            );
        }
    }
    Ok(format!(
        "wrote {written} in {:.2} s (rendering and PNGs {:.2} s, {} threads)",
        start.elapsed().as_secs_f64(),
        render_time.as_secs_f64(),
        pool.current_num_threads()
    ))
}

fn main() -> ExitCode {
    let args = Args::parse();
    match run(&args) {
        Ok(summary) => {
            println!("{summary}");
            ExitCode::SUCCESS
        }
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}
