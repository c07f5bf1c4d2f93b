//! The JSON output of `run`: a tree of numbers rendered as strings.
//!
//! An algorithm builds an [`Out<T>`] in whatever number type it ran in. Rendering is the only
//! place the number type matters: exact fractions for rationals, shortest round-trip decimals
//! for f64, and for MPFR the digits on which two runs at p and 2p bits agree.

use super::input::RunError;
use crate::scalar::ball::Ball;
use crate::scalar::certify::{certify, format_float_digits};
use crate::scalar::{Field, Float, Real};
use serde_json::{Map, Value};

/// A JSON-like tree whose numbers are values of `T`.
#[derive(Clone, Debug)]
pub enum Out<T> {
    Num(T),
    /// A number that may vanish mathematically, with the scale of the quantities it was
    /// computed from. Printed like [`Out::Num`], except that when two precisions agree on
    /// no digit and both values lie below [`noise_level`] of the scale at the lower
    /// precision, it is printed as 0: it is zero to the precision printed (a straight line's
    /// conversion error, an ERBS weight far below the resolution), not unknown.
    MaybeZero(T, T),
    List(Vec<Out<T>>),
    Object(Vec<(String, Out<T>)>),
    /// A count or an index: printed as a JSON integer, not a string.
    Int(i64),
    Text(String),
    /// A yes/no answer, printed as a JSON boolean.
    Bool(bool),
    /// A double reported as a JSON number (e.g. an f64 reference value), or null if not finite.
    F64(f64),
    Null,
}

impl<T> Out<T> {
    /// An object from (name, value) pairs, in order.
    pub fn object(fields: Vec<(&str, Out<T>)>) -> Self {
        Out::Object(
            fields
                .into_iter()
                .map(|(k, v)| (k.to_string(), v))
                .collect(),
        )
    }
    /// This object with one more field at the end (a non-object is returned unchanged).
    pub fn with_field(self, name: &str, value: Out<T>) -> Self {
        match self {
            Out::Object(mut fields) => {
                fields.push((name.to_string(), value));
                Out::Object(fields)
            }
            other => other,
        }
    }
    /// A list of numbers.
    pub fn nums(values: Vec<T>) -> Self {
        Out::List(values.into_iter().map(Out::Num).collect())
    }
}

/// The level below which a value computed at the working precision cannot be told from 0
/// next to quantities of size `scale`: 2^(16−p)·|scale| at p bits.
///
/// A quantity that vanishes mathematically comes out as rounding noise of either sign, on
/// which no two precisions agree, so printing it certified is impossible; below this level
/// it is printed as 0. Used only where the output has a natural scale (coordinates next to
/// the largest coordinate), never for values computed with relative accuracy.
pub fn noise_level<T: Real>(scale: &T) -> T {
    let ctx = scale.ctx();
    let bits = T::precision_bits(&ctx).saturating_sub(16);
    scale.clone().abs() * &crate::scalar::powi(&T::from_ratio(1, 2, &ctx), bits)
}

/// x, or 0 when |x| is below `level` (never for enclosures, whose balls around 0 are the
/// honest answer).
pub fn flush<T: Real>(x: T, level: Option<&T>) -> T {
    if T::ENCLOSURE {
        return x;
    }
    match level {
        Some(l) if x.clone().abs() < *l => T::zero_in(&x.ctx()),
        _ => x,
    }
}

/// The largest |x| of `values`, if there is one.
pub fn largest<'a, T: Real + 'a>(values: impl IntoIterator<Item = &'a T>) -> Option<T> {
    if T::ENCLOSURE {
        return None; // only used to scale the noise level, which enclosures do not flush
    }
    values.into_iter().fold(None, |m: Option<T>, x| {
        let a = x.clone().abs();
        match m {
            Some(m) if m >= a => Some(m),
            _ => Some(a),
        }
    })
}

fn f64_value(x: f64) -> Value {
    serde_json::Number::from_f64(x).map_or(Value::Null, |n| {
        // With arbitrary_precision a Number keeps text; give it the shortest round-trip form.
        serde_json::from_str(&crate::scalar::float_text(x)).unwrap_or(Value::Number(n))
    })
}

