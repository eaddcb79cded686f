//! The attitude filters' updates, for the flash column of `cargo xtask
//! filter-cost --peers` (`bin/size.rs` links one of them): ours and
//! uf-ahrs's VQF, Mahony and Madgwick, each made as its docs show (ours
//! with `FilterParams::DEFAULT`, uf-ahrs's with `new(3.5 ms, default
//! parameters)`), then one 6D or one 9D update. The filter is handed to
//! the update through `black_box`, so that the build keeps every path of
//! the update, not only those a new filter's first sample takes. The
//! gyroscope is `u`, the accelerometer `v`, the magnetometer the vector
//! part of `a`. Their instruction counts come from `bin/filter_cost.rs`,
//! not from the bench's table.

use core::hint::black_box;
use core::time::Duration;

use rigtform::attitude::{FilterParams, OrientationFilter};
use rigtform::Cvec3;
use uf_ahrs::{Ahrs, Madgwick, MadgwickParams, Mahony, MahonyParams, Vqf, VqfParams};

use super::{put, Input, Output};

/// BROAD's sample period, the one `bin/filter_cost.rs` runs at.
const PERIOD: Duration = Duration::from_micros(3500);

fn vectors(x: &Input) -> [[f32; 3]; 3] {
    [x.u, x.v, [x.a[1], x.a[2], x.a[3]]]
}

fn cvec3(v: [f32; 3]) -> Cvec3 {
    Cvec3::new(v[0], v[1], v[2])
}

fn vector(v: [f32; 3]) -> nalgebra::Vector3<f32> {
    nalgebra::Vector3::new(v[0], v[1], v[2])
}

fn nalgebra_out(o: &mut Output, q: nalgebra::UnitQuaternion<f32>) {
    put(o, &[q.w, q.i, q.j, q.k]);
}

pub fn rigtform_filter_6d(x: &Input, o: &mut Output) {
    let [gyr, acc, _] = vectors(x);
    let mut f = OrientationFilter::new(FilterParams::DEFAULT);
    let q = black_box(&mut f).update(cvec3(gyr), cvec3(acc), 0.0035);
    put(o, &[q.w, q.x, q.y, q.z]);
}
pub fn rigtform_filter_9d(x: &Input, o: &mut Output) {
    let [gyr, acc, mag] = vectors(x);
    let mut f = OrientationFilter::new(FilterParams::DEFAULT);
    let q = black_box(&mut f).update_with_mag(cvec3(gyr), cvec3(acc), cvec3(mag), 0.0035);
    put(o, &[q.w, q.x, q.y, q.z]);
}

/// One 6D update of `filter`, made by `new`.
fn peer_6d(x: &Input, o: &mut Output, mut filter: impl Ahrs) {
    let [gyr, acc, _] = vectors(x);
    nalgebra_out(
        o,
        black_box(&mut filter).update_imu(vector(gyr), vector(acc)),
    );
}
/// One 9D update of `filter`.
fn peer_9d(x: &Input, o: &mut Output, mut filter: impl Ahrs) {
    let [gyr, acc, mag] = vectors(x);
    nalgebra_out(
        o,
        black_box(&mut filter).update(vector(gyr), vector(acc), vector(mag)),
    );
}

pub fn uf_ahrs_vqf_6d(x: &Input, o: &mut Output) {
    peer_6d(x, o, Vqf::new(PERIOD, VqfParams::default()));
}
pub fn uf_ahrs_vqf_9d(x: &Input, o: &mut Output) {
    peer_9d(x, o, Vqf::new(PERIOD, VqfParams::default()));
}
pub fn uf_ahrs_mahony_6d(x: &Input, o: &mut Output) {
    peer_6d(x, o, Mahony::new(PERIOD, MahonyParams::default()));
}
pub fn uf_ahrs_mahony_9d(x: &Input, o: &mut Output) {
    peer_9d(x, o, Mahony::new(PERIOD, MahonyParams::default()));
}
pub fn uf_ahrs_madgwick_6d(x: &Input, o: &mut Output) {
    peer_6d(x, o, Madgwick::new(PERIOD, MadgwickParams::default()));
}
pub fn uf_ahrs_madgwick_9d(x: &Input, o: &mut Output) {
    peer_9d(x, o, Madgwick::new(PERIOD, MadgwickParams::default()));
}
