//! Reading a plain JS options object (`{ outputWidth: 256, seed: 7 }`): unknown keys are refused
//! by name, and every value is checked for its type and range before it reaches the methods.

use js_sys::{Array, Object, Reflect};
use wasm_bindgen::{JsCast, JsValue};

use std::cell::Cell;

use super::error::JsResult;
pub use super::object::object;
use super::schema::{Kind, Opt, Schema, invalid, undeclared};
use crate::core::Error;
use crate::core::budget::{
    DEFAULT_MEMORY_BUDGET_MIB, MAX_MEMORY_BUDGET_MIB, MIN_MEMORY_BUDGET_MIB,
};

/// An options object whose keys have been checked against a session's options table
/// ([`Schema`]); each value is read by its key and checked against the table's type and range.
pub struct OptionsReader {
    object: Object,
    schema: &'static Schema,
    /// One bit per option of the table, set when it is read: [`Self::finish`] reports a declared
    /// option that the binding never reads.
    read: Cell<u64>,
}

impl OptionsReader {
    /// Accepts `undefined`/`null` (all defaults) or a plain object with only the table's keys.
    pub fn new(value: &JsValue, schema: &'static Schema) -> JsResult<OptionsReader> {
        debug_assert!(schema.options.len() <= 64);
        let reader = |object| OptionsReader {
            object,
            schema,
            read: Cell::new(0),
        };
        if value.is_undefined() || value.is_null() {
            return Ok(reader(Object::new()));
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
            if !schema.options.iter().any(|o| o.key == key) {
                let known: Vec<&str> = schema.options.iter().map(|o| o.key).collect();
                let mut msg = Error::UnknownOption(key).to_string();
                msg.push_str(&format!(" (known options: {})", known.join(", ")));
                return Err(wasm_bindgen::JsError::new(&msg));
            }
        }
        Ok(reader(object.clone()))
    }

    /// The table entry of `name`, marked as read.
    fn declared(&self, name: &'static str) -> JsResult<&'static Opt> {
        let index = self
            .schema
            .options
            .iter()
            .position(|o| o.key == name)
            .ok_or_else(|| undeclared(self.schema.class, name))?;
        self.read.set(self.read.get() | 1 << index);
        Ok(&self.schema.options[index])
    }

    /// Every declared option has been read: a table entry that no code reads would be accepted
    /// and silently ignored.
    pub fn finish(&self) -> JsResult<()> {
        let all = if self.schema.options.len() == 64 {
            u64::MAX
        } else {
            (1u64 << self.schema.options.len()) - 1
        };
        let unread = all & !self.read.get();
        if unread == 0 {
            return Ok(());
        }
        let keys: Vec<&str> = (0..self.schema.options.len())
            .filter(|i| unread >> i & 1 == 1)
            .map(|i| self.schema.options[i].key)
            .collect();
        Err(wasm_bindgen::JsError::new(&format!(
            "{}: declared options never read: {}",
            self.schema.class,
            keys.join(", ")
        )))
    }

    /// The raw value of `name`, for options that are objects or typed arrays.
    pub fn value(&self, name: &'static str) -> JsResult<Option<JsValue>> {
        self.declared(name)?;
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
        self.declared(name)?;
        self.finite(name)
    }

    fn finite(&self, name: &'static str) -> JsResult<Option<f64>> {
        match self.get(name)? {
            None => Ok(None),
            Some(v) => match v.as_f64() {
                Some(n) if n.is_finite() => Ok(Some(n)),
                Some(n) => Err(invalid(name, format!("must be a finite number, got {n}"))),
                None => Err(invalid(name, "must be a number")),
            },
        }
    }

    /// A whole number in the table's range.
    pub fn integer(&self, name: &'static str) -> JsResult<Option<u64>> {
        let Kind::Integer { min, max } = self.declared(name)?.kind else {
            return Err(kind_mismatch(name));
        };
        match self.finite(name)? {
            None => Ok(None),
            Some(n) if n.fract() == 0.0 && n >= min as f64 && n <= max as f64 => Ok(Some(n as u64)),
            Some(n) => Err(invalid(
                name,
                format!("must be a whole number from {min} to {max}, got {n}"),
            )),
        }
    }

    /// A whole number in the table's range, as a size or count.
    pub fn size(&self, name: &'static str) -> JsResult<Option<usize>> {
        Ok(self.integer(name)?.map(|v| v as usize))
    }

    pub fn boolean(&self, name: &'static str) -> JsResult<Option<bool>> {
        self.declared(name)?;
        match self.get(name)? {
            None => Ok(None),
            Some(v) => v
                .as_bool()
                .map(Some)
                .ok_or_else(|| invalid(name, "must be true or false")),
        }
    }

    /// One of the table's choices, turned into the method's value by `parse` (its `from_name`).
    pub fn choice<T>(
        &self,
        name: &'static str,
        parse: impl Fn(&str) -> Option<T>,
    ) -> JsResult<Option<T>> {
        let Kind::Choice(names) = self.declared(name)?.kind else {
            return Err(kind_mismatch(name));
        };
        let Some(v) = self.get(name)? else {
            return Ok(None);
        };
        let Some(text) = v.as_string() else {
            return Err(invalid(name, "must be a string"));
        };
        match parse(&text) {
            Some(value) if names.contains(&text.as_str()) => Ok(Some(value)),
            _ => Err(invalid(
                name,
                format!("must be {}, got '{text}'", one_of(names)),
            )),
        }
    }

    /// An array of whole numbers in the table's range.
    pub fn integers(&self, name: &'static str) -> JsResult<Option<Vec<u64>>> {
        let Kind::Integers { min, max } = self.declared(name)?.kind else {
            return Err(kind_mismatch(name));
        };
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

    /// An array of finite numbers.
    pub fn numbers(&self, name: &'static str) -> JsResult<Option<Vec<f64>>> {
        self.declared(name)?;
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

/// "'a', 'b' or 'c'".
fn one_of(names: &[&str]) -> String {
    let quoted: Vec<String> = names.iter().map(|n| format!("'{n}'")).collect();
    match quoted.split_last() {
        None => String::new(),
        Some((last, [])) => last.clone(),
        Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
    }
}

fn kind_mismatch(name: &'static str) -> wasm_bindgen::JsError {
    wasm_bindgen::JsError::new(&format!(
        "option '{name}' is read as another type than its table declares"
    ))
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
