//! The members every JS-visible session shares (`step()`, `done`, `width`, `height`,
//! `memoryEstimate`, `renderInto`), written once: a binding implements [`JsSession`] and
//! `js_session!` gives its class the JS members. Iteration and `run()` are added to every class
//! with a `step()` by the package's `iterate.js`.

use js_sys::Uint8ClampedArray;
use wasm_bindgen::JsValue;

use super::error::JsResult;

/// What a binding says about its session; the JS members come from `js_session!`.
pub trait JsSession {
    /// Runs one step and returns its event object (built through the class's event table).
    fn step_event(&mut self) -> JsResult<JsValue>;
    fn is_done(&self) -> bool;
    /// The output's width and height as far as it is made.
    fn size(&self) -> (usize, usize);
    /// The estimated peak memory in bytes: what the constructor compared with the budget.
    fn memory_bytes(&self) -> u64;
    /// Writes the current output as RGBA8 into `target` (`width * height * 4` long).
    fn render(&self, target: &Uint8ClampedArray) -> JsResult<()>;
}

/// The shared JS members of a class that implements [`JsSession`].
macro_rules! js_session {
    ($class:ident) => {
        #[wasm_bindgen::prelude::wasm_bindgen]
        impl $class {
            /// Runs one step and returns its event.
            pub fn step(&mut self) -> $crate::bindings::error::JsResult<wasm_bindgen::JsValue> {
                $crate::bindings::session::JsSession::step_event(self)
            }

            /// True once the last step has run.
            #[wasm_bindgen(getter)]
            pub fn done(&self) -> bool {
                $crate::bindings::session::JsSession::is_done(self)
            }

            /// The output's width in pixels.
            #[wasm_bindgen(getter)]
            pub fn width(&self) -> u32 {
                $crate::bindings::session::JsSession::size(self).0 as u32
            }

            /// The output's height in pixels.
            #[wasm_bindgen(getter)]
            pub fn height(&self) -> u32 {
                $crate::bindings::session::JsSession::size(self).1 as u32
            }

            /// The estimated peak memory of this session, in bytes: what the constructor
            /// compared with the memory budget (`memoryBudgetMiB`).
            #[wasm_bindgen(getter, js_name = memoryEstimate)]
            pub fn memory_estimate(&self) -> f64 {
                $crate::bindings::session::JsSession::memory_bytes(self) as f64
            }

            /// Writes the current output as RGBA8 into `target` (`width * height * 4` long).
            #[wasm_bindgen(js_name = renderInto)]
            pub fn render_into(
                &self,
                target: &js_sys::Uint8ClampedArray,
            ) -> $crate::bindings::error::JsResult<()> {
                $crate::bindings::session::JsSession::render(self, target)
            }
        }
    };
}

pub(crate) use js_session;
