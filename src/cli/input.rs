//! Reading the JSON input of `run`: every error names the field it is about.
//!
//! Numbers may be JSON numbers or strings; both are read exactly as GMP rationals
//! ([`Exact`]; serde_json is built with `arbitrary_precision`, so a JSON number keeps its
//! decimal text and `0.1` means 1/10, not the double nearest to it). Each number type then
//! rounds once from the exact value ([`Field::from_exact`](crate::scalar::Field::from_exact)).

use crate::scalar::parse::parse_exact;
use crate::scalar::Exact;
use serde_json::{Map, Value};

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
/// object (serde_json would silently keep the last of two equal keys).
pub fn parse_document(text: &str) -> Result<Map<String, Value>, InputError> {
    let value = serde_json::from_str::<Value>(text)
        .map_err(|e| InputError(format!("input: malformed JSON: {e}")))?;
    if let Some((key, offset)) = repeated_key(text) {
        let before = text.get(..offset).unwrap_or(text);
        let line = before.matches('\n').count() + 1;
        let column = before.len() - before.rfind('\n').map_or(0, |i| i + 1);
        return fail(format!(
            "input: malformed JSON: the key \"{key}\" appears twice at line {line} column {column}"
        ));
    }
    match value {
        Value::Object(map) => Ok(map),
        other => fail(format!(
            "input: expected a JSON object, found {}",
            kind(&other)
        )),
    }
}

/// The first key that an object of `text` repeats, with the byte offset just after it.
///
/// `text` has already parsed as JSON, so a scan of its bytes suffices: a string is a key when
/// it opens an object's member (after `{` or after `,` inside an object). A key with escapes
/// is decoded before it is compared (`"a"` and `"\u0061"` are the same key). One pass over
/// the bytes, against a second serde pass that cost as much as the parse itself.
fn repeated_key(text: &str) -> Option<(String, usize)> {
    use std::borrow::Cow;
    use std::collections::HashSet;
    let bytes = text.as_bytes();
    // One entry per open container: the keys seen so far for an object, None for an array.
    let mut open: Vec<Option<HashSet<Cow<str>>>> = Vec::new();
    let mut expect_key = false;
    let mut i = 0;
    while let Some(&byte) = bytes.get(i) {
        match byte {
            b'{' => {
                open.push(Some(HashSet::new()));
                expect_key = true;
            }
            b'[' => {
                open.push(None);
                expect_key = false;
            }
            b'}' | b']' => {
                open.pop();
                expect_key = false;
            }
            b',' => expect_key = matches!(open.last(), Some(Some(_))),
            b'"' => {
                let start = i;
                let mut escaped = false;
                i += 1;
                while let Some(&b) = bytes.get(i) {
                    match b {
                        b'"' => break,
                        b'\\' => {
                            escaped = true;
                            i += 2;
                        }
                        _ => i += 1,
                    }
                }
                if expect_key {
                    let quoted = text.get(start..=i)?;
                    let key: Cow<str> = if escaped {
                        Cow::Owned(serde_json::from_str::<String>(quoted).ok()?)
                    } else {
                        Cow::Borrowed(&quoted[1..quoted.len() - 1])
                    };
                    if let Some(Some(seen)) = open.last_mut() {
                        if seen.contains(&key) {
                            return Some((key.into_owned(), i + 1));
                        }
                        seen.insert(key);
                    }
                    expect_key = false;
                }
            }
            _ => {}
        }
        i += 1;
    }
    None
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
pub fn field<'a>(obj: &'a Map<String, Value>, name: &str) -> Result<&'a Value, InputError> {
    obj.get(name)
        .ok_or_else(|| InputError(format!("input: missing field \"{name}\"")))
}

/// Reject fields the algorithm does not know (a misspelt optional field would otherwise be
/// silently ignored).
pub fn only_fields(obj: &Map<String, Value>, known: &[&str]) -> Result<(), InputError> {
    match obj.keys().find(|k| !known.contains(&k.as_str())) {
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
        Value::String(s) => Ok(s.as_str()),
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
pub fn number_value(v: &Value, path: impl std::fmt::Display) -> Result<&Value, InputError> {
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
    obj: &Map<String, Value>,
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
pub fn array<'a>(v: &'a Value, path: &str) -> Result<&'a Vec<Value>, InputError> {
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
    v: &'a Value,
    path: &str,
    read: impl Fn(&'a Value, &dyn std::fmt::Display) -> Result<N, InputError>,
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
    use serde_json::json;

    #[test]
    fn numbers_are_exact_from_json_and_strings() {
        let doc = parse_document(r#"{"a": 0.1, "b": "3/5", "c": 1e-3}"#).unwrap();
        assert_eq!(number(&doc["a"], "a").unwrap(), Exact::from((1, 10)));
        assert_eq!(number(&doc["b"], "b").unwrap(), Exact::from((3, 5)));
        assert_eq!(number(&doc["c"], "c").unwrap(), Exact::from((1, 1000)));
    }

    #[test]
    fn errors_name_the_field() {
        let e = number(&json!("NaN"), "start[2]").unwrap_err();
        assert!(e.0.starts_with("field \"start[2]\""), "{e}");
        let e = uniform_values(&json!([1, [1, 2]]), "end").unwrap_err();
        assert!(
            e.0.contains("end[1]") && e.0.contains("mixed dimensions"),
            "{e}"
        );
        let e = interval(&json!([1, 1]), "interval").unwrap_err();
        assert!(e.0.contains("interval"), "{e}");
        assert!(parse_document("[1]").is_err());
        assert!(parse_document("{")
            .unwrap_err()
            .0
            .contains("malformed JSON"));
        let e = parse_document(r#"{"a": 1, "b": {"c": 2, "c": 3}}"#).unwrap_err();
        assert!(e.0.contains("\"c\" appears twice"), "{e}");
    }

    #[test]
    fn repeated_keys_are_found_in_their_own_object_only() {
        let repeated = |text: &str| repeated_key(text).map(|(key, _)| key);
        // Decoded before comparison: an escaped spelling is the same key.
        assert_eq!(repeated(r#"{"a": 1, "\u0061": 2}"#), Some("a".into()));
        assert_eq!(
            repeated(r#"{"x": [1, {"k": 1, "k": 2}]}"#),
            Some("k".into())
        );
        // Equal keys of different objects, and keys spelt inside string values, are not.
        assert_eq!(repeated(r#"[{"a": 1}, {"a": 1}]"#), None);
        assert_eq!(repeated(r#"{"a": {"b": 1}, "b": 2}"#), None);
        assert_eq!(repeated(r#"{"a": "x,\"a\":{", "b": ["a", "a"]}"#), None);
        assert_eq!(repeated(r#"{"a\"": 1, "a": 2}"#), None);
        let e = parse_document("{\n \"a\": 1,\n \"a\": 2}").unwrap_err();
        assert!(e.0.ends_with("appears twice at line 3 column 4"), "{e}");
        assert!(parse_document(r#"{"a": [1, {"c": 2}, {"c": 3}], "b": 1.5}"#).is_ok());
        let e = count(&json!(2.5), "derivatives", 10).unwrap_err();
        assert!(e.0.contains("whole number"), "{e}");
    }
}
