//! Library errors become JS `Error` objects carrying the library's message: `wasm_bindgen::JsError`
//! converts any `std::error::Error` through its `Display`, which is why every message of
//! [`crate::core::Error`] names the problem in full.

use wasm_bindgen::JsError;

/// Shorthand for exported functions.
pub type JsResult<T> = Result<T, JsError>;
