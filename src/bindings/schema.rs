//! The declared shape of everything JS passes in and gets back: per session, one table of its
//! options (key, type, range, default, doc) and one of its event's fields (key, TypeScript type,
//! doc). The options reader checks keys and values against the table, so the error naming a bad
//! key or value comes from it; events are built through the table, so a field cannot be added or
//! dropped without it; and the package's TypeScript declarations of options and events
//! (`schema.d.ts`) are written from it by `scripts/make-typings.mjs`, which reads the tables
//! through the hidden export `__schema()`.

use js_sys::Array;
use wasm_bindgen::prelude::*;

use super::error::JsResult;
use super::object::object;
use crate::core::Error;

/// What an option's value must be.
#[derive(Clone, Copy, Debug)]
pub enum Kind {
    /// A whole number in `min..=max`.
    Integer { min: u64, max: u64 },
    /// A finite number (ranges are checked by the method, which names them).
    Number,
    /// `true` or `false`.
    Boolean,
    /// One of these strings.
    Choice(&'static [&'static str]),
    /// An array of whole numbers in `min..=max`.
    Integers { min: u64, max: u64 },
    /// An array of finite numbers.
    Numbers,
    /// A value the binding reads itself (an object, a typed array); the TypeScript type.
    Value(&'static str),
}

impl Kind {
    /// The TypeScript type of a value of this kind.
    fn typescript(self) -> String {
        match self {
            Kind::Integer { .. } | Kind::Number => "number".into(),
            Kind::Boolean => "boolean".into(),
            Kind::Choice(names) => names
                .iter()
                .map(|n| format!("'{n}'"))
                .collect::<Vec<_>>()
                .join(" | "),
            Kind::Integers { .. } | Kind::Numbers => "number[]".into(),
            Kind::Value(ts) => ts.into(),
        }
    }
}

/// One option of a session.
#[derive(Clone, Copy, Debug)]
pub struct Opt {
    pub key: &'static str,
    pub kind: Kind,
    /// The default as a JS literal (`256`, `'patchmatch'`, `[32, 16, 8]`), or `None` where it
    /// depends on other options or on the input (the doc says how).
    pub default: Option<&'static str>,
    pub doc: &'static str,
}

/// One field of a session's event (or of another object a binding returns).
#[derive(Clone, Copy, Debug)]
pub struct EventField {
    pub key: &'static str,
    /// Its TypeScript type; `| null` where it can be absent.
    pub ts: &'static str,
    pub doc: &'static str,
}

/// The declared shape of one JS-visible class.
#[derive(Clone, Copy, Debug)]
pub struct Schema {
    /// The class (or function) the options belong to: `TextureOptimization`.
    pub class: &'static str,
    /// The TypeScript name of its options interface: `TextureOptimizationOptions`.
    pub options_name: &'static str,
    pub options: &'static [Opt],
    /// Keys that must be given (all others are optional).
    pub required: &'static [&'static str],
    /// The TypeScript name of its event interface, and the fields; empty for classes without
    /// `step()`.
    pub event_name: &'static str,
    pub event: &'static [EventField],
}

/// Output width or height: every session that makes an image of a chosen size takes them.
pub const fn output_size(
    key: &'static str,
    max: u64,
    default: Option<&'static str>,
    doc: &'static str,
) -> Opt {
    Opt {
        key,
        kind: Kind::Integer { min: 1, max },
        default,
        doc,
    }
}

/// A boolean option with its default.
pub const fn boolean(key: &'static str, default: &'static str, doc: &'static str) -> Opt {
    Opt {
        key,
        kind: Kind::Boolean,
        default: Some(default),
        doc,
    }
}

/// A number option (ranges are the method's to check).
pub const fn number(key: &'static str, default: Option<&'static str>, doc: &'static str) -> Opt {
    Opt {
        key,
        kind: Kind::Number,
        default,
        doc,
    }
}

/// `memoryBudgetMiB`, which every session that allocates by its options takes.
pub const MEMORY_BUDGET: Opt = Opt {
    key: "memoryBudgetMiB",
    kind: Kind::Number,
    default: Some("1024"),
    doc: "The largest working set the session may plan, in MiB (16 to 3584); larger inputs are \
          refused by the constructor with the estimate and this budget in the message.",
};

/// `seed`, for sessions that draw random numbers.
pub const SEED: Opt = Opt {
    key: "seed",
    kind: Kind::Integer {
        min: 0,
        max: (1 << 53) - 1,
    },
    default: Some("1"),
    doc: "Seed of the random choices: the same seed, options and input give the same bytes.",
};

/// The first two fields of every event.
pub const fn kind_field(ts: &'static str) -> EventField {
    EventField {
        key: "kind",
        ts,
        doc: "What the step did; 'done' on the last step.",
    }
}

/// `done`, the second field of every event.
pub const DONE: EventField = EventField {
    key: "done",
    ts: "boolean",
    doc: "True on the last step (then `kind` is 'done').",
};

impl Schema {
    /// A plain event object with exactly the declared fields, in the declared order.
    pub fn event(&self, entries: &[(&'static str, JsValue)]) -> JsResult<JsValue> {
        let same = entries.len() == self.event.len()
            && entries
                .iter()
                .zip(self.event)
                .all(|((k, _), f)| *k == f.key);
        if !same {
            let given: Vec<&str> = entries.iter().map(|(k, _)| *k).collect();
            let declared: Vec<&str> = self.event.iter().map(|f| f.key).collect();
            return Err(JsError::new(&format!(
                "{} event fields [{}] differ from the declared [{}]",
                self.class,
                given.join(", "),
                declared.join(", ")
            )));
        }
        Ok(object(entries))
    }

    /// The table as a plain JS object, for the typings generator and the drift test.
    pub fn to_js(self) -> JsValue {
        let options: Array = self
            .options
            .iter()
            .map(|o| {
                object(&[
                    ("key", o.key.into()),
                    ("ts", o.kind.typescript().into()),
                    ("default", o.default.map_or(JsValue::NULL, JsValue::from)),
                    ("doc", o.doc.into()),
                    ("choices", choices(o.kind)),
                ])
            })
            .collect();
        let event: Array = self
            .event
            .iter()
            .map(|f| {
                object(&[
                    ("key", f.key.into()),
                    ("ts", f.ts.into()),
                    ("doc", f.doc.into()),
                ])
            })
            .collect();
        object(&[
            ("class", self.class.into()),
            ("optionsName", self.options_name.into()),
            ("options", options.into()),
            (
                "required",
                self.required
                    .iter()
                    .map(|&k| JsValue::from(k))
                    .collect::<Array>()
                    .into(),
            ),
            ("eventName", self.event_name.into()),
            ("event", event.into()),
        ])
    }
}

fn choices(kind: Kind) -> JsValue {
    match kind {
        Kind::Choice(names) => names
            .iter()
            .map(|&n| JsValue::from(n))
            .collect::<Array>()
            .into(),
        _ => JsValue::NULL,
    }
}

pub fn undeclared(class: &str, key: &str) -> JsError {
    JsError::new(&format!(
        "{class}: option '{key}' is read but not declared in its options table"
    ))
}

/// The error for a bad value of option `name`.
pub fn invalid(name: &'static str, reason: impl Into<String>) -> JsError {
    Error::InvalidParameter {
        name,
        reason: reason.into(),
    }
    .into()
}
