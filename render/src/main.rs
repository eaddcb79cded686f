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
use rigtform_render::output::{write_gif, write_png};
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
    /// included (2 to the frame count).
    #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u32).range(2..=1000))]
    sheet_rows: u32,

    /// Skip the GIF (it is the slowest file to encode).
    #[arg(long)]
    no_gif: bool,

    /// Render the keyframe comparison instead: five keyframes by slerp key
    /// to key beside the Catmull-Rom spline, over 4 s, and a plot of their
    /// angular speed (angular_speed.png).
    #[arg(long, conflicts_with = "comparison")]
    spline: bool,

    /// Play a glTF 2.0 file's animation instead (.gltf with its buffers
    /// inline or beside it, or .glb): every channel of every animation on
    /// one clock, from the earliest key to the latest, through rigtform's
    /// samplers. Skins and morph targets are not played (a note says so).
    #[arg(long, value_name = "FILE", conflicts_with_all = ["comparison", "spline", "obj"])]
    gltf: Option<PathBuf>,
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

/// Removes frame files an earlier, longer run left behind.
fn remove_old_frames(dir: &Path) -> std::io::Result<()> {
    for entry in std::fs::read_dir(dir)? {
        let path = entry?.path();
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
        if name.starts_with("frame_") && name.ends_with(".png") {
            std::fs::remove_file(&path)?;
        }
    }
    Ok(())
}

/// `--gltf`: loads and checks the whole file before anything is written,
/// then renders its animation into frames, a contact sheet and a GIF.
fn run_gltf(args: &Args, path: &Path, start: Instant) -> Result<String, String> {
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
    let frames_dir = args.out.join("frames");
    std::fs::create_dir_all(&frames_dir)
        .map_err(|e| format!("cannot create {}: {e}", frames_dir.display()))?;
    remove_old_frames(&frames_dir)
        .map_err(|e| format!("cannot clean {}: {e}", frames_dir.display()))?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads.unwrap_or(0) as usize)
        .build()
        .map_err(|e| format!("cannot start threads: {e}"))?;
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
    let rows: Vec<(f32, &Image)> = sheet_frames(args.frames, args.sheet_rows)
        .into_iter()
        .map(|i| (demo.time(i, args.frames), &images[i as usize]))
        .collect();
    let sheet_path = args.out.join("contact_sheet.png");
    write_png(&sheet_path, &labelled_contact_sheet(&rows, "t (s)")).map_err(|e| e.to_string())?;
    let mut written = format!(
        "{} frames of {} channel(s), {t0:.3} s to {t1:.3} s, in {}, {}",
        args.frames,
        demo.scene().channels.len(),
        frames_dir.display(),
        sheet_path.display()
    );
    if !args.no_gif {
        let gif_path = args.out.join("animation.gif");
        let sequence = gltf::gif_sequence(args.frames, t1 - t0);
        pool.install(|| write_gif(&gif_path, &images, &sequence))
            .map_err(|e| e.to_string())?;
        written += &format!(", {}", gif_path.display());
    }
    Ok(format!(
        "wrote {written} in {:.2} s",
        start.elapsed().as_secs_f64()
    ))
}

fn run(args: &Args) -> Result<String, String> {
    let start = Instant::now();
    if args.sheet_rows > args.frames {
        return Err(format!(
            "--sheet-rows {} is more than --frames {}",
            args.sheet_rows, args.frames
        ));
    }
    if let Some(path) = &args.gltf {
        return run_gltf(args, path, start);
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
    let frames_dir = args.out.join("frames");
    std::fs::create_dir_all(&frames_dir)
        .map_err(|e| format!("cannot create {}: {e}", frames_dir.display()))?;
    remove_old_frames(&frames_dir)
        .map_err(|e| format!("cannot clean {}: {e}", frames_dir.display()))?;

    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads.unwrap_or(0) as usize)
        .build()
        .map_err(|e| format!("cannot start threads: {e}"))?;
    let bar = ProgressBar::new(u64::from(args.frames)).with_style(
        ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} frames, {elapsed}")
            .map_err(|e| e.to_string())?
            .progress_chars("=> "),
    );
    bar.set_message("rendering");
    // Frames in parallel (and bands in parallel inside each): every frame is
    // a pure function of its alpha, so the files do not depend on the order.
    let images: Vec<Image> = pool.install(|| {
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
                Ok(image)
            })
            .collect::<Result<_, String>>()
    })?;
    bar.finish_and_clear();
    let render_time = start.elapsed();

    let rows: Vec<(f32, &Image)> = sheet_frames(args.frames, args.sheet_rows)
        .into_iter()
        .map(|i| (Demo::alpha(i, args.frames), &images[i as usize]))
        .collect();
    let sheet_path = args.out.join("contact_sheet.png");
    write_png(&sheet_path, &contact_sheet(&rows)).map_err(|e| e.to_string())?;
    let mut written = format!(
        "{} frames in {}, {}",
        args.frames,
        frames_dir.display(),
        sheet_path.display()
    );
    if let Some(s) = &spline_demo {
        let plot_path = args.out.join("angular_speed.png");
        write_png(&plot_path, &spline::speed_plot(s.keys(), 640, 320))
            .map_err(|e| e.to_string())?;
        written += &format!(", {}", plot_path.display());
        for method in Keyed::BOTH {
            let (jump, key) = spline::largest_jump(method, s.keys());
            println!(
                "{}: largest angular velocity jump at a key {jump:.3e} rad/s (key {key})",
                method.title()
            );
        }
    }
    if !args.no_gif {
        let there_and_back = gif_sequence(args.frames);
        let gif_path = args.out.join("animation.gif");
        pool.install(|| write_gif(&gif_path, &images, &there_and_back))
            .map_err(|e| e.to_string())?;
        written += &format!(", {}", gif_path.display());
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
