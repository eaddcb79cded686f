//! Image files: PNG frames (`png` crate) and the animated GIF (`gif` crate),
//! each written to a temporary file beside its target and renamed into
//! place only once complete, so a failure never leaves a half-written file.

use std::fs::{self, File};
use std::io::{self, BufReader, BufWriter, Write};
use std::path::{Path, PathBuf};

use rayon::prelude::*;

use crate::image::Image;

/// The temporary name used while `path` is being written: hidden, beside
/// it (so that the rename stays on one file system), and unique to this
/// process.
fn temporary_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    path.with_file_name(format!(".{name}.tmp-{}", std::process::id()))
}

/// Writes a file through `write`, atomically: into a temporary file that is
/// renamed to `path` only after `write` succeeded and the data reached the
/// disk. On any error the temporary file is removed and `path` is left as
/// it was.
///
/// # Errors
///
/// The first I/O error, with the path in its message.
pub fn write_atomically(
    path: &Path,
    write: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>,
) -> io::Result<()> {
    let tmp = temporary_path(path);
    let result = (|| {
        let mut out = BufWriter::new(File::create(&tmp)?);
        write(&mut out)?;
        let file = out.into_inner().map_err(io::IntoInnerError::into_error)?;
        file.sync_all()?;
        fs::rename(&tmp, path)
    })();
    if result.is_err() {
        // The temporary file may not exist; there is nothing more to do.
        let _ = fs::remove_file(&tmp);
    }
    result.map_err(|e| io::Error::new(e.kind(), format!("cannot write {}: {e}", path.display())))
}

fn other(e: impl std::fmt::Display) -> io::Error {
    io::Error::other(e.to_string())
}

/// Writes `image` as an 8-bit RGB PNG, atomically.
///
/// # Errors
///
/// I/O and encoding errors, with the path in the message.
///
/// ```
/// use rigtform_render::output::{read_png, write_png};
/// use rigtform_render::Image;
/// let path = std::env::temp_dir().join(format!("rigtform-doc-{}.png", std::process::id()));
/// write_png(&path, &Image::new(2, 2, [1, 2, 3])).unwrap();
/// assert_eq!(read_png(&path).unwrap().pixel(1, 1), [1, 2, 3]);
/// std::fs::remove_file(&path).unwrap();
/// ```
pub fn write_png(path: &Path, image: &Image) -> io::Result<()> {
    write_atomically(path, |out| {
        let mut encoder = png::Encoder::new(out, image.width(), image.height());
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder.write_header().map_err(other)?;
        writer
            .write_image_data(&image.to_rgb_bytes())
            .map_err(other)?;
        writer.finish().map_err(other)
    })
}

/// Reads an 8-bit RGB or RGBA PNG (alpha is dropped).
///
/// # Errors
///
/// I/O and decoding errors, and other colour types or depths.
pub fn read_png(path: &Path) -> io::Result<Image> {
    let file = File::open(path)
        .map_err(|e| io::Error::new(e.kind(), format!("{}: {e}", path.display())))?;
    let mut reader = png::Decoder::new(BufReader::new(file))
        .read_info()
        .map_err(other)?;
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| other("PNG too large"))?;
    let mut buf = vec![0; size];
    let info = reader.next_frame(&mut buf).map_err(other)?;
    let bytes = &buf[..info.buffer_size()];
    let channels = match (info.color_type, info.bit_depth) {
        (png::ColorType::Rgb, png::BitDepth::Eight) => 3,
        (png::ColorType::Rgba, png::BitDepth::Eight) => 4,
        (c, d) => {
            return Err(other(format!(
                "{}: unsupported PNG format {c:?} {d:?}",
                path.display()
            )))
        }
    };
    let rgb: Vec<u8> = bytes
        .chunks_exact(channels)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect();
    Image::from_rgb_bytes(info.width, info.height, &rgb).ok_or_else(|| other("PNG size mismatch"))
}

