//! Option validation: every session type built from options filled with values a JS caller
//! could pass after the bindings' type checks (any finite number, any whole number, any flag),
//! on a fixed small exemplar. Each must be refused with an error or make a session that takes a
//! first step; never a panic, never an allocation beyond the memory budget.
#![no_main]

#[path = "common/mod.rs"]
mod common;

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut u = arbitrary::Unstructured::new(data);
    let exemplar = common::fixed_exemplar();
    let _ = common::drive(&mut u, &exemplar, common::Values::Wild, 1);
});
