//! The renderer's OBJ loader (`Mesh::parse_obj`, behind `Mesh::load_obj`
//! and `--obj`) on any bytes: an error or a mesh it can draw, never a
//! panic: finite positions within the requested size, unit normals, one
//! normal and colour per position, and every triangle's indices in range.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rigtform_render::Mesh;

/// The longest side the loaded mesh is scaled to.
const SIZE: f32 = 2.0;

fuzz_target!(|text: &[u8]| {
    let Ok(mesh) = Mesh::parse_obj(text, SIZE, [0.8, 0.6, 0.4]) else {
        return;
    };
    let n = mesh.positions.len();
    assert!(!mesh.triangles.is_empty());
    assert_eq!(mesh.normals.len(), n);
    assert_eq!(mesh.colors.len(), n);
    assert!(mesh.triangles.iter().flatten().all(|&i| (i as usize) < n));
    // Centred on its box, its longest side SIZE: every coordinate within
    // SIZE / 2, up to rounding.
    let limit = SIZE / 2.0 * (1.0 + 1e-5);
    for p in &mesh.positions {
        assert!(p.is_finite(), "{p:?}");
        assert!(
            p.x.abs() <= limit && p.y.abs() <= limit && p.z.abs() <= limit,
            "{p:?}"
        );
    }
    for normal in &mesh.normals {
        assert!((normal.norm() - 1.0).abs() <= 1e-5, "{normal:?}");
    }
});