/// Writes a looping animated GIF, atomically: `sequence` lists which of
/// `images` to show, in order, each for its delay in hundredths of a
/// second (an image may be shown more than once). Each image gets its own
/// 256-colour palette (NeuQuant, from the `gif` crate), computed once per
/// image, in parallel.
///
/// # Errors
///
/// An empty sequence, an index out of range, images of different sizes or
/// larger than 65535 pixels, and I/O or encoding errors.
///
/// ```
/// use rigtform_render::output::write_gif;
/// use rigtform_render::Image;
/// let images = [Image::new(4, 4, [255, 0, 0]), Image::new(4, 4, [0, 0, 255])];
/// let path = std::env::temp_dir().join(format!("rigtform-doc-{}.gif", std::process::id()));
/// write_gif(&path, &images, &[(0, 50), (1, 10), (0, 10)]).unwrap();
/// assert!(std::fs::metadata(&path).unwrap().len() > 0);
/// std::fs::remove_file(&path).unwrap();
/// ```
pub fn write_gif(path: &Path, images: &[Image], sequence: &[(usize, u16)]) -> io::Result<()> {
    if sequence.is_empty() {
        return Err(other("no frame for the GIF"));
    }
    if sequence.iter().any(|&(i, _)| i >= images.len()) {
        return Err(other("GIF frame index out of range"));
    }
    let (w, h) = (images[0].width(), images[0].height());
    if images.iter().any(|f| f.width() != w || f.height() != h) {
        return Err(other("GIF frames differ in size"));
    }
    let (w16, h16) = (
        u16::try_from(w).map_err(|_| other("image too wide for a GIF"))?,
        u16::try_from(h).map_err(|_| other("image too tall for a GIF"))?,
    );
    let frames: Vec<gif::Frame<'static>> = images
        .par_iter()
        .map(|image| gif::Frame::from_rgb_speed(w16, h16, &image.to_rgb_bytes(), 10))
        .collect();
    write_atomically(path, |out| {
        let mut encoder = gif::Encoder::new(out, w16, h16, &[]).map_err(other)?;
        encoder.set_repeat(gif::Repeat::Infinite).map_err(other)?;
        for &(i, delay) in sequence {
            let mut frame = frames[i].clone();
            frame.delay = delay;
            encoder.write_frame(&frame).map_err(other)?;
        }
        encoder.into_inner().map_err(other)?.flush()
    })
}

/// The files one run writes into its output folder, as paths relative to
/// it: the files named in `files`, and in the folder `frames` every file
/// whose name starts with `frame_` and ends with `.png`. Other files are
/// the user's and left alone.
#[derive(Clone, Copy, Debug)]
pub struct OutputSet<'a> {
    /// Files directly in the output folder.
    pub files: &'a [&'a str],
    /// The folder of numbered frames.
    pub frames: &'a str,
}

impl OutputSet<'_> {
    /// Whether `name`, a file of the folder `frames`, is one of the set's.
    fn is_frame(name: &str) -> bool {
        name.starts_with("frame_") && name.ends_with(".png")
    }

    /// The set's files that exist under `dir`, relative to it.
    fn existing(&self, dir: &Path) -> io::Result<Vec<PathBuf>> {
        let mut found: Vec<PathBuf> = self
            .files
            .iter()
            .map(PathBuf::from)
            .filter(|f| dir.join(f).is_file())
            .collect();
        match fs::read_dir(dir.join(self.frames)) {
            Ok(entries) => {
                for entry in entries {
                    let name = entry?.file_name();
                    if name.to_str().is_some_and(Self::is_frame) {
                        found.push(Path::new(self.frames).join(name));
                    }
                }
            }
            Err(e) if e.kind() == io::ErrorKind::NotFound => {}
            Err(e) => return Err(e),
        }
        found.sort();
        Ok(found)
    }
}

