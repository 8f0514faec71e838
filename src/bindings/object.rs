//! Plain JS objects built by the bindings: events, views, results.

use js_sys::{Object, Reflect};
use wasm_bindgen::JsValue;

/// Builds a plain JS object from (key, value) pairs.
pub fn object(entries: &[(&str, JsValue)]) -> JsValue {
    let obj = Object::new();
    for (key, value) in entries {
        Reflect::set(&obj, &(*key).into(), value).expect("setting a property of a fresh object");
    }
    obj.into()
}

/// Sets `key` on an object a binding made (it cannot fail on a plain object).
pub fn set(object: &JsValue, key: &str, value: JsValue) {
    let _ = Reflect::set(object, &key.into(), &value);
}
