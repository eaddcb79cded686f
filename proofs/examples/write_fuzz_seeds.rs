//! Writes the fuzz targets' seed corpus (`fuzz/seeds/<target>/`) from the
//! shared edge values, in the byte layout `arbitrary` reads: each `f32` as
//! its four little-endian bytes, fields in declaration order, a `bool` as
//! one byte (odd is true). It also writes the inputs the fuzzers found
//! (`fuzz/regressions/<target>/`), which `.ci/run` fuzzes from and
//! `tests/fuzz_regressions.rs` replays through the targets' laws.
//!
//! One quirk of `arbitrary` 1.5: when the last field is an array, its last
//! element is read again from the bytes after the array (zero if there are
//! none). The regressions are written with that element in both places, so
//! that every reading of the file agrees; in the edge seeds it is whatever
//! follows.
//!
//! Run from the repository root: `cargo run -p rigtform-proofs --example write_fuzz_seeds`.

use rigtform_proofs::edge::EDGE_F32;
use std::fs;
use std::path::Path;

fn bytes(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}

/// Replaces the `edge-*` seeds of `target`; other files stay.
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

/// `values`, then the last of them again: the layout whose every field
/// `arbitrary` reads as written when the last field is an array.
fn bytes_with_last_again(values: &[f32]) -> Vec<u8> {
    let mut all = values.to_vec();
    all.extend(values.last());
    bytes(&all)
}

/// Writes (or rewrites) the named regressions of `target`; other files in
/// the folder stay.
fn write_regressions(target: &str, inputs: &[(&str, Vec<u8>)]) -> std::io::Result<()> {
    let dir = Path::new("fuzz/regressions").join(target);
    fs::create_dir_all(&dir)?;
    for (name, input) in inputs {
        fs::write(dir.join(name), input)?;
    }
    println!("{}: {} regressions", dir.display(), inputs.len());
    Ok(())
}

/// The inputs the fuzzers found that broke a law once.
fn regressions() -> std::io::Result<()> {
    // pow of a huge w beside a vector part below 2^-80, to the power -1e30:
    // the vector part's scaling overflows w to infinity, phi rounds to 0,
    // and the result must still be finite and unit (alpha is beyond the
    // range of the law of the notes' angle).
    write_regressions(
        "pow",
        &[(
            "huge-w-tiny-vector-alpha-minus-1e30",
            bytes(&[2.7e10, 1.0e-26, -9.6e-35, 2.5e-30, -1e30]),
        )],
    )?;
    // Rotations exactly pi apart (a . b = 0): either way round is the short
    // way, at alpha in the middle and extrapolated beyond both ends.
    let (a, b) = ([1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]);
    let c = [0.5, 0.5, 0.5, 0.5];
    let pair = |alpha: f32| {
        bytes_with_last_again(&[a.as_slice(), &b, &c, &[alpha, 1.0, 1.0, 1.0]].concat())
    };
    write_regressions(
        "slerp",
        &[
            ("pi-apart-half-way", pair(0.5)),
            ("pi-apart-extrapolated", pair(-0.75)),
            ("pi-apart-far-extrapolated", pair(1.0e6)),
        ],
    )
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
    let mut sampler = Vec::new();
    for (i, e) in EDGE_F32.into_iter().enumerate() {
        // Key times with one edge value, identity keys with one edge
        // component, each interpolation and key count (the selector's
        // bits), and an edge time.
        let mut values = [0.0f32; 48];
        for q in values.chunks_exact_mut(4) {
            q[3] = 1.0;
        }
        values[i % 48] = e;
        for selector in [0u32, 1, 2, 13, 14, 15] {
            sampler.push(bytes(
                &[
                    [0.0, 0.5, e, 2.0].as_slice(),
                    &values,
                    &[f32::from_bits(selector), e],
                ]
                .concat(),
            ));
        }
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
    write("sampler", sampler)?;
    regressions()
}
