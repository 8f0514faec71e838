//! Small helpers shared by the wasm-bindgen test cases: building options objects, reading event
//! fields and the message of a thrown JS `Error`.

use js_sys::{Object, Reflect};
use wasm_bindgen::{JsCast, JsValue};

/// A plain JS object from (key, value) pairs, as a page would pass options.
pub fn options(entries: &[(&str, JsValue)]) -> JsValue {
    let obj = Object::new();
    for (k, v) in entries {
        Reflect::set(&obj, &(*k).into(), v).unwrap();
    }
    obj.into()
}

/// A property of a JS object.
pub fn get(value: &JsValue, key: &str) -> JsValue {
    Reflect::get(value, &key.into()).unwrap()
}

/// The message of the JS `Error` a failed call produced.
pub fn error_message<T>(result: Result<T, wasm_bindgen::JsError>) -> String {
    let Err(err) = result else {
        panic!("expected an error")
    };
    let value: JsValue = err.into();
    String::from(
        value
            .dyn_ref::<js_sys::Error>()
            .expect("a JS Error object")
            .message(),
    )
}