/// The path of field `key` inside the object at `path` ("a.b"), for error messages.
fn field_path(path: &str, key: &str) -> String {
    if path.is_empty() {
        key.to_string()
    } else {
        format!("{path}.{key}")
    }
}

/// Render with every number as its plain string (`to_plain_string`).
pub fn render_plain<T: Field>(out: &Out<T>) -> Value {
    match out {
        Out::Num(x) | Out::MaybeZero(x, _) => Value::String(x.to_plain_string()),
        Out::List(items) => Value::Array(items.iter().map(render_plain).collect()),
        Out::Object(fields) => Value::Object(
            fields
                .iter()
                .map(|(k, v)| (k.clone(), render_plain(v)))
                .collect::<Map<_, _>>(),
        ),
        Out::Int(i) => Value::from(*i),
        Out::Text(s) => Value::String(s.clone()),
        Out::Bool(b) => Value::Bool(*b),
        Out::F64(x) => f64_value(*x),
        Out::Null => Value::Null,
    }
}

/// Render a ball tree: each number as {"value", "radius"}, two decimals with every point
/// of the ball inside [value − radius, value + radius] as printed ([`Ball::printed`]):
/// `value` carries the digits every point of the ball rounds to (the midpoint to two digits
/// when not even one is proven) and `radius` is measured from `value`, rounded up.
/// Fails, naming the field, when a ball is not finite (an unbounded enclosure).
pub fn render_proven(out: &Out<Ball>, path: &str) -> Result<Value, RunError> {
    Ok(match out {
        Out::Num(b) | Out::MaybeZero(b, _) => {
            let Some(printed) = b.printed() else {
                if b.mid().is_finite() && b.mid().clone().abs() > 1e290 {
                    return Err(RunError::Input(format!(
                        "output \"{path}\" is about {} in ball:{}: beyond the range of a ball's radius (an f64, about 1e308); use mpfr:<bits>",
                        format_float_digits(b.mid(), 3),
                        b.ctx()
                    )));
                }
                return Err(RunError::Input(format!(
                    "output \"{path}\" has no finite enclosure in ball:{}: an operation met a ball containing a singularity \
                     (a division by a ball around 0, a square root or logarithm of one reaching below 0); raise the precision",
                    b.ctx()
                )));
            };
            let mut m = Map::new();
            m.insert("value".into(), Value::String(printed.value));
            m.insert("radius".into(), Value::String(printed.radius));
            Value::Object(m)
        }
        Out::List(items) => Value::Array(
            items
                .iter()
                .enumerate()
                .map(|(i, v)| render_proven(v, &format!("{path}[{i}]")))
                .collect::<Result<_, _>>()?,
        ),
        Out::Object(fields) => Value::Object(
            fields
                .iter()
                .map(|(k, v)| render_proven(v, &field_path(path, k)).map(|r| (k.clone(), r)))
                .collect::<Result<Map<_, _>, _>>()?,
        ),
        Out::Int(i) => Value::from(*i),
        Out::Text(s) => Value::String(s.clone()),
        Out::Bool(b) => Value::Bool(*b),
        Out::F64(x) => f64_value(*x),
        Out::Null => Value::Null,
    })
}

/// Render the more precise tree `hi` with the digits it shares with `lo`. Fails (naming the
/// field) if a number is not finite or has no certified digit at all (input errors: the
/// input is beyond the precision), or if the trees differ in shape (an internal error).
pub fn render_certified(lo: &Out<Float>, hi: &Out<Float>, path: &str) -> Result<Value, RunError> {
    Ok(match (lo, hi) {
        (Out::Num(a), Out::Num(b)) => certified_number(a, b, None, path)?,
        (Out::MaybeZero(a, sa), Out::MaybeZero(b, sb)) => {
            certified_number(a, b, Some((sa, sb)), path)?
        }
        (Out::List(xs), Out::List(ys)) if xs.len() == ys.len() => Value::Array(
            xs.iter()
                .zip(ys)
                .enumerate()
                .map(|(i, (x, y))| render_certified(x, y, &format!("{path}[{i}]")))
                .collect::<Result<_, _>>()?,
        ),
        (Out::Object(xs), Out::Object(ys)) if xs.len() == ys.len() => {
            let mut map = Map::new();
            for ((k, x), (_, y)) in xs.iter().zip(ys) {
                map.insert(k.clone(), render_certified(x, y, &field_path(path, k))?);
            }
            Value::Object(map)
        }
        (_, other @ (Out::Int(_) | Out::Text(_) | Out::Bool(_) | Out::F64(_) | Out::Null)) => {
            render_plain(other)
        }
        _ => {
            return Err(RunError::internal(format!(
                "outputs at two precisions differ in shape at \"{path}\""
            )))
        }
    })
}

