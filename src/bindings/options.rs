//! Reading a plain JS options object (`{ outputWidth: 256, seed: 7 }`): unknown keys are refused
//! by name, and every value is checked for its type and range before it reaches the methods.

use js_sys::{Array, Object, Reflect};
use wasm_bindgen::{JsCast, JsValue};

use super::error::JsResult;
use crate::core::Error;
use crate::core::budget::{
    DEFAULT_MEMORY_BUDGET_MIB, MAX_MEMORY_BUDGET_MIB, MIN_MEMORY_BUDGET_MIB,
};

/// An options object whose keys have been checked against the known ones.
pub struct OptionsReader {
    object: Object,
}

fn invalid(name: &'static str, reason: impl Into<String>) -> wasm_bindgen::JsError {
    Error::InvalidParameter {
        name,
        reason: reason.into(),
    }
    .into()
}

impl OptionsReader {
    /// Accepts `undefined`/`null` (all defaults) or a plain object with only `known` keys.
    pub fn new(value: &JsValue, known: &[&str]) -> JsResult<OptionsReader> {
        if value.is_undefined() || value.is_null() {
            return Ok(OptionsReader {
                object: Object::new(),
            });
        }
        let Some(object) = value.dyn_ref::<Object>().filter(|_| value.is_object()) else {
            return Err(invalid(
                "options",
                "must be an object such as { outputWidth: 256 }",
            ));
        };
        // Reflect.ownKeys catches a Proxy's throwing trap (Object.keys would unwind through
        // the wasm); symbol keys are not options and are passed over.
        let keys = Reflect::own_keys(object)
            .map_err(|_| invalid("options", "its keys could not be read"))?;
        for key in keys.iter() {
            let Some(key) = key.as_string() else {
                continue;
            };
            if !known.contains(&key.as_str()) {
                let mut msg = Error::UnknownOption(key).to_string();
                msg.push_str(&format!(" (known options: {})", known.join(", ")));
                return Err(wasm_bindgen::JsError::new(&msg));
            }
        }
        Ok(OptionsReader {
            object: object.clone(),
        })
    }

    /// The raw value of `name`, for options that are objects or typed arrays.
    pub fn value(&self, name: &'static str) -> JsResult<Option<JsValue>> {
        self.get(name)
    }

    /// The value of `name`, None when absent. A getter that throws is an error naming the
    /// option (caught here, so it cannot unwind through a session and leave it borrowed).
    fn get(&self, name: &'static str) -> JsResult<Option<JsValue>> {
        let v = Reflect::get(&self.object, &name.into()).map_err(|e| {
            let why = e
                .dyn_ref::<js_sys::Error>()
                .map(|e| String::from(e.message()))
                .or_else(|| e.as_string())
                .unwrap_or_else(|| "it threw".into());
            invalid(name, format!("could not be read: {why}"))
        })?;
        Ok((!v.is_undefined() && !v.is_null()).then_some(v))
    }

    /// A finite number.
    pub fn number(&self, name: &'static str) -> JsResult<Option<f64>> {
        match self.get(name)? {
            None => Ok(None),
            Some(v) => match v.as_f64() {
                Some(n) if n.is_finite() => Ok(Some(n)),
                Some(n) => Err(invalid(name, format!("must be a finite number, got {n}"))),
                None => Err(invalid(name, "must be a number")),
            },
        }
    }

    /// A whole number in `min..=max`.
    pub fn integer(&self, name: &'static str, min: u64, max: u64) -> JsResult<Option<u64>> {
        match self.number(name)? {
            None => Ok(None),
            Some(n) if n.fract() == 0.0 && n >= min as f64 && n <= max as f64 => Ok(Some(n as u64)),
            Some(n) => Err(invalid(
                name,
                format!("must be a whole number from {min} to {max}, got {n}"),
            )),
        }
    }

    pub fn boolean(&self, name: &'static str) -> JsResult<Option<bool>> {
        match self.get(name)? {
            None => Ok(None),
            Some(v) => v
                .as_bool()
                .map(Some)
                .ok_or_else(|| invalid(name, "must be true or false")),
        }
    }

    pub fn string(&self, name: &'static str) -> JsResult<Option<String>> {
        match self.get(name)? {
            None => Ok(None),
            Some(v) => v
                .as_string()
                .map(Some)
                .ok_or_else(|| invalid(name, "must be a string")),
        }
    }

    /// An array of whole numbers in `min..=max`.
    pub fn integers(&self, name: &'static str, min: u64, max: u64) -> JsResult<Option<Vec<u64>>> {
        let Some(v) = self.get(name)? else {
            return Ok(None);
        };
        if !Array::is_array(&v) {
            return Err(invalid(name, "must be an array of whole numbers"));
        }
        let mut out = Vec::new();
        for item in Array::from(&v).iter() {
            match item.as_f64() {
                Some(n) if n.fract() == 0.0 && n >= min as f64 && n <= max as f64 => {
                    out.push(n as u64)
                }
                _ => {
                    return Err(invalid(
                        name,
                        format!(
                            "each entry must be a whole number from {min} to {max}, got {item:?}"
                        ),
                    ));
                }
            }
        }
        Ok(Some(out))
    }
}

impl OptionsReader {
    /// An array of finite numbers.
    pub fn numbers(&self, name: &'static str) -> JsResult<Option<Vec<f64>>> {
        let Some(v) = self.get(name)? else {
            return Ok(None);
        };
        if !Array::is_array(&v) {
            return Err(invalid(name, "must be an array of numbers"));
        }
        Array::from(&v)
            .iter()
            .map(|item| match item.as_f64() {
                Some(n) if n.is_finite() => Ok(n),
                _ => Err(invalid(
                    name,
                    format!("each entry must be a finite number, got {item:?}"),
                )),
            })
            .collect::<JsResult<Vec<f64>>>()
            .map(Some)
    }
}

/// Builds a plain JS object from (key, value) pairs.
pub fn object(entries: &[(&str, JsValue)]) -> JsValue {
    let obj = Object::new();
    for (key, value) in entries {
        Reflect::set(&obj, &(*key).into(), value).expect("setting a property of a fresh object");
    }
    obj.into()
}

impl OptionsReader {
    /// `memoryBudgetMiB`: the session's memory budget in MiB (a finite number from
    /// [`MIN_MEMORY_BUDGET_MIB`] to [`MAX_MEMORY_BUDGET_MIB`], rounded down), or the default
    /// [`DEFAULT_MEMORY_BUDGET_MIB`] when absent. See [`crate::core::budget`].
    pub fn memory_budget(&self) -> JsResult<usize> {
        const NAME: &str = "memoryBudgetMiB";
        match self.number(NAME)? {
            None => Ok(DEFAULT_MEMORY_BUDGET_MIB),
            Some(n) if n >= MIN_MEMORY_BUDGET_MIB as f64 && n <= MAX_MEMORY_BUDGET_MIB as f64 => {
                Ok(n as usize)
            }
            Some(n) => Err(invalid(
                NAME,
                format!(
                    "must be a number of MiB from {MIN_MEMORY_BUDGET_MIB} to \
                     {MAX_MEMORY_BUDGET_MIB}, got {n}"
                ),
            )),
        }
    }
}
