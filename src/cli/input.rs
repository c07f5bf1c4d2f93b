//! Reading the JSON input of `run`: every error names the field it is about.
//!
//! Numbers may be JSON numbers or strings; both are read exactly as GMP rationals
//! ([`Exact`]; the input's tree, [`json`](super::json), keeps a JSON number's decimal text, so
//! `0.1` means 1/10, not the double nearest to it). Each number type then
//! rounds once from the exact value ([`Field::from_exact`](crate::scalar::Field::from_exact)).

use super::json::{Map, Value};
use crate::scalar::parse::parse_exact;
use crate::scalar::Exact;

/// A user-facing input error: one line, naming the field.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct InputError(pub String);

/// `Err` with a one-line input error; the error type is whatever the caller returns (an
/// [`InputError`], or a [`RunError`] at the top of a command).
pub fn fail<T, E: From<InputError>>(message: impl Into<String>) -> Result<T, E> {
    Err(InputError(message.into()).into())
}

/// Why a `run` command did not produce its output.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum RunError {
    /// The input (or the chosen scalar) cannot be answered: exit status 2.
    Input(String),
    /// The input was accepted but a method did not do its job (an iteration that did not
    /// converge, an internal consistency check): exit status 3. Not the user's fault.
    Internal(String),
}

impl From<InputError> for RunError {
    fn from(e: InputError) -> Self {
        RunError::Input(e.0)
    }
}

impl RunError {
    /// An internal failure; the message is prefixed with "internal: ".
    pub fn internal(message: impl std::fmt::Display) -> Self {
        RunError::Internal(format!("internal: {message}"))
    }
}

/// Parse the whole input document, which must be a JSON object with no key repeated in any
/// object (serde_json would silently keep the last of two equal keys). Numbers keep their
/// text ([`json`](super::json)); a text that is not JSON gets serde_json's message.
pub fn parse_document(text: &str) -> Result<Map<'_>, InputError> {
    let parsed = match super::json::parse(text) {
        Ok(parsed) => parsed,
        Err(malformed) => {
            let message = match serde_json::from_str::<serde_json::Value>(text) {
                Err(e) => e.to_string(),
                // Not expected (the tests compare the two parsers): say where this one stopped.
                Ok(_) => {
                    let (line, column) = line_column(text, malformed.offset);
                    format!("unexpected text at line {line} column {column}")
                }
            };
            return fail(format!("input: malformed JSON: {message}"));
        }
    };
    if let Some((key, offset)) = parsed.repeated_key {
        let (line, column) = line_column(text, offset);
        return fail(format!(
            "input: malformed JSON: the key \"{key}\" appears twice at line {line} column {column}"
        ));
    }
    match parsed.value {
        Value::Object(map) => Ok(map),
        other => fail(format!(
            "input: expected a JSON object, found {}",
            kind(&other)
        )),
    }
}

/// The line (from 1) and column (bytes since the line's start) of byte `offset` of `text`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = text.get(..offset).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let column = before.len() - before.rfind('\n').map_or(0, |i| i + 1);
    (line, column)
}

/// A short name for the JSON type of `v`, for error messages.
pub fn kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// The field `name` of `obj`, or an error naming it.
pub fn field<'a>(obj: &'a Map<'a>, name: &str) -> Result<&'a Value<'a>, InputError> {
    obj.get(name)
        .ok_or_else(|| InputError(format!("input: missing field \"{name}\"")))
}

/// Reject fields the algorithm does not know (a misspelt optional field would otherwise be
/// silently ignored).
pub fn only_fields(obj: &Map, known: &[&str]) -> Result<(), InputError> {
    match obj.keys().find(|k| !known.contains(k)) {
        Some(k) => fail(format!(
            "input: unknown field \"{k}\" (expected {})",
            known.join(", ")
        )),
        None => Ok(()),
    }
}