/// The digits `a` (at p bits) and `b` (at 2p bits) agree on; with `scales` (the scales of
/// the quantities each was computed from), "0" when they agree on none but both lie below
/// [`noise_level`] of their scale (see [`Out::MaybeZero`]); the flag says which. `None`: no
/// digit is certified.
pub fn agreed_text(
    a: &Float,
    b: &Float,
    scales: Option<(&Float, &Float)>,
) -> Option<(String, bool)> {
    let c = certify(a, b);
    if c.digits > 0 || (a.is_zero() && b.is_zero()) {
        return Some((c.text, false));
    }
    // Both below the lower precision's resolution: the higher one may resolve a real value
    // there (an ERBS weight of 1e-58 beside a path of size 20), but a p-bit result holds no
    // digit of it, so 0 is its value to the precision printed.
    let (sa, _) = scales?;
    let level = noise_level(sa);
    let noise = a.clone().abs() < level && b.clone().abs() < level;
    noise.then(|| ("0".to_string(), true))
}

/// One number with the digits `lo` and `hi` agree on; with `scales`, a value that is noise
/// at both precisions is 0 (see [`Out::MaybeZero`]).
fn certified_number(
    a: &Float,
    b: &Float,
    scales: Option<(&Float, &Float)>,
    path: &str,
) -> Result<Value, RunError> {
    if !a.is_finite() || !b.is_finite() {
        let bad = if a.is_finite() { b } else { a };
        return Err(not_finite(
            path,
            &bad.to_string(),
            &format!("mpfr:{}", bad.prec()),
        ));
    }
    if let Some((text, _)) = agreed_text(a, b, scales) {
        return Ok(Value::String(text));
    }
    Err(RunError::Input(format!(
        "output \"{path}\": no digit agrees between {} and {} bits ({} vs {}); raise the precision",
        a.prec(),
        b.prec(),
        format_float_digits(a, 6),
        format_float_digits(b, 6)
    )))
}

/// The refusal of a result that is not finite in the chosen number type.
fn not_finite(path: &str, value: &str, scalar: &str) -> RunError {
    RunError::Input(format!(
        "output \"{path}\" is {value} in {scalar}: the input is beyond what this number type can carry (smaller magnitudes, or --scalar mpfr:<bits>)"
    ))
}

/// Whether a printed number says NaN or an infinity (as f64, MPFR or our own printing do).
fn says_not_finite(text: &str) -> bool {
    let t = text.trim_start_matches(['-', '+']).trim_matches('@');
    t.eq_ignore_ascii_case("nan")
        || t.eq_ignore_ascii_case("inf")
        || t.eq_ignore_ascii_case("infinity")
}

/// Refuse an output in which any number is NaN or infinite, naming the first such field.
///
/// The last check before anything is printed, whatever path built the output (typed
/// [`Out`] trees or JSON assembled directly): a non-finite result is never printed.
pub fn check_finite(value: &Value, path: &str, scalar: &str) -> Result<(), RunError> {
    match value {
        Value::String(s) if says_not_finite(s) => Err(not_finite(path, s, scalar)),
        Value::Array(items) => items
            .iter()
            .enumerate()
            .try_for_each(|(i, v)| check_finite(v, &format!("{path}[{i}]"), scalar)),
        Value::Object(map) => map
            .iter()
            .try_for_each(|(k, v)| check_finite(v, &field_path(path, k), scalar)),
        _ => Ok(()),
    }
}
