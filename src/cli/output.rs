//! The JSON output of `run`: a tree of numbers rendered as strings.
//!
//! An algorithm builds an [`Out<T>`] in whatever number type it ran in. Rendering is the only
//! place the number type matters: exact fractions for rationals, shortest round-trip decimals
//! for f64, and for MPFR the digits on which two runs at p and 2p bits agree.

use crate::scalar::certify::{certify, format_float_digits};
use crate::scalar::{Field, Float, Real};
use serde_json::{Map, Value};

/// A JSON-like tree whose numbers are values of `T`.
#[derive(Clone, Debug)]
pub enum Out<T> {
    Num(T),
    List(Vec<Out<T>>),
    Object(Vec<(String, Out<T>)>),
    /// A count or an index: printed as a JSON integer, not a string.
    Int(i64),
    Text(String),
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

/// x, or 0 when |x| is below `level`.
pub fn flush<T: Real>(x: T, level: Option<&T>) -> T {
    match level {
        Some(l) if x.clone().abs() < *l => T::zero_in(&x.ctx()),
        _ => x,
    }
}

/// The largest |x| of `values`, if there is one.
pub fn largest<'a, T: Real + 'a>(values: impl IntoIterator<Item = &'a T>) -> Option<T> {
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

/// Render with every number as its plain string (`to_plain_string`).
pub fn render_plain<T: Field>(out: &Out<T>) -> Value {
    match out {
        Out::Num(x) => Value::String(x.to_plain_string()),
        Out::List(items) => Value::Array(items.iter().map(render_plain).collect()),
        Out::Object(fields) => Value::Object(
            fields
                .iter()
                .map(|(k, v)| (k.clone(), render_plain(v)))
                .collect::<Map<_, _>>(),
        ),
        Out::Int(i) => Value::from(*i),
        Out::Text(s) => Value::String(s.clone()),
        Out::F64(x) => f64_value(*x),
        Out::Null => Value::Null,
    }
}

/// Render the more precise tree `hi` with the digits it shares with `lo`. Fails (naming the
/// field) if the trees differ in shape or a number has no certified digit at all.
pub fn render_certified(lo: &Out<Float>, hi: &Out<Float>, path: &str) -> Result<Value, String> {
    Ok(match (lo, hi) {
        (Out::Num(a), Out::Num(b)) => {
            let c = certify(a, b);
            if c.digits == 0 && !(a.is_zero() && b.is_zero()) {
                return Err(format!(
                    "output \"{path}\": no digit agrees between {} and {} bits ({} vs {}); raise the precision",
                    a.prec(),
                    b.prec(),
                    format_float_digits(a, 6),
                    format_float_digits(b, 6)
                ));
            }
            Value::String(c.text)
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
                let p = if path.is_empty() {
                    k.clone()
                } else {
                    format!("{path}.{k}")
                };
                map.insert(k.clone(), render_certified(x, y, &p)?);
            }
            Value::Object(map)
        }
        (_, other @ (Out::Int(_) | Out::Text(_) | Out::F64(_) | Out::Null)) => render_plain(other),
        _ => {
            return Err(format!(
                "internal: outputs at two precisions differ in shape at \"{path}\""
            ))
        }
    })
}
