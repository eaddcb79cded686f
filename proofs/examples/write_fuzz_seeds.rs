//! Writes the fuzz targets' seed corpus (`fuzz/seeds/<target>/`) from the
//! shared edge values, in the byte layout `arbitrary` reads: each `f32` as
//! its four little-endian bytes, fields in declaration order, a `bool` as
//! one byte (odd is true).
//!
//! Run from the repository root: `cargo run -p rigtform-proofs --example write_fuzz_seeds`.

use rigtform_proofs::edge::EDGE_F32;
use std::fs;
use std::path::Path;

fn bytes(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}

/// Replaces the `edge-*` seeds of `target`; other seeds (the inputs of
/// regression tests) stay.
fn write(target: &str, seeds: Vec<Vec<u8>>) -> std::io::Result<()> {
    let dir = Path::new("fuzz/seeds").join(target);
    fs::create_dir_all(&dir)?;
    for entry in fs::read_dir(&dir)? {
        let path = entry?.path();
        if path
            .file_name()
            .and_then(|n| n.to_str())
            .is_some_and(|n| n.starts_with("edge-"))
        {
            fs::remove_file(path)?;
        }
    }
    for (i, seed) in seeds.iter().enumerate() {
        fs::write(dir.join(format!("edge-{i:03}")), seed)?;
    }
    println!("{}: {} seeds", dir.display(), seeds.len());
    Ok(())
}

fn main() -> std::io::Result<()> {
    if !Path::new("fuzz/Cargo.toml").exists() {
        eprintln!("error: run this from the repository root (fuzz/Cargo.toml not found)");
        std::process::exit(2);
    }
    let mut pow = Vec::new();
    let mut slerp = Vec::new();
    let mut rigid = Vec::new();
    let mut matrix = Vec::new();
    let mut constructors = Vec::new();
    for (i, e) in EDGE_F32.into_iter().enumerate() {
        // The atan2 edge cases: w itself, a tiny or huge vector part beside
        // w = +-1 or 0, every component alike, and e as the exponent.
        pow.push(bytes(&[e, 0.0, 0.0, 0.0, 0.5]));
        pow.push(bytes(&[1.0, e, 0.0, 0.0, 0.5]));
        pow.push(bytes(&[-1.0, 0.0, e, 0.0, 0.5]));
        pow.push(bytes(&[0.0, e, e, 0.0, 2.0]));
        pow.push(bytes(&[e, e, e, e, e]));
        pow.push(bytes(&[0.5, 0.5, 0.5, 0.5, e]));
        // Identical, antipodal and opposite pairs, and an edge alpha.
        let a = [0.5, 0.5, 0.5, 0.5];
        let pair = |b: [f32; 4], alpha: f32| {
            bytes(
                &[
                    a.as_slice(),
                    &b,
                    &[1.0, 0.0, 0.0, 0.0],
                    &[alpha, 1.0, e, -1.0],
                ]
                .concat(),
            )
        };
        slerp.push(pair(a, e));
        slerp.push(pair([-0.5, -0.5, -0.5, -0.5], 0.5));
        slerp.push(pair([0.5, -0.5, -0.5, -0.5], e));
        slerp.push(pair([e, 0.5, 0.5, 0.5], 0.25));
        // A rigid motion with an edge translation, rotation component or point.
        let mut rbt = bytes(&[
            e, 1.0, -2.0, 1.0, e, 0.0, 0.0, 3.0, 0.0, e, 0.0, 1.0, 0.0, 0.5, e, 2.0, 3.0,
        ]);
        rbt.push(1);
        rigid.push(rbt);
        let mut rbt = bytes(&[
            1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 1.0, e, e, e, e, e, e, e, 4.0, e, 6.0,
        ]);
        rbt.push(0);
        rigid.push(rbt);
        // The identity with one edge entry, and a matrix of one value.
        for k in [0, 5, 12, 15] {
            let mut m = [
                1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
            ];
            m[k] = e;
            matrix.push(bytes(&m));
        }
        matrix.push(bytes(&[e; 16]));
        // Euler angles at gimbal lock and of an edge rotation, opposite and
        // edge directions, and an edge entry in a rotation matrix; the
        // order byte cycles through the six orders.
        let lock = core::f32::consts::FRAC_PI_2;
        let order = [u8::try_from(i % 6).unwrap_or(0)];
        let identity = [
            1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
        ];
        for (q, angles, from, to, up) in [
            (
                [e, 0.5, 0.5, 0.5],
                [0.3, lock, e],
                [1.0, 0.0, 0.0],
                [-1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
            ),
            (
                [0.5, -0.5, 0.5, e],
                [e, -lock, 0.2],
                [e, 1.0, 2.0],
                [-e, -1.0, -2.0],
                [e, e, e],
            ),
            (
                [0.0, 0.0, e, 1.0],
                [1.0, e, 1.0],
                [0.0, 0.0, e],
                [e, 0.0, 1.0],
                [0.0, 0.0, 1.0],
            ),
        ] {
            let mut m = identity;
            m[i % 11] = e;
            constructors.push(
                [
                    bytes(&q),
                    bytes(&angles),
                    order.to_vec(),
                    bytes(&[from, to, up].concat()),
                    bytes(&m),
                ]
                .concat(),
            );
        }
    }
    write("pow", pow)?;
    write("slerp", slerp)?;
    write("rigtform", rigid)?;
    write("matrix", matrix)?;
    write("constructors", constructors)?;
    Ok(())
}
