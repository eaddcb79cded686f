//! What [`RigTForm::interpolate_slice`] adds to the slerp of many
//! rotations (`quat/slerp/slice.rs`): the translations, lerped beside them.

use super::RigTForm;
use crate::quat::{Quat, Slerped, WithRotation};

impl WithRotation for RigTForm {
    #[inline(always)]
    fn rotation(&self) -> &Quat {
        &self.r
    }
    #[inline(always)]
    fn rotation_mut(&mut self) -> &mut Quat {
        &mut self.r
    }
}

impl Slerped for RigTForm {
    #[inline(always)]
    fn lerp_rest(start: &Self, end: &Self, alpha: f32, out: &mut Self) {
        out.t = start.t.lerp(end.t, alpha);
    }
    #[cfg(x86_sse_lanes)]
    #[inline(always)]
    fn lerp_rest_of(starts: &[Self], ends: &[Self], alpha: f32, out: &mut [Self]) {
        lerp_all_components(starts, ends, alpha, out);
    }
}

/// `out[i].t = starts[i].t.lerp(ends[i].t, alpha)` for many RigTForms at
/// once: every one of their f32 components (rotations too, which are
/// written again afterwards) as `x (1 - alpha) + y alpha`, the operations
/// of `Cvec3::lerp`, in a loop the compiler vectorizes. One of the few
/// places of the crate's `unsafe` code: the slices of RigTForms seen as
/// slices of f32.
#[cfg(x86_sse_lanes)]
#[allow(unsafe_code)]
#[inline(always)]
fn lerp_all_components(starts: &[RigTForm], ends: &[RigTForm], alpha: f32, out: &mut [RigTForm]) {
    /// The f32 components of a RigTForm.
    const FLOATS: usize = 7;
    const { assert!(core::mem::size_of::<RigTForm>() == 4 * FLOATS) };
    const { assert!(core::mem::align_of::<RigTForm>() == 4) };
    let n = starts.len().min(ends.len()).min(out.len());
    // SAFETY: `RigTForm` is `repr(C)` of a `Cvec3` and a `Quat`, each
    // `repr(C)` of f32s: `FLOATS` f32 with no padding and the alignment of
    // f32 (checked above, at compile time), every bit pattern of which is
    // a valid value, so `n` of them, which each slice has, are `n FLOATS`
    // f32. The views borrow the slices as they are borrowed here (`out`
    // mutably, and only through its view while that is alive).
    let (x, y, to) = unsafe {
        (
            core::slice::from_raw_parts(starts.as_ptr().cast::<f32>(), n * FLOATS),
            core::slice::from_raw_parts(ends.as_ptr().cast::<f32>(), n * FLOATS),
            core::slice::from_raw_parts_mut(out.as_mut_ptr().cast::<f32>(), n * FLOATS),
        )
    };
    for ((to, x), y) in to.iter_mut().zip(x).zip(y) {
        *to = x * (1.0 - alpha) + y * alpha;
    }
}
