//! The one error type of the library. Every message names the problem and the value that caused it,
//! because it travels unchanged to JavaScript as the message of an `Error`.

use std::fmt;

/// Everything that can go wrong when building or running a synthesis.
#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// The input bytes were empty.
    EmptyInput,
    /// The bytes could not be decoded as an image (not PNG/JPEG, truncated, corrupt).
    Decode(String),
    /// The image could not be encoded.
    Encode(String),
    /// A width or height of zero, or a size that does not fit the limits.
    InvalidSize {
        /// What has the size ("exemplar", "output", "crop", ...), as the message names it.
        what: &'static str,
        /// The width given, in pixels.
        width: usize,
        /// The height given, in pixels.
        height: usize,
        /// Why the size is refused.
        reason: String,
    },
    /// A buffer whose length does not match the size it is said to have.
    LengthMismatch {
        /// The buffer, as the message names it.
        what: &'static str,
        /// The length the stated size calls for.
        expected: usize,
        /// The length the buffer has.
        actual: usize,
    },
    /// A channel count other than 1 to 4.
    UnsupportedChannels(usize),
    /// A named option or parameter with an impossible value.
    InvalidParameter {
        /// The option or parameter, as the message names it.
        name: &'static str,
        /// What is wrong with its value.
        reason: String,
    },
    /// An option name that the method does not know.
    UnknownOption(String),
    /// A session whose estimated working set exceeds its memory budget (see
    /// `crate::core::budget`); the message names the size, the estimate and the limit.
    MemoryBudget(String),
}

/// The largest side an image may have, in pixels. A decoded image of this size already needs
/// 16384 * 16384 * 4 * 4 bytes = 4 GiB as f32, more than wasm32 can address; refuse before allocating.
pub const MAX_SIDE: usize = 8192;
/// The largest number of pixels an image may have (a 4096 x 4096 image, 256 MiB as RGBA f32).
pub const MAX_PIXELS: usize = 4096 * 4096;

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::EmptyInput => write!(f, "empty input: no image bytes were given"),
            Error::Decode(msg) => write!(f, "could not decode the image: {msg}"),
            Error::Encode(msg) => write!(f, "could not encode the image: {msg}"),
            Error::InvalidSize {
                what,
                width,
                height,
                reason,
            } => {
                write!(f, "invalid {what} size {width}x{height}: {reason}")
            }
            Error::LengthMismatch {
                what,
                expected,
                actual,
            } => {
                write!(f, "{what} has length {actual}, expected {expected}")
            }
            Error::UnsupportedChannels(c) => {
                write!(
                    f,
                    "unsupported channel count {c}: images have 1 to 4 channels"
                )
            }
            Error::InvalidParameter { name, reason } => write!(f, "invalid {name}: {reason}"),
            Error::UnknownOption(name) => write!(f, "unknown option '{name}'"),
            Error::MemoryBudget(msg) => write!(f, "{msg}"),
        }
    }
}

impl std::error::Error for Error {}

/// Shorthand for results of this library.
pub type Result<T> = std::result::Result<T, Error>;

/// Checks that a `width` x `height` image is non-empty and within [`MAX_SIDE`] and [`MAX_PIXELS`].
pub fn check_size(what: &'static str, width: usize, height: usize) -> Result<()> {
    let fail = |reason: String| {
        Err(Error::InvalidSize {
            what,
            width,
            height,
            reason,
        })
    };
    if width == 0 || height == 0 {
        return fail("width and height must be at least 1".into());
    }
    if width > MAX_SIDE || height > MAX_SIDE {
        return fail(format!("each side must be at most {MAX_SIDE} pixels"));
    }
    if width.saturating_mul(height) > MAX_PIXELS {
        return fail(format!("at most {MAX_PIXELS} pixels are supported"));
    }
    Ok(())
}

/// Checks that a parameter is a finite number.
pub fn check_finite(name: &'static str, value: f64) -> Result<()> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(Error::InvalidParameter {
            name,
            reason: format!("must be a finite number, got {value}"),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn size_checks_name_the_problem() {
        assert!(check_size("exemplar", 1, 1).is_ok());
        let zero = check_size("exemplar", 0, 5).unwrap_err().to_string();
        assert!(zero.contains("exemplar") && zero.contains("0x5"), "{zero}");
        let huge = check_size("output", 100_000, 100_000)
            .unwrap_err()
            .to_string();
        assert!(
            huge.contains("100000x100000") && huge.contains("at most"),
            "{huge}"
        );
        let many = check_size("output", 8192, 8192).unwrap_err().to_string();
        assert!(many.contains("pixels"), "{many}");
    }

    #[test]
    fn finite_check_names_the_parameter() {
        assert!(check_finite("r", 0.8).is_ok());
        let msg = check_finite("r", f64::NAN).unwrap_err().to_string();
        assert!(msg.contains("invalid r") && msg.contains("NaN"), "{msg}");
        assert!(check_finite("mu", f64::INFINITY).is_err());
    }
}