/// Writes a whole set of outputs into `dir` (created if missing), or
/// nothing: `write` writes the new set into a hidden staging folder inside
/// `dir`; only once it succeeded are the old set's files removed and the
/// new ones renamed into place. If `write` fails, the staging folder is
/// removed and `dir` keeps the old set untouched, so a folder never holds
/// files of two runs side by side.
///
/// # Errors
///
/// `write`'s error, or a message naming the path that could not be
/// created, removed or renamed.
///
/// ```
/// use rigtform_render::output::{replace_outputs, OutputSet};
/// let dir = std::env::temp_dir().join(format!("rigtform-doc-set-{}", std::process::id()));
/// let set = OutputSet { files: &["sheet.txt"], frames: "frames" };
/// replace_outputs(&dir, set, |stage| {
///     std::fs::write(stage.join("sheet.txt"), "new").map_err(|e| e.to_string())
/// })
/// .unwrap();
/// let failed = replace_outputs(&dir, set, |stage| {
///     std::fs::write(stage.join("sheet.txt"), "newer").map_err(|e| e.to_string())?;
///     Err("out of disk".to_string())
/// });
/// assert_eq!(failed.unwrap_err(), "out of disk");
/// assert_eq!(std::fs::read_to_string(dir.join("sheet.txt")).unwrap(), "new");
/// std::fs::remove_dir_all(&dir).unwrap();
/// ```
pub fn replace_outputs(
    dir: &Path,
    set: OutputSet<'_>,
    write: impl FnOnce(&Path) -> Result<(), String>,
) -> Result<(), String> {
    let stage = dir.join(format!(".rigtform-render-{}", std::process::id()));
    let created = fs::create_dir_all(stage.join(set.frames));
    created.map_err(|e| format!("cannot create {}: {e}", stage.display()))?;
    let result = write(&stage).and_then(|()| {
        let new = set
            .existing(&stage)
            .map_err(|e| format!("cannot list {}: {e}", stage.display()))?;
        let old = set
            .existing(dir)
            .map_err(|e| format!("cannot list {}: {e}", dir.display()))?;
        for f in &old {
            let path = dir.join(f);
            fs::remove_file(&path).map_err(|e| format!("cannot remove {}: {e}", path.display()))?;
        }
        fs::create_dir_all(dir.join(set.frames))
            .map_err(|e| format!("cannot create {}: {e}", dir.join(set.frames).display()))?;
        for f in &new {
            let to = dir.join(f);
            fs::rename(stage.join(f), &to)
                .map_err(|e| format!("cannot move {} into place: {e}", to.display()))?;
        }
        Ok(())
    });
    // Empty after a success; what a failure left is of no use.
    let _ = fs::remove_dir_all(&stage);
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("rigtform-output-{}-{name}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn png_round_trips() {
        let dir = scratch("png");
        let mut image = Image::new(5, 3, [10, 200, 30]);
        image.set_pixel(4, 2, [1, 2, 3]);
        let path = dir.join("a.png");
        write_png(&path, &image).unwrap();
        assert_eq!(read_png(&path).unwrap(), image);
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn failed_write_leaves_no_file_behind() {
        let dir = scratch("fail");
        let path = dir.join("b.png");
        fs::write(&path, b"old").unwrap();
        let err = write_atomically(&path, |out| {
            out.write_all(b"half")?;
            Err(io::Error::other("disk full"))
        })
        .unwrap_err();
        assert!(err.to_string().contains("b.png"), "{err}");
        assert_eq!(fs::read(&path).unwrap(), b"old");
        let left: Vec<_> = fs::read_dir(&dir).unwrap().collect();
        assert_eq!(left.len(), 1, "only the original file remains");
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn write_into_missing_folder_fails_cleanly() {
        let path = Path::new("/nonexistent-rigtform-dir/c.png");
        let err = write_png(path, &Image::new(1, 1, [0; 3])).unwrap_err();
        assert!(err.to_string().contains("c.png"));
    }

    #[test]
    fn failed_run_leaves_the_old_set_and_a_good_run_replaces_it_whole() {
        let dir = scratch("set");
        let set = OutputSet {
            files: &["sheet.png", "anim.gif"],
            frames: "frames",
        };
        let write = |names: &'static [&'static str], fail: bool| {
            move |stage: &Path| {
                for name in names {
                    fs::write(stage.join(name), "new").map_err(|e| e.to_string())?;
                }
                if fail {
                    Err("encoder failed".to_string())
                } else {
                    Ok(())
                }
            }
        };
        let old: &[&str] = &[
            "anim.gif",
            "frames/frame_000.png",
            "frames/frame_001.png",
            "frames/frame_002.png",
            "sheet.png",
        ];
        replace_outputs(&dir, set, write(old, false)).unwrap();
        fs::write(dir.join("frames/mine.png"), "mine").unwrap();
        fs::write(dir.join("notes.txt"), "mine").unwrap();
        let listing = || {
            let mut all: Vec<String> = ["", "frames"]
                .iter()
                .flat_map(|sub| fs::read_dir(dir.join(sub)).unwrap())
                .map(|e| e.unwrap().path())
                .filter(|p| p.is_file())
                .map(|p| p.strip_prefix(&dir).unwrap().display().to_string())
                .collect();
            all.sort();
            all
        };
        let before = listing();
        // A run that fails after writing part of its set changes nothing.
        let partial: &[&str] = &["frames/frame_000.png", "sheet.png"];
        let err = replace_outputs(&dir, set, write(partial, true)).unwrap_err();
        assert_eq!(err, "encoder failed");
        assert_eq!(listing(), before);
        assert_eq!(fs::read_to_string(dir.join("sheet.png")).unwrap(), "new");
        // A shorter run without the GIF leaves exactly its own files.
        replace_outputs(&dir, set, write(partial, false)).unwrap();
        assert_eq!(
            listing(),
            [
                "frames/frame_000.png",
                "frames/mine.png",
                "notes.txt",
                "sheet.png"
            ]
        );
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn gif_has_every_frame() {
        let dir = scratch("gif");
        let path = dir.join("a.gif");
        let images: Vec<_> = (0..3).map(|i| Image::new(8, 4, [i * 100, 50, 0])).collect();
        write_gif(&path, &images, &[(0, 50), (1, 4), (2, 7), (1, 4)]).unwrap();
        let mut decoder = gif::DecodeOptions::new()
            .read_info(File::open(&path).unwrap())
            .unwrap();
        let mut shown = Vec::new();
        while let Some(frame) = decoder.read_next_frame().unwrap() {
            let red = frame
                .palette
                .as_ref()
                .map_or(0, |p| p[3 * frame.buffer[0] as usize]);
            shown.push((red, frame.delay));
        }
        assert_eq!(shown, [(0, 50), (100, 4), (200, 7), (100, 4)]);
        assert!(write_gif(&path, &images, &[]).is_err());
        assert!(write_gif(&path, &images, &[(3, 1)]).is_err());
        for odd in [Image::new(8, 3, [0; 3]), Image::new(7, 4, [0; 3])] {
            let pair = [images[0].clone(), odd];
            assert!(write_gif(&path, &pair, &[(0, 1)]).is_err());
        }
        fs::remove_dir_all(&dir).unwrap();
    }
}
