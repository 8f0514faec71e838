//! The first steps of each session type on a fuzzed small exemplar (any size up to 24x24, 1, 3
//! or 4 channels, any pixels, flat or not) with small, mostly sensible options: a session that
//! was built must step without panicking.
#![no_main]

#[path = "common/mod.rs"]
mod common;

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut u = arbitrary::Unstructured::new(data);
    let Ok(exemplar) = common::exemplar(&mut u) else {
        return;
    };
    let _ = common::drive(&mut u, &exemplar, common::Values::Small, 3);
});
