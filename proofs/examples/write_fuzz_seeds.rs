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
            // Then an axis and angle, and a scaled axis.
            constructors.push(
                [
                    bytes(&q),
                    bytes(&angles),
                    order.to_vec(),
                    bytes(&[from, to, up].concat()),
                    bytes(&m),
                    bytes(&[e, 1.0, 0.0, angles[0], 0.0, e, 1.0]),
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
    write("slices", slices_seeds())?;
    write("blend", blend_seeds())?;
    write("laws", laws_seeds())?;
    write("obj", obj_seeds())?;
    write("csv", csv_seeds())?;
    regressions()
}

/// The laws target's seeds: each law of the registry once, with a seed of
/// its own (the law's index byte, then the seed's eight bytes).
fn laws_seeds() -> Vec<Vec<u8>> {
    (0..rigtform_proofs::laws::registry::LAWS.len())
        .map(|i| {
            let mut seed = vec![i as u8];
            seed.extend_from_slice(&(i as u64 * 7919).to_le_bytes());
            seed
        })
        .collect()
}

/// The slices target's seeds: `alpha`, whether it is taken into (0, 1],
/// the extra length of `out`, then elements of two quaternions, a
/// translation and a kind byte (raw, unit, identical, opposite, one ulp
/// apart, raw identical), at the lengths around the vector lanes' steps of
/// sixteen pairs.
fn slices_seeds() -> Vec<Vec<u8>> {
    let mut seeds = Vec::new();
    for (i, &len) in [1usize, 7, 15, 16, 17, 31, 32, 33, 40].iter().enumerate() {
        for (alpha, in_unit) in [(0.5f32, 1u8), (0.25, 0), (EDGE_F32[i % EDGE_F32.len()], 0)] {
            let mut seed = bytes(&[alpha]);
            seed.extend([in_unit, u8::try_from(len % 4).unwrap_or(0)]);
            for k in 0..len {
                let t = k as f32;
                let e = EDGE_F32[(i + k) % EDGE_F32.len()];
                seed.extend(bytes(&[0.5, 0.1 * t, -0.3, 0.7]));
                seed.extend(bytes(&[0.2, -0.4 * t, 0.6, e]));
                seed.extend(bytes(&[t, e, -1.0]));
                seed.push(u8::try_from(k % 6).unwrap_or(0) | u8::try_from(k % 8 * 16).unwrap_or(0));
            }
            seeds.push(seed);
        }
    }
    seeds
}

/// The blend target's seeds: whether to normalize, the power of two, then
/// entries of a quaternion and a weight, with the weights from the
/// subnormal to `f32::MAX` and the edge values.
fn blend_seeds() -> Vec<Vec<u8>> {
    let mut seeds = Vec::new();
    let weights = [f32::MAX, -f32::MAX, 1.0, f32::from_bits(1), 1e38, 0.5];
    for (i, e) in EDGE_F32.into_iter().enumerate() {
        let power = [1i8, -1, 60, -60][i % 4].to_le_bytes()[0];
        let mut seed = vec![1, power];
        let entries = [
            ([0.5, 0.5, 0.5, 0.5], weights[i % weights.len()]),
            ([0.0, 1.0, 0.0, 0.0], e),
            ([0.5, -0.5, 0.5, -0.5], weights[(i + 1) % weights.len()]),
            ([e, 0.0, 0.0, 1.0], 1.0),
        ];
        for (q, w) in entries.iter().take(1 + i % 4) {
            seed.extend(bytes(q));
            seed.extend(bytes(&[*w]));
        }
        seeds.push(seed);
    }
    seeds
}

/// The OBJ target's seeds: OBJ text as a user gives it, good and bad.
fn obj_seeds() -> Vec<Vec<u8>> {
    [
        "v 0 0 0\nv 4 0 0\nv 0 2 0\nf 1 2 3\n",
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
         f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\nf 1/1/1 2/1/1 3/1/1\n",
        "o a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 0\nf 1//1 2//1 3//1\no b\nv 0 0 1\nv 0 1 1\nv 1 0 1\nf 4 5 6\n",
        "v -2e38 0 0\nv 2e38 0 0\nv 0 1 0\nf 1 2 3\n",
        "v 0 0 0\nv 1e-45 0 0\nv 0 1e-45 0\nf 1 2 3\n",
        "v 1e20 0 0\nv 3e20 0 0\nv 1e20 2e20 0\nf 1 2 3\n",
        "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\nf -1 -2 -3\n",
        "v nan 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n",
        "mtllib missing.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 \\\n",
    ]
    .iter()
    .map(|s| s.as_bytes().to_vec())
    .collect()
}

/// The CSV target's seeds: BROAD trials and a Fusion log, with a
/// byte-order mark, blank lines, CRLF, and bad rows.
fn csv_seeds() -> Vec<Vec<u8>> {
    let broad = "gyr_x,gyr_y,gyr_z,acc_x,acc_y,acc_z,mag_x,mag_y,mag_z,quat_w,quat_x,quat_y,quat_z,movement";
    let row = "0.1,0,0,0,0,9.81,0,16,-41,1,0,0,0,1";
    let fusion = "Time (s),Gyroscope X (deg/s),Gyroscope Y (deg/s),Gyroscope Z (deg/s),Accelerometer X (g),Accelerometer Y (g),Accelerometer Z (g),Magnetometer X (uT),Magnetometer Y (uT),Magnetometer Z (uT)";
    let fusion_row = "0.01,1,2,3,0,0,1,20,0,-40";
    [
        format!("{broad}\n{row}\n{row}\n"),
        format!("\u{feff}{broad}\n{row}\n"),
        format!("{broad}\r\n\r\n{row}\r\n  \r\n{row}\r\n"),
        format!("{broad}\n{row}\n0.1,0,0,x,0,9.81,0,16,-41,1,0,0,0,1\n"),
        format!("{broad}\n0.1,0,0,0,0,9.81,0,16,-41,nan,nan,nan,nan,2\n"),
        format!("{broad}\n{row},7\n0,0\n"),
        format!("{fusion}\n{fusion_row}\n{fusion_row}\n"),
        "a,b\n1,2\n".to_string(),
        String::new(),
    ]
    .into_iter()
    .map(String::into_bytes)
    .collect()
}
