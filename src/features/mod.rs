//! Optional integrations, one file each.

#[cfg(feature = "mint")]
mod impl_mint;