/// A number (JSON number or numeric string) at `path`, read exactly. The path is any
/// `Display` (`format_args!("at[{i}]")`), formatted only for an error message.
pub fn number(v: &Value, path: impl std::fmt::Display) -> Result<Exact, InputError> {
    let text = number_text(v, &path)?;
    parse_exact(text).map_err(|e| InputError(format!("field \"{path}\": {e}")))
}

/// The text of a JSON number or string at `path`, the refusal for any other JSON type.
fn number_text<'a>(v: &'a Value, path: &dyn std::fmt::Display) -> Result<&'a str, InputError> {
    match v {
        Value::Number(n) => Ok(n.as_str()),
        Value::String(s) => Ok(s),
        other => fail(format!(
            "field \"{path}\": expected a number or a numeric string, found {}",
            kind(other)
        )),
    }
}

/// The number at `path` in the number type `T`: the same value as `T::from_exact` of
/// [`number`] gives, through the type's shortcut for JSON numbers where it has one
/// ([`Field::from_json_number`](crate::scalar::Field::from_json_number): an f64 run reads a
/// decimal straight to its double, without a big rational per number).
pub fn number_in<T: crate::scalar::Field>(
    v: &Value,
    path: impl std::fmt::Display,
    ctx: &T::Ctx,
) -> Result<T, InputError> {
    if let Value::Number(n) = v {
        if let Some(x) = T::from_json_number(n.as_str(), ctx) {
            return Ok(x);
        }
    }
    number(v, path).map(|q| T::from_exact(&q, ctx))
}

/// The JSON value at `path` if it can be a number (a JSON number or a string), read later
/// by [`number_in`] in the number type of the run.
pub fn number_value<'a>(
    v: &'a Value<'a>,
    path: impl std::fmt::Display,
) -> Result<&'a Value<'a>, InputError> {
    number_text(v, &path).map(|_| v)
}

/// The path of coordinate `coordinate` of entry `index` of a [`uniform_values`] list named
/// `name`: `name[index][coordinate]` for points, `name[index]` for numbers.
pub struct ValuePath<'a> {
    pub name: &'a str,
    pub index: usize,
    pub coordinate: usize,
    pub is_point: bool,
}

impl std::fmt::Display for ValuePath<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        match self.is_point {
            true => write!(f, "{}[{}][{}]", self.name, self.index, self.coordinate),
            false => write!(f, "{}[{}]", self.name, self.index),
        }
    }
}

/// A real input: an exact number, or a constant expression such as `"pi/8"` (the curve
/// language without t) that is evaluated in the working precision.
pub use crate::curve::expr::ExactReal as RealInput;

/// The value of an exact input in `T`; an error naming `path` if it is not finite.
pub fn real_in<T: crate::scalar::Real>(
    x: &RealInput,
    ctx: &T::Ctx,
    path: &str,
) -> Result<T, InputError> {
    let v = x.eval::<T>(ctx);
    if !v.is_finite() {
        return fail(format!("field \"{path}\": the expression is not finite"));
    }
    Ok(v)
}

/// A number, or a string holding a number or a constant expression (`"pi/8"`), at `path`.
pub fn real(v: &Value, path: &str) -> Result<RealInput, InputError> {
    match v {
        Value::String(text) if parse_exact(text).is_err() => RealInput::parse(text)
            .map_err(|message| InputError(format!("field \"{path}\": {message}"))),
        _ => number(v, path).map(|q| RealInput::Exact(crate::scalar::big_rational(&q))),
    }
}

/// One of the keywords `options` (name, value) at `path`; `default` when the field is absent
/// (`None`: the field is required).
pub fn choice<T: Copy>(
    obj: &Map,
    path: &str,
    options: &[(&str, T)],
    default: Option<T>,
) -> Result<T, InputError> {
    let v = match (obj.get(path), default) {
        (None, Some(d)) => return Ok(d),
        (None, None) => return fail(format!("input: missing field \"{path}\"")),
        (Some(v), _) => v,
    };
    if let Value::String(s) = v {
        if let Some((_, value)) = options.iter().find(|(name, _)| name == s) {
            return Ok(*value);
        }
    }
    let names: Vec<String> = options.iter().map(|(n, _)| format!("\"{n}\"")).collect();
    let found = match v {
        Value::String(s) => format!("{s:?}"),
        other => kind(other).to_string(),
    };
    fail(format!(
        "field \"{path}\": expected {}, found {found}",
        names.join(" or ")
    ))
}

