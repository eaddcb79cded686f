//! The pre-generated inputs every library is timed on, drawn with the
//! testkit's [`Draws`](rigtform_testkit::Draws), as the tests' and the
//! accuracy report's inputs are.

/// One set of random inputs, drawn once from a fixed seed.
pub struct Inputs {
    /// Uniformly distributed unit quaternions `[w, x, y, z]`.
    pub a: Vec<[f32; 4]>,
    /// A second, independent set of them.
    pub b: Vec<[f32; 4]>,
    /// Vectors with components in [-10, 10] (also the translations).
    pub v: Vec<[f32; 3]>,
    /// A second set of vectors.
    pub u: Vec<[f32; 3]>,
    /// Interpolation parameters in [0, 1].
    pub alpha: Vec<f32>,
}

impl Inputs {
    /// `n` of each input, from the seed `seed`.
    pub fn new(n: usize, seed: u64) -> Self {
        let mut d = rigtform_testkit::Draws::new(seed);
        let quats = |d: &mut rigtform_testkit::Draws| -> Vec<[f32; 4]> {
            (0..n)
                .map(|_| {
                    let q = d.unit_quat();
                    [q.w, q.x, q.y, q.z]
                })
                .collect()
        };
        let (a, b) = (quats(&mut d), quats(&mut d));
        let vec3s = |d: &mut rigtform_testkit::Draws| -> Vec<[f32; 3]> {
            (0..n)
                .map(|_| core::array::from_fn(|_| d.uniform(-10.0, 10.0) as f32))
                .collect()
        };
        let (v, u) = (vec3s(&mut d), vec3s(&mut d));
        let alpha = (0..n).map(|_| d.uniform(0.0, 1.0) as f32).collect();
        Self { a, b, v, u, alpha }
    }
}
