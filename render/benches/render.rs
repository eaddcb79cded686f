//! Rendering the demo scene at 640x480: `rigtform-render` with 4x MSAA and
//! with one sample per pixel, on one thread and on all cores, side by side
//! with the `euc` software rasterizer (0.5.3, single-threaded, no MSAA and
//! no clipping) drawing the same triangles with the same matrices, a depth
//! test, back-face culling and the same per-pixel shading function.
//!
//! Run with `cargo bench -p rigtform-render`. Criterion reports the time
//! per frame and, as throughput, submitted triangles per second.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use euc::buffer::Buffer2d;
use euc::rasterizer::{BackfaceCullingEnabled, Triangles};
use euc::Pipeline;
use rigtform_render::demo::{Comparison, Demo};
use rigtform_render::{
    linear_to_srgb8, Cull, Lighting, Mesh, Msaa, Scene, Settings, Transforms, ATTRIBUTES,
};

const WIDTH: u32 = 640;
const HEIGHT: u32 = 480;

type V3 = (f32, f32, f32);

/// One draw of the scene as an `euc` pipeline: the vertex shader is our
/// vertex stage, the fragment shader our shading function.
struct EucDraw<'a> {
    mesh: &'a Mesh,
    t: Transforms,
    tint: [f32; 3],
    lighting: &'a Lighting,
}

impl Pipeline for EucDraw<'_> {
    type Vertex = u32;
    type VsOut = (V3, V3, V3);
    type Pixel = u32;

    fn vert(&self, &i: &u32) -> ([f32; 4], Self::VsOut) {
        let i = i as usize;
        let (p, n, c) = (
            self.mesh.positions[i],
            self.mesh.normals[i],
            self.mesh.colors[i],
        );
        let p4 = rigtform::Cvec4::from_point(p);
        let clip = self.t.mvp * p4;
        let eye = (self.t.mvm * p4).xyz();
        let normal = (self.t.nmvm * rigtform::Cvec4::from_vector(n)).xyz();
        (
            clip.to_array(),
            (
                (eye.x, eye.y, eye.z),
                (normal.x, normal.y, normal.z),
                (
                    c[0] * self.tint[0],
                    c[1] * self.tint[1],
                    c[2] * self.tint[2],
                ),
            ),
        )
    }

    fn frag(&self, &(p, n, c): &Self::VsOut) -> u32 {
        let a: [f32; ATTRIBUTES] = [p.0, p.1, p.2, n.0, n.1, n.2, c.0, c.1, c.2];
        let [r, g, b] = self.lighting.shade(&a).map(linear_to_srgb8);
        u32::from(r) << 16 | u32::from(g) << 8 | u32::from(b)
    }
}

/// The scene drawn by `euc`; `indices` holds each draw's triangles as a
/// flat index list.
fn render_euc(scene: &Scene, indices: &[Vec<u32>]) -> Buffer2d<u32> {
    let mut color = Buffer2d::new([WIDTH as usize, HEIGHT as usize], 0u32);
    let mut depth = Buffer2d::new([WIDTH as usize, HEIGHT as usize], 1.0f32);
    let lighting = Lighting::new(scene.camera.eye, scene.lights, scene.intensity);
    let projection = scene.camera.projection(WIDTH as f32 / HEIGHT as f32);
    for (draw, idx) in scene.draws.iter().zip(indices) {
        let Some(t) = Transforms::new(scene.camera.eye, draw.placement, draw.scale, projection)
        else {
            continue;
        };
        let pipeline = EucDraw {
            mesh: draw.mesh,
            t,
            tint: draw.tint,
            lighting: &lighting,
        };
        pipeline.draw::<Triangles<'_, Buffer2d<f32>, BackfaceCullingEnabled>, _>(
            idx,
            &mut color,
            Some(&mut depth),
        );
    }
    color
}

fn bench(c: &mut Criterion) {
    let demo = Demo::new(Comparison::Slerp, None);
    let scene = demo.scene(&demo.panels()[0], 0.5);
    let indices: Vec<Vec<u32>> = scene
        .draws
        .iter()
        .map(|d| d.mesh.triangles.iter().flatten().copied().collect())
        .collect();
    let triangles: usize = scene.draws.iter().map(|d| d.mesh.triangles.len()).sum();
    let settings = |msaa| Settings {
        width: WIDTH,
        height: HEIGHT,
        msaa,
        cull: Cull::Back,
    };

    // The two renderers draw the same picture: compare the pixels covered.
    let ours = scene.render(&settings(Msaa::Off));
    let theirs = render_euc(&scene, &indices);
    let background = ours.pixel(0, 0);
    let differing = ours
        .pixels()
        .iter()
        .zip(theirs.as_ref())
        .filter(|(a, &b)| {
            let b = [(b >> 16) as u8, (b >> 8) as u8, b as u8];
            let b = if b == [0; 3] { background } else { b };
            (0..3).any(|k| a[k].abs_diff(b[k]) > 8)
        })
        .count();
    println!(
        "demo scene: {triangles} triangles; euc and rigtform-render (1 sample) differ by more than 8/255 \
         on {differing} of {} pixels ({:.2}%)",
        ours.pixels().len(),
        100.0 * differing as f64 / ours.pixels().len() as f64
    );

    let mut group = c.benchmark_group("demo_640x480");
    group.throughput(Throughput::Elements(triangles as u64));
    group.sample_size(20);
    group.measurement_time(Duration::from_secs(6));
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    for (msaa, name) in [
        (Msaa::X4, "rigtform-render 4x MSAA"),
        (Msaa::Off, "rigtform-render 1 sample"),
    ] {
        for threads in [1, cores] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            group.bench_function(BenchmarkId::new(name, format!("{threads} threads")), |b| {
                b.iter(|| pool.install(|| black_box(scene.render(&settings(msaa)))));
            });
        }
    }
    group.bench_function(BenchmarkId::new("euc 0.5.3 1 sample", "1 thread"), |b| {
        b.iter(|| black_box(render_euc(&scene, &indices)));
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