/// A point [x_1, …, x_N] of exactly N numbers at `path`.
pub fn point<const N: usize>(v: &Value, path: &str) -> Result<[Exact; N], InputError> {
    let items = array(v, path)?;
    if items.len() != N {
        let names = ["x", "y", "z"];
        let shape = if N <= names.len() {
            names[..N].join(", ")
        } else {
            format!("{N} numbers")
        };
        return fail(format!(
            "field \"{path}\": expected [{shape}], found {} values",
            items.len()
        ));
    }
    let mut out = Vec::with_capacity(N);
    for (k, x) in items.iter().enumerate() {
        out.push(number(x, format_args!("{path}[{k}]"))?);
    }
    out.try_into()
        .map_err(|_| InputError(format!("internal: field \"{path}\" has {N} entries")))
}

/// A non-negative whole number at `path`, at most `max`.
pub fn count(v: &Value, path: &str, max: usize) -> Result<usize, InputError> {
    let q = number(v, path)?;
    let n = crate::scalar::parse::exact_integer(&q)
        .filter(|n| *n >= 0)
        .ok_or_else(|| {
            InputError(format!(
                "field \"{path}\": expected a whole number ≥ 0, found {q}"
            ))
        })?;
    if n as u128 > max as u128 {
        return fail(format!(
            "field \"{path}\": {n} is larger than the supported maximum {max}"
        ));
    }
    Ok(n as usize)
}

/// An array at `path`.
pub fn array<'a>(v: &'a Value<'a>, path: &str) -> Result<&'a Vec<Value<'a>>, InputError> {
    v.as_array().ok_or_else(|| {
        InputError(format!(
            "field \"{path}\": expected an array, found {}",
            kind(v)
        ))
    })
}

/// An interval [a, b] with b > a at `path`.
pub fn interval(v: &Value, path: &str) -> Result<(Exact, Exact), InputError> {
    let items = array(v, path)?;
    if items.len() != 2 {
        return fail(format!(
            "field \"{path}\": expected [t0, t1], found {} values",
            items.len()
        ));
    }
    let a = number(&items[0], format_args!("{path}[0]"))?;
    let b = number(&items[1], format_args!("{path}[1]"))?;
    if b <= a {
        return fail(format!(
            "field \"{path}\": t1 = {b} must be greater than t0 = {a}"
        ));
    }
    Ok((a, b))
}

/// A value that is either a number or a point (an array of numbers).
#[derive(Clone, Debug, PartialEq)]
pub enum NumOrPoint<N> {
    Number(N),
    Point(Vec<N>),
}

/// A list whose entries are all numbers or all points of one dimension d ≥ 1. Returns the
/// entries as points (a number is a point of dimension 1) and whether they were points.
pub fn uniform_values(v: &Value, path: &str) -> Result<(Vec<Vec<Exact>>, bool), InputError> {
    uniform_values_with(v, path, |x, p| number(x, p))
}

/// [`uniform_values`] with each number read by `read` (given the value and its path):
/// [`number`] reads exactly, [`number_value`] keeps the JSON values for [`number_in`].
pub fn uniform_values_with<'a, N>(
    v: &'a Value<'a>,
    path: &str,
    read: impl Fn(&'a Value<'a>, &dyn std::fmt::Display) -> Result<N, InputError>,
) -> Result<(Vec<Vec<N>>, bool), InputError> {
    let items = array(v, path)?;
    if items.is_empty() {
        return fail(format!(
            "field \"{path}\": needs at least one value (the position)"
        ));
    }
    let mut out = Vec::with_capacity(items.len());
    let mut shape: Option<Option<usize>> = None; // Some(None): numbers, Some(Some(d)): points
    for (i, item) in items.iter().enumerate() {
        let p = format_args!("{path}[{i}]");
        let value = match item {
            Value::Array(coords) => {
                if coords.is_empty() {
                    return fail(format!(
                        "field \"{p}\": a point needs at least one coordinate"
                    ));
                }
                let c = coords
                    .iter()
                    .enumerate()
                    .map(|(k, x)| read(x, &format_args!("{path}[{i}][{k}]")))
                    .collect::<Result<Vec<_>, _>>()?;
                NumOrPoint::Point(c)
            }
            other => NumOrPoint::Number(read(other, &p)?),
        };
        let this = match &value {
            NumOrPoint::Number(_) => None,
            NumOrPoint::Point(c) => Some(c.len()),
        };
        match shape {
            None => shape = Some(this),
            Some(s) if s != this => {
                let describe = |s: Option<usize>| {
                    s.map_or("a number".to_string(), |d| {
                        format!("a point of dimension {d}")
                    })
                };
                return fail(format!(
                    "field \"{p}\": mixed dimensions: {} where earlier values are {}",
                    describe(this),
                    describe(s)
                ));
            }
            Some(_) => {}
        }
        out.push(match value {
            NumOrPoint::Number(q) => vec![q],
            NumOrPoint::Point(c) => c,
        });
    }
    Ok((out, matches!(shape, Some(Some(_)))))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The JSON value of `text`.
    fn value(text: &str) -> Value<'_> {
        super::super::json::parse(text).unwrap().value
    }

    #[test]
    fn numbers_are_exact_from_json_and_strings() {
        let doc = parse_document(r#"{"a": 0.1, "b": "3/5", "c": 1e-3}"#).unwrap();
        let read = |name: &str| number(field(&doc, name).unwrap(), name).unwrap();
        assert_eq!(read("a"), Exact::from((1, 10)));
        assert_eq!(read("b"), Exact::from((3, 5)));
        assert_eq!(read("c"), Exact::from((1, 1000)));
    }

    #[test]
    fn errors_name_the_field() {
        let e = number(&value("\"NaN\""), "start[2]").unwrap_err();
        assert!(e.0.starts_with("field \"start[2]\""), "{e}");
        let e = uniform_values(&value("[1, [1, 2]]"), "end").unwrap_err();
        assert!(
            e.0.contains("end[1]") && e.0.contains("mixed dimensions"),
            "{e}"
        );
        let e = interval(&value("[1, 1]"), "interval").unwrap_err();
        assert!(e.0.contains("interval"), "{e}");
        assert!(parse_document("[1]").is_err());
        let e = count(&value("2.5"), "derivatives", 10).unwrap_err();
        assert!(e.0.contains("whole number"), "{e}");
    }

    #[test]
    fn malformed_documents_get_serde_json_messages_and_repeated_keys_their_place() {
        // serde_json's own message, position included.
        assert_eq!(
            parse_document("{").unwrap_err().0,
            "input: malformed JSON: EOF while parsing an object at line 1 column 1"
        );
        assert_eq!(
            parse_document("{\"a\": [1, 2,]}").unwrap_err().0,
            "input: malformed JSON: trailing comma at line 1 column 13"
        );
        let e = parse_document(r#"{"a": 1, "b": {"c": 2, "c": 3}}"#).unwrap_err();
        assert!(e.0.contains("\"c\" appears twice"), "{e}");
        let e = parse_document("{\n \"a\": 1,\n \"a\": 2}").unwrap_err();
        assert!(e.0.ends_with("appears twice at line 3 column 4"), "{e}");
        // A text that is not JSON is refused as such even after a repeated key.
        let e = parse_document(r#"{"a": 1, "a": 2, }"#).unwrap_err();
        assert!(e.0.contains("trailing comma"), "{e}");
        assert!(parse_document(r#"{"a": [1, {"c": 2}, {"c": 3}], "b": 1.5}"#).is_ok());
    }
}
